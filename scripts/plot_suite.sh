#!/usr/bin/env bash
# Draws robustness against deviation from a `fragsim suite --out FILE` CSV with
# data/plots/suite.gp: one point per strategy (edge-min per camera model), the clean share of its
# player-camera runs against its mean deviation. Usage: scripts/plot_suite.sh CSV [OUT.png]
# (default: CSV with .png in place of .csv). MODES=all (or a comma list) counts other rows.
set -euo pipefail

usage="usage: scripts/plot_suite.sh CSV [OUT.png]   (CSV: written by fragsim suite --out CSV)"
if [ $# -lt 1 ] || [ $# -gt 2 ] || [ "$1" = "-h" ] || [ "$1" = "--help" ]; then
  echo "$usage" >&2
  exit 2
fi
csv="$1"
out="${2:-${csv%.csv}.png}"
gp_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../data/plots" && pwd)"

if ! command -v gnuplot >/dev/null 2>&1; then
  echo "plot_suite.sh: gnuplot is not installed (Debian: apt-get install gnuplot-nox)" >&2
  exit 1
fi
case "$csv$out${MODES:-}" in *"'"*)
  echo "plot_suite.sh: paths and MODES must not contain a single quote" >&2
  exit 1 ;;
esac
if [ ! -r "$csv" ]; then
  echo "plot_suite.sh: cannot read $csv; $usage" >&2
  exit 1
fi
header=",$(head -n 1 "$csv" | tr -d '\r'),"
for c in mode strategy near_fragments camera_hit_fragments deviation_mean_m; do
  case "$header" in *",$c,"*) ;; *)
    echo "plot_suite.sh: $csv lacks the column $c; was it written by fragsim suite --out?" >&2
    exit 1 ;;
  esac
done
modes="${MODES:-player,player-instant}"
if ! gnuplot -e "csv='$csv'; out='$out'; modes='$modes'" "$gp_dir/suite.gp"; then
  echo "plot_suite.sh: suite.gp failed" >&2
  exit 1
fi
echo "wrote $out"
