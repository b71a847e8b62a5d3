#!/usr/bin/env bash
# Cross-builds the water model (model/water: the height field, its stencils and the leapfrog
# kernel with its NEON and scalar paths) and its Boost.Test suite for aarch64 with Debian's
# g++-aarch64-linux-gnu, and runs the tests under qemu-user (qemu-aarch64 -L /usr/aarch64-linux-gnu).
# What it shows: the water code compiles for aarch64 and its tests pass there, every supported
# kernel path against the scalar one included. What it does not: the rest of stoneskip (SUNDIALS,
# HDF5, FFTW and the other libraries have no aarch64 builds here), nor speed (qemu emulates).
# Eigen and Boost.Test are header-only here (Boost.Test's "included" variant), read from the host's
# /usr/include, which holds no architecture-specific code for them.
#
#   tools/setup/cross-aarch64.sh                # build into build-aarch64/ and run the tests
# Exits 77 (skipped, one line saying what is missing) when the cross tools are absent.
# Needs: g++-aarch64-linux-gnu qemu-user (tools/setup/install-deps.sh installs them).
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${STONESKIP_CROSS_BUILD:-$root/build-aarch64}"
cxx=aarch64-linux-gnu-g++
qemu=qemu-aarch64
sysroot=/usr/aarch64-linux-gnu

missing=()
command -v "$cxx" >/dev/null 2>&1 || missing+=("$cxx (g++-aarch64-linux-gnu)")
command -v "$qemu" >/dev/null 2>&1 || missing+=("$qemu (qemu-user)")
[ -d "$sysroot" ] || missing+=("$sysroot")
[ -d /usr/include/boost/test ] || missing+=("/usr/include/boost/test (libboost-test-dev)")
[ -d /usr/include/eigen3 ] || missing+=("/usr/include/eigen3 (libeigen3-dev)")
if [ ${#missing[@]} -ne 0 ]; then
  echo "cross-aarch64: skipped: missing ${missing[*]}" >&2
  exit 77
fi

mkdir -p "$out/include"
# Only the header-only libraries, not the host's whole /usr/include (its glibc is x86-64's).
ln -sfn /usr/include/boost "$out/include/boost"
ln -sfn /usr/include/eigen3 "$out/include/eigen3"

cat > "$out/test_main.cpp" <<'CPP'
// The Boost.Test entry point, header-only (no aarch64 build of the Boost.Test library here).
#define BOOST_TEST_MODULE stoneskip_water_aarch64
#include <boost/test/included/unit_test.hpp>
CPP

flags=(-std=c++20 -O2 -pthread -Wall -Wextra -I"$root" -isystem "$out/include" -isystem "$out/include/eigen3")
objects=()
compile() {  # source, object [extra flags]
  local src="$1" obj="$2"
  shift 2
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find "$root/model" -name '*.hpp' -newer "$obj" -print -quit)" ]; then
    echo "cross-aarch64: compiling ${src#"$root"/}" >&2
    "$cxx" "${flags[@]}" "$@" -c "$src" -o "$obj"
  fi
  objects+=("$obj")
}
for src in "$root"/model/water/*.cpp; do
  name="$(basename "$src" .cpp)"
  extra=()
  # The kernel's paths must round alike: no FMA contraction (as model/CMakeLists.txt sets it).
  [ "$name" = leapfrog_kernel ] && extra=(-ffp-contract=off)
  compile "$src" "$out/$name.o" "${extra[@]}"
done
compile "$out/test_main.cpp" "$out/test_main.o"
"$cxx" -pthread "${objects[@]}" -o "$out/stoneskip_water_tests"
echo "cross-aarch64: running $out/stoneskip_water_tests under $qemu" >&2
cd "$root"
"$qemu" -L "$sysroot" "$out/stoneskip_water_tests" --report_level=short --color_output=no
