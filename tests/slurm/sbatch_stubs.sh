#!/usr/bin/env bash
# Runs slurm/sbm_ensemble.sbatch outside Slurm, with stub `srun` and `scontrol` first in PATH that
# record their calls; the stub srun "runs" until the test lets it finish (or is terminated).
# Cases: a run that completes; the time-limit signal (USR1) during a run that then completes
# (exit 0, no requeue); the signal and a run that does not finish in the grace period (srun
# stopped, requeue, exit 0); the same without requeue permission (srun's status); a failing run
# (its status, no requeue); the rank count read from Slurm's variables.
#   sbatch_stubs.sh <source-dir> <work-dir>
set -uo pipefail
source=$1
work=$2
sbatch=$source/slurm/sbm_ensemble.sbatch
rm -rf "$work" && mkdir -p "$work/bin"
failures=0
fail() { echo "FAIL [$case]: $*" >&2; failures=$((failures + 1)); }

cp "$source/tests/slurm/srun_stub.sh" "$work/bin/srun"  # waits for $STUB_DIR/finish or SIGTERM
cat > "$work/bin/scontrol" <<'STUB'
#!/bin/bash
echo "scontrol $*" >> "$STUB_DIR/calls"
STUB
printf '#!/bin/sh\nexit 0\n' > "$work/bin/gradfric-fake"
chmod +x "$work/bin/"*
echo "-sbm_N 4" > "$work/scene.opts"

# start_case <name> [VAR=value...]: runs the sbatch script in the background with a fresh stub state.
start_case() {
  case=$1; shift
  export STUB_DIR=$work/$case
  mkdir -p "$STUB_DIR"
  env PATH="$work/bin:$PATH" SLURM_JOB_ID=4242 SLURM_SUBMIT_DIR="$work" SLURM_JOB_NUM_NODES=2 \
    SLURM_JOB_CPUS_PER_NODE="4(x2)" GRADFRIC="$work/bin/gradfric-fake" "$@" \
    bash "$sbatch" "$work/scene.opts" "$STUB_DIR/out.h5" -extra_option 1 > "$STUB_DIR/log" 2>&1 &
  script_pid=$!
  until [ -e "$STUB_DIR/started" ]; do
    kill -0 "$script_pid" 2>/dev/null || { fail "script ended before srun started: $(cat "$STUB_DIR/log")"; return 1; }
    sleep 0.1
  done
}
signal_case() {  # sends the time-limit signal and waits until the script has taken it
  kill -USR1 "$script_pid"
  until grep -q "time limit near" "$STUB_DIR/log"; do sleep 0.1; done
}
finish_case() {  # lets srun end (if still running), returns the script's exit status in $status
  touch "$STUB_DIR/finish"
  wait "$script_pid"; status=$?
}
expect_status() { [ "$status" -eq "$1" ] || fail "exit status $status, expected $1 (log: $(tr '\n' '|' < "$STUB_DIR/log"))"; }
expect_call() { grep -qF -- "$1" "$STUB_DIR/calls" || fail "no call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls")"; }
expect_no_call() { ! grep -qF -- "$1" "$STUB_DIR/calls" || fail "unexpected call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls")"; }

start_case completes && {
  finish_case; expect_status 0
  expect_call "srun --ntasks=8 $work/bin/gradfric-fake -options_file $work/scene.opts -output $STUB_DIR/out.h5 -resume -ensemble_monitor -extra_option 1"
  expect_no_call scontrol
}

start_case signal_then_completes GRADFRIC_GRACE=600 && {
  signal_case; finish_case; expect_status 0
  expect_no_call scontrol; expect_no_call "srun terminated"
}

start_case signal_interrupted GRADFRIC_GRACE=1 && {
  signal_case; wait "$script_pid"; status=$?; expect_status 0
  expect_call "srun terminated"; expect_call "scontrol requeue 4242"
}

start_case signal_no_requeue GRADFRIC_GRACE=1 GRADFRIC_NO_REQUEUE=1 && {
  signal_case; wait "$script_pid"; status=$?; expect_status 143
  expect_call "srun terminated"; expect_no_call scontrol
}

start_case run_fails STUB_STATUS=3 && {
  finish_case; expect_status 3; expect_no_call scontrol
}

start_case ntasks_given SLURM_NTASKS=6 SLURM_CPUS_PER_TASK=2 && {
  finish_case; expect_status 0; expect_call "srun --ntasks=6 "
}

start_case cpus_per_task SLURM_JOB_CPUS_PER_NODE="128(x2),64" SLURM_CPUS_PER_TASK=2 && {
  finish_case; expect_status 0; expect_call "srun --ntasks=160 "
}

case=missing_driver
mkdir -p "$work/$case"
env PATH="$work/bin:$PATH" SLURM_SUBMIT_DIR="$work" GRADFRIC="$work/none" \
  bash "$sbatch" "$work/scene.opts" "$work/out.h5" > "$work/$case/log" 2>&1
status=$?
[ "$status" -eq 2 ] || fail "exit status $status for a missing driver, expected 2"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "sbatch script: all cases passed"
