#!/usr/bin/env bash
# Runs slurm/fem_sweep.sbatch and slurm/design.sbatch outside Slurm with stub srun/scontrol that
# record their calls (as sbatch_stubs.sh does for sbm_ensemble.sbatch). Only the cases a real
# one-node Slurm cannot reproduce stay here; a sweep that completes, one stopped by the time-limit
# signal, requeued and resumed, too few ranks for a group, a design's exit status and a missing
# driver run on a real Slurm in real_slurm_fem_design.sh. Stub cases:
#   sweep_groups: the ranks rounded down to a multiple of the ranks per run on two nodes of 4
#     CPUs (8 ranks, 3 per run: 6); the test cluster is one node with the machine's CPUs.
#   launch_no_pmix (both scripts): an srun without pmix (Debian's Slurm always has it): the job
#     refuses with one line naming GRADFRIC_SRUN and exit 2, and starts nothing.
#   sweep_design_stubs.sh <source-dir> <work-dir>
set -uo pipefail
source=$1
work=$2
rm -rf "$work" && mkdir -p "$work/bin"
failures=0
fail() { echo "FAIL [$case]: $*" >&2; failures=$((failures + 1)); }
cp "$source/tests/slurm/srun_stub.sh" "$work/bin/srun"
export STUB_WAIT=0  # srun ends at once
printf '#!/bin/bash\necho "scontrol $*" >> "$STUB_DIR/calls"\n' > "$work/bin/scontrol"
printf '#!/bin/sh\nexit 0\n' > "$work/bin/fem-fake"
printf '#!/bin/sh\nexit 0\n' > "$work/bin/design-fake"
chmod +x "$work/bin/"*
echo "-fem_nx 4" > "$work/scene.opts"

run_case() {  # run_case <name> <script> [VAR=value...]: runs the script, its status in $status
  case=$1; local script=$2; shift 2
  export STUB_DIR=$work/$case
  mkdir -p "$STUB_DIR"
  : > "$STUB_DIR/calls"
  env -u GRADFRIC_SRUN PATH="$work/bin:$PATH" SLURM_JOB_ID=4242 SLURM_SUBMIT_DIR="$work" SLURM_JOB_NUM_NODES=2 \
    SLURM_JOB_CPUS_PER_NODE="4(x2)" "$@" bash "$source/slurm/$script" "$work/scene.opts" "$STUB_DIR/out.h5" -x 1 \
    > "$STUB_DIR/log" 2>&1
  status=$?
}
expect_status() { [ "$status" -eq "$1" ] || fail "exit status $status, expected $1 (log: $(tr '\n' '|' < "$STUB_DIR/log"))"; }
expect_call() { grep -qF -- "$1" "$STUB_DIR/calls" || fail "no call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls" 2>/dev/null)"; }
expect_no_call() { ! grep -qF -- "$1" "$STUB_DIR/calls" || fail "unexpected call '$1'"; }
expect_refusal() {  # one line naming GRADFRIC_SRUN, exit 2, no run started
  expect_status 2
  [ "$(grep -c . "$STUB_DIR/log")" -eq 1 ] && grep -q "GRADFRIC_SRUN" "$STUB_DIR/log" ||
    fail "not one line naming GRADFRIC_SRUN: $(tr '\n' '|' < "$STUB_DIR/log")"
  expect_call "srun --mpi=list"; expect_no_call "--ntasks"
}

run_case sweep_groups fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-fake" GRADFRIC_RANKS_PER_RUN=3
expect_status 0
expect_call "srun --mpi=pmix --ntasks=6 $work/bin/fem-fake -options_file $work/scene.opts -output $STUB_DIR/out.h5 -resume -fem_sweep_ranks_per_run 3 -x 1"

run_case sweep_no_pmix fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-fake" STUB_MPI_PLUGINS="none pmi2"
expect_refusal
run_case design_no_pmix design.sbatch GRADFRIC_DESIGN="$work/bin/design-fake" STUB_MPI_PLUGINS="none pmi2"
expect_refusal

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "sweep and design sbatch scripts: all cases passed"
