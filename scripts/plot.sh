#!/usr/bin/env bash
# Plots the CSV export of `fragsim compare --csv DIR` into DIR/plots/*.png with the gnuplot
# scripts in data/plots/ (see data/plots/README.md). Usage: scripts/plot.sh DIR
# The fragment-path figures need DIR/trajectories.csv (`compare --trajectories`); without it they
# are skipped with a note.
set -euo pipefail

usage="usage: scripts/plot.sh DIR   (DIR: a folder written by fragsim compare --csv DIR)"
if [ $# -ne 1 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  echo "$usage" >&2
  exit 2
fi
dir="${1%/}"
[ -n "$dir" ] || dir="/"
gp_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../data/plots" && pwd)"

if ! command -v gnuplot >/dev/null 2>&1; then
  echo "plot.sh: gnuplot is not installed (Debian: apt-get install gnuplot-nox)" >&2
  exit 1
fi
if [ ! -d "$dir" ]; then
  echo "plot.sh: $dir is not a folder; $usage" >&2
  exit 1
fi
case "$dir" in *"'"*)
  echo "plot.sh: the folder's path must not contain a single quote: $dir" >&2
  exit 1 ;;
esac

# needs_columns FILE COLUMN...: the CSV file exists and its header names every COLUMN
needs_columns() {
  local file="$1"
  shift
  if [ ! -r "$file" ]; then
    echo "plot.sh: $file is missing; write it with: fragsim compare --csv $dir" >&2
    return 1
  fi
  local header missing=()
  header=",$(head -n 1 "$file" | tr -d '\r'),"
  for c in "$@"; do
    case "$header" in *",$c,"*) ;; *) missing+=("$c") ;; esac
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "plot.sh: $file lacks the column(s) ${missing[*]}; was it written by fragsim compare --csv?" >&2
    return 1
  fi
  if [ "$(wc -l <"$file")" -lt 2 ]; then
    echo "plot.sh: $file has no data rows" >&2
    return 1
  fi
}

needs_columns "$dir/steps.csv" strategy step t_s candidates near_intersections occlusion \
  central_occlusion near_m || exit 1
paths=1
if [ ! -e "$dir/trajectories.csv" ]; then
  paths=0
  echo "plot.sh: no $dir/trajectories.csv (opt-in: fragsim compare --trajectories), skipping the paths figures"
else
  needs_columns "$dir/trajectories.csv" strategy step fragment x_m y_m z_m candidate || exit 1
  needs_columns "$dir/camera.csv" strategy step eye_x_m eye_y_m eye_z_m || exit 1
fi

outdir="$dir/plots"
mkdir -p "$outdir"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
touch "$tmp/start"
sleep 0.01 # the PNGs written below are newer than this marker

run() { # run SCRIPT [EXTRA]: one gnuplot script on $dir, stops the whole run on an error
  local script="$1" extra="${2:-}"
  if ! gnuplot -e "dir='$dir'; outdir='$outdir'$extra" "$gp_dir/$script"; then
    echo "plot.sh: $script failed" >&2
    exit 1
  fi
}
run candidates.gp
run over_time.gp
if [ "$paths" = 1 ]; then
  mkdir "$tmp/paths"
  run paths.gp "; tmpdir='$tmp/paths'"
fi

written="$(find "$outdir" -maxdepth 1 -name '*.png' -newer "$tmp/start" | sort)"
if [ -z "$written" ]; then
  echo "plot.sh: no PNG written" >&2
  exit 1
fi
echo "wrote:"
while IFS= read -r png; do echo "  $png"; done <<<"$written"
