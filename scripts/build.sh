#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release). Usage: scripts/build.sh [preset] [targets...]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
shift || true
cmake --preset "$preset" >/dev/null
# One compile job a core: Ninja's default (cores + 2) was 15-20 % slower on two cores, where each job needs
# 1-1.5 GB (docs/measurements/ci_time.md, "One compile job a core").
jobs="$(nproc)"
if [ $# -gt 0 ]; then
  cmake --build --preset "$preset" --parallel "$jobs" --target "$@"
else
  cmake --build --preset "$preset" --parallel "$jobs"
fi
