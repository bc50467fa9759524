#!/usr/bin/env bash
# The largest -fem_dt accepted is a step that is stable while sliding (stable_step.hpp): the
# springs-alone stable step did not bound the penalty contact's friction coupling, and 0.99 of it
# blew up while sliding with the Coulomb and Eq. 1 laws on this scene. Now a run at 0.999 of the
# largest step slides to its kinetic window with the hardest law (Eq. 1: it slides at mu_s), 0.99
# of the springs-alone step is refused naming -fem_dt, and a -fem_dt_safety above the ratio names
# -fem_dt_safety.
#   check_largest_step.sh <gradfric-fem> <input dir> <work dir>
set -euo pipefail
driver=$1; input=$2; work=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir -p "$work"; cd "$work"
scene=(-options_file "$input/fem_fig2_H050_coarse.opts" -friction_law exponential)
mpiexec --oversubscribe -n 2 "$driver" "${scene[@]}" -fem_ts_max_steps 1 > plan.log 2>&1 || { cat plan.log; fail "the plan run failed"; }
stable=$(sed -n 's/^ *stable step *= *\([0-9.e+-]*\).*/\1/p' plan.log | head -1)
largest=$(sed -n 's/^ *largest step *= *\([0-9.e+-]*\).*/\1/p' plan.log | head -1)
[ -n "$stable" ] && [ -n "$largest" ] || fail "stable and largest step not printed"
python3 -c "import sys; s, l = $stable, $largest; sys.exit(0 if 0.5 * s < l < s else 1)" \
  || fail "largest step $largest not between half the stable step $stable and it"
near=$(python3 -c "print(repr(0.999 * $largest))")
mpiexec --oversubscribe -n 2 "$driver" "${scene[@]}" -fem_dt "$near" > near.log 2>&1 \
  || { tail -5 near.log; fail "a run at 0.999 of the largest step failed"; }
grep -q "mu_k (kinetic window) *[0-9]" near.log || fail "the run at 0.999 of the largest step did not reach mu_k"
old=$(python3 -c "print(repr(0.99 * $stable))")
set +e
mpiexec --oversubscribe -n 2 "$driver" "${scene[@]}" -fem_dt "$old" > old.log 2>&1; status=$?
set -e
[ "$status" = 2 ] || fail "0.99 of the stable step: exit $status, expected 2"
grep -q "invalid option -fem_dt = .*friction's coupling" old.log || { cat old.log; fail "no -fem_dt refusal naming the coupling"; }
set +e
mpiexec --oversubscribe -n 2 "$driver" "${scene[@]}" -fem_dt_safety 0.95 > safety.log 2>&1; status=$?
set -e
[ "$status" = 2 ] || fail "-fem_dt_safety 0.95: exit $status, expected 2"
grep -q "invalid option -fem_dt_safety = 0.95" safety.log || { cat safety.log; fail "no -fem_dt_safety refusal"; }
echo "largest step OK: stable $stable s, largest $largest s (ratio $(python3 -c "print(round($largest / $stable, 4))")); 0.999 x largest slides; 0.99 x stable and dt_safety 0.95 refused"
