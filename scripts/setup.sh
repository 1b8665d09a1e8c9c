#!/usr/bin/env bash
# Installs every Debian 12 package poinsot needs to build, test, benchmark and plot.
# Idempotent: packages already present are skipped, and apt-get runs only when something is missing.
# Run as root (or with sudo available). Nothing is downloaded from outside Debian's archive.
# Extra Debian packages given as arguments are installed the same way (scripts/bench-peers.sh passes the peers).
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build g++ clang-format git pkg-config
  # the man pages, generated from the tool's own --help at build time
  help2man
  # C++ libraries
  libeigen3-dev libboost-math-dev libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libassimp-dev libtinyxml2-dev libgtest-dev libgmock-dev libbenchmark-dev
  # optimal control: the NLP solver of the direct method, and OpenBLAS as the BLAS behind its MUMPS and NumPy
  # (Debian's alternatives prefer it to the reference BLAS; poinsot holds it at one thread while Ipopt runs,
  # docs/install.md)
  coinor-libipopt-dev libopenblas0
  # Python module, its tests and the plots
  python3 python3-dev pybind11-dev python3-numpy python3-matplotlib python3-pytest
  # the viewer: three.js inlined into view.html; headless Chromium and Selenium for its tests
  libjs-three chromium chromium-driver python3-selenium
  # ensembles: counter-based random numbers (Random123, header-only); optional: MPI ranks, HDF5 tables
  librandom123-dev libopenmpi-dev openmpi-bin libhdf5-dev python3-h5py
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} Debian packages present"
  exit 0
fi

echo "setup: installing ${#missing[@]} missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: must run as root (or with sudo) to install: ${missing[*]}" >&2
    exit 2
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
