#!/usr/bin/env bash
# Lists the logic written twice in the library, the tool and the Python module: blocks of 6 or more lines (and
# 60 tokens) that appear twice, found by the public copy-paste detector jscpd (npm, version pinned by
# tools/jscpd/package-lock.json). Usage: scripts/check_duplicates.sh [--strict] [PATH...]
#   default paths: src include apps python/src python/poinsot; --strict exits 1 when any clone is found.
# Installs jscpd with `npm ci` into tools/jscpd/node_modules on first use (Node.js and npm from Debian or the
# machine). docs/architecture.md ("One place for each piece of logic") says what it lists and why.
set -euo pipefail
cd "$(dirname "$0")/.."
strict=0
if [ "${1:-}" = "--strict" ]; then strict=1; shift; fi
paths=("$@")
[ ${#paths[@]} -gt 0 ] || paths=(src include apps python/src python/poinsot)
if [ ! -x tools/jscpd/node_modules/.bin/jscpd ]; then
  command -v npm >/dev/null || { echo "check_duplicates: npm not found; expected Node.js and npm (apt-get install npm)" >&2; exit 2; }
  npm ci --prefix tools/jscpd --no-audit --no-fund --silent
fi
report=$(mktemp -d)
trap 'rm -rf "$report"' EXIT
tools/jscpd/node_modules/.bin/jscpd --min-lines 6 --min-tokens 60 --format cpp,python \
  --formats-exts "cpp:cpp,hpp,h;python:py,pyi" --ignore "**/*.pyi" --reporters console,json --output "$report" \
  --silent "${paths[@]}" >/dev/null
python3 - "$report/jscpd-report.json" "$strict" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
for d in data.get("duplicates", []):
    a, b = d["firstFile"], d["secondFile"]
    print(f"{a['name']}:{a['start']}-{a['end']}  =  {b['name']}:{b['start']}-{b['end']}  ({d['lines']} lines)")
total = data["statistics"]["total"]
n = len(data.get("duplicates", []))
print(f"check_duplicates: {n} clone(s), {total['duplicatedLines']} duplicated lines of {total['lines']} "
      f"({total['percentage']} %) in {total['sources']} files")
sys.exit(1 if n and sys.argv[2] == "1" else 0)
PY
