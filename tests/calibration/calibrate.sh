#!/usr/bin/env bash
# gradfric-calibrate against our own FEM (docs/calibration.md), on a reduced plate:
#  - the reference: gradfric-fem's non-graded plate on 10 x 10 x 5 (mu_s only, a few seconds);
#  - l_z and sigma fitted on 2 ranks (20 x 20 blocks, 16 realisations): converged, and gradfric
#    run on the written scene file reproduces the reference's loading slope within 1 % and has the
#    FEM's peak inside its 95 % CI (check_calibration.py, from the ensemble file alone); l_z agrees
#    with G v / (p slope) of the FEM curve; the same scene file on 1 rank;
#  - l_z alone on the FEM's undispersed surface: the same l_z, sigma 0 in the scene file, the peak
#    reported, not fitted (the undispersed SBM's is the local mu_s); the default surface refused;
#  - the same curve as CSV and as HDF5 datasets gives the same l_z and sigma;
#  - bad input: exit 2, one message naming the option, nothing written, an earlier file kept;
#  - a peak no sigma reaches, or no convergence in the evaluations allowed: exit 1, nothing written.
set -u
calibrate=$1; fem=$2; sbm=$3; source_dir=$4; scratch=$5
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
python=/usr/bin/python3
rm -rf "$scratch"; mkdir -p "$scratch"; cd "$scratch"
fail() { echo "FAILED: $*" >&2; exit 1; }
run() {  # name, ranks, expected exit, command...
  local name=$1 ranks=$2 code=$3; shift 3
  timeout 300 mpiexec -n "$ranks" "$@" >"$name.out" 2>"$name.err"
  local rc=$?
  [ $rc -ne 124 ] || fail "$name: no exit within 300 s (a hang)"
  [ $rc -eq "$code" ] || { tail -n 5 "$name.err" "$name.out" >&2; fail "$name: exit $rc, expected $code"; }
}

run fem 1 0 "$fem" -fem_nx 10 -fem_ny 10 -fem_nz 5 -friction_observables mu_s -output fem.h5
fit=(-calibrate_fit lz_sigma -sbm_N 20 -calibrate_realisations 16)
run fit 2 0 "$calibrate" -calibrate_reference fem.h5 "${fit[@]}" -output fit.opts -calibrate_curve fit.csv
grep -q "Calibration converged" fit.out || fail "fit: not converged: $(cat fit.out | tail -12)"
[ -s fit.opts ] && [ -s fit.csv ] && ! ls ./*.tmp >/dev/null 2>&1 || fail "fit: files not written whole"
grep -q "^-sbm_lz " fit.opts && grep -q "^-surface_sigma_s " fit.opts && grep -q "^-sbm_N 20" fit.opts || fail "fit.opts: $(cat fit.opts)"
run one 1 0 "$calibrate" -calibrate_reference fem.h5 "${fit[@]}" -output one.opts
diff <(grep -v "^# gradfric -options_file" fit.opts) <(grep -v "^# gradfric -options_file" one.opts) >/dev/null ||
  fail "1 and 2 ranks give different scene files: $(diff fit.opts one.opts)"

# The scene file, run by gradfric, reproduces the reference.
run verify 2 0 "$sbm" -options_file fit.opts -output verify.h5
$python "$source_dir/tests/calibration/check_calibration.py" fem.h5 verify.h5 fit.opts || fail "the calibrated scene"

# l_z alone (the default) on the surface the FEM ran: sigma 0, not fitted.
run layer 2 0 "$calibrate" -calibrate_reference fem.h5 -sbm_N 20 -calibrate_realisations 2 -surface_sigma_s 0 \
  -surface_sigma_k 0 -output layer.opts
grep -q "sigma_s = 0.000000, sigma_k = 0.000000: the surface's" layer.out && grep -q "what the two models differ by" layer.out ||
  fail "layer: $(tail -8 layer.out)"
[ "$(grep '^-sbm_lz' layer.opts)" = "$(grep '^-sbm_lz' fit.opts)" ] || fail "layer: another l_z: $(grep '^-sbm_lz' layer.opts fit.opts)"
run layer_verify 1 0 "$sbm" -options_file layer.opts -output layer.h5
grep -q "the surface is undispersed at every point" layer_verify.out || fail "layer_verify: identical realisations not reported"
$python "$source_dir/tests/calibration/check_calibration.py" fem.h5 layer.h5 layer.opts || fail "the l_z-only scene"

# The same curve as CSV and as plain HDF5 datasets.
$python - <<'PY' || fail "could not write the CSV and HDF5 references"
import h5py, numpy as np
with h5py.File("fem.h5", "r") as f:
    n = int(f["history/length"][0, 0])  # the one run of a gradfric-fem results file
    t, mu = f["history/time"][0, 0, :n], f["history/mu"][0, 0, :n]
np.savetxt("fem.csv", np.column_stack([t, mu]), delimiter=",", header="t,mu", comments="")
with h5py.File("plain.h5", "w") as g:
    g["t"], g["curves/mu"] = t, mu
np.savetxt("flat.csv", np.column_stack([t, np.full_like(t, 0.5)]), delimiter=",")
np.savetxt("high.csv", np.column_stack([t, 1.3 * mu]), delimiter=",")
open("bad.csv", "w").write("t,mu\n0,0\n1e-6,abc\n")
PY
run csv 1 0 "$calibrate" -calibrate_reference fem.csv "${fit[@]}" -output csv.opts
run plain 1 0 "$calibrate" -calibrate_reference plain.h5 -calibrate_reference_time t -calibrate_reference_mu curves/mu \
  "${fit[@]}" -output plain.opts
for f in csv plain; do
  [ "$(grep '^-sbm_lz' $f.opts)" = "$(grep '^-sbm_lz' fit.opts)" ] || fail "$f: another l_z: $(grep '^-sbm_lz' $f.opts fit.opts)"
done
grep -q "^-surface_sigma_s" csv.opts || fail "csv: no sigma"

# Bad input: exit 2, one message naming the option, nothing written (on 2 ranks where a rank could
# differ: the file checks, the plate against the reference).
bad() {  # name, ranks, regex, options...
  local name=$1 ranks=$2 regex=$3; shift 3
  run "$name" "$ranks" 2 "$calibrate" "$@" -output "$name.opts"
  [ "$(grep -c '^gradfric: error:' "$name.err")" -eq 1 ] || fail "$name: not one message: $(cat "$name.err")"
  grep -Eq "$regex" "$name.err" || fail "$name: message does not match $regex: $(cat "$name.err")"
  ! ls "$name".opts* >/dev/null 2>&1 || fail "$name: a file was written"
}
bad no_reference 1 "invalid option -calibrate_reference = \(not set\): allowed a gradfric-fem results file" "${fit[@]}"
bad missing 2 "invalid option -calibrate_reference = nothing.h5: allowed a readable HDF5 file" -calibrate_reference nothing.h5
bad bad_csv 1 "invalid option -calibrate_reference = bad.csv: allowed a CSV file with columns t, mu \(line 3" -calibrate_reference bad.csv
bad no_dataset 1 "invalid option -calibrate_reference = plain.h5: allowed a file with the dataset history/time" -calibrate_reference plain.h5
bad flat 1 "invalid option -calibrate_reference = flat.csv: allowed a curve that rises through 0.2-0.6 of its peak" -calibrate_reference flat.csv
bad lz 2 "invalid option -sbm_lz = 5e-5: allowed not set in a calibration: the calibration fits it" -calibrate_reference fem.h5 -sbm_lz 5e-5
bad window 1 "invalid option -calibrate_window = \(2 values\): allowed lo,hi with 0 < lo < hi < 1" -calibrate_reference fem.h5 -calibrate_window 0.6,0.2
bad realisations 1 "invalid option -calibrate_realisations = 1" -calibrate_reference fem.h5 -calibrate_realisations 1
# Fitting l_z alone, the surface is the FEM's (its sigma 0, not the spring blocks' default 2.8 %), and
# the options of the sigma fit have no effect.
bad surface 2 "invalid option -surface_sigma_s = 0.028: allowed the reference's value 0 \(fem.h5\): calibrate the surface the FEM ran" \
  -calibrate_reference fem.h5 -sbm_N 20
bad sigma_guess 1 "invalid option -calibrate_sigma_guess = 0.02: allowed not set in a calibration: only with -calibrate_fit lz_sigma" \
  -calibrate_reference fem.h5 -calibrate_sigma_guess 0.02
bad sigma_fitted 2 "invalid option -surface_sigma_s = 0.02: allowed not set in a calibration: -calibrate_fit lz_sigma fits it" \
  -calibrate_reference fem.h5 -calibrate_fit lz_sigma -surface_sigma_s 0.02
# A per-grading g must exist for the calibrated grading: checked before the first evaluation.
bad pressure 2 "invalid option -pressure_response_file = .*E_\+0.2.h5: allowed a g measured under the grading of every run .*the calibrated scene \(non-graded" \
  -calibrate_reference fem.h5 -pressure_response fem -pressure_response_select grading \
  -pressure_response_file "$source_dir/input/fields/pressure_response_fem100_E_+0.2.h5"
bad plate 2 "invalid option -plate_E = 20000000: allowed the reference's value 10000000 \(fem.h5\)" -calibrate_reference fem.h5 -plate_E 2e7
echo "earlier" >kept.opts
run kept 2 2 "$calibrate" -calibrate_reference fem.h5 "${fit[@]}" -output kept.opts
grep -q "invalid option -output = kept.opts: .*-output_overwrite" kept.err || fail "kept: $(cat kept.err)"
[ "$(cat kept.opts)" = "earlier" ] || fail "an existing scene file was replaced"

# A peak above what any sigma gives (1.3 x the FEM curve: above every block's mu_s): exit 1, no file.
run high 2 1 "$calibrate" -calibrate_reference high.csv "${fit[@]}" -output high.opts
grep -q "is out of reach of this spring-block scene: at sigma = 0 its peak is" high.err || fail "high: $(cat high.err)"
! ls high.opts* >/dev/null 2>&1 || fail "high: a file was written"
# Not converged within the evaluations allowed (a tolerance no 16-realisation ensemble meets in 2):
# exit 1, the best printed, no file.
run short 1 1 "$calibrate" -calibrate_reference fem.h5 "${fit[@]}" -calibrate_max_evaluations 2 \
  -calibrate_peak_tolerance 0.001 -output short.opts
grep -q "did NOT converge" short.out && grep -q "did not converge in 2 evaluations" short.err || fail "short: $(cat short.err)"
! ls short.opts* >/dev/null 2>&1 || fail "short: a file was written"
echo "calibration OK"
