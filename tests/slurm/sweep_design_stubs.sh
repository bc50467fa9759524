#!/usr/bin/env bash
# Runs slurm/fem_sweep.sbatch and slurm/design.sbatch outside Slurm with stub srun/scontrol that
# record their calls (as sbatch_stubs.sh does for sbm_ensemble.sbatch): the command each starts
# (ranks rounded to a multiple of the ranks per run, the driver's file and resume options whichever
# names it has), the sweep's requeue at the time limit, the design's exit status passed on, and a
# missing driver refused.
#   sweep_design_stubs.sh <source-dir> <work-dir>
set -uo pipefail
source=$1
work=$2
rm -rf "$work" && mkdir -p "$work/bin"
failures=0
fail() { echo "FAIL [$case]: $*" >&2; failures=$((failures + 1)); }
cp "$source/tests/slurm/srun_stub.sh" "$work/bin/srun"
export STUB_WAIT=0  # srun ends at once, unless a case sets STUB_WAIT=1
printf '#!/bin/bash\necho "scontrol $*" >> "$STUB_DIR/calls"\n' > "$work/bin/scontrol"
printf '#!/bin/sh\necho "  -output <>: HDF5 results file"\n' > "$work/bin/fem-new"
printf '#!/bin/sh\nexit 0\n' > "$work/bin/design-fake"
chmod +x "$work/bin/"*
echo "-fem_nx 4" > "$work/scene.opts"

run_case() {  # run_case <name> <script> [VAR=value...]: runs the script, its status in $status
  case=$1; local script=$2; shift 2
  export STUB_DIR=$work/$case
  mkdir -p "$STUB_DIR"
  env PATH="$work/bin:$PATH" SLURM_JOB_ID=4242 SLURM_SUBMIT_DIR="$work" SLURM_JOB_NUM_NODES=2 \
    SLURM_JOB_CPUS_PER_NODE="4(x2)" "$@" bash "$source/slurm/$script" "$work/scene.opts" "$STUB_DIR/out.h5" -x 1 \
    > "$STUB_DIR/log" 2>&1 &
  script_pid=$!
}
finish() { wait "$script_pid"; status=$?; }
expect_status() { [ "$status" -eq "$1" ] || fail "exit status $status, expected $1 (log: $(tr '\n' '|' < "$STUB_DIR/log"))"; }
expect_call() { grep -qF -- "$1" "$STUB_DIR/calls" || fail "no call '$1' in: $(tr '\n' '|' < "$STUB_DIR/calls" 2>/dev/null)"; }
expect_no_call() { ! grep -qF -- "$1" "$STUB_DIR/calls" || fail "unexpected call '$1'"; }

run_case sweep_groups fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-new" GRADFRIC_RANKS_PER_RUN=3 && finish
expect_status 0
expect_call "srun --ntasks=6 $work/bin/fem-new -options_file $work/scene.opts -output $STUB_DIR/out.h5 -resume -fem_sweep_ranks_per_run 3 -x 1"
run_case sweep_new fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-new" && finish
expect_status 0
expect_call "srun --ntasks=8 $work/bin/fem-new -options_file $work/scene.opts -output $STUB_DIR/out.h5 -resume -fem_sweep_ranks_per_run 1 -x 1"
run_case sweep_too_few fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-new" GRADFRIC_RANKS_PER_RUN=16 && finish
expect_status 2

run_case sweep_interrupted fem_sweep.sbatch GRADFRIC_FEM="$work/bin/fem-new" GRADFRIC_GRACE=1 STUB_WAIT=1
until [ -e "$STUB_DIR/started" ]; do sleep 0.1; done
kill -USR1 "$script_pid"
finish
expect_status 0
expect_call "srun terminated"
expect_call "scontrol requeue 4242"

run_case design design.sbatch GRADFRIC_DESIGN="$work/bin/design-fake" && finish
expect_status 0
expect_call "srun --ntasks=8 $work/bin/design-fake -options_file $work/scene.opts -output $STUB_DIR/out.h5 -design_monitor -x 1"
run_case design_unreachable design.sbatch GRADFRIC_DESIGN="$work/bin/design-fake" STUB_STATUS=4 SLURM_NTASKS=5 && finish
expect_status 4
expect_call "srun --ntasks=5 "
expect_no_call scontrol
run_case design_missing design.sbatch GRADFRIC_DESIGN="$work/none" && finish
expect_status 2

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "sweep and design sbatch scripts: all cases passed"
