#!/usr/bin/env bash
# Submits a fragsim sweep or suite as N array tasks (one slice each) and the merge after them.
# Usage: scripts/slurm/submit.sh N OUT sweep|suite OPTIONS...
# The slices go to OUT.slices/ (which must hold none yet); the merged file is OUT. Extra sbatch
# options come from SBATCH_* variables (e.g. SBATCH_PARTITION) or FRAGSIM_SBATCH_OPTIONS. Prints
# the two job ids; the fragsim binary is $FRAGSIM (default: fragsim on PATH), passed to the jobs.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ "$#" -lt 3 ]; then
  echo "usage: scripts/slurm/submit.sh N OUT sweep|suite OPTIONS..." >&2
  exit 2
fi
n="$1"
out="$2"
shift 2
if ! [[ "$n" =~ ^[1-9][0-9]*$ ]]; then
  echo "submit.sh: N '$n': a whole number >= 1" >&2
  exit 2
fi
slices="$out.slices"
if compgen -G "$slices/shard_*.csv" >/dev/null; then
  echo "submit.sh: $slices already holds slices; remove them or choose another OUT" >&2
  exit 2
fi
mkdir -p "$slices"
# shellcheck disable=SC2086  # FRAGSIM_SBATCH_OPTIONS is a list of options
array="$(sbatch --parsable ${FRAGSIM_SBATCH_OPTIONS:-} --array="0-$((n - 1))" \
  --output="$slices/task-%a.out" "$here/sweep.sbatch" "$slices" "$@")"
array="${array%%;*}"  # "id;cluster" on a federation
# shellcheck disable=SC2086
merge="$(sbatch --parsable ${FRAGSIM_SBATCH_OPTIONS:-} --dependency="afterok:$array" \
  --kill-on-invalid-dep=yes --output="$slices/merge.out" "$here/merge.sbatch" "$out" "$slices")"
merge="${merge%%;*}"
echo "submitted: array job $array ($n slices into $slices/), merge job $merge (into $out)"
echo "$array $merge" >"$slices/jobs"
