#!/usr/bin/env bash
# The side-by-side comparison of issue 8: poinsot's RATTLE beside Bullet, ODE, MuJoCo and Simbody on the same
# chain of ball-jointed rods, in one Google Benchmark program (bench/peers/, docs/benchmarks.md).
#   1. installs the four peers' Debian packages (idempotent, like scripts/setup.sh; they are NOT in setup.sh:
#      poinsot and its CI do not need them),
#   2. configures the release preset with -DPOINSOT_BENCH_PEERS=ON and builds bench_multibody_peers only,
#   3. runs it with tabular counters; extra arguments go to the benchmark, e.g.
#        bash scripts/bench-peers.sh --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#        bash scripts/bench-peers.sh --benchmark_filter='/(16|64)/'
# Run from anywhere; takes a few minutes (MuJoCo's 256-link chain alone is about a minute a repetition).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libbullet-dev libode-dev libmujoco-dev libsimbody-dev pkg-config)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bench-peers: all ${#packages[@]} Debian packages present"
else
  echo "bench-peers: installing ${#missing[@]} missing Debian packages: ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
      echo "bench-peers: must run as root (or with sudo) to install: ${missing[*]}" >&2
      exit 2
    fi
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake --preset release -DPOINSOT_BENCH_PEERS=ON >/dev/null
cmake --build --preset release --target bench_multibody_peers
echo "bench-peers: $(uptime)"
exec build/release/bench/peers/bench_multibody_peers --benchmark_counters_tabular=true "$@"
