#!/usr/bin/env bash
# Checkpoints of a single FEM run and -resume (include/gradfric/fem/checkpoint.hpp): a run stopped
# by SIGTERM, SIGINT or SIGKILL and resumed gives the uninterrupted run's results bit for bit
# (every dataset of the physics groups), on 1 and 2 ranks; the stop says what was kept and how to
# continue; a finished resume removes its checkpoint; a checkpoint of another scene or rank count,
# and -resume where no checkpoint can exist, are refused with exit 2 before any work.
#  1. SIGTERM after step 6000 (while sliding), checkpoints only on signals;
#  2. SIGINT after step 300 (while pressing): the state of the pressure step;
#  3. SIGKILL after step 7000, periodic checkpoints every 0.02 s of wall time: the last one;
#  4. 2 ranks, SIGTERM: resumed on 2 ranks it equals the 1-rank run; on 1 rank it is refused;
#  5. a real SIGTERM from outside to both ranks once the first periodic checkpoint exists;
#  6. refusals;
#  7. the other terms and laws with state (kinematic contact, bulk viscosity, the peak's
#     stiffness damping, friction grading with the normal-stress memory, the weight; the slip-length
#     memory of a stateless law),
#     and a dispersed random surface (its node coefficients rebuilt from the seed on resume).
set -u
driver=$1; scratch=$2
mkdir -p "$scratch"; cd "$scratch"; rm -f ./*.h5 ./*.partial ./*.log
fail=0
scene="-fem_nx 16 -fem_ny 16 -fem_nz 2"
physics="/history /fem /realisations /statistics /properties"
mpi="mpiexec --oversubscribe"

same() {  # same <name> <file>: the physics groups equal the reference's
  for group in $physics; do
    h5diff -r ref.h5 "$2" "$group" >"$1.diff" 2>&1 || { echo "$1: $group differs from the uninterrupted run"; head -5 "$1.diff"; fail=1; }
  done
}
expect() {  # expect <name> <status> <got> <log> <regex>
  [ "$3" = "$2" ] || { echo "$1: exit status $3, expected $2"; tail -5 "$4"; fail=1; }
  grep -Eq -- "$5" "$4" || { echo "$1: no line matching '$5'"; tail -5 "$4"; fail=1; }
}

$driver $scene -checkpoint_interval 0 -output ref.h5 >ref.log 2>&1 || { echo "reference: exit status $?"; fail=1; }

# 1. SIGTERM while sliding.
$driver $scene -checkpoint_interval 0 -checkpoint_test_signal TERM@6000 -output term.h5 >term1.log 2>&1
expect term 143 $? term1.log "interrupted \(SIGTERM\): no checkpoint yet; writing one of this step to term.checkpoint.h5"
grep -q "stopped by SIGTERM at step 6000 .*its checkpoint is in term.checkpoint.h5; continue with the same command and -resume" term1.log ||
  { echo "term: no stop line"; fail=1; }
[ -e term.h5 ] && { echo "term: a results file was written by the stopped run"; fail=1; }
[ -e term.checkpoint.h5 ] || { echo "term: no checkpoint"; fail=1; }
$driver $scene -checkpoint_interval 0 -output term.h5 -resume >term2.log 2>&1
expect term-resume 0 $? term2.log "resumed from the checkpoint of step 6000 \(t - t0 = "
same term term.h5
[ -e term.checkpoint.h5 ] && { echo "term: the checkpoint outlived the complete results"; fail=1; }

# 2. SIGINT while pressing.
$driver $scene -checkpoint_interval 0 -checkpoint_test_signal INT@300 -output int.h5 >int1.log 2>&1
expect int 130 $? int1.log "stopped by SIGINT at step 300"
$driver $scene -checkpoint_interval 0 -output int.h5 -resume >int2.log 2>&1
expect int-resume 0 $? int2.log "resumed from the checkpoint of step 300 \(t = .* while pressing\)"
same int int.h5

# 3. SIGKILL: the last periodic checkpoint.
$driver $scene -checkpoint_interval 0.02 -checkpoint_test_signal KILL@7000 -output kill.h5 >kill1.log 2>&1
status=$?
[ "$status" = 137 ] || { echo "kill: exit status $status, expected 137"; fail=1; }
$driver $scene -checkpoint_interval 0.02 -output kill.h5 -resume >kill2.log 2>&1
expect kill-resume 0 $? kill2.log "resumed from the checkpoint of step [0-9]+ "
same kill kill.h5

# 4. Two ranks: the same bits as one; the checkpoint refused on another number of ranks.
$mpi -n 2 $driver $scene -checkpoint_interval 0 -checkpoint_test_signal TERM@6000 -output two.h5 >two1.log 2>&1
status=$?
[ "$status" = 0 ] && { echo "two: exit status 0 after SIGTERM"; fail=1; }
grep -q "stopped by SIGTERM at step 6000" two1.log || { echo "two: no stop line"; tail -5 two1.log; fail=1; }
$driver $scene -checkpoint_interval 0 -output two.h5 -resume >two-one.log 2>&1
expect two-on-one 2 $? two-one.log "invalid option -resume = two.checkpoint.h5: allowed a checkpoint written on this number of ranks \(1\); it was written on 2"
$mpi -n 2 $driver $scene -checkpoint_interval 0 -output two.h5 -resume >two2.log 2>&1
expect two-resume 0 $? two2.log "resumed from the checkpoint of step 6000 "
same two two.h5

# 5. A real SIGTERM from outside, to both ranks.
$mpi -n 2 $driver $scene -checkpoint_interval 0.01 -output real.h5 >real1.log 2>&1 &
run=$!
# Once a checkpoint exists, SIGTERM to the ranks themselves, as a scheduler (scancel) sends it:
# mpiexec forwards one only once it counts the whole job as running, and a run of a second can end
# before that.
for _ in $(seq 500); do [ -e real.checkpoint.h5 ] && break; sleep 0.01; done
pkill -TERM -f "^$driver .*-output real.h5"; wait $run
status=$?
[ "$status" = 0 ] && { echo "real: exit status 0 after SIGTERM"; fail=1; }
grep -Eq "interrupted \(SIGTERM\): the checkpoint of step [0-9]+ .* is kept in real.checkpoint.h5" real1.log ||
  { echo "real: no interrupted line"; tail -5 real1.log; fail=1; }
$mpi -n 2 $driver $scene -checkpoint_interval 0.01 -output real.h5 -resume >real2.log 2>&1
expect real-resume 0 $? real2.log "resumed from the checkpoint of step [0-9]+ "
same real real.h5

# 6. Refusals, before any work.
$driver $scene -checkpoint_interval 0 -checkpoint_test_signal TERM@6000 -output other.h5 >other1.log 2>&1
$driver $scene -plate_mu_s 0.9 -checkpoint_interval 0 -output other.h5 -resume >other2.log 2>&1
expect other-scene 2 $? other2.log "invalid option -resume = other.checkpoint.h5: allowed a checkpoint of this run's scene: the checkpoint has '-plate_mu_s 1', this run '-plate_mu_s 0.9'"
$driver $scene -resume >nooutput.log 2>&1
expect no-output 2 $? nooutput.log "invalid option -resume = true: allowed a single run with checkpoints \(they are off: no -output"
$driver $scene -fem_snapshot_times 1e-4 -output snap.h5 -resume >snap.log 2>&1
expect snapshots 2 $? snap.log "invalid option -resume = true: .*-fem_snapshot_times"
$driver $scene -checkpoint_file no/such/folder/c.h5 -output nofolder.h5 >nofolder.log 2>&1
expect no-folder 2 $? nofolder.log "invalid option -checkpoint_file = no/such/folder/c.h5: allowed a file in an existing, writable folder \(the folder no/such/folder does not exist\)"
mkdir -p adir
$driver $scene -checkpoint_file adir -output dir.h5 >dir.log 2>&1
expect directory 2 $? dir.log "invalid option -checkpoint_file = adir: allowed a file in an existing, writable folder \(adir is a directory\)"
$driver $scene -checkpoint_interval -1 -output neg.h5 >neg.log 2>&1
expect negative 2 $? neg.log "invalid option -checkpoint_interval = -1"
$driver $scene -checkpoint_interval 0 -checkpoint_test_signal TERM@6000 -output again.h5 >again1.log 2>&1
$driver $scene -checkpoint_interval 0 -output again.h5 >again2.log 2>&1
expect forgotten-resume 2 $? again2.log "invalid option -resume = false: allowed -resume to continue from the checkpoint again.checkpoint.h5 of an interrupted run, or -output_overwrite to start again"
$driver $scene -checkpoint_interval 0 -output again.h5 -output_overwrite >again3.log 2>&1
expect start-again 0 $? again3.log "Checkpoints: on SIGINT/SIGTERM only"
same again again.h5
[ -e again.checkpoint.h5 ] && { echo "again: the replaced checkpoint outlived the complete results"; fail=1; }
$driver $scene -output fresh.h5 -resume >fresh.log 2>&1
expect fresh 0 $? fresh.log "-resume: no checkpoint fresh.checkpoint.h5 yet: the run starts from the beginning"
same fresh fresh.h5

# 7. Every other term and law that carries state from step to step.
for variant in "-fem_contact kinematic -fem_bulk_viscosity -fem_peak_stiffness_damping 1e-9" \
               "-grading_profile linear -grading_property friction -grading_delta -0.3 -friction_memory_length 4 -fem_gravity 9.81" \
               "-friction_law coulomb -fem_slip_length 1e-7 -fem_pressure_step static" \
               "-surface_sigma_s 0.05 -surface_sigma_k 0.05 -surface_length 5e-4 -fem_seed 3"; do
  small="-fem_nx 12 -fem_ny 12 -fem_nz 2 $variant"
  rm -f variant*.h5
  $driver $small -checkpoint_interval 0 -output variant_ref.h5 >variant_ref.log 2>&1 || { echo "variant ($variant): reference exit $?"; fail=1; }
  $driver $small -checkpoint_interval 0 -checkpoint_test_signal TERM@3000 -output variant.h5 >variant1.log 2>&1
  expect "variant ($variant)" 143 $? variant1.log "stopped by SIGTERM at step 3000"
  $driver $small -checkpoint_interval 0 -output variant.h5 -resume >variant2.log 2>&1
  expect "variant ($variant) resume" 0 $? variant2.log "resumed from the checkpoint of step 3000 "
  for group in $physics; do
    h5diff -r variant_ref.h5 variant.h5 "$group" >variant.diff 2>&1 || { echo "variant ($variant): $group differs"; fail=1; }
  done
done

[ "$fail" = 0 ] && echo "checkpoint resume OK"
exit "$fail"
