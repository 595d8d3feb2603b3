#!/usr/bin/env bash
# Builds the libFuzzer targets (preset fuzz: clang, ASan + UBSan) and runs each for SECONDS
# (default 60) on a copy of its seed corpus in tests/fuzz/corpus/, so the repository is never
# written. Exits non-zero on any crash, trap, sanitizer report, leak or timeout; the reproducer is
# kept in the printed directory. Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"

# clang and its libFuzzer/sanitizer runtimes, installed as scripts/setup.sh installs the rest.
scripts/install_packages.sh clang libclang-rt-dev

scripts/setup.sh fuzz  # the project's other packages, then configure and build the fuzz preset

work="$(mktemp -d "${TMPDIR:-/tmp}/fragsim-fuzz.XXXXXX")"
fuzzers=(scene_parser first_root)

# Runs one fuzzer on a fresh copy of its corpus; its exit status is libFuzzer's.
run() {
  local fuzzer="$1" dir="$work/$1" extra=()
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp tests/fuzz/corpus/"$fuzzer"/* "$dir/corpus/"
  if [ "$fuzzer" = scene_parser ]; then
    cp data/scenes/*.ini "$dir/corpus/"  # the shipped scenes as they are now
  else
    extra=(-max_len=57)  # first_root reads 7 doubles and a form byte, nothing more
  fi
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    build/fuzz/tests/fuzz/"${fuzzer}_fuzz" "$dir/corpus" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "${extra[@]}" \
    >"$dir/log.txt" 2>&1
}

# One core each, side by side.
echo "fuzz: ${fuzzers[*]} for ${seconds}s each"
pids=()
for fuzzer in "${fuzzers[@]}"; do
  run "$fuzzer" &
  pids+=($!)
done
status=0
for i in "${!fuzzers[@]}"; do
  fuzzer="${fuzzers[$i]}"
  dir="$work/$fuzzer"
  rc=0
  wait "${pids[$i]}" || rc=$?
  # The last status line ("#N DONE cov: ... ft: ... corp: ...") and the final stats.
  echo "fuzz: $fuzzer: $(grep -E '^#[0-9]+[[:space:]]+(DONE|INITED|pulse|NEW|REDUCE)' \
    "$dir/log.txt" | tail -n 1 || true)"
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb|slowest_unit_time_sec)' \
    "$dir/log.txt" | sed "s/^/fuzz: $fuzzer: /" || true
  if [ "$rc" -ne 0 ] || [ -n "$(ls -A "$dir/artifacts")" ]; then
    echo "fuzz: $fuzzer FAILED (exit $rc); log $dir/log.txt, reproducers in $dir/artifacts:" >&2
    grep -E -A 40 '^==[0-9]+==|runtime error|deadly signal|ALARM|out-of-memory' "$dir/log.txt" |
      head -n 80 >&2 || true
    for a in "$dir"/artifacts/*; do
      [ -e "$a" ] || continue
      echo "fuzz: $(basename "$a") (hex):" >&2
      od -An -tx1 -v "$a" | head -n 20 >&2
    done
    status=1
  fi
done
if [ "$status" -eq 0 ]; then
  rm -rf "$work"
  echo "fuzz: no crash, sanitizer report, leak or timeout"
fi
exit "$status"
