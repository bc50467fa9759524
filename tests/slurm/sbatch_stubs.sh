#!/usr/bin/env bash
# Runs slurm/sbm_ensemble.sbatch outside Slurm, with stub `srun` and `scontrol` first in PATH that
# record their calls. Only the cases a real one-node Slurm cannot reproduce stay here; the rest
# (a run that completes, the time-limit signal with a run that completes or is stopped and
# requeued, no requeue, a failing run, the MPI start-up chosen from Debian's srun, GRADFRIC_SRUN
# honoured, a missing driver) run on a real Slurm in real_slurm_sbm.sh. Stub cases:
#   ntasks_given, cpus_per_task: the rank count from allocations of many CPUs on several nodes
#     ("128(x2),64", --cpus-per-task=2): the test cluster is one node with the machine's CPUs.
#   launch_pmix_version_only: an srun whose --mpi=list shows only a pmix_vN line (the listings of
#     Slurm versions other than the installed one).
#   launch_no_pmix: an srun without pmix (Debian's Slurm always has it): the job refuses with one
#     line naming GRADFRIC_SRUN and exit 2, and starts nothing.
#   sbatch_stubs.sh <source-dir> <work-dir>
set -uo pipefail
source=$1
work=$2
sbatch=$source/slurm/sbm_ensemble.sbatch
rm -rf "$work" && mkdir -p "$work/bin"
failures=0
fail() { echo "FAIL [$case]: $*" >&2; failures=$((failures + 1)); }

cp "$source/tests/slurm/srun_stub.sh" "$work/bin/srun"
export STUB_WAIT=0  # srun ends at once
cat > "$work/bin/scontrol" <<'STUB'
#!/bin/bash
echo "scontrol $*" >> "$STUB_DIR/calls"
STUB
printf '#!/bin/sh\nexit 0\n' > "$work/bin/gradfric-fake"
chmod +x "$work/bin/"*
echo "-sbm_N 4" > "$work/scene.opts"

# run_case <name> [VAR=value...]: runs the sbatch script with a fresh stub state, status in $status.
run_case() {
  case=$1; shift
  export STUB_DIR=$work/$case
  mkdir -p "$STUB_DIR"
  : > "$STUB_DIR/calls"
  env -u GRADFRIC_SRUN PATH="$work/bin:$PATH" SLURM_JOB_ID=4242 SLURM_SUBMIT_DIR="$work" SLURM_JOB_NUM_NODES=2 \
    SLURM_JOB_CPUS_PER_NODE="4(x2)" GRADFRIC="$work/bin/gradfric-fake" "$@" \
    bash "$sbatch" "$work/scene.opts" "$STUB_DIR/out.h5" -extra_option 1 > "$STUB_DIR/log" 2>&1
  status=$?
}
expect_status() { [ "$status" -eq "$1" ] || fail "exit status $status, expected $1 (log: $(tr '\n' '|' < "$STUB_DIR/log"))"; }
expect_call() { grep -qF -- "$1" "$STUB_DIR/calls" || fail "no call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls")"; }
expect_no_call() { ! grep -qF -- "$1" "$STUB_DIR/calls" || fail "unexpected call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls")"; }

run_case ntasks_given SLURM_NTASKS=6 SLURM_CPUS_PER_TASK=2
expect_status 0; expect_call "srun --mpi=pmix --ntasks=6 $work/bin/gradfric-fake -options_file $work/scene.opts -output $STUB_DIR/out.h5 -resume -ensemble_monitor -extra_option 1"

run_case cpus_per_task SLURM_JOB_CPUS_PER_NODE="128(x2),64" SLURM_CPUS_PER_TASK=2
expect_status 0; expect_call "srun --mpi=pmix --ntasks=160 "

run_case launch_pmix_version_only STUB_MPI_PLUGINS="none pmi2 pmix_v3"
expect_status 0; expect_call "srun --mpi=pmix --ntasks=8 "

run_case launch_no_pmix STUB_MPI_PLUGINS="none pmi2 cray_shasta"
expect_status 2
[ "$(grep -c . "$STUB_DIR/log")" -eq 1 ] && grep -q "GRADFRIC_SRUN" "$STUB_DIR/log" ||
  fail "not one line naming GRADFRIC_SRUN: $(tr '\n' '|' < "$STUB_DIR/log")"
expect_call "srun --mpi=list"; expect_no_call "--ntasks"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "sbatch script: all cases passed"
