#!/usr/bin/env bash
# The controller's cost per fragment per step in WebAssembly (Node) against the native library, on
# the same recorded states: every dump of the test suite (`fragsim run --dump-control`, the
# default scene's runs) replayed by tests/control/replay.c built both ways, `--time REPEATS`
# (processor time of the step calls only, median of the repeats), native and WebAssembly
# alternating in one run. Prints a table: ns per fragment-step for each, and their ratio.
#
#   scripts/web_bench.sh [BUILD_DIR [REPEATS]]    defaults: build/release, 9
#
# Needs BUILD_DIR's test dumps (ctest --preset release -R Control.Dump) and the web build in
# BUILD_DIR/web (ctest -R Web.Build, or scripts/web_build.sh BUILD_DIR/web).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath "${1:-$root/build/release}")
repeats=${2:-9}
native=$build/tests/control/control_replay
wasm=$build/web/replay.cjs
for f in "$native" "$wasm"; do
  [[ -f $f ]] || { echo "web_bench: $f is missing (see the header of this script)" >&2; exit 1; }
done
shopt -s nullglob
dumps=("$build"/tests/control/dumps/*.bin)
[[ ${#dumps[@]} -gt 0 ]] || { echo "web_bench: no dumps in $build/tests/control/dumps" >&2; exit 1; }

ns() { sed -n 's/^replay: time: \([0-9.]*\) ns.*/\1/p'; }
printf '%-28s %-8s %12s %12s %7s\n' dump arrays native_ns wasm_ns ratio
for dump in "${dumps[@]}"; do
  for mode in structs floats; do
    flag=()
    [[ $mode == floats ]] && flag=(--floats)
    n=$("$native" "$dump" "${flag[@]}" --time "$repeats" | ns)
    w=$(node "$wasm" "$dump" "${flag[@]}" --time "$repeats" | ns)
    awk -v d="$(basename "$dump" .bin)" -v m="$mode" -v n="$n" -v w="$w" \
      'BEGIN { printf "%-28s %-8s %12.1f %12.1f %6.2fx\n", d, m, n, w, w / n }'
  done
done
