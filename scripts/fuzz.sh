#!/usr/bin/env bash
# Builds the libFuzzer targets (preset fuzz: clang, ASan + UBSan) and runs each on a copy of its
# seed corpus in tests/fuzz/corpus/, so the repository is never written. Exits non-zero on any
# crash, trap, sanitizer report, leak or timeout; the reproducer is kept in the printed directory.
#
# Usage: scripts/fuzz.sh [--runs N] [--parallel P] [--only a,b] [--keep DIR] [SECONDS]
#   SECONDS (default 60): the wall-clock budget; every target runs that long, all side by side
#     (CI: the time stays SECONDS however many targets there are; each gets cores/targets of it).
#   --runs N: instead of a time, each target runs N inputs (scripts/soak.sh: 10 million), at most
#     P at a time (--parallel, default: the number of online CPUs).
#   --only: these targets (scene_parser, first_root, camera_track, obj_mesh, gltf_mesh,
#     control_api).
#   --keep DIR: also leave each target's log in DIR/<target>.log (the soak's record).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=60
runs=""
parallel=""
keep=""
fuzzers=(scene_parser first_root camera_track obj_mesh gltf_mesh control_api)
while [ "$#" -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --parallel) parallel="$2"; shift 2 ;;
    --only) IFS=, read -r -a fuzzers <<<"$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    -h | --help) sed -n '2,12p' "$0"; exit 0 ;;
    *) seconds="$1"; shift ;;
  esac
done
if [ -n "$runs" ]; then
  parallel="${parallel:-$(nproc)}"
else
  parallel="${#fuzzers[@]}"  # a time budget: all at once
fi

# clang and its libFuzzer/sanitizer runtimes, installed as scripts/setup.sh installs the rest.
scripts/install_packages.sh clang libclang-rt-dev

scripts/setup.sh fuzz  # the project's other packages, then configure and build the fuzz preset

work="$(mktemp -d "${TMPDIR:-/tmp}/fragsim-fuzz.XXXXXX")"

# Runs one fuzzer on a fresh copy of its corpus; its exit status is libFuzzer's.
run() {
  local fuzzer="$1" dir="$work/$1" extra=()
  mkdir -p "$dir/corpus" "$dir/artifacts"
  cp tests/fuzz/corpus/"$fuzzer"/* "$dir/corpus/"
  case "$fuzzer" in
    scene_parser) cp data/scenes/*.ini "$dir/corpus/" ;;  # the shipped scenes as they are now
    first_root) extra=(-max_len=57) ;;  # 7 doubles and a form byte, nothing more
    obj_mesh | gltf_mesh) extra=(-max_len=16384) ;;  # a few pieces; qhull per piece is the cost
  esac
  if [ -n "$runs" ]; then
    extra+=(-runs="$runs")
  else
    extra+=(-max_total_time="$seconds")
  fi
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    build/fuzz/tests/fuzz/"${fuzzer}_fuzz" "$dir/corpus" -timeout=5 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$dir/artifacts/" "${extra[@]}" \
    >"$dir/log.txt" 2>&1
}

if [ -n "$runs" ]; then
  echo "fuzz: ${fuzzers[*]}: $runs inputs each, $parallel at a time"
else
  echo "fuzz: ${fuzzers[*]} for ${seconds}s, side by side"
fi
declare -A rcs=()
declare -A running=()  # pid -> target
# Waits for whichever running fuzzer ends first and records its status.
reap() {
  local rc=0 pid=""
  wait -n -p pid "${!running[@]}" || rc=$?
  rcs["${running[$pid]}"]="$rc"
  unset "running[$pid]"
}
for fuzzer in "${fuzzers[@]}"; do
  [ -x "build/fuzz/tests/fuzz/${fuzzer}_fuzz" ] || { echo "fuzz: no target $fuzzer" >&2; exit 2; }
  while [ "${#running[@]}" -ge "$parallel" ]; do reap; done
  run "$fuzzer" &
  running[$!]="$fuzzer"
done
while [ "${#running[@]}" -gt 0 ]; do reap; done

status=0
for fuzzer in "${fuzzers[@]}"; do
  dir="$work/$fuzzer"
  rc="${rcs[$fuzzer]}"
  [ -n "$keep" ] && { mkdir -p "$keep"; cp "$dir/log.txt" "$keep/$fuzzer.log"; }
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
