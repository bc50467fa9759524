# Shared by the real-Slurm tests (sourced): a one-node Slurm on localhost
# (scripts/slurm_local_cluster.sh) started for the test and stopped at its end, whatever the end;
# jobs followed with scontrol (no accounting, so no sacct).
#   real_slurm_start <source-dir> <cluster-dir>   starts the cluster, installs the EXIT trap
#   job_field <job> <Field>                      one field of `scontrol show job`
#   wait_job <job> <seconds>                     waits until the job has ended for good
#   wait_log <file> <regex> <seconds>            waits until a job's log shows the line
# Every failure ends the test with "FAIL: ..." and the tails of the job and daemon logs.

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

real_slurm_stop() {
  local status=$?
  if [ "$status" -ne 0 ] && [ -n "${real_slurm_work:-}" ]; then
    local log
    for log in "$real_slurm_work"/*.log "$GRADFRIC_SLURM_DIR"/log/*.log; do
      [ -f "$log" ] || continue
      echo "---- $log (last 30 lines)" >&2
      tail -n 30 "$log" >&2
    done
  fi
  bash "$real_slurm_source/scripts/slurm_local_cluster.sh" stop > /dev/null 2>&1 || true
  local name left=""
  for name in munged slurmctld slurmd; do
    if [ -r "$GRADFRIC_SLURM_DIR/$name.pid" ] && kill -0 "$(cat "$GRADFRIC_SLURM_DIR/$name.pid")" 2>/dev/null; then
      left="$left $name"
    fi
  done
  if [ -n "$left" ]; then
    echo "FAIL: daemons left running after stop:$left" >&2
    status=1
  fi
  exit "$status"
}

real_slurm_start() {
  real_slurm_source=$1
  export GRADFRIC_SLURM_DIR=$2
  export GRADFRIC_SLURM_PORT=${GRADFRIC_SLURM_PORT:-16837}
  export SLURM_CONF=$GRADFRIC_SLURM_DIR/slurm.conf
  # A cluster a killed earlier run left behind (same folder) is stopped, then started afresh.
  bash "$real_slurm_source/scripts/slurm_local_cluster.sh" stop > /dev/null 2>&1 || true
  rm -rf "$GRADFRIC_SLURM_DIR"
  trap real_slurm_stop EXIT
  bash "$real_slurm_source/scripts/slurm_local_cluster.sh" start || fail "the local Slurm did not start"
  unset GRADFRIC_SRUN  # the scripts choose the MPI start-up themselves
}

job_field() {
  scontrol show job -o "$1" 2>/dev/null | tr ' ' '\n' | sed -n "s/^$2=//p" | head -n 1
}

wait_job() {
  local job=$1 limit=$2 waited=0 state
  while :; do
    state=$(job_field "$job" JobState)
    case $state in
      COMPLETED|FAILED|TIMEOUT|CANCELLED|NODE_FAIL|OUT_OF_MEMORY|BOOT_FAIL|DEADLINE|PREEMPTED) return 0 ;;
    esac
    [ "$waited" -lt "$limit" ] || fail "job $job still ${state:-unknown} after $limit s"
    sleep 1
    waited=$((waited + 1))
  done
}

wait_log() {
  local file=$1 regex=$2 limit=$3 waited=0
  until [ -f "$file" ] && grep -qE -- "$regex" "$file"; do
    [ "$waited" -lt "$((limit * 2))" ] || fail "no line /$regex/ in $file after $limit s"
    sleep 0.5
    waited=$((waited + 1))
  done
}

# expect_job <job> <state> <exit code> : the job's final state and ExitCode (status:signal).
expect_job() {
  local state exit_code
  state=$(job_field "$1" JobState)
  exit_code=$(job_field "$1" ExitCode)
  [ "$state" = "$2" ] && [ "$exit_code" = "$3" ] || fail "job $1 ended $state with ExitCode $exit_code, expected $2 and $3"
}
