#!/usr/bin/env bash
# slurm/fem_sweep.sbatch and slurm/design.sbatch on a real one-node Slurm
# (scripts/slurm_local_cluster.sh), as root. All jobs are submitted at once and run one after
# the other (the scripts ask for the whole node):
#   fem_reference   the coarse FEM sweep of Figure 4 (7 runs of 20 x 20 x 2 hexahedra) uninterrupted
#   fem_requeue     the same sweep given Slurm's time-limit signal (scancel --batch --signal=USR1,
#                   what --signal=B:USR1 sends) after its first run, GRADFRIC_GRACE=1: the sweep is
#                   stopped, the job requeues itself and resumes; the file equals fem_reference's
#   fem_too_few     GRADFRIC_RANKS_PER_RUN above the allocated CPUs: refused with status 2
#   single_reference  one FEM run (slurm/fem_run.sbatch, 48 x 48 x 4) uninterrupted
#   single_requeue  the same run given the time-limit signal once it started, GRADFRIC_GRACE=1: its
#                   tasks get SIGTERM, write their checkpoint and stop, the job requeues itself and
#                   resumes from the checkpoint; the file equals single_reference's
#   design          an unreachable design target on a reduced plate: the job ends with
#                   gradfric-design's status 4 (the closest design in the file), not requeued
#   design_missing  GRADFRIC_DESIGN names no driver: status 2
#   real_slurm_fem_design.sh <source-dir> <work-dir> <cluster-dir> <gradfric-fem> <gradfric-design>
set -euo pipefail
source=$1
work=$2
cluster=$3
export GRADFRIC_FEM=$4
export GRADFRIC_DESIGN=$5
python=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work"
cd "$work"
real_slurm_work=$work
. "$source/tests/slurm/real_slurm_lib.sh"
t0=$SECONDS
real_slurm_start "$source" "$cluster"

sweep=$source/input/fem_fig4_sweep_coarse.opts
fem_script=$source/slurm/fem_sweep.sbatch
design_script=$source/slurm/design.sbatch
run_script=$source/slurm/fem_run.sbatch
printf -- '-fem_nx 48\n-fem_ny 48\n-fem_nz 4\n' > single.opts
submit() { sbatch --parsable "$@"; }
fem_reference=$(submit "$fem_script" "$sweep" fem_reference.h5)
fem_requeue=$(GRADFRIC_GRACE=1 submit "$fem_script" "$sweep" fem_requeue.h5)
fem_too_few=$(GRADFRIC_RANKS_PER_RUN=$(( $(nproc) + 2 )) submit "$fem_script" "$sweep" fem_too_few.h5)
single_reference=$(submit "$run_script" single.opts single_reference.h5)
single_requeue=$(GRADFRIC_GRACE=1 submit "$run_script" single.opts single_requeue.h5)
design=$(submit "$design_script" "$source/input/design_friction_delta.opts" design.h5 \
  -sbm_N 24 -design_target 0.99 -design_scan_points 1)
design_missing=$(GRADFRIC_DESIGN=$work/no-such-driver submit "$design_script" "$source/input/design_friction_delta.opts" none.h5)
echo "jobs: fem_reference $fem_reference, fem_requeue $fem_requeue, fem_too_few $fem_too_few, single_reference $single_reference, single_requeue $single_requeue, design $design, design_missing $design_missing"
fem_log() { echo "$work/gradfric-fem-sweep-$1.log"; }
design_log() { echo "$work/gradfric-design-$1.log"; }
run_log() { echo "$work/gradfric-fem-run-$1.log"; }

wait_log "$(fem_log "$fem_requeue")" '^\[group [0-9]+\] point' 300
scancel --batch --signal=USR1 "$fem_requeue"
wait_log "$(run_log "$single_requeue")" '^Checkpoints: every' 400
scancel --batch --signal=USR1 "$single_requeue"
for job in "$fem_reference" "$fem_requeue" "$fem_too_few" "$single_reference" "$single_requeue" "$design" "$design_missing"; do
  wait_job "$job" 400
done
echo "all jobs ended after $((SECONDS - t0)) s"

expect_job "$fem_reference" COMPLETED 0:0
grep -q "MPI start-up: srun options '--mpi=pmix' (srun --mpi=list offers pmix)" "$(fem_log "$fem_reference")" ||
  fail "fem_reference: the MPI start-up was not chosen from srun --mpi=list"
"$python" "$source/tests/slurm/check_complete.py" fem_reference.h5 7 || fail "fem_reference incomplete"

expect_job "$fem_requeue" COMPLETED 0:0
restarts=$(job_field "$fem_requeue" Restarts)
[ "${restarts:-0}" -ge 1 ] || fail "fem_requeue: the job was not requeued (Restarts=$restarts)"
requeue_log=$(fem_log "$fem_requeue")
grep -q "time limit near" "$requeue_log" || fail "fem_requeue: the signal was not taken"
grep -q "stopping the sweep (finished points are in fem_requeue.h5.partial)" "$requeue_log" || fail "fem_requeue: the sweep was not stopped"
grep -qE "requeued job $fem_requeue; it resumes from fem_requeue.h5.partial|JOB $fem_requeue ON .* DUE TO JOB REQUEUE" "$requeue_log" ||
  fail "fem_requeue: no requeue"
grep -q "job $fem_requeue (restart $restarts)" "$requeue_log" || fail "fem_requeue: restart $restarts did not start"
grep -q "^Resuming fem_requeue.h5.partial" "$requeue_log" || fail "fem_requeue: the restart did not resume"
grep -qE "^FEM sweep: 7 point\(s\) .*, [1-6] to run" "$requeue_log" || fail "fem_requeue: no finished point kept for the restart"
[ ! -e fem_requeue.h5.partial ] || fail "fem_requeue: the partial file is left"
"$python" "$source/tests/slurm/check_complete.py" fem_requeue.h5 7 || fail "fem_requeue incomplete"
"$python" "$source/tests/ensemble/compare_bytes.py" fem_reference.h5 fem_requeue.h5 || fail "fem_requeue: numbers differ from the uninterrupted sweep"
echo "fem_requeue: $restarts restart(s), complete, identical to the uninterrupted sweep"

expect_job "$single_reference" COMPLETED 0:0
expect_job "$single_requeue" COMPLETED 0:0
restarts=$(job_field "$single_requeue" Restarts)
[ "${restarts:-0}" -ge 1 ] || fail "single_requeue: the job was not requeued (Restarts=$restarts)"
single_log=$(run_log "$single_requeue")
grep -q "stopping the run: it writes its checkpoint to single_requeue.checkpoint.h5" "$single_log" || fail "single_requeue: the run was not stopped"
grep -qE "interrupted \(SIGTERM\): .*single_requeue.checkpoint.h5" "$single_log" || fail "single_requeue: the tasks did not get SIGTERM"
grep -qE "stopped by SIGTERM at step [0-9]+ .*its checkpoint is in single_requeue.checkpoint.h5" "$single_log" || fail "single_requeue: no checkpoint written at the stop"
grep -qE "resumed from the checkpoint of step [0-9]+ " "$single_log" || fail "single_requeue: the restart did not resume from the checkpoint"
[ ! -e single_requeue.checkpoint.h5 ] || fail "single_requeue: the checkpoint outlived the complete results"
"$python" "$source/tests/ensemble/compare_bytes.py" single_reference.h5 single_requeue.h5 || fail "single_requeue: numbers differ from the uninterrupted run"
echo "single_requeue: $restarts restart(s), resumed from its checkpoint, identical to the uninterrupted run"

expect_job "$fem_too_few" FAILED 2:0
grep -q "fewer ranks than GRADFRIC_RANKS_PER_RUN" "$(fem_log "$fem_too_few")" || fail "fem_too_few: no message"

expect_job "$design" FAILED 4:0
[ "$(job_field "$design" Restarts)" = 0 ] || fail "design was requeued"
grep -q "gradfric-design finished with status 4" "$(design_log "$design")" || fail "design: not the driver's status 4"
"$python" "$source/tests/design/check_design.py" status design.h5 unreachable || fail "design: the file does not say unreachable"
expect_job "$design_missing" FAILED 2:0
grep -q "gradfric-design driver not found" "$(design_log "$design_missing")" || fail "design_missing: no message"

echo "real slurm fem and design: all cases passed in $((SECONDS - t0)) s"
