#!/usr/bin/env bash
# The README's second command: installs what is missing, builds the release preset and runs every test
# (GoogleTest suites of each layer, the command-line tests and the Python module's pytest suite) with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release
ctest --preset release
