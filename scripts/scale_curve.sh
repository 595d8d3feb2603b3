#!/usr/bin/env bash
# The physics scale curve: ODE time per step and peak memory from 1,000 to
# ~100,000 fragments, in three configurations, each point in its own process (bench/scale_curve.cpp),
# written as one CSV and, when gnuplot is installed, drawn by data/plots/scale.gp.
#
#   scripts/scale_curve.sh [OUT.csv]      (default: scale_curve.csv; the PNG goes beside it)
#
# Scene: data/scenes/front.ini's 1.2 m cube with the blast not aimed (explosion.toward_camera_mps
# = 0), cut into splits^3 fragments: by t = 1 s the fragments lie on the ground. Each point steps
# to t = 1 s untimed, then times steps one by one (thread CPU time of World::set_camera +
# World::step) and reports their median and 95th percentile. Configurations:
#   ballistic   no ground, no fragment pairs (ground.enabled = off)
#   ground      ground contacts, no fragment pairs (the default physics; exact solver)
#   collisions  ground and fragment pairs (simulation.fragment_collisions = on; QuickStep, 20 it.)
# Time limits: full collisions get slower than linearly (one island of all the fragments on the
# ground: 0.6 s a step at 15,625 fragments, 7.5 s and 1.5 GB at 97,336), so they are timed over
# fewer steps as they grow (the STEPS column), and the 97,336-fragment point with collisions
# (6.5 minutes alone) only runs with FULL=1. Without it the script takes about 6 minutes on an
# AMD EPYC core at 2.6 GHz, 12 with FULL=1 (one point at a time, so that no two points share the
# machine). A point that exceeds POINT_LIMIT_S seconds (default 600) is written with empty times.
#
# Environment: FRAGSIM_BUILD_DIR (default build/release, built by scripts/setup.sh when missing),
# FULL=1, POINT_LIMIT_S.
set -euo pipefail
cd "$(dirname "$0")/.."

out="${1:-scale_curve.csv}"
build="${FRAGSIM_BUILD_DIR:-build/release}"
bin="$build/bench/scale_curve"
if [ ! -x "$bin" ]; then
  if [ "$build" = "build/release" ]; then
    scripts/setup.sh release >/dev/null
  else
    cmake --build "$build" --target scale_curve >/dev/null
  fi
fi
limit="${POINT_LIMIT_S:-600}"
scene="data/scenes/front.ini"
settle=60

# timed_steps CONFIG SPLITS: how many steps to time for one point.
timed_steps() {
  if [ "$1" != collisions ]; then
    echo 60
  elif [ "$2" -le 17 ]; then
    echo 60
  elif [ "$2" -le 25 ]; then
    echo 10
  elif [ "$2" -le 30 ]; then
    echo 5
  else
    echo 3
  fi
}

tmp="$(mktemp "${out}.XXXXXX")"
trap 'rm -f "$tmp"' EXIT
"$bin" --header >"$tmp"
start=$SECONDS
for config in ballistic ground collisions; do
  for splits in 10 13 17 22 25 30 37 46; do
    steps="$(timed_steps "$config" "$splits")"
    if [ "$config" = collisions ] && [ "$splits" -ge 46 ] && [ "${FULL:-0}" != 1 ]; then
      echo "scale_curve.sh: $((splits ** 3)) fragments with collisions skipped (FULL=1 runs it)" >&2
      continue
    fi
    t0=$SECONDS
    if line="$(timeout "$limit" "$bin" "$scene" "$splits" "$config" "$steps" "$settle" \
      explosion.toward_camera_mps=0)"; then
      echo "$line" >>"$tmp"
    else
      echo "$((splits ** 3)),$config,,,,$steps,$settle," >>"$tmp"
      echo "scale_curve.sh: $((splits ** 3)) fragments, $config: no result within ${limit} s" >&2
    fi
    echo "scale_curve.sh: $config $((splits ** 3)) fragments: $((SECONDS - t0)) s" >&2
  done
done
mv "$tmp" "$out"
trap - EXIT
echo "scale_curve.sh: wrote $out in $((SECONDS - start)) s" >&2

if command -v gnuplot >/dev/null 2>&1; then
  png="${out%.csv}.png"
  gnuplot -e "csv='$out'; out='$png'" data/plots/scale.gp
  echo "scale_curve.sh: drew $png" >&2
fi
