#!/usr/bin/env bash
# Runs the job-array sweep for real on a one-node Slurm started here: munged, slurmctld and slurmd
# as plain daemons (no systemd), a minimal slurm.conf and a fresh munge key in a temporary folder,
# this machine's CPUs and memory as the one node. Submits a small sweep as a 4-task array plus the
# merge (scripts/slurm/submit.sh), waits for both, and checks the merged file against the same
# sweep run here unsharded, byte for byte. Every daemon is stopped and the folder removed on any
# exit. Needs root (the daemons run as root here) and the Debian packages below.
# Usage: scripts/slurm/test.sh [FRAGSIM_BINARY]   (default build/release/fragsim)
set -euo pipefail
cd "$(dirname "$0")/../.."
repo="$(pwd)"
fragsim="$(realpath "${1:-build/release/fragsim}")"
[ -x "$fragsim" ] || { echo "slurm test: no fragsim binary at $fragsim" >&2; exit 2; }
if [ "$(id -u)" -ne 0 ]; then
  # The daemons run as root (SlurmUser=root): become root through sudo, or say why not.
  command -v sudo >/dev/null 2>&1 || { echo "slurm test: needs root or sudo" >&2; exit 1; }
  exec sudo -E "$0" "$fragsim"
fi
scripts/install_packages.sh slurmctld slurmd slurm-client munge
start_s="$(date +%s)"

tmp="$(mktemp -d "${TMPDIR:-/tmp}/fragsim-slurm.XXXXXX")"
pids=()
cleanup() {
  local rc=$?
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$p" 2>/dev/null || true
  done
  if [ "$rc" -ne 0 ]; then
    for log in "$tmp"/*.log "$tmp"/work/*.slices/*.out; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 15 "$log"; }
    done >&2
  fi
  rm -rf "$tmp"
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Free ports of our own, so this never meets another Slurm (or a second copy of this test).
free_port() {
  python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}
ctld_port="$(free_port)"
slurmd_port="$(free_port)"
while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port="$(free_port)"; done

# munge: its own key and socket.
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 0400 "$tmp/munge.key"
/usr/sbin/munged --force --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.sock" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge.seed" \
  >>"$tmp/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$tmp/munge.sock" ] && break; sleep 0.1; done
[ -S "$tmp/munge.sock" ] || { echo "slurm test: munged did not start" >&2; exit 1; }

node="$(hostname -s)"
# The node as slurmd sees it (CPUs, sockets, cores, memory), so slurmd accepts its registration.
node_line="$(/usr/sbin/slurmd -C | head -n 1 | sed "s/^NodeName=[^ ]*/NodeName=$node/")"
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/work"
cat >"$tmp/slurm.conf" <<CONF
ClusterName=fragsimtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.sock
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool/%n
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SlurmdTimeout=60
MinJobAge=600
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$tmp/slurm.conf"
/usr/sbin/slurmctld -D -i -f "$SLURM_CONF" >>"$tmp/slurmctld.log" 2>&1 &
pids+=($!)
/usr/sbin/slurmd -D -f "$SLURM_CONF" -N "$node" >>"$tmp/slurmd.log" 2>&1 &
pids+=($!)
for _ in $(seq 150); do
  state="$(sinfo -h -N -o %T 2>/dev/null | head -n 1 || true)"
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || { echo "slurm test: the node is not idle (state '$state')" >&2; exit 1; }
up_s="$(date +%s)"

# The sweep: 3 distances x 4 seeds = 12 jobs of thesis125 cut short, three strategies.
# shellcheck disable=SC2054  # the commas are fragsim's lists, not array separators
args=(sweep --scene "$repo/data/scenes/thesis125.ini" --object.splits 3
      --simulation.duration_s 0.5 --vary object.distance_m=3,5,7 --seeds 4
      --strategies none,edge,edge-min)
cd "$tmp/work"
FRAGSIM="$fragsim" "$repo/scripts/slurm/submit.sh" 4 "$tmp/work/sweep.csv" "${args[@]}"
read -r array merge <"$tmp/work/sweep.csv.slices/jobs"

# Waits until the merge job has left the queue or finished; fails on any other end.
for _ in $(seq 600); do
  st="$(scontrol show job "$merge" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p')"
  case "$st" in
    COMPLETED) break ;;
    FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE)
      echo "slurm test: merge job $merge ended $st" >&2
      scontrol show job "$array" >&2 || true
      exit 1 ;;
  esac
  sleep 0.5
done
[ "$st" = COMPLETED ] || { echo "slurm test: merge job $merge not done (state '$st')" >&2; exit 1; }
done_s="$(date +%s)"
slices=("$tmp/work/sweep.csv.slices"/shard_*.csv)
tasks="${#slices[@]}"
[ "$tasks" -eq 4 ] || { echo "slurm test: $tasks slices, expected 4" >&2; exit 1; }

"$fragsim" "${args[@]}" --jobs 1 --out "$tmp/work/local.csv" >/dev/null
if ! cmp "$tmp/work/local.csv" "$tmp/work/sweep.csv"; then
  echo "slurm test: the merged file differs from the unsharded sweep" >&2
  diff "$tmp/work/local.csv" "$tmp/work/sweep.csv" | head -n 10 >&2
  exit 1
fi
end_s="$(date +%s)"
echo "slurm test: 4-task array ($array) + merge ($merge): $(($(wc -l <"$tmp/work/sweep.csv") - 1)) rows, byte-identical to the unsharded sweep"
echo "slurm test: daemons up $((up_s - start_s)) s, jobs $((done_s - up_s)) s, local check $((end_s - done_s)) s, total $((end_s - start_s)) s"
