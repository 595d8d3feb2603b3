#!/usr/bin/env bash
# The bake read by Blender: bakes the default scene's edge-min run (`fragsim run --bake`, with
# --trajectories), imports it with Blender's own glTF importer in a headless Blender and checks
# the piece count and every piece's position (1e-5 m) and rotation (1e-5) at steps 0, 90 and 180
# against trajectories.csv (tests/report/blender_check.py). Then the same file against the
# `none` run's CSV, which must fail: the check can tell a wrong run from the right one.
# Blender is not installed for you (Debian's blender is about 170 packages): without it the test
# is skipped (status 77). To run it: apt-get install blender python3-numpy, then
# ctest --preset release -L blender.
# Usage: tests/report/blender_check.sh FRAGSIM_BINARY
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
fragsim="$1"
if ! command -v blender >/dev/null 2>&1; then
  echo "blender_check: skipped: blender is not installed (apt-get install blender python3-numpy)" >&2
  exit 77
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
run() {
  "$fragsim" run --scene "$root/data/scenes/front.ini" --no-occlusion --trajectories "$@" \
    >"$tmp/log" 2>&1 || {
    cat "$tmp/log" >&2
    echo "blender_check: fragsim run $* failed" >&2
    exit 1
  }
}
run --strategy edge-min --bake "$tmp/shot.glb" --csv "$tmp/edge-min"
run --strategy none --csv "$tmp/none"
check() {
  blender -b --factory-startup --python-exit-code 1 --python "$root/tests/report/blender_check.py" \
    -- "$tmp/shot.glb" "$1" 0,90,180 2>&1 | grep '^blender_check'
}
check "$tmp/edge-min/trajectories.csv"
if check "$tmp/none/trajectories.csv" >"$tmp/wrong.log" 2>&1; then
  cat "$tmp/wrong.log" >&2
  echo "blender_check: the edge-min bake passed against the none run's CSV" >&2
  exit 1
fi
echo "blender_check: the none run's CSV is told apart: $(tail -n 1 "$tmp/wrong.log")"
