#!/usr/bin/env bash
# Writes the viewer's screenshots (docs/images/viewer_*.png, shown in docs/viewer.md and the README) with the
# test browser of tests/viewer/: every page is made by `poinsot run --html` from the examples.
# Needs a release build (cmake --build --preset release --target poinsot_cli) and scripts/setup.sh's packages.
set -euo pipefail
cd "$(dirname "$0")/.."
POINSOT_CLI="${POINSOT_CLI:-$PWD/build/release/apps/poinsot/poinsot}" \
POINSOT_VIEWER_SCREENSHOTS="$PWD/docs/images" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/viewer/test_view_screenshots.py
ls -la docs/images/viewer_*.png
