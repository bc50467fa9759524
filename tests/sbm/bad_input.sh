#!/usr/bin/env bash
# Every kind of bad spring-block input is refused before any work: exit code 2, one message that
# names the option, and no results file (not even a partial one) left behind.
# Usage: bad_input.sh <gradfric driver> <scratch folder>
set -u
driver=$1
scratch=$2
mkdir -p "$scratch"
out="$scratch/bad_input.h5"
failures=0
# expect <option named in the message> <arguments...>
expect() {
  local named=$1; shift
  rm -f "$out" "$out.partial"
  local message
  message=$("$driver" -output "$out" "$@" 2>&1 >/dev/null)
  local status=$?
  if [ $status -ne 2 ]; then
    echo "FAIL ($*): exit $status, expected 2"; failures=$((failures + 1))
  elif ! grep -q -- "$named" <<<"$message"; then
    echo "FAIL ($*): message does not name $named: $message"; failures=$((failures + 1))
  elif [ -e "$out" ] || [ -e "$out.partial" ]; then
    echo "FAIL ($*): left $out behind"; failures=$((failures + 1))
  else
    echo "ok   ($*): $message"
  fi
}
expect -grading_delta -grading_profile linear -grading_delta 1
expect -grading_delta -grading_profile linear -grading_delta -1.5
expect -ensemble_delta -grading_profile linear -ensemble_delta 0,0.5,1.0
expect -plate_E -plate_E 0
expect -plate_E -plate_E -1e6
expect -plate_L -plate_L 0
expect -sbm_lz -sbm_lz -1
expect -plate_rho -plate_rho 0
expect -plate_p -plate_p 0
expect -plate_v -plate_v -0.001
expect -sbm_dt -sbm_dt 0
expect -sbm_dt -sbm_dt 1e-3
expect -sbm_N -sbm_N 1
expect -friction_law -friction_law rate_and_state
expect "-friction_d_c = 0: allowed > 0" -friction_law state -friction_d_c 0
expect "-friction_d_c = 0.0001: allowed 0 < D_c <= H" -friction_law state -friction_d_c 1e-4
expect "-friction_d_c = 1e-08: allowed only with -friction_law state" -friction_law exponential -friction_d_c 1e-8
expect -friction_v_c -friction_law exponential -friction_v_c 0
expect -friction_v_c -friction_v_c -1e-4
expect -sbm_friction_law -sbm_friction_law exponential
expect -sbm_v_c -sbm_v_c 1e-4
expect -plate_mu_k -plate_mu_s 0.5 -plate_mu_k 0.6
expect -surface_sigma_s -surface_sigma_s -0.01
expect -surface_sigma_k -surface_sigma_k -0.2
expect "-surface_sigma_s = nan" -surface_sigma_s nan
expect "-surface_length = 0: allowed l_c >= L/8192" -surface_length 0
expect "-surface_length = -1e-05: allowed l_c >= L/8192" -surface_length -1e-5
expect "-surface_length = 1e-06: allowed l_c >= L/2048" -surface_kind gaussian -surface_length 1e-6
expect -surface_length -surface_length inf
expect "-surface_length = 1e-4: allowed not with -surface_kind blocks" -surface_kind blocks -surface_length 1e-4
expect -surface_kind -surface_kind fractal
# The dispersion moved from the lattice to the surface: refused with the new spelling.
expect "use -surface_sigma_s = 0.03" -sbm_sigma_s 0.03
expect "use -surface_sigma_k = 0.03" -sbm_sigma_k 0.03
expect -grading_profile -grading_profile parabolic
expect -grading_property -grading_property hardness
expect -ensemble_property -grading_profile linear -ensemble_property E,stiffness
expect -plate_E -plate_E ten
# Names from before the plate record: refused with the new spelling.
expect "use -plate_E = 2e7" -sbm_E 2e7
expect "use -plate_H = 1e-4" -fem_H 1e-4
expect "use -plate_theta = 90" -sbm_theta 90
# The lattice fixes Poisson's ratio at 1/3.
expect -plate_nu -plate_nu 0.3
expect -options_file -options_file "$scratch/no_such_scene.opts"
expect -output -output /no/such/folder/results.h5
expect -sbm_dealta -sbm_dealta 0.1
# An existing result is never overwritten by accident.
rm -f "$out"; echo "precious" > "$out"
message=$("$driver" -output "$out" -sbm_N 4 2>&1 >/dev/null); status=$?
if [ $status -ne 2 ] || [ "$(cat "$out")" != "precious" ]; then
  echo "FAIL (existing file): exit $status, file changed"; failures=$((failures + 1))
else
  echo "ok   (existing file kept): $message"
fi
rm -f "$out"
echo "bad input: $failures failure(s)"
exit $((failures > 0))
