#!/usr/bin/env bash
# The README's first command: installs what is missing (Debian 12, as root), builds the command-line tool, and
# runs the main job, the tennis-racket demo: examples/tennis_racket.toml (Brody's measured moments, spun mostly
# about the intermediate axis). It prints the report (the flips beside their closed-form interval 2K(k)/ω_p)
# and writes trajectory.csv, summary.json and the figures (PNG) into out/tennis_racket/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release poinsot_cli
out=out/tennis_racket
./build/release/apps/poinsot/poinsot run examples/tennis_racket.toml --out "$out" --plot
echo
echo "demo: files in $out/: trajectory.csv, summary.json, omega.png, invariants.png, polhode.png"
echo "demo: more scenarios in examples/ (docs/scenario.md, docs/run.md)"
