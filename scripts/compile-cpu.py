#!/usr/bin/env python3
"""CPU seconds (user + sys) of compiling translation units of a configured build tree, without ccache.

Runs each selected command of BUILD/compile_commands.json (the ccache launcher dropped, the object written to a
temporary file, the build tree left as it is) and prints the compiler's user + sys time, then the total. CPU time,
unlike wall time, does not depend on how loaded the machine is (docs/measurements/ci_time.md).

Usage: scripts/compile-cpu.py BUILD [REGEX] [--every N] [--add FLAG]...
  REGEX       only the sources whose path matches (default: all)
  --every N   every N-th command in source order, starting with the fourth (a sample of the tree)
  --add FLAG  a flag added before -c (e.g. --add=-O1 to compare)
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("regex", nargs="?", default=".")
    ap.add_argument("--every", type=int, default=0)
    ap.add_argument("--add", action="append", default=[])
    a = ap.parse_args()
    path = os.path.join(a.build, "compile_commands.json")
    if not os.path.exists(path):
        sys.exit(f"compile-cpu: {path}: not found; configure with CMAKE_EXPORT_COMPILE_COMMANDS=ON (the presets do)")
    commands = sorted(json.load(open(path)), key=lambda e: (e["file"], e["command"]))
    if a.every > 0:
        commands = commands[3::a.every]
    total, n = 0.0, 0
    with tempfile.TemporaryDirectory() as tmp:
        for e in commands:
            if not re.search(a.regex, e["file"]):
                continue
            args = shlex.split(e["command"])
            if os.path.basename(args[0]) == "ccache":
                args = args[1:]
            args[args.index("-o") + 1] = os.path.join(tmp, "tu.o")
            c = args.index("-c")
            args = args[:c] + a.add + args[c:]
            p = subprocess.Popen(args, cwd=e["directory"])
            _, status, usage = os.wait4(p.pid, 0)
            cpu = usage.ru_utime + usage.ru_stime
            ok = os.waitstatus_to_exitcode(status) == 0
            total += cpu
            n += 1
            print(f"{cpu:7.2f} {'ok ' if ok else 'ERR'} {os.path.relpath(e['file'])}", flush=True)
    print(f"total {total:.1f} s CPU over {n} translation units")


if __name__ == "__main__":
    main()
