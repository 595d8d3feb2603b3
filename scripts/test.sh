#!/usr/bin/env bash
# Sets up (missing Debian packages, configure, build) and runs every test: the release build, then
# the same suite under AddressSanitizer + UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="$(nproc)"
scripts/setup.sh release
scripts/install_packages.sh chromium chromium-driver python3 # the Browser.ReportLoads test
ctest --preset release -j"$jobs"
scripts/setup.sh asan
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j"$jobs"
scripts/fuzz.sh 60
