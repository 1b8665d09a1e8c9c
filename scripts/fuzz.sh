#!/usr/bin/env bash
# Runs every libFuzzer harness of fuzz/ for SECONDS each (default 60), one after the other, under ASan + UBSan
# (the fuzz preset: Debian's clang and libfuzzer-14-dev; `scripts/setup.sh clang libfuzzer-14-dev` installs
# them). Usage: scripts/fuzz.sh [SECONDS] [HARNESS...]
#
# Each harness starts from its committed seeds (fuzz/corpus/NAME) and grows a working corpus in
# build/fuzz/corpus/NAME; a crash, a sanitizer report, a leak or a run over 1 s (a hang) is written to
# build/fuzz/findings/NAME/ and the script goes on with the next harness. At the end it prints, per harness,
# the executions, libFuzzer's coverage (cov: edges, ft: features) and the number of findings, and exits 1 if
# there was any finding. To keep a finding as a regression test, copy it to fuzz/regressions/NAME/ (CTest
# replays it, see fuzz/CMakeLists.txt); to refresh the committed seeds with a minimised corpus:
#   build/fuzz/fuzz/poinsot_fuzz_NAME -merge=1 fuzz/corpus/NAME build/fuzz/corpus/NAME
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
all=(scenario multibody_scenario body_file mesh_stl_ascii mesh_stl_binary mesh_obj mesh_ply mesh_off robot_model cli)
harnesses=("${@:-${all[@]}}")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${all[@]}")

if [ ! -f build/fuzz/build.ninja ]; then
  CXX=clang++ cmake --preset fuzz >/dev/null
fi
targets=()
for name in "${harnesses[@]}"; do targets+=("poinsot_fuzz_$name"); done
cmake --build --preset fuzz -j2 --target "${targets[@]}" >/dev/null

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp  # libassimp's own leak, see the file
summary=build/fuzz/summary.txt
: >"$summary"
status=0
for name in "${harnesses[@]}"; do
  exe=build/fuzz/fuzz/poinsot_fuzz_$name
  work=build/fuzz/corpus/$name
  findings=build/fuzz/findings/$name
  mkdir -p "$work" "$findings"
  log=build/fuzz/$name.log
  # -timeout: a run over FUZZ_TIMEOUT seconds (default 1) is a hang; -rss_limit_mb: no input may need 2 GB.
  nice -n 10 "$exe" "$work" "fuzz/corpus/$name" -dict="fuzz/dict/$name.dict" -max_total_time="$seconds" \
    -timeout="${FUZZ_TIMEOUT:-1}" -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" \
    >"$log" 2>&1 || true
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || true)
  found=$(find "$findings" -type f | wc -l)
  [ "$found" -gt 0 ] && status=1
  printf '%-20s execs %10s  %-22s findings %s\n' "$name" "${execs:-0}" "${cov:-cov: ? ft: ?}" "$found" | tee -a "$summary"
done
awk '{s += $3} END {printf "total executions: %d\n", s}' "$summary" | tee -a "$summary"
exit $status
