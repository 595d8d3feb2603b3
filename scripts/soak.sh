#!/usr/bin/env bash
# The long checks that do not belong in every CI run (README, "Soak"): the stress generator's
# random scenes by the thousand, every strategy on each (tests/stress/soak/soak.cpp: zero
# non-finite numbers, zero ODE messages, zero crashes, forces within their caps, energy within its
# budget), and every libFuzzer target for millions of inputs (scripts/fuzz.sh --runs).
#
# Usage: scripts/soak.sh [--scenes N] [--first SEED] [--chunk C] [--scale X] [--fuzz-runs R]
#                        [--no-stress] [--no-fuzz] [--out DIR]
#   --scenes N     random scenes (default 10000: seeds FIRST .. FIRST+N-1, FIRST default 1)
#   --chunk C      scenes per process (default 50); a crash names its seed and the soak goes on
#                  with the next seed in a fresh process
#   --scale X      FRAGSIM_STRESS_SCALE: each scene's fragment-steps (default 1, the CI suite's)
#   --fuzz-runs R  inputs per fuzz target (default 10000000)
#   --out DIR      logs and the summary (default: a new folder under ${TMPDIR:-/tmp})
# The stress part runs on one core while the fuzzers share the others (at least one); run it
# under `nice` on a shared machine. Exits non-zero if any check failed.
set -euo pipefail
cd "$(dirname "$0")/.."
scenes=10000
first=1
chunk=50
scale=1
fuzz_runs=10000000
stress=1
fuzz=1
out=""
while [ "$#" -gt 0 ]; do
  case "$1" in
    --scenes) scenes="$2"; shift 2 ;;
    --first) first="$2"; shift 2 ;;
    --chunk) chunk="$2"; shift 2 ;;
    --scale) scale="$2"; shift 2 ;;
    --fuzz-runs) fuzz_runs="$2"; shift 2 ;;
    --no-stress) stress=0; shift ;;
    --no-fuzz) fuzz=0; shift ;;
    --out) out="$2"; shift 2 ;;
    -h | --help) sed -n '2,16p' "$0"; exit 0 ;;
    *) echo "soak: unknown argument '$1' (--help)" >&2; exit 2 ;;
  esac
done
out="${out:-$(mktemp -d "${TMPDIR:-/tmp}/fragsim-soak.XXXXXX")}"
mkdir -p "$out"
echo "soak: logs in $out"
started="$(date -u +%FT%TZ)"

stress_status=0
run_stress() {
  scripts/setup.sh release >/dev/null
  local tracks="$out/tracks" seed="$first" last=$((first + scenes - 1)) crashes=0
  mkdir -p "$tracks"
  : >"$out/stress.log"
  while [ "$seed" -le "$last" ]; do
    local n=$((last - seed + 1))
    [ "$n" -gt "$chunk" ] && n="$chunk"
    local rc=0
    FRAGSIM_STRESS_SCALE="$scale" FRAGSIM_STRESS_DIR="$tracks" \
      build/release/tests/fragsim_soak "$seed" "$n" >"$out/chunk.log" 2>&1 || rc=$?
    cat "$out/chunk.log" >>"$out/stress.log"
    if [ "$rc" -gt 1 ]; then
      # Died (a signal, an abort): the seed it began last is the culprit; go on after it.
      local bad
      bad="$(grep -E '^begin [0-9]+$' "$out/chunk.log" | tail -n 1 | cut -d' ' -f2)"
      echo "CRASH $bad (exit $rc)" >>"$out/stress.log"
      crashes=$((crashes + 1))
      seed=$((bad + 1))
    else
      seed=$((seed + n))
    fi
    rm -f "$tracks"/*.csv
  done
  # The chunks' summary lines added up.
  awk -v crashes="$crashes" '
    /^soak: / { for (i = 2; i < NF; i += 2) { sum[$i] += $(i + 1); if (!($i in seen)) { seen[$i] = 1; order[++k] = $i } } }
    /^soak: / { for (i = 2; i < NF; i += 2) if ($i == "largest" && $(i + 1) > max) max = $(i + 1) }
    END { printf "stress:"; for (j = 1; j <= k; ++j) printf " %s %s", order[j], (order[j] == "largest" ? max : sum[order[j]]); printf " crashes %d\n", crashes }
  ' "$out/stress.log" | tee "$out/stress_summary.txt"
  grep -E '^(FAIL|CRASH) ' "$out/stress.log" | head -n 20 || true
  if grep -qE '^(FAIL|CRASH) ' "$out/stress.log"; then return 1; fi
}

fuzz_status=0
if [ "$stress" -eq 1 ] && [ "$fuzz" -eq 1 ]; then
  cores="$(nproc)"
  fuzz_parallel=$((cores > 1 ? cores - 1 : 1))
  run_stress &
  stress_pid=$!
  scripts/fuzz.sh --runs "$fuzz_runs" --parallel "$fuzz_parallel" --keep "$out/fuzz" \
    >"$out/fuzz.txt" 2>&1 || fuzz_status=$?
  wait "$stress_pid" || stress_status=$?
elif [ "$stress" -eq 1 ]; then
  run_stress || stress_status=$?
elif [ "$fuzz" -eq 1 ]; then
  scripts/fuzz.sh --runs "$fuzz_runs" --keep "$out/fuzz" >"$out/fuzz.txt" 2>&1 || fuzz_status=$?
fi
[ "$fuzz" -eq 1 ] && grep -E '^fuzz: ' "$out/fuzz.txt" | grep -E 'executed_units|exec_per_sec|FAILED|no crash'
echo "soak: $started .. $(date -u +%FT%TZ), $(nproc) CPUs ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)), scale $scale"
[ "$stress_status" -eq 0 ] && [ "$fuzz_status" -eq 0 ]
