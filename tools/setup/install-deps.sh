#!/usr/bin/env bash
# Installs what stoneskip needs from Debian's archive, and nothing when all of it is present.
# Safe to run again. Works as root or through sudo.
#   bash tools/setup/install-deps.sh        what the build and the main job need
#   bash tools/setup/install-deps.sh test   that, and what only the tests use (a browser: large)
set -euo pipefail
what="${1:-}"
case "$what" in ""|test) ;; *) echo "usage: bash tools/setup/install-deps.sh [test]" >&2; exit 2 ;; esac

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev libsundials-dev libfftw3-dev libhdf5-dev
  libboost-test-dev libtoml11-dev libcli11-dev nlohmann-json3-dev libbenchmark-dev
  gnuplot-nox
  ffmpeg                       # `stoneskip scene --movie` assembles the frames; ffprobe checks them in the tests
  openmpi-bin libopenmpi-dev   # `mpirun stoneskip sweep` (optional at build time: CMake says if absent)
  g++-aarch64-linux-gnu qemu-user  # tools/setup/cross-aarch64.sh: the water tests built for aarch64, run emulated (optional)
  python3-h5py python3-numpy   # tools/python/stoneskip_data.py, the Python reader, and its test (for /usr/bin/python3)
)
if [ "$what" = test ]; then
  packages+=(chromium)         # the report pages opened in headless Chromium (ctest stoneskip_browser; skipped without it)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
