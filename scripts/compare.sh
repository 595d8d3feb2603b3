#!/usr/bin/env bash
# Sets up (missing Debian packages, configure, build the tool alone: not the tests and benchmarks)
# and compares every strategy on a scene (default: data/scenes/front.ini). Extra arguments go to
# `fragsim compare`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh release fragsim >/dev/null
scene="data/scenes/front.ini"
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then
  scene="$1"
  shift
fi
exec build/release/fragsim compare --scene "$scene" "$@"
