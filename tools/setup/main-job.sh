#!/usr/bin/env bash
# The main job: every built-in case and every report, into OUT (default ./out).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${1:-$root/out}"
mkdir -p "$out"
exe="$root/build/tools/stoneskip"
cd "$root"

echo "== The built-in throws (real-time model) =="
for c in cases/*.toml; do
  case "$(basename "$c")" in wave_*) continue ;; esac
  echo "-- $c"
  "$exe" run "$c" --out "$out/$(basename "${c%.toml}").h5"
done
