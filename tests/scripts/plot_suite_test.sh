#!/usr/bin/env bash
# The suite's figure: a two-run slice of the battery, then scripts/plot_suite.sh; the PNG must
# exist and be a PNG. Usage: plot_suite_test.sh FRAGSIM_BINARY SOURCE_DIR
set -euo pipefail
fragsim="$1"
src="$2"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$fragsim" suite --scene-dir "$src/data/scenes" --scenes thesis125 --seeds 1 --limit 3 \
  --out "$out/suite.csv" >/dev/null
bash "$src/scripts/plot_suite.sh" "$out/suite.csv" >/dev/null
f="$out/suite.png"
if [ ! -s "$f" ] || [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" != "89504e470d0a1a0a" ]; then
  echo "missing or not a PNG: suite.png"
  exit 1
fi
echo "plot_suite_test: suite.png written"
