#!/usr/bin/env bash
# The FEM blow-up monitor from the command line, on 2 ranks: a run that goes unstable stops at once
# with a message naming the quantity and the likely cause, exits non-zero and leaves no results file
# (neither the history nor the snapshots, nor their temporaries).
#  1. dt above the stable step, accepted only through the TESTING-ONLY bypass -fem_dt_check false;
#  2. PETSc's SSP Runge-Kutta (-fem_ts_type ssp, default rks2) at the default step: its stability region
#     on the imaginary axis is smaller than the central difference's, so it blows up.
set -u
driver=$1; source_dir=$2; scratch=$3
mkdir -p "$scratch"; cd "$scratch"
scene="$source_dir/input/fem_fig2_H050_coarse.opts"
fail=0
check() {  # name, expected cause regex, extra options...
  local name=$1 cause=$2; shift 2
  rm -f "$name".h5* "$name"_fields.*
  mpiexec --oversubscribe -n 2 "$driver" -options_file "$scene" -output "$name.h5" -fem_snapshot_times 0 "$@" \
    >"$name.log" 2>&1
  local rc=$?
  if [ $rc -eq 0 ]; then echo "$name: exit status 0, expected a failure"; fail=1; fi
  grep -q "FEM run unstable at t = [0-9.e+-]* s (step [0-9]*): .*\(exceeds\|not finite\)" "$name.log" \
    || { echo "$name: no monitor message"; fail=1; }
  grep -q "Likely cause: $cause" "$name.log" || { echo "$name: cause not named ($cause)"; fail=1; }
  if ls "$name".h5* "$name"_fields.* >/dev/null 2>&1; then echo "$name: files left behind:"; ls "$name"*; fail=1; fi
  grep -m1 "FEM run unstable" "$name.log" | cut -c1-400
}
check dt_above_limit "the time step dt = 3e-07 s is above the stable step" -fem_dt 3e-7 -fem_dt_check false
# (undamped after the peak, as measured: the damping of the sliding plate slows its growth enough
# for the run to end first)
check ssp_integrator "the integrator -fem_ts_type ssp is unstable" -fem_ts_type ssp -fem_peak_damping 0
# Without the bypass the same dt is refused before any work (exit 2).
mpiexec --oversubscribe -n 2 "$driver" -options_file "$scene" -fem_dt 3e-7 >refused.log 2>&1
rc=$?
[ $rc -ne 0 ] && grep -q "allowed <= [0-9.e+-]* s, the stable step" refused.log || { echo "dt above the limit not refused"; fail=1; }
[ $fail -eq 0 ] && echo "blow-up monitor OK"
exit $fail
