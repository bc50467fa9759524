#!/usr/bin/env bash
# A real one-node Slurm on localhost, for trying and testing slurm/*.sbatch (docs/cluster.md,
# "A local test cluster"): Debian's slurmctld, slurmd and munge (scripts/setup.sh --tests installs
# them), started as root in the background (no systemd needed), with everything (slurm.conf,
# cgroup.conf, munge key and socket, state, spool, logs, pid files) under one folder.
#
#   scripts/slurm_local_cluster.sh start|stop|status
#   then: export SLURM_CONF=<folder>/slurm.conf  (start prints it), sbatch/squeue/scontrol as usual
#
# start: writes the configuration for this machine (NodeName from `hostname -s`, CPUs from nproc),
#   creates a munge key if there is none, starts munged, slurmctld and slurmd, and waits (at most
#   GRADFRIC_SLURM_WAIT seconds, default 60) until sinfo shows the node idle. On a running cluster
#   it only checks it and reuses it. A restarted cluster begins with an empty queue.
# stop: cancels the cluster's jobs, stops the three daemons (bounded waits, then SIGKILL) and
#   leaves the folder (logs) in place.
# status: says what runs; exit 0 only if the node answers.
# Environment:
#   GRADFRIC_SLURM_DIR   the folder (default /tmp/gradfric-slurm)
#   GRADFRIC_SLURM_PORT  slurmctld's port; slurmd uses the next one (default 16817, away from a
#                        site Slurm's 6817/6818)
#   GRADFRIC_SLURM_WAIT  seconds start waits for the node (default 60)
# The configuration: MpiDefault=none (the sbatch scripts choose the MPI plugin themselves),
# proctrack/linuxproc and task/none (no cgroups or systemd needed: containers work), no
# accounting (sacct is not available: use scontrol show job and squeue), OverTimeLimit=0 and
# KillWait=5 (a time limit ends a job within seconds), cred_expire=10 (a requeued job may start
# again 10 s later instead of 120), requeue allowed, scheduling every 2 s.
set -euo pipefail
dir=${GRADFRIC_SLURM_DIR:-/tmp/gradfric-slurm}
port=${GRADFRIC_SLURM_PORT:-16817}
wait_limit=${GRADFRIC_SLURM_WAIT:-60}
conf=$dir/slurm.conf
export SLURM_CONF=$conf
me="slurm_local_cluster"
die() { echo "$me: error: $*" >&2; exit 1; }

[ $# -eq 1 ] || { echo "usage: scripts/slurm_local_cluster.sh start|stop|status" >&2; exit 2; }
command=$1

pid_alive() { [ -r "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }
node=$(hostname -s)

# Finds a daemon: PATH, then Debian's sbin (a non-login root shell may lack it).
find_tool() {
  local name=$1 candidate
  for candidate in "$(command -v "$name" 2>/dev/null || true)" "/usr/sbin/$name" "/usr/bin/$name" "/sbin/$name"; do
    if [ -n "$candidate" ] && [ -x "$candidate" ]; then echo "$candidate"; return 0; fi
  done
  return 1
}

node_state() { sinfo -h -n "$node" -o %T 2>/dev/null | head -1 || true; }

status() {
  local ok=0 name
  for name in munged slurmctld slurmd; do
    if pid_alive "$dir/$name.pid"; then echo "$name: running (pid $(cat "$dir/$name.pid"))"
    else echo "$name: not running"; ok=1; fi
  done
  if [ "$ok" = 0 ]; then
    echo "node $node: $(node_state)"
    echo "export SLURM_CONF=$conf"
  fi
  return "$ok"
}

write_config() {
  local cpus memory
  cpus=$(nproc)
  # A modest RealMemory: half the machine's, at most 4 GB (a node reporting less than its
  # configuration would be drained).
  memory=$(awk '/^MemTotal:/ { m = int($2 / 1024 / 2); if (m > 4096) m = 4096; print m }' /proc/meminfo)
  mkdir -p "$dir/state" "$dir/spool" "$dir/log" "$dir/munge"
  cat > "$conf" <<EOF
# Written by scripts/slurm_local_cluster.sh: one node on localhost, for tests.
ClusterName=gradfric-local
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket,cred_expire=10
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=2,bf_interval=2,sched_min_interval=100000
SchedulerTimeSlice=5
SlurmdParameters=config_overrides
MessageTimeout=10
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
OverTimeLimit=0
MinJobAge=600
MailProg=/bin/true
JobRequeue=1
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
  cat > "$dir/cgroup.conf" <<'EOF'
# Written by scripts/slurm_local_cluster.sh: no cgroup plugin is used (proctrack/linuxproc,
# task/none); this file only keeps slurmd from looking for one elsewhere.
CgroupAutomount=no
EOF
}

start_munge() {
  pid_alive "$dir/munged.pid" && return 0
  local munged
  munged=$(find_tool munged) || die "munged not found (apt-get install munge; scripts/setup.sh --tests installs it)"
  chmod 755 "$dir/munge"  # munged: the socket folder readable by all, the key 0600
  if [ ! -s "$dir/munge/munge.key" ]; then
    if command -v mungekey > /dev/null || [ -x /usr/sbin/mungekey ]; then
      "$(find_tool mungekey)" --create --keyfile="$dir/munge/munge.key"
    else
      dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
    fi
    chmod 600 "$dir/munge/munge.key"
  fi
  "$munged" --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
    --pid-file="$dir/munged.pid" --log-file="$dir/log/munged.log" --seed-file="$dir/munge/munged.seed" \
    || die "munged did not start (log: $dir/log/munged.log)"
}

start() {
  [ "$(id -u)" -eq 0 ] || die "run as root (the daemons run as root, SlurmUser=root)"
  local slurmctld slurmd
  slurmctld=$(find_tool slurmctld) || die "slurmctld not found (apt-get install slurmctld slurmd slurm-client munge)"
  slurmd=$(find_tool slurmd) || die "slurmd not found (apt-get install slurmctld slurmd slurm-client munge)"
  command -v sinfo > /dev/null || die "sinfo not found (apt-get install slurm-client)"
  if pid_alive "$dir/slurmctld.pid" && pid_alive "$dir/slurmd.pid" && pid_alive "$dir/munged.pid"; then
    echo "$me: reusing the running cluster in $dir"
  else
    mkdir -p "$dir"
    chmod 755 "$dir"
    write_config
    start_munge
    if ! pid_alive "$dir/slurmctld.pid"; then
      "$slurmctld" -c -f "$conf" || die "slurmctld did not start (log: $dir/log/slurmctld.log)"
    fi
    if ! pid_alive "$dir/slurmd.pid"; then
      "$slurmd" -f "$conf" || die "slurmd did not start (log: $dir/log/slurmd.log)"
    fi
  fi
  local waited=0 state=""
  while :; do
    state=$(node_state)
    case $state in
      idle|mixed|allocated|completing) break ;;
      down*|drain*|fail*) scontrol update NodeName="$node" State=RESUME > /dev/null 2>&1 || true ;;
    esac
    [ "$waited" -lt "$wait_limit" ] || die "node $node not idle after ${wait_limit} s (state '${state:-no answer}'; logs: $dir/log/)"
    sleep 1
    waited=$((waited + 1))
  done
  echo "$me: node $node $state, $(nproc) CPUs, partition local"
  echo "export SLURM_CONF=$conf"
}

# stop_daemon <name> <seconds>: waits for its exit, then SIGKILL.
stop_daemon() {
  local name=$1 limit=$2 pid waited=0
  [ -r "$dir/$name.pid" ] || return 0
  pid=$(cat "$dir/$name.pid")
  kill -0 "$pid" 2>/dev/null || { rm -f "$dir/$name.pid"; return 0; }
  kill -TERM "$pid" 2>/dev/null || true
  while kill -0 "$pid" 2>/dev/null && [ "$waited" -lt "$limit" ]; do sleep 0.5; waited=$((waited + 1)); done
  if kill -0 "$pid" 2>/dev/null; then
    echo "$me: $name (pid $pid) did not stop: SIGKILL" >&2
    kill -KILL "$pid" 2>/dev/null || true
  fi
  rm -f "$dir/$name.pid"
}

stop() {
  if pid_alive "$dir/slurmctld.pid"; then
    # Jobs first, so that no job step outlives slurmd.
    local jobs waited=0
    jobs=$(squeue -h -o %i 2>/dev/null || true)
    if [ -n "$jobs" ]; then
      # shellcheck disable=SC2086
      scancel $jobs 2>/dev/null || true
      while [ -n "$(squeue -h -o %i 2>/dev/null || true)" ] && [ "$waited" -lt 30 ]; do sleep 1; waited=$((waited + 1)); done
    fi
  fi
  stop_daemon slurmd 20
  stop_daemon slurmctld 20
  stop_daemon munged 10
  echo "$me: stopped (logs in $dir/log)"
}

case $command in
  start) start ;;
  stop) stop ;;
  status) status ;;
  *) echo "usage: scripts/slurm_local_cluster.sh start|stop|status" >&2; exit 2 ;;
esac
