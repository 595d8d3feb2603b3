#!/usr/bin/env bash
# The scene keys' property test at soak size (tests/property/scene_keys_test.cpp): random legal
# values of every ranged scene key, several at once, extremes favoured, each case a short run in a
# child process; any abort, hang or non-finite number is printed as a fragsim command line. CI
# runs 500 cases of seed 1 (ctest -L property); this runs 10,000 of another seed by default.
#
# Usage: scripts/soak_scene_keys.sh [--cases N] [--seed S] [--limit SECONDS] [--build DIR]
#   --cases N        cases (default 10000)
#   --seed S         the case list's seed (default 2; CI uses 1)
#   --limit SECONDS  a case silent this long is a hang (default 60)
#   --build DIR      the build folder holding tests/fragsim_property_tests (default build/release)
# Run it under `nice` on a shared machine. Exits non-zero if any case failed.
set -euo pipefail
cd "$(dirname "$0")/.."
cases=10000
seed=2
limit=60
build=build/release
while [ "$#" -gt 0 ]; do
  case "$1" in
    --cases) cases="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --limit) limit="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    *) echo "soak_scene_keys.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
binary="$build/tests/fragsim_property_tests"
[ -x "$binary" ] || { echo "soak_scene_keys.sh: $binary not built (cmake --build $build --target fragsim_property_tests)" >&2; exit 2; }
FRAGSIM_SCENE_KEYS_CASES="$cases" FRAGSIM_SCENE_KEYS_SEED="$seed" FRAGSIM_SCENE_KEYS_LIMIT_S="$limit" \
  "$binary" --gtest_filter='SceneKeys.RandomLegalValuesRunOrAreRefusedWithOneLine'
