#!/usr/bin/env bash
# The FEM run is a TSSolve: PETSc's TS options, with the prefix fem_, work as PETSc users expect.
#  1. -fem_ts_monitor prints every step, -fem_ts_view the TS (type gfverlet), -fem_ts_max_steps stops the run
#     (exit 0, the stop named), on 2 ranks, and no -fem_ts_ option is reported unused;
#  2. a full run with -fem_ts_monitor: the experiment stops itself (TS_CONVERGED_USER) and the last
#     monitored step is the run's last step;
#  3. -fem_ts_type rk runs (the view names it); an unknown -fem_ts_type is refused (exit 2);
#  4. the spelling without the prefix (-ts_type, -ts_monitor) is refused naming the new one (exit 2).
set -u
driver=$1; scratch=$2
mkdir -p "$scratch"; cd "$scratch"
fail=0
small="-fem_nx 8 -fem_ny 8 -fem_nz 2"

mpiexec --oversubscribe -n 2 "$driver" $small -fem_ts_max_steps 5 -fem_ts_monitor -fem_ts_view >limits.log 2>&1
rc=$?
[ $rc -eq 0 ] || { echo "limits: exit status $rc"; fail=1; }
[ "$(grep -c '^[0-9]* TS dt ' limits.log)" -eq 6 ] || { echo "limits: -fem_ts_monitor did not print steps 0..5"; fail=1; }
grep -q '^5 TS dt [0-9.e+-]* time ' limits.log || { echo "limits: no monitor line for step 5"; fail=1; }
grep -q '^TS Object: (fem_) 2 MPI processes' limits.log || { echo "limits: no -fem_ts_view"; fail=1; }
grep -q '^  type: gfverlet' limits.log || { echo "limits: the view does not name gfverlet"; fail=1; }
grep -q 'maximum steps=5' limits.log || { echo "limits: -fem_ts_max_steps not in the view"; fail=1; }
grep -q 'ended the run before the sliding step' limits.log || { echo "limits: the early stop is not named"; fail=1; }
if grep -q 'WARNING: option -fem_ts_' limits.log; then echo "limits: a -fem_ts_ option reported unused"; fail=1; fi

"$driver" $small -fem_ts_monitor >full.log 2>&1
rc=$?
[ $rc -eq 0 ] || { echo "full: exit status $rc"; fail=1; }
steps=$(sed -n 's/^  steps \([0-9]*\), dt.*/\1/p' full.log)
last=$(grep '^[0-9]* TS dt ' full.log | tail -1 | cut -d' ' -f1)
[ -n "$steps" ] && [ "$steps" = "$last" ] || { echo "full: last monitored step $last, run steps $steps"; fail=1; }
grep -q 'mu_s (global) *0\.[0-9]' full.log || { echo "full: no mu_s"; fail=1; }
if grep -q "TS's limits" full.log; then echo "full: stopped by the TS limits, not by the experiment"; fail=1; fi

"$driver" $small -fem_ts_type rk -fem_ts_max_steps 20 -fem_ts_view >rk.log 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q '^  type: rk' rk.log || { echo "rk: exit status $rc or type not rk"; fail=1; }

"$driver" $small -fem_ts_type nosuch >unknown.log 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q 'invalid option -fem_ts_type = nosuch' unknown.log || { echo "unknown type: exit $rc"; fail=1; }

"$driver" $small -ts_monitor >old.log 2>&1
rc=$?
[ $rc -eq 2 ] && grep -q 'invalid option -ts_monitor: the plate.s TS reads its options with the prefix fem_; use -fem_ts_monitor' old.log ||
  { echo "old spelling: exit $rc"; cat old.log; fail=1; }

[ $fail -eq 0 ] && echo "ts options OK"
exit $fail
