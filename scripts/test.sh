#!/usr/bin/env bash
# Sets up (missing Debian packages, configure, build) and runs every test: the release build and
# the one-node Slurm test of sliced sweeps, then the same suite under AddressSanitizer +
# UndefinedBehaviorSanitizer, then the fuzz targets.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"
scripts/setup.sh release
scripts/install_packages.sh chromium chromium-driver python3 # the Browser.ReportLoads test
# clang: the library built alone with clang and ThreadSanitizer (Control.Library.BuildsAlone)
scripts/install_packages.sh clang libclang-rt-dev abigail-tools # abidw, abidiff: Control.Library.Abi*
scripts/install_packages.sh emscripten # the WebAssembly build (Web.*: scripts/web_build.sh)
ctest --preset release -j"$jobs"
scripts/slurm/test.sh build/release/fragsim # a 4-task Slurm job array and its merge, ~10 s
scripts/setup.sh asan
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j"$jobs"
scripts/fuzz.sh 120 # the six targets side by side, 2 minutes in all
