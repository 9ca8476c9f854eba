#!/usr/bin/env bash
# Starts a one-node Slurm cluster on this machine (munged, slurmctld and slurmd, all in a
# temporary folder, on free ports), runs a small sun study through sun-study.sh as a job array
# of 4 shards and its merge job, and checks that the merged contract files are byte for byte
# those of one unsharded run. Stops every daemon it started, whatever happens.
#   test_sun_study_slurm.sh SHADOWKIT
# Exit status 77 (skipped) only when the Slurm or MUNGE programs are not installed
# (scripts/install-deps.sh installs them). docs/sun-study-cluster.md describes the cluster.
# SHADOWKIT_SLURM_TEST_KEEP=1 keeps the temporary folder.
set -euo pipefail
shadowkit=${1:?usage: test_sun_study_slurm.sh SHADOWKIT}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
export PATH=$PATH:/usr/sbin:/sbin
start=$SECONDS
budget=120  # seconds until the study is done; CTest's TIMEOUT leaves room for the cleanup

missing=()
for program in munged munge unmunge slurmctld slurmd slurmstepd sbatch scontrol sinfo squeue \
  scancel; do
  command -v "$program" >/dev/null || missing+=("$program")
done
if ((${#missing[@]})); then
  echo "SKIP: not installed: ${missing[*]} (Debian: apt-get install slurmctld slurmd slurm-client munge)"
  exit 77
fi
[[ -x $shadowkit ]] || {
  echo "FAIL: $shadowkit is not executable" >&2
  exit 1
}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/shadowkit-slurm.XXXXXX")
# munged wants every folder above its socket searchable by all.
chmod 755 "$tmp"
mkdir -p "$tmp"/{munge,run,log,state,spool}
chmod 700 "$tmp/munge"
conf=$tmp/slurm.conf
export SLURM_CONF=$conf
export SHADOWKIT_CACHE_DIR=  # no import cache in the home folder
pids=()  # the daemons, in start order
failed=1

log_tails() {
  local f
  if ((${#pids[@]} > 1)); then
    echo "---- the cluster's nodes and jobs"
    timeout 5 sinfo --Node --long
    timeout 5 scontrol show node
    timeout 5 scontrol show job
  fi
  for f in "$tmp"/log/* "$tmp"/study/slurm/*; do
    [[ -f $f ]] || continue
    echo "---- $f (last 60 lines)"
    tail -n 60 "$f"
  done
}

# Processes started by this cluster's daemons (slurmstepd, the jobs' programs) carry its
# SLURM_CONF in their environment: find them by it, to end them by id.
cluster_processes() {
  local environ pid
  for environ in /proc/[0-9]*/environ; do
    pid=${environ#/proc/}
    pid=${pid%/environ}
    [[ $pid != "$$" && $pid != "$BASHPID" ]] || continue
    { tr '\0' '\n' <"$environ"; } 2>/dev/null | grep -qxF "SLURM_CONF=$conf" && echo "$pid"
  done
}

# running PID: the process is there and not a zombie waiting for its parent.
running() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  [[ ${stat##*) } != Z* ]]
}

# stop PID...: TERM, up to 10 s, then KILL.
stop() {
  local pid deadline=$((SECONDS + 10)) alive
  kill -TERM "$@" 2>/dev/null || true
  while :; do
    alive=()
    for pid in "$@"; do running "$pid" && alive+=("$pid"); done
    ((${#alive[@]})) || return 0
    if ((SECONDS >= deadline)); then
      echo "still running after 10 s, killed: ${alive[*]}" >&2
      kill -KILL "${alive[@]}" 2>/dev/null || true
      return 0
    fi
    sleep 0.2
  done
}

cleanup() {
  local status=$? pid daemons=() rest=()
  set +e
  trap - EXIT INT TERM
  ((status == 0 && !failed)) || {
    echo "FAIL after $((SECONDS - start)) s; the daemons' and jobs' logs:" >&2
    log_tails >&2
    ((status)) || status=1
  }
  if ((${#pids[@]} > 1)); then
    # Let the jobs end (cancelled, or completing) while slurmd is there to see to them.
    timeout 10 scancel --quiet --user="$(id -un)" 2>/dev/null
    local deadline=$((SECONDS + 10))
    while ((SECONDS < deadline)) && [[ -n $(timeout 5 squeue --noheader 2>&1) ]]; do sleep 0.25; done
  fi
  # slurmd and slurmctld first (they start no more jobs), then what they left, then munged.
  for ((i = ${#pids[@]} - 1; i >= 1; --i)); do daemons+=("${pids[i]}"); done
  ((${#daemons[@]})) && stop "${daemons[@]}"
  mapfile -t rest < <(cluster_processes)
  if ((${#rest[@]})); then
    echo "ending what the cluster left running: $(ps -o pid=,args= -p "$(
      IFS=,
      echo "${rest[*]}"
    )" 2>/dev/null | tr '\n' ';')" >&2
    stop "${rest[@]}"
  fi
  ((${#pids[@]})) && stop "${pids[0]}"
  wait 2>/dev/null
  if [[ ${SHADOWKIT_SLURM_TEST_KEEP:-0} == 1 ]]; then
    echo "kept $tmp" >&2
  else
    rm -rf "$tmp"
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# wait_for WHAT SECONDS COMMAND...: runs COMMAND until it succeeds, at most SECONDS (and never
# past the test's budget).
wait_for() {
  local what=$1 seconds=$2
  shift 2
  local deadline=$((SECONDS + seconds))
  ((deadline <= start + budget)) || deadline=$((start + budget))
  until "$@" >/dev/null 2>&1; do
    ((SECONDS < deadline)) || fail "$what: not after $seconds s"
    sleep 0.25
  done
}

# background COMMAND...: runs COMMAND and waits for it in a way a signal interrupts, so that
# INT or TERM reach the cleanup at once (the cleanup ends COMMAND: it carries SLURM_CONF).
background() {
  "$@" &
  wait $!
}

free_ports() {
  python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks:
    s.bind(("", 0))
print(*(s.getsockname()[1] for s in socks))'
}

# MUNGE: its own key, socket, pid, log and seed files.
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$tmp/munge/munge.key"
socket=$tmp/run/munge.socket
env -u SLURM_CONF munged --foreground --force --key-file="$tmp/munge/munge.key" --socket="$socket" \
  --pid-file="$tmp/run/munged.pid" --log-file="$tmp/log/munged.log" \
  --seed-file="$tmp/munge/munged.seed" >"$tmp/log/munged.out" 2>&1 &
pids+=($!)
credential() { munge --socket="$socket" --no-input | unmunge --socket="$socket"; }
wait_for "munged answering on $socket" 15 credential

# slurm.conf: one node, this machine, named as slurmd will name itself.
node=$(hostname -s 2>/dev/null || uname -n)
node=${node%%.*}
user=$(id -un)
cpus=$(nproc)
read -r ctld_port slurmd_port < <(free_ports)
touch "$tmp/plugstack.conf"
cat >"$conf" <<EOF
ClusterName=shadowkit-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/run/slurmctld.pid
SlurmdPidFile=$tmp/run/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$tmp/plugstack.conf
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
ReturnToService=2
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=256 State=UNKNOWN
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -D -i -f "$conf" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
controller_up() { scontrol ping | grep -q 'is UP'; }
wait_for "slurmctld up on port $ctld_port" 30 controller_up
slurmd -D -N "$node" -f "$conf" >"$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
node_idle() { [[ $(sinfo --noheader --nodes="$node" --format=%t) == idle ]]; }
wait_for "node $node idle" 40 node_idle
echo "cluster up after $((SECONDS - start)) s: node $node, $cpus CPUs, ports $ctld_port/$slurmd_port"

# A small study: examples/open-meshes.json (405 polygons, open sheets and quads over a ground,
# many of them partly lit) over one day at 25-minute steps: 58 steps, in shards of 14 and 15
# steps, each with the sun up for some of them. (examples/default.json takes seconds per step
# in the sanitizer build.)
study=("$root/examples/open-meshes.json" --lat 48.85 --lon 2.35 --utc-offset 1
  --from 2024-06-21T00:00 --to 2024-06-21T23:59 --step 25)
background timeout 60 "$shadowkit" sun-study "${study[@]}" --out "$tmp/single" >/dev/null ||
  fail "the unsharded run failed (status $?)"
left=$((start + budget - SECONDS - 5))
((left > 10)) || fail "no time left for the study"
background timeout "$left" "$here/sun-study.sh" --shards 4 --out "$tmp/study" --shadowkit "$shadowkit" \
  --time 5 --merge-time 5 --wait --poll 1 "${study[@]}" ||
  fail "sun-study.sh --wait failed (status $?)"

for i in 0 1 2 3; do
  grep -q "\"shard\": $i," "$tmp/study/shard-$i/sun_study.json" ||
    fail "shard-$i/sun_study.json is not shard $i's"
done
for f in times.csv polygons.csv sunlit_fraction.f32 sun_hours.csv; do
  cmp "$tmp/single/$f" "$tmp/study/$f" || fail "$f: the merged shards differ from one run"
done
[[ $(wc -l <"$tmp/study/times.csv") == 59 ]] || fail "times.csv does not hold 58 steps"
failed=0
echo "PASS: 4 shards on Slurm merged byte for byte as one run, in $((SECONDS - start)) s"
