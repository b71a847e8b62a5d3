#!/usr/bin/env bash
# Installs missing dependencies, configures and builds stoneskip (Release) into ./build.
#   bash tools/setup/build.sh [test]   `test`: also what only the tests use (install-deps.sh test)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bash "$root/tools/setup/install-deps.sh" "${1:-}"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$jobs"
