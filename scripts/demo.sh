#!/usr/bin/env bash
# The README's first command: installs what is missing, builds the command-line tool and runs the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release poinsot_cli
# Until the dynamics layer lands, the main job is a conversion of the classical 3-1-3 Euler angles of a top.
./build/release/apps/poinsot/poinsot rotation --euler ZXZ 30 45 60 --degrees --sequence ZXZ
