#!/usr/bin/env bash
# The plot command draws the figures: a comparison with trajectories, then scripts/plot.sh; every
# expected PNG must exist and be a PNG. Usage: plot_test.sh FRAGSIM_BINARY SOURCE_DIR
set -euo pipefail
fragsim="$1"
src="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$fragsim" compare --scene "$src/data/scenes/thesis125.ini" --csv "$out/csv" --trajectories \
  --simulation.duration_s 1.5 >/dev/null
bash "$src/scripts/plot.sh" "$out/csv" >/dev/null
status=0
for png in paths_none_edge_side paths_none_edge_top candidates occlusion near_intersections near_m; do
  f="$out/csv/plots/$png.png"
  if [ ! -s "$f" ] || [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" != "89504e470d0a1a0a" ]; then
    echo "missing or not a PNG: $png.png"
    status=1
  fi
done
[ "$status" = 0 ] && echo "plot_test: 6 PNGs written"
exit "$status"
