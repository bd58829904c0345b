#!/usr/bin/env bash
# The README's Slurm job array, run on a one-node Slurm cluster started on this machine:
#   1. installs Debian's slurm-wlm and munge when they are missing (apt-get, as scripts/setup.sh);
#   2. starts munged, slurmctld and slurmd, as root, from a minimal slurm.conf generated in a
#      temporary folder: this node with its real CPU count and memory (`slurmd -C`), no accounting,
#      no cgroups (proctrack/linuxproc, task/none), so that it works in a container too;
#   3. submits the README's job array -- one `pe batch ... --shard K/N --resume` per task -- over a
#      folder or a list of meshes and waits for it (bounded by --timeout);
#   4. merges the shards with `pe batch-merge`;
#   5. runs the same batch unsharded and compares: the two `--drop-timings` merges must be the same
#      bytes (same inputs, statuses, exit statuses and certificates), and every task must have run
#      to its end (exit 0: all valid, or 1: some mesh not valid);
#   6. stops the daemons it started and removes what it made (unless --keep).
# It prints `sinfo`, the array's tasks (`scontrol show job`: no accounting, so no `sacct`), their
# output files and the per-input comparison.
#
# Usage: scripts/slurm_batch.sh [OPTIONS] INPUTS [WORK_DIR]
#   INPUTS            a folder of meshes or a list file, as for `pe batch`
#   WORK_DIR          where the shards, merges and logs are written (default: a temporary folder,
#                     removed at the end unless --keep)
#   --pe PATH         the `pe` tool (default: build/bin/pe of this repository)
#   --pipeline P      untangle (default), embed, optimize or constrain
#   --shards N        tasks of the job array (default 2)
#   --jobs J          `pe batch --jobs` of each task, and its --cpus-per-task (default 1)
#   --memory-limit MB `pe batch --memory-limit` (default 8192)
#   --timeout S       bound on every wait for the array and for the unsharded run (default 300)
#   --no-install      do not install missing packages (exit 77 instead)
#   --keep            keep WORK_DIR and the Slurm folder (slurm.conf, daemon logs)
#
# Exit status: 0 the merged shards equal the unsharded run; 1 they differ, a task failed or a wait
# timed out; 2 bad arguments; 77 Slurm cannot run here (not root, packages missing and not
# installable, or a daemon refuses to start): the reason is printed (ctest: SKIP_RETURN_CODE 77).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
SKIP=77
repo=$(cd "$(dirname "$0")/.." && pwd)

pe_tool=$repo/build/bin/pe pipeline=untangle shards=2 jobs=1 memory_limit=8192 timeout=300 install=1 keep=0
args=()
usage() { sed -n '/^# Usage:/,/^# Exit status/p' "$0" | sed 's/^# \{0,1\}//' | sed '$d' >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --pe) pe_tool=${2:?}; shift 2 ;;
    --pipeline) pipeline=${2:?}; shift 2 ;;
    --shards) shards=${2:?}; shift 2 ;;
    --jobs) jobs=${2:?}; shift 2 ;;
    --memory-limit) memory_limit=${2:?}; shift 2 ;;
    --timeout) timeout=${2:?}; shift 2 ;;
    --no-install) install=0; shift ;;
    --keep) keep=1; shift ;;
    -h|--help) usage ;;
    -*) echo "slurm_batch: unknown option $1" >&2; usage ;;
    *) args+=("$1"); shift ;;
  esac
done
[ ${#args[@]} -ge 1 ] && [ ${#args[@]} -le 2 ] || usage
for n in "$shards" "$jobs" "$timeout" "$memory_limit"; do
  [[ "$n" =~ ^[0-9]+$ ]] || { echo "slurm_batch: not a number: $n" >&2; exit 2; }
done
[ "$shards" -ge 1 ] && [ "$jobs" -ge 1 ] && [ "$timeout" -ge 1 ] || { echo "slurm_batch: --shards, --jobs and --timeout must be >= 1" >&2; exit 2; }
inputs=$(realpath -e "${args[0]}" 2>/dev/null) || { echo "slurm_batch: no such folder or list: ${args[0]}" >&2; exit 2; }
[ -x "$pe_tool" ] || { echo "slurm_batch: the pe tool is not built: $pe_tool (build it, or give --pe PATH)" >&2; exit 2; }
pe_tool=$(realpath "$pe_tool")

skip() { echo "slurm_batch: SKIPPED: $*" >&2; exit $SKIP; }
fail() { echo "slurm_batch: FAILED: $*" >&2; exit 1; }

# ---- 1. packages --------------------------------------------------------------------------------
[ "$(id -u)" -eq 0 ] || skip "starting slurmd and munged needs root (this is uid $(id -u))"
packages=(slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  [ $install -eq 1 ] || skip "${missing[*]} not installed (scripts/slurm_batch.sh without --no-install installs them)"
  command -v apt-get >/dev/null || skip "${missing[*]} not installed and no apt-get"
  echo "slurm_batch: installing ${missing[*]}"
  { apt-get update && apt-get install -y --no-install-recommends "${packages[@]}"; } \
    || skip "apt-get could not install ${missing[*]}"
fi
for c in munged munge slurmctld slurmd sbatch squeue sinfo scontrol scancel python3; do
  command -v $c >/dev/null || skip "$c not found after installing ${packages[*]}"
done

# ---- 2. daemons ---------------------------------------------------------------------------------
slurm_dir=$(mktemp -d /tmp/pe-slurm.XXXXXX)
chmod 755 "$slurm_dir"   # munged wants its socket's folder searchable by all
if [ ${#args[@]} -eq 2 ]; then
  work=$(realpath -m "${args[1]}"); mkdir -p "$work"; own_work=0
else
  work=$slurm_dir/work; mkdir -p "$work"; own_work=1
fi
export SLURM_CONF=$slurm_dir/slurm.conf
job_id=""

stop_pid() {  # stop_pid PIDFILE NAME: TERM, then KILL after 10 s
  local f=$1 pid i
  [ -s "$f" ] || return 0
  pid=$(cat "$f")
  kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for i in $(seq 50); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.2; done
  echo "slurm_batch: $2 (pid $pid) did not stop in 10 s: killed" >&2
  kill -KILL "$pid" 2>/dev/null || true
}
cleanup() {
  local rc=$? i
  set +e
  if [ -n "$job_id" ] && [ -n "$(squeue -h -j "$job_id" 2>/dev/null)" ]; then
    echo "slurm_batch: cancelling job $job_id"
    scancel "$job_id"
    for i in $(seq 50); do [ -z "$(squeue -h -j "$job_id" 2>/dev/null)" ] && break; sleep 0.2; done
  fi
  stop_pid "$slurm_dir/slurmd.pid" slurmd
  stop_pid "$slurm_dir/slurmctld.pid" slurmctld
  stop_pid "$slurm_dir/munged.pid" munged
  if [ $keep -eq 1 ]; then
    echo "slurm_batch: kept $slurm_dir (slurm.conf, logs) and $work"
  else
    rm -rf "$slurm_dir"
  fi
  exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT TERM

show_logs() {
  local f
  for f in "$slurm_dir"/munged.log "$slurm_dir"/slurmctld.log "$slurm_dir"/slurmd.log; do
    if [ -f "$f" ]; then echo "---- last lines of $f"; tail -n 15 "$f"; fi
  done >&2
  return 0
}

# munged: its own key and socket (the machine's munged, if any, is left alone)
dd if=/dev/urandom of="$slurm_dir/munge.key" bs=1024 count=1 status=none
chmod 600 "$slurm_dir/munge.key"
socket=$slurm_dir/munge.socket
timeout 20 munged --force --key-file="$slurm_dir/munge.key" --socket="$socket" --pid-file="$slurm_dir/munged.pid" \
  --log-file="$slurm_dir/munged.log" --seed-file="$slurm_dir/munged.seed" \
  || { show_logs; skip "munged does not start"; }
ok=0
for i in $(seq 50); do
  if munge -n -S "$socket" 2>/dev/null | unmunge -S "$socket" >/dev/null 2>&1; then ok=1; break; fi
  sleep 0.2
done
[ $ok -eq 1 ] || { show_logs; skip "munged does not answer on $socket"; }

# two free TCP ports, so that this cluster meets no other one on the machine
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
host=$(uname -n); host=${host%%.*}   # the short host name, as slurmctld compares it
# this node as slurmd sees it: CPUs, sockets, cores, threads, RealMemory
node_hw=$(slurmd -C 2>/dev/null | head -n 1 | tr ' ' '\n' | grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore|RealMemory)=' | tr '\n' ' ') \
  || true
cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$node_hw")
memory=$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$node_hw")
[ -n "$cpus" ] && [ -n "$memory" ] || skip "slurmd -C does not describe this node"
mkdir -p "$slurm_dir/state" "$slurm_dir/spool"
cat > "$SLURM_CONF" <<EOF
# one-node cluster of scripts/slurm_batch.sh: no accounting, no cgroups
ClusterName=pe
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$slurm_dir/state
SlurmdSpoolDir=$slurm_dir/spool
SlurmctldPidFile=$slurm_dir/slurmctld.pid
SlurmdPidFile=$slurm_dir/slurmd.pid
SlurmctldLogFile=$slurm_dir/slurmctld.log
SlurmdLogFile=$slurm_dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
MailProg=/bin/true
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=3600
NodeName=pe-node NodeHostname=$host NodeAddr=127.0.0.1 ${node_hw}State=UNKNOWN
PartitionName=pe Nodes=pe-node Default=YES MaxTime=INFINITE State=UP
EOF
up=$SECONDS
timeout 30 slurmctld -f "$SLURM_CONF" || { show_logs; skip "slurmctld does not start"; }
timeout 30 slurmd -f "$SLURM_CONF" -N pe-node || { show_logs; skip "slurmd does not start"; }
state=""
for i in $(seq 150); do   # 30 s for the node to register
  state=$(timeout 10 sinfo -h -N -o %T 2>/dev/null | head -n 1) || true
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || { show_logs; timeout 10 scontrol show node pe-node >&2 || true
                         skip "the node does not come up (state '${state:-none}')"; }
echo "slurm_batch: one-node Slurm $(sinfo -V | cut -d' ' -f2) on $host: $cpus CPUs, $memory MB, up in $((SECONDS - up)) s (ports $ctld_port, $slurmd_port)"
echo '$ sinfo'
sinfo

# ---- 3. the job array ---------------------------------------------------------------------------
[ "$jobs" -le "$cpus" ] || { echo "slurm_batch: --jobs $jobs > $cpus CPUs: $cpus"; jobs=$cpus; }
mem_per_task=$(( memory * jobs / cpus ))
minutes=$(( (timeout + 59) / 60 ))
out=$work/shards
rm -rf "$work/slurm-logs" "$out" "$work/merged" "$work/unsharded" "$work/compare"
mkdir -p "$work/slurm-logs" "$out"
cat > "$work/slurm-logs/array.sh" <<EOF
#!/bin/bash
#SBATCH --array=1-$shards
#SBATCH --cpus-per-task=$jobs --mem=${mem_per_task}M --time=$minutes
#SBATCH --job-name=pe-batch --output=$work/slurm-logs/task-%a.out
"$pe_tool" batch $pipeline "$inputs" "$out/shard-\$SLURM_ARRAY_TASK_ID" \\
   --shard \$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT --jobs $jobs --memory-limit $memory_limit --resume --no-progress
EOF
echo '$ cat array.sh'
cat "$work/slurm-logs/array.sh"
job_id=$(timeout 30 sbatch --parsable --chdir="$work" "$work/slurm-logs/array.sh") || fail "sbatch refused the job array"
job_id=${job_id%%;*}
echo "slurm_batch: submitted job array $job_id ($shards tasks)"
start=$SECONDS
while [ -n "$(timeout 10 squeue -h -j "$job_id" 2>/dev/null)" ]; do
  [ $((SECONDS - start)) -lt "$timeout" ] || fail "job array $job_id not finished after $timeout s (--timeout)"
  sleep 1
done
echo "slurm_batch: job array $job_id finished in $((SECONDS - start)) s"
echo "\$ scontrol show job $job_id   (one record per task)"
tasks=$(timeout 10 scontrol -o show job "$job_id") || fail "scontrol show job $job_id"
field() { tr ' ' '\n' <<<"$1" | sed -n "s/^$2=//p" | head -n 1; }
bad=0 n=0
while read -r rec; do
  [ -n "$rec" ] || continue
  n=$((n + 1))
  t=$(field "$rec" ArrayTaskId) s=$(field "$rec" JobState) e=$(field "$rec" ExitCode)
  printf '  task %-3s JobId=%-5s JobState=%-10s ExitCode=%-5s RunTime=%s\n' "$t" "$(field "$rec" JobId)" "$s" "$e" "$(field "$rec" RunTime)"
  # `pe batch` exits 0 if every mesh is valid and 1 if not: both are a task that ran to its end
  case "$s:$e" in COMPLETED:0:0|FAILED:1:0) ;; *) bad=$((bad + 1)) ;; esac
done < <(while read -r r; do [ -z "$r" ] || printf '%s\t%s\n' "$(field "$r" ArrayTaskId)" "$r"; done <<<"$tasks" \
           | sort -n | cut -f2-)
for f in "$work"/slurm-logs/task-*.out; do
  echo "---- $(basename "$f")"; cat "$f"
done
[ "$n" -eq "$shards" ] || fail "scontrol lists $n tasks of job $job_id, not $shards"
[ $bad -eq 0 ] || fail "$bad task(s) of job $job_id did not run to their end (state and exit status above)"

# ---- 4. merge -----------------------------------------------------------------------------------
shard_dirs=()
for k in $(seq "$shards"); do shard_dirs+=("$out/shard-$k"); done
echo "\$ pe batch-merge shards/shard-* --out merged/"
timeout "$timeout" "$pe_tool" batch-merge "${shard_dirs[@]}" --out "$work/merged" || [ $? -eq 1 ] \
  || fail "pe batch-merge of the shards"
cat "$work/merged/summary.md"

# ---- 5. the unsharded run and the comparison ----------------------------------------------------
echo "\$ pe batch $pipeline INPUTS unsharded/ --jobs $jobs --memory-limit $memory_limit   (without Slurm)"
rc=0
timeout "$timeout" "$pe_tool" batch $pipeline "$inputs" "$work/unsharded" --jobs "$jobs" --memory-limit "$memory_limit" \
  --no-progress > "$work/unsharded.log" 2>&1 || rc=$?
tail -n 1 "$work/unsharded.log"
[ $rc -le 1 ] || { cat "$work/unsharded.log" >&2; fail "the unsharded pe batch exits $rc"; }
mkdir -p "$work/compare"
"$pe_tool" batch-merge "${shard_dirs[@]}" --out "$work/compare/shards" --drop-timings >/dev/null || [ $? -eq 1 ] || fail "merge"
"$pe_tool" batch-merge "$work/unsharded" --out "$work/compare/unsharded" --drop-timings >/dev/null || [ $? -eq 1 ] || fail "merge"
python3 - "$work/compare/shards" "$work/compare/unsharded" "$work/merged" <<'EOF' || fail "the merged shards differ from the unsharded run"
import json, os, sys
a_dir, b_dir, timed_dir = sys.argv[1:4]
def load(d):
    with open(os.path.join(d, "results.jsonl"), encoding="utf-8") as f:
        return {r["input"]: r for r in map(json.loads, filter(str.strip, f))}
a, b, timed = load(a_dir), load(b_dir), load(timed_dir)
print("comparison: the job array's merge against the unsharded run, record by record (timings dropped)")
row = "  %-20s %-5s %-12s %-22s %-6s %-9s %-8s %-6s %-11s %s"
print(row % ("input", "shard", "status", "code", "valid", "invalid0", "flipped", "degen.", "mean_energy", "same"))
same = True
for k in sorted(set(a) | set(b)):
    ra, rb = a.get(k, {}), b.get(k, {})
    eq = ra == rb
    same &= eq
    r = ra or rb
    e = r.get("mean_energy_3d")
    print(row % (os.path.basename(k) if os.path.isabs(k) else k, timed.get(k, {}).get("shard", "-"), r.get("status"),
                 r.get("code", "-"), r.get("valid"), r.get("invalid_before", "-"), r.get("flipped", "-"),
                 r.get("degenerate", "-"), "-" if e is None else "%.6g" % e,
                 "yes" if eq else "NO: " + ", ".join(sorted(x for x in set(ra) | set(rb) if ra.get(x) != rb.get(x)))))
files = ("results.jsonl", "results.csv", "summary.md")
bytes_same = all(open(os.path.join(a_dir, f), "rb").read() == open(os.path.join(b_dir, f), "rb").read() for f in files)
print("  %d inputs, %d valid; records %s; --drop-timings merges (%s) %s" % (len(a), sum(bool(r.get("valid")) for r in a.values()),
      "all equal" if same else "DIFFER", ", ".join(files), "byte for byte equal" if bytes_same else "DIFFER"))
sys.exit(0 if same and bytes_same and len(a) > 0 else 1)
EOF
echo "slurm_batch: OK: the job array's merged shards equal the unsharded run"
