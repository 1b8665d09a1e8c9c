#!/usr/bin/env bash
# The side-by-side comparison: poinsot's RATTLE beside Bullet, ODE, MuJoCo and Simbody on the same
# chain of ball-jointed rods, in one Google Benchmark program (bench/peers/, docs/measurements/peers.md).
#   1. installs the four peers' Debian packages with scripts/setup.sh (idempotent; they are not in its own list:
#      poinsot and its CI do not need them),
#   2. configures the release preset with -DPOINSOT_BENCH_PEERS=ON and builds bench_multibody_peers only,
#   3. runs it with tabular counters; extra arguments go to the benchmark, e.g.
#        bash scripts/bench-peers.sh --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#        bash scripts/bench-peers.sh --benchmark_filter='/(16|64)/'
# Run from anywhere; takes a few minutes (MuJoCo's 256-link chain alone is about a minute a repetition).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh libbullet-dev libode-dev libmujoco-dev libsimbody-dev

cmake --preset release -DPOINSOT_BENCH_PEERS=ON >/dev/null
cmake --build --preset release --target bench_multibody_peers
echo "bench-peers: $(uptime)"
exec build/release/bench/peers/bench_multibody_peers --benchmark_counters_tabular=true "$@"
