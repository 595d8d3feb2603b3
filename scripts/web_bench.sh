#!/usr/bin/env bash
# The controller's cost per fragment per step in WebAssembly (Node and Chromium) against the native
# library, on the same recorded states: every dump of the test suite (`fragsim run
# --dump-control`, the default scene's runs), in one run, dump by dump:
#   native    tests/control/replay.c natively, `--time REPEATS`: the processor time of the step
#             calls only, the median of the repeats
#   wasm      the same program built for WebAssembly, in Node
#   api-node  the JavaScript API in Node (bench/web/api_bench.mjs): its copies in and out included
#   api-chr   the same in headless Chromium (bench/web/browser_bench.py)
# through doubles (structs) and float arrays (floats). Prints ns per fragment-step, and each
# WebAssembly figure over the native one.
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
printf '%-26s %-7s %8s %8s %8s %8s %6s %6s %6s\n' dump arrays native wasm api-node api-chr \
  wasm/n node/n chr/n
for dump in "${dumps[@]}"; do
  for mode in structs floats; do
    flag=()
    [[ $mode == floats ]] && flag=(--floats)
    n=$("$native" "$dump" "${flag[@]}" --time "$repeats" | ns)
    w=$(node "$wasm" "$dump" "${flag[@]}" --time "$repeats" | ns)
    a=$(node "$root/bench/web/api_bench.mjs" "$build/web/package" "$dump" "$repeats" "${flag[@]}" | ns)
    c=$(python3 "$root/bench/web/browser_bench.py" "$build/web/package" "$dump" "$repeats" \
      "${flag[@]}" | ns)
    awk -v d="$(basename "$dump" .bin)" -v m="$mode" -v n="$n" -v w="$w" -v a="$a" -v c="$c" \
      'BEGIN { printf "%-26s %-7s %8.1f %8.1f %8.1f %8.1f %6.2f %6.2f %6.2f\n", d, m, n, w, a, c,
               w / n, a / n, c / n }'
  done
done
