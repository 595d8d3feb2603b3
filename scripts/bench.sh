#!/usr/bin/env bash
# Every benchmark behind docs/benchmarks.md, from one command. Builds the release preset
# (installing what is missing), then writes into OUT (default bench-results/):
#   machine.txt                     the machine, compiler and date the numbers belong to
#   micro.txt, micro.json           Google Benchmark: prediction kernel, strategy step, physics
#                                   step per configuration, whole runs, rendering (5 repetitions)
#   time_vs_error.{txt,csv}, pareto.png
#                                   fragsim bench on the default scene (3 timed runs each)
#   compare.txt                     fragsim compare on the default scene, all metrics, timed
#   play.txt                        fragsim play's frame at 640x360 (--bench-frames, 3 runs each)
#   scale_curve.csv, scale_curve.png
#                                   time per step and peak memory, 1k to 100k fragments
#   worst_frame.txt                 edge and edge-min by phase of the explosion, timed in-run
#                                   (bench/worst_frame.cpp), at 1,728 and 15,625 fragments;
#                                   edge-min beside a shadow with one exact solve a step, so
#                                   its exact solves' cost shows apart from its rejection's
# Run it on an otherwise idle machine: medians are robust to a little noise, not to a busy core.
# Usage: scripts/bench.sh [OUT]     (about 15 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-bench-results}"
scripts/setup.sh release
mkdir -p "$out"
bin=build/release

{
  echo "date: $(date -u +%F)"
  echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) online"
  echo "os: $(. /etc/os-release && echo "$PRETTY_NAME"), $(uname -r)"
  echo "compiler: $(g++ --version | head -n 1)"
  echo "ode: $(pkg-config --modversion ode)"
} | tee "$out/machine.txt"

echo "== micro-benchmarks"
"$bin/bench/fragsim_bench" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out="$out/micro.json" --benchmark_out_format=json | tee "$out/micro.txt"

echo "== run time against error"
"$bin/fragsim" bench --scene data/scenes/front.ini --out "$out/time_vs_error.csv" --force \
  | tee "$out/time_vs_error.txt"
gnuplot -e "csv='$out/time_vs_error.csv'; out='$out/pareto.png'" data/plots/pareto.gp

echo "== compare on the default scene, all strategies and metrics"
TIMEFORMAT="compare wall %R s"
for i in 1 2 3; do
  { time "$bin/fragsim" compare --scene data/scenes/front.ini >/dev/null; } 2>&1
done | tee "$out/compare.txt"

echo "== play: a frame's parts, scripted route, no window"
for i in 1 2 3; do
  for s in edge-min none; do
    echo "$s: $("$bin/fragsim" play --scene data/scenes/front.ini --bench-frames 300 --strategy "$s" | tail -n 1)"
  done
done | tee "$out/play.txt"

echo "== the worst frame: the controller's cost by phase, inside a real run"
for s in edge-min edge; do
  shadow=()
  if [ "$s" = edge-min ]; then shadow=(--shadow edge-min.max_solves=1); fi
  for splits in 12 25; do
    "$bin/bench/worst_frame" data/scenes/front.ini "$s" 5 "object.splits=$splits" "${shadow[@]}"
  done
done | tee "$out/worst_frame.txt"

echo "== scale curve"
scripts/scale_curve.sh "$out/scale_curve.csv" # draws scale_curve.png beside it

echo "wrote $out/"
