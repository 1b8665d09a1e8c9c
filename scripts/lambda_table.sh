#!/usr/bin/env bash
# Produces the table of docs/lambda.md: the theorems of Vallée & Dumitriu (2002) on Λ (with docs/conventions.md)
# checked numerically by `poinsot lambda --json` on prolate, oblate, spherical, asymmetric and lamina bodies,
# with the exact solution and with rattle. Prints the Markdown table; with --update it also rewrites the
# block between the lambda-table markers in docs/lambda.md.
#   usage: scripts/lambda_table.sh [--update] [path/to/poinsot]
set -euo pipefail
cd "$(dirname "$0")/.."
update=0
if [[ "${1:-}" == "--update" ]]; then update=1; shift; fi
exe="${1:-build/release/apps/poinsot/poinsot}"
[[ -x "$exe" ]] || { echo "lambda_table.sh: $exe not found; build it first (cmake --build --preset release --target poinsot_cli)" >&2; exit 2; }

# name | body flags | omega0
cases=(
  "prolate (case b)|--A 2 --C 1|0.3 -0.4 1.2"
  "oblate (case c)|--A 1 --C 1.8|1.0 0.5 -2.0"
  "sphere A = C = 1.5|--A 1.5 --C 1.5|0.3 -0.4 1.2"
  "flat disc A = C/2|--A 1 --C 2 --k 1 1 1|0.5 -0.2 0.9"
  "asymmetric (2, 3, 4) (C3)|--moments 2 3 4|1.0 0.5 0.3"
  "lamina (1, 2, 3)|--moments 1 2 3|0.4 1.0 -0.6"
)
t_end=20
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
i=0
for c in "${cases[@]}"; do
  IFS='|' read -r name body omega <<<"$c"
  for method in exact rattle; do
    # shellcheck disable=SC2086
    "$exe" lambda $body --omega0 $omega --t-end "$t_end" --method "$method" --dt 1e-3 --sample-dt 0.01 --json \
      >"$tmp/$i.json"
    printf '%s\n' "$name" >"$tmp/$i.name"
    i=$((i + 1))
  done
done

/usr/bin/python3 - "$tmp" "$i" "$t_end" >"$tmp/table.md" <<'PY'
import json, sys
d, n, t_end = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def e(x):
    return "—" if x is None else f"{x:.1e}"
def v(xs):
    return "(" + ", ".join(f"{x:.4f}" for x in xs) + ")"
print(f"Each row: `poinsot lambda ... --t-end {t_end} --dt 1e-3 --sample-dt 0.01 --json` "
      f"({int(float(t_end) / 0.01) + 1} checked states). Units: J.")
print()
print("| body | method | eig Λ(0), ascending | closed form λ (sorted) | max eig (≤ 0, Prop. 1) "
      "| max \\|tr Λ + 2T\\| | eig variation (Theorem) | max \\|eig − closed form\\| | max \\|Λv − λ3 v\\|, v = k×ω "
      "| EᵀΛE drift (Prop. 3) | rattle \\|Λ_h − Λ\\| |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for i in range(n):
    name = open(f"{d}/{i}.name").read().strip()
    j = json.load(open(f"{d}/{i}.json"))
    cf = j["closed_form"]
    im = j["integrator_multiplier"]
    print("| " + " | ".join([
        name, j["method"], v(j["eigenvalues_initial"]),
        v(cf["eigenvalues"]) if cf else "— (not axisymmetric)",
        e(j["max_eigenvalue_max"]), e(j["trace_plus_2T_max"]), e(j["eigenvalue_max_variation"]),
        e(cf["max_deviation"]) if cf else "—",
        e(cf["eigenvector_residual_max"]) if cf else "—",
        e(cf["constant_matrix_deviation_max"]) if cf else "—",
        e(im["deviation_max"]) if im else "—",
    ]) + " |")
PY
cat "$tmp/table.md"
if [[ $update == 1 ]]; then
  /usr/bin/python3 - docs/lambda.md "$tmp/table.md" <<'PY'
import sys
doc, table = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
begin, end = "<!-- lambda-table:begin -->", "<!-- lambda-table:end -->"
a, b = text.index(begin) + len(begin), text.index(end)
open(doc, "w").write(text[:a] + "\n" + table + text[b:])
PY
  echo "lambda_table.sh: updated docs/lambda.md" >&2
fi
