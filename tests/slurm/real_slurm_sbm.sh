#!/usr/bin/env bash
# slurm/sbm_ensemble.sbatch and slurm/submit_chain.sh on a real one-node Slurm
# (scripts/slurm_local_cluster.sh; Debian's slurmctld, slurmd, munge), as root. All jobs are
# submitted at once and run one after the other (the script asks for the whole node):
#   fails_option   a scene option the driver refuses: the job fails with the driver's status 2,
#                  not requeued
#   srun_empty     GRADFRIC_SRUN= (empty) is honoured: srun's default (MpiDefault=none) cannot
#                  start Debian's Open MPI, the job fails in MPI_Init ("OMPI was not built with
#                  SLURM's PMI support")
#   no_driver      GRADFRIC names no driver: the job fails with status 2
#   requeue        --time=1: Slurm's time-limit signal (--signal=B:USR1, sent at its first check,
#                  every 30 s), GRADFRIC_GRACE=2 s, the run stopped, `scontrol requeue`, the job
#                  restarted with -resume, as often as it takes, and completed
#   reference      the same scene uninterrupted, given the same signal by scancel with a long grace
#                  period: it completes in the same job (no requeue)
#   chain          slurm/submit_chain.sh 3 jobs of a smaller scene: job 1 stopped by the signal
#                  (scancel), no requeue, srun's status; job 2 starts after it, resumes and
#                  completes; job 3 after it only reports; the file equals chain_reference's
# Checks: each job's final state, exit code and restart count, the MPI start-up it chose
# (--mpi=pmix from `srun --mpi=list`), the order of the chain, the results files complete and
# byte for byte equal to the uninterrupted runs' (tests/ensemble/compare_bytes.py, /run excluded).
#   real_slurm_sbm.sh <source-dir> <work-dir> <cluster-dir> <gradfric>
set -euo pipefail
source=$1
work=$2
cluster=$3
export GRADFRIC=$4
python=/usr/bin/python3
sbatch_script=$source/slurm/sbm_ensemble.sbatch
rm -rf "$work" && mkdir -p "$work"
cd "$work"
real_slurm_work=$work
. "$source/tests/slurm/real_slurm_lib.sh"
t0=$SECONDS
real_slurm_start "$source" "$cluster"

# The default scene reduced: 2 points x 320 realisations of 60 x 60 blocks (about 50 s on 2
# idle cores, 0.15 s a task: longer than the signal's latest arrival, 30 s after the start, plus
# the grace period, so that the first run is always stopped; 160 took 25 s and once finished
# before the signal); the chain's scene 2 x 40 realisations of 40 x 40 blocks (a few seconds).
scene=(-sbm_N 60 -ensemble_realisations 320 -ensemble_history false -plot false)
chain_scene=(-sbm_N 40 -ensemble_realisations 40 -ensemble_history false -plot false)
default=$source/input/default.opts
submit() { sbatch --parsable "$@"; }

fails_option=$(submit "$sbatch_script" "$default" fails.h5 "${scene[@]}" -grading_delta 1.2)
srun_empty=$(GRADFRIC_SRUN="" submit "$sbatch_script" "$default" empty.h5 "${scene[@]}")
no_driver=$(GRADFRIC=$work/no-such-driver submit "$sbatch_script" "$default" none.h5 "${scene[@]}")
requeue=$(GRADFRIC_GRACE=2 submit --time=1 "$sbatch_script" "$default" requeue.h5 "${scene[@]}")
reference=$(GRADFRIC_GRACE=600 submit "$sbatch_script" "$default" reference.h5 "${scene[@]}")
chain_reference=$(submit "$sbatch_script" "$default" chain_reference.h5 "${chain_scene[@]}")
mapfile -t chain < <(GRADFRIC_GRACE=1 bash "$source/slurm/submit_chain.sh" 3 "$default" chain.h5 -- "${chain_scene[@]}" | sed -n 's/^job [0-9]* of 3: //p')
[ "${#chain[@]}" -eq 3 ] || fail "submit_chain.sh did not submit 3 jobs: ${chain[*]}"
echo "jobs: fails_option $fails_option, srun_empty $srun_empty, no_driver $no_driver, requeue $requeue, reference $reference, chain_reference $chain_reference, chain ${chain[*]}"
log() { echo "$work/gradfric-sbm-$1.log"; }

# The signal Slurm sends at the time limit, sent by scancel once a task has finished.
wait_log "$(log "$reference")" '^\[1/' 300
scancel --batch --signal=USR1 "$reference"
wait_log "$(log "${chain[0]}")" '^\[1/' 300
scancel --batch --signal=USR1 "${chain[0]}"

for job in "$fails_option" "$srun_empty" "$no_driver" "$reference" "$chain_reference" "${chain[@]}" "$requeue"; do
  wait_job "$job" 400
done
echo "all jobs ended after $((SECONDS - t0)) s"

# fails_option: the driver's refusal, its status, no requeue.
expect_job "$fails_option" FAILED 2:0
grep -q "gradfric: error: invalid option -grading_delta" "$(log "$fails_option")" || fail "fails_option: no refusal in its log"
[ "$(job_field "$fails_option" Restarts)" = 0 ] || fail "fails_option was requeued"
# srun_empty: GRADFRIC_SRUN honoured, and without --mpi=pmix Debian's Open MPI does not start.
[ "$(job_field "$srun_empty" JobState)" = FAILED ] || fail "srun_empty did not fail"
grep -q "MPI start-up: srun options '' (GRADFRIC_SRUN)" "$(log "$srun_empty")" || fail "srun_empty: GRADFRIC_SRUN= not honoured"
grep -q "PMI support" "$(log "$srun_empty")" || fail "srun_empty: not the MPI_Init failure without pmix"
[ ! -e empty.h5 ] || fail "srun_empty wrote a results file"
# no_driver
expect_job "$no_driver" FAILED 2:0
grep -q "gradfric driver not found: $work/no-such-driver (set GRADFRIC)" "$(log "$no_driver")" || fail "no_driver: no message"

# reference: the signal taken, the run completed within the grace period, no requeue.
expect_job "$reference" COMPLETED 0:0
[ "$(job_field "$reference" Restarts)" = 0 ] || fail "reference was requeued"
grep -q "MPI start-up: srun options '--mpi=pmix' (srun --mpi=list offers pmix)" "$(log "$reference")" ||
  fail "reference: the MPI start-up was not chosen from srun --mpi=list"
grep -q "time limit near" "$(log "$reference")" || fail "reference: the signal was not taken"
! grep -q "stopping the run" "$(log "$reference")" || fail "reference: stopped within its grace period"
"$python" "$source/tests/slurm/check_complete.py" reference.h5 640 || fail "reference incomplete"

# requeue: stopped at the time limit, requeued, resumed, complete, the reference's numbers.
expect_job "$requeue" COMPLETED 0:0
restarts=$(job_field "$requeue" Restarts)
[ "${restarts:-0}" -ge 1 ] || fail "requeue: the job was not requeued (Restarts=$restarts)"
requeue_log=$(log "$requeue")
grep -q "time limit near" "$requeue_log" || fail "requeue: no time-limit signal"
grep -q "stopping the run (finished tasks are in requeue.h5.partial)" "$requeue_log" || fail "requeue: the run was not stopped"
# (the script's own line may be cut short by the requeue it asked for; slurmstepd's is not)
grep -qE "requeued job $requeue; it resumes from requeue.h5.partial|JOB $requeue ON .* DUE TO JOB REQUEUE" "$requeue_log" ||
  fail "requeue: no requeue"
grep -q "job $requeue (restart $restarts)" "$requeue_log" || fail "requeue: restart $restarts did not start"
grep -q "^Resuming requeue.h5.partial" "$requeue_log" || fail "requeue: the restart did not resume"
grep -qE "^[1-9][0-9]* of 640 tasks already finished" "$requeue_log" || fail "requeue: no finished task kept for the restart"
! grep -q "CANCELLED AT .* DUE TO TIME LIMIT" "$requeue_log" || fail "requeue: killed by the time limit instead of requeued"
[ ! -e requeue.h5.partial ] || fail "requeue: the partial file is left"
"$python" "$source/tests/slurm/check_complete.py" requeue.h5 640 || fail "requeue incomplete"
"$python" "$source/tests/ensemble/compare_bytes.py" reference.h5 requeue.h5 || fail "requeue: numbers differ from the uninterrupted run"
echo "requeue: $restarts restart(s), complete, identical to the uninterrupted run"

# chain: job 1 stopped (no requeue, srun's status), job 2 after it resumes and completes, job 3
# after job 2 only reports; the file equals the uninterrupted run's.
expect_job "$chain_reference" COMPLETED 0:0
"$python" "$source/tests/slurm/check_complete.py" chain_reference.h5 80 || fail "chain_reference incomplete"
# srun's status: 137 (srun ends the step with SIGKILL when it gets SIGTERM) or 143
[ "$(job_field "${chain[0]}" JobState)" = FAILED ] && [[ $(job_field "${chain[0]}" ExitCode) =~ ^(137|143):0$ ]] ||
  fail "chain job 1 ended $(job_field "${chain[0]}" JobState) $(job_field "${chain[0]}" ExitCode), expected FAILED with srun's status"
grep -q "^Resuming chain.h5.partial" "$(log "${chain[1]}")" || fail "chain job 2 did not resume"
grep -q "^Resuming chain.h5$" "$(log "${chain[2]}")" || fail "chain job 3 did not find the complete file"
grep -q "stopping the run" "$(log "${chain[0]}")" || fail "chain job 1 was not stopped"
! grep -q "requeued job" "$(log "${chain[0]}")" || fail "chain job 1 requeued itself"
expect_job "${chain[1]}" COMPLETED 0:0
expect_job "${chain[2]}" COMPLETED 0:0
for k in 0 1 2; do
  [ "$(job_field "${chain[$k]}" Restarts)" = 0 ] || fail "chain job $((k + 1)) was requeued"
done
for k in 1 2; do
  previous_end=$(date -d "$(job_field "${chain[$((k - 1))]}" EndTime)" +%s)
  start=$(date -d "$(job_field "${chain[$k]}" StartTime)" +%s)
  [ "$start" -ge "$previous_end" ] || fail "chain job $((k + 1)) started before job $k ended"
done
# (a resumed run numbers its tasks on from the finished ones: [13/80], ...)
grep -qE '^\[[0-9]+/80\]' "$(log "${chain[1]}")" || fail "chain job 2 ran no task"
! grep -qE '^\[[0-9]+/80\]' "$(log "${chain[2]}")" || fail "chain job 3 ran tasks of a complete file"
grep -q "Global static friction" "$(log "${chain[2]}")" || fail "chain job 3 did not report the statistics"
"$python" "$source/tests/slurm/check_complete.py" chain.h5 80 || fail "chain incomplete"
"$python" "$source/tests/ensemble/compare_bytes.py" chain_reference.h5 chain.h5 || fail "chain: numbers differ from the uninterrupted run"

echo "real slurm sbm: all cases passed in $((SECONDS - t0)) s"
