#!/usr/bin/env bash
# Installs poinsot the three ways its users do and checks each from outside the source tree.
#
#   wheel  `python3 -m build --wheel --no-isolation` and `pip install --no-build-isolation .`, each into a
#          fresh virtual environment made by Debian's /usr/bin/python3 with --system-site-packages (NumPy and
#          Matplotlib from Debian, no network); then examples/python/tennis_racket.py, copied out of the tree,
#          runs there, and the package's metadata version, poinsot.__version__ and the stubs are checked.
#   deb    the release build's installed targets, `cpack -G DEB`, the package's files and Depends; then a clean
#          Debian 12 root made by debootstrap in a temporary folder (entered with chroot, /proc mounted: this
#          machine has no container daemon), `apt-get install ./poinsot_*.deb` there, and in it
#          `poinsot run /usr/share/doc/poinsot/examples/tennis_racket.toml --plot`, `python3 -c "import poinsot"`,
#          the Python example, the man pages and the bash completion.
#
# Usage: scripts/test-install.sh [wheel|deb|all]   (default: all). As root: apt-get, debootstrap, chroot.
# The packaging tools (python3-build, python3-venv, python3-pip; help2man, debootstrap) are installed here
# through scripts/setup.sh: the normal build and tests do not need them.
# Environment:
#   POINSOT_CMAKE_BUILD_DIR  passed to setup.py: build the wheel from this existing build tree (build/release
#                            after scripts/test.sh: seconds) instead of configuring build/wheel (a full compile);
#   POINSOT_DEBIAN_ROOT_TAR  a tarball of a debootstrapped Debian 12 root to start from; made on first use
#                            (saves the debootstrap, about 1.5 min);
#   POINSOT_DEBIAN_MIRROR    the archive debootstrap reads (default http://deb.debian.org/debian).
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-all}"
case "$what" in wheel | deb | all) ;; *)
  echo "test-install: expected wheel, deb or all, got \"$what\"" >&2
  exit 2
  ;;
esac

work=$(mktemp -d /var/tmp/poinsot-test-install.XXXXXX)
root="$work/root"
cleanup() {
  if mountpoint -q "$root/proc" 2>/dev/null; then umount "$root/proc"; fi
  rm -rf "$work"
}
trap cleanup EXIT
phase_start=$(date +%s)
phase() {  # phase "what was done": prints it with the seconds since the previous phase
  local now
  now=$(date +%s)
  echo "test-install: $1 ($((now - phase_start)) s)"
  phase_start=$now
}
fail() {
  echo "test-install: FAILED: $*" >&2
  exit 1
}

version=$(sed -n 's/^project(poinsot VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || fail "no version in the project() call of CMakeLists.txt"

# The example from a folder outside the source tree, with the interpreter given; checks what it prints against
# the closed form it compares with (7 flips in 20 s; differences from the exact solution at round-off).
check_example() {  # check_example PYTHON FOLDER
  local out
  out=$(cd "$2" && "$1" examples/python/tennis_racket.py)
  sed 's/^/  | /' <<<"$out"
  grep -q "^poinsot $version: " <<<"$out" || fail "the example did not print poinsot $version"
  grep -q "^flips of the intermediate axis: 7," <<<"$out" || fail "the example did not find 7 flips"
  # largest difference from the exact solution: below 1e-9 (the exact method, round-off only)
  awk '/^largest difference from the exact solution/ { r = $11 + 0; w = $13 + 0; ok = (r < 1e-9 && w < 1e-9) }
       END { exit ok ? 0 : 1 }' <<<"$out" || fail "the example's run is not the exact solution"
}

test_wheel() {
  bash scripts/setup.sh python3-build python3-venv python3-pip python3-setuptools python3-wheel
  phase "packaging tools present"
  mkdir -p "$work/outside/examples/python"
  cp examples/tennis_racket.toml "$work/outside/examples/"
  cp examples/python/tennis_racket.py "$work/outside/examples/python/"

  /usr/bin/python3 -m build --wheel --no-isolation --outdir "$work/dist" . >"$work/build.log" 2>&1 ||
    { tail -n 30 "$work/build.log"; fail "python3 -m build --wheel --no-isolation"; }
  local wheel
  wheel=$(ls "$work"/dist/poinsot-"$version"-*.whl) || fail "no wheel poinsot-$version-*.whl"
  phase "built $(basename "$wheel")"
  /usr/bin/python3 - "$wheel" <<'EOF' || fail "the wheel lacks files"
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
need = ["poinsot/__init__.py", "poinsot/_core.pyi", "poinsot/so3.pyi", "poinsot/py.typed", "poinsot/plot.py"]
missing = [n for n in need if n not in names] + ([] if any(n.startswith("poinsot/_core.") and n.endswith(".so") for n in names) else ["poinsot/_core*.so"])
sys.exit(f"missing in the wheel: {missing}" if missing else 0)
EOF

  # --without-pip: the venv's `python -m pip` is Debian's pip, seen through --system-site-packages (the
  # same pip 23.0.1 that ensurepip would copy in, 14 s saved per venv).
  /usr/bin/python3 -m venv --system-site-packages --without-pip "$work/venv-wheel"
  "$work/venv-wheel/bin/python" -m pip install -q --no-index "$wheel"
  phase "installed the wheel into a fresh venv"
  check_example "$work/venv-wheel/bin/python" "$work/outside"
  check_installed "$work/venv-wheel/bin/python"
  phase "the example ran from $work/outside with the wheel's module"

  /usr/bin/python3 -m venv --system-site-packages --without-pip "$work/venv-pip"
  "$work/venv-pip/bin/python" -m pip install -q --no-build-isolation . >"$work/pip.log" 2>&1 ||
    { tail -n 30 "$work/pip.log"; fail "pip install --no-build-isolation ."; }
  phase "pip install --no-build-isolation . into a fresh venv"
  check_installed "$work/venv-pip/bin/python"
  (cd "$work/outside" && "$work/venv-pip/bin/python" examples/python/tennis_racket.py >/dev/null) ||
    fail "the example with pip install ."
  phase "the example ran with the module of pip install ."
}

check_installed() {  # check_installed PYTHON: imported from its own site-packages, one version everywhere
  (cd "$work" && "$1" - "$version" "$(dirname "$(dirname "$1")")") <<'EOF' || fail "the installed module"
import importlib.metadata, pathlib, sys
import poinsot
version, venv = sys.argv[1], pathlib.Path(sys.argv[2])
where = pathlib.Path(poinsot.__file__).resolve()
assert venv.resolve() in where.parents, f"poinsot imported from {where}, not from {venv}"
assert poinsot.__version__ == version, (poinsot.__version__, version)
assert importlib.metadata.version("poinsot") == version, importlib.metadata.version("poinsot")
assert (where.parent / "_core.pyi").exists() and (where.parent / "py.typed").exists(), "stubs not installed"
print(f"  | poinsot {poinsot.__version__} from {where.parent}")
EOF
}

test_deb() {
  bash scripts/setup.sh help2man debootstrap dpkg-dev
  phase "packaging tools present"
  bash scripts/build.sh release poinsot_cli poinsot_python poinsot_cli_docs >"$work/build.log" 2>&1 ||
    { tail -n 30 "$work/build.log"; fail "building the release targets"; }
  phase "release build of the installed targets"
  rm -f build/release/poinsot_*.deb
  (cd build/release && cpack -G DEB >"$work/cpack.log" 2>&1) || { tail -n 30 "$work/cpack.log"; fail "cpack -G DEB"; }
  local deb
  deb=$(ls build/release/poinsot_"$version"_*.deb) || fail "no poinsot_${version}_*.deb"
  phase "cpack -G DEB: $deb"

  dpkg-deb -c "$deb" | awk '{print $6}' >"$work/files"
  for f in ./usr/bin/poinsot ./usr/include/poinsot/version.hpp ./usr/lib/cmake/poinsot/poinsotConfig.cmake \
    ./usr/share/man/man1/poinsot.1.gz ./usr/share/man/man1/poinsot-run.1.gz \
    ./usr/share/bash-completion/completions/poinsot ./usr/share/doc/poinsot/examples/tennis_racket.toml \
    ./usr/share/doc/poinsot/examples/python/tennis_racket.py; do
    grep -qx "$f" "$work/files" || fail "$f is not in the package"
  done
  grep -q '^./usr/lib/python3[.0-9]*/dist-packages/poinsot/_core\..*\.so$' "$work/files" ||
    fail "the Python module is not in the package"
  local depends
  depends=$(dpkg-deb -f "$deb" Depends)
  echo "  | Depends: $depends"
  for d in libc6 libstdc++6 libfmt python3 python3-numpy; do
    grep -q "\(^\|, \)$d" <<<"$depends" || fail "Depends lacks $d"
  done

  mkdir -p "$root"
  if [ -n "${POINSOT_DEBIAN_ROOT_TAR:-}" ] && [ -f "$POINSOT_DEBIAN_ROOT_TAR" ]; then
    tar -C "$root" -xf "$POINSOT_DEBIAN_ROOT_TAR"
    phase "clean Debian 12 root unpacked from $POINSOT_DEBIAN_ROOT_TAR"
  else
    debootstrap --variant=minbase bookworm "$root" "${POINSOT_DEBIAN_MIRROR:-http://deb.debian.org/debian}" \
      >"$work/debootstrap.log" 2>&1 || { tail -n 30 "$work/debootstrap.log"; fail "debootstrap"; }
    if [ -n "${POINSOT_DEBIAN_ROOT_TAR:-}" ]; then tar -C "$root" -cf "$POINSOT_DEBIAN_ROOT_TAR" .; fi
    phase "clean Debian 12 root made by debootstrap (minbase)"
  fi
  cp "$deb" "$root/tmp/"
  mount -t proc proc "$root/proc"
  chroot "$root" /bin/sh -c "export DEBIAN_FRONTEND=noninteractive; apt-get update -qq &&
    cd /tmp && apt-get install -y -qq ./poinsot_*.deb" >"$work/apt.log" 2>&1 ||
    { tail -n 30 "$work/apt.log"; fail "apt-get install ./poinsot_*.deb in the clean root"; }
  phase "apt-get install ./$(basename "$deb") in the clean root ($(grep -c '^Setting up' "$work/apt.log") packages)"

  chroot "$root" /bin/bash -euo pipefail -c "
    mkdir -p /tmp/run && cd /tmp/run
    poinsot run /usr/share/doc/poinsot/examples/tennis_racket.toml --plot --quiet > report.txt
    grep -A 3 '^  flips of the intermediate axis' report.txt | sed 's/^/  | /'
    grep -q '^  flips of the intermediate axis .*: 7\$' report.txt
    test \"\$(python3 -c 'import poinsot; print(poinsot.__version__)')\" = $version
    python3 -c 'import poinsot; print(\"  | python3 -c import poinsot:\", poinsot.__version__, poinsot.__file__)'
    test -s tennis_racket-run/summary.json && test -s tennis_racket-run/omega.png
    python3 /usr/share/doc/poinsot/examples/python/tennis_racket.py > example.txt
    grep -q '^flips of the intermediate axis: 7,' example.txt
    test -s /usr/share/man/man1/poinsot-inertia-box.1.gz
    source /usr/share/bash-completion/completions/poinsot
    COMP_WORDS=(poinsot inertia b); COMP_CWORD=2; _poinsot; test \"\${COMPREPLY[*]}\" = 'box body'
  " || fail "the installed package in the clean root"
  phase "in the clean root: poinsot run (with --plot), import poinsot, the Python example, man, completion"
}

start=$(date +%s)
if [ "$what" = wheel ] || [ "$what" = all ]; then test_wheel; fi
if [ "$what" = deb ] || [ "$what" = all ]; then test_deb; fi
echo "test-install: $what passed in $(($(date +%s) - start)) s"
