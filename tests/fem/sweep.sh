#!/usr/bin/env bash
# The FEM sweep in one command (docs/fem.md, "Sweeps"), on a coarse 10 x 10 x 2 plate, three
# points of a friction grading (Delta = 0, 0.2, -0.2):
#  - determinism: the sweep on 1 rank and on 2 ranks (-fem_sweep_ranks_per_run 1: two groups)
#    writes the same file value for value (h5diff without /run), and so does one group of 2 ranks;
#  - the file has the spring-block ensemble's layout (check_sweep_layout.py against an ensemble
#    of the same lists);
#  - resume: a sweep killed after its first run leaves <output>.partial and no result; re-run with
#    -resume (on another rank count) it skips the finished point and writes the same file;
#  - the table prints "reference" for the reference point;
#  - bad input: exit 2, one message naming the option, on both ranks, nothing written;
#  - a sweep that fails leaves the earlier result whole;
#  - the plotting tool pairs each FEM point with the spring-block point of the same grading and
#    refuses (exit 2) a sweep that does not match;
#  - a property-field parameter as the sweep axis (-ensemble_field): the ensemble's points,
#    field values and per-point maps, paired on the value; mismatches and bad values refused.
set -u
driver=$1; sbm_driver=$2; source_dir=$3; scratch=$4; study_driver=${5:-$(dirname "$1")/gradfric-study}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
python=/usr/bin/python3
rm -rf "$scratch"; mkdir -p "$scratch"; cd "$scratch"
fail() { echo "FAILED: $*" >&2; exit 1; }
grading=(-grading_profile linear -grading_property friction -ensemble_delta 0,0.2,-0.2)
# The penalty before the penalty study (E0/hz on nz = 2): a softer contact, a larger step, a shorter test.
sweep=("${grading[@]}" -fem_nx 10 -fem_ny 10 -fem_nz 2 -fem_kn 4e11)
source "$source_dir/tests/common/driver_runs.sh"  # fem, same

# Determinism over rank counts.
fem one 1 0 "${sweep[@]}" -output one.h5
grep -q "on 1 group(s) of 1 rank(s)" one.out || fail "one: plan line missing"
[ "$(grep -c '^\[group 0\] point' one.out)" -eq 3 ] || fail "one: not three runs"
# The table: the Delta = 0 point is the reference (printed so, not as +0.000), the others vary.
grep -Eq "^  0 +Delta=0 .* reference +[0-9.]+ +reference$" one.out || fail "one: the reference point is not printed as such: $(grep -A4 'FEM sweep results' one.out)"
grep -Eq "^  1 +Delta=0.2 .* [-+][0-9]+\.[0-9]{3} +[0-9.]+ +[-+][0-9]+\.[0-9]{3}$" one.out || fail "one: no variation for Delta = 0.2"
fem two 2 0 "${sweep[@]}" -output two.h5
grep -q "on 2 group(s) of 1 rank(s)" two.out || fail "two: not two groups"
grep -q '^\[group 1\] point' two.out || fail "two: group 1 ran nothing"
same one.h5 two.h5
fem pair 2 0 "${sweep[@]}" -output pair.h5 -fem_sweep_ranks_per_run 2
grep -q "on 1 group(s) of 2 rank(s)" pair.out || fail "pair: not one group of two"
# One run on 2 ranks gives the same bits as on 1, the whole history included (fem/ordered_assembly.hpp,
# core/exact_sum.hpp): before, the sliding phase amplified the partition's round-off to 1e-7 in mu(t).
same one.h5 pair.h5

# The ensemble's layout, against a spring-block ensemble of the same lists.
timeout 300 "$sbm_driver" "${grading[@]}" -sbm_N 10 -ensemble_realisations 2 -output sbm.h5 >sbm.out 2>&1 ||
  fail "the spring-block ensemble failed: $(tail -3 sbm.out)"
$python "$source_dir/tests/fem/check_sweep_layout.py" sbm.h5 one.h5 || fail "layout"

# Each point's discretisation bar (docs/fem_study.tsv, core/study_table.hpp): the verdict
# gradfric-study -study_judge gives the 50x50x5 member of the ladder of the point's scene: bounded
# for Delta 0 and for E -0.2 (50x50x5 is the coarsest of their ladders refined in every direction),
# NaN for Delta 0.5 (no study row of that scene); printed in the table and drawn by the plotting tool.
fem bars 1 0 -grading_profile linear -grading_property E -ensemble_delta 0,-0.2,0.5 -fem_nx 50 -fem_ny 50 \
  -fem_nz 5 -friction_observables mu_s -output bars.h5
"$study_driver" -study_judge "$source_dir/docs/fem_study.tsv" -output judge.tsv >judge.out 2>&1 ||
  fail "gradfric-study -study_judge: $(tail -3 judge.out)"
$python - bars.h5 judge.tsv <<'PY' || fail "bars: the error bars in the file are not the study's"
import csv, math, sys, h5py
f = h5py.File(sys.argv[1], "r")
study = {(r["observable"], r["scene"], r["mesh"]): r for r in csv.DictReader(open(sys.argv[2]), delimiter="\t")}
scenes = ["-", "grading_delta=-0.2,grading_profile=linear", "grading_delta=0.5,grading_profile=linear"]
for mu in ("mu_s", "mu_k"):
    stored = f[f"statistics/{mu}_discretisation_error"][:]
    convergence = f[f"statistics/{mu}_discretisation_error"].attrs["convergence"].split("\n")
    for p, scene in enumerate(scenes):
        row = study.get((mu, scene, "50x50x5"))
        want = float(row["relative_uncertainty"]) if row and int(row["members"]) >= 3 else math.nan
        assert (math.isnan(want) and math.isnan(stored[p])) or abs(stored[p] - want) <= 1e-5 * want, \
            f"{mu} point {p} ({scene}): stored {stored[p]}, -study_judge {want}"
        assert not row or int(row["members"]) < 3 or convergence[p] == row["convergence"], (mu, p, convergence)
s = f["statistics/mu_s_discretisation_error"][:]
assert math.isfinite(s[0]) and math.isfinite(s[1]) and math.isnan(s[2]), f"mu_s bars: {s}"
assert all(math.isfinite(x) for x in f["statistics/mu_s_mean"][:]), "a point without mu_s"
PY
for point in "0 +Delta=0" "1 +Delta=-0\.2"; do
  grep -Eq "^  ${point% *} ${point#* } +0\.[0-9]+ +[0-9]+\.[0-9]+ " bars.out || fail "bars: the table lacks the bar ($point): $(cat bars.out)"
done
grep -Eq "^  2 +Delta=0\.5 +0\.[0-9]+ +n/m" bars.out || fail "bars: the table does not say n/m (Delta 0.5): $(cat bars.out)"
timeout 300 "$sbm_driver" -grading_profile linear -grading_property E -ensemble_delta 0,-0.2,0.5 -sbm_N 10 \
  -ensemble_realisations 2 -output sbm_bars.h5 >sbm_bars.out 2>&1 || fail "sbm_bars: $(tail -3 sbm_bars.out)"
$python "$source_dir/scripts/gradfric_plot.py" sbm_bars.h5 --fem bars.h5 --out bars_plots >bars_plot.out 2>&1 ||
  fail "bars plot: $(cat bars_plot.out)"
[ -s bars_plots/sbm_bars_variation.png ] || fail "bars plot: no variation figure: $(ls bars_plots)"
# Single-run history files with --fem (as scripts/reproduce_paper.sh draws the paper's figures): their
# /results hold text next to the numbers (the bars' basis); each run's bar is drawn.
for d in 0 -0.2; do
  fem "hist$d" 1 0 -grading_profile linear -grading_property E -grading_delta "$d" -fem_nx 50 -fem_ny 50 \
    -fem_nz 5 -friction_observables mu_s -output "hist$d.h5"
done
$python "$source_dir/scripts/gradfric_plot.py" sbm_bars.h5 --fem hist0.h5 hist-0.2.h5 --out hist_plots >hist_plot.out 2>&1 ||
  fail "history plot: $(cat hist_plot.out)"
[ -s hist_plots/sbm_bars_variation.png ] || fail "history plot: no variation figure: $(ls hist_plots)"

# Resume after a kill: the same file.
fem killed 1 86 "${sweep[@]}" -output resumed.h5 -fem_sweep_abort_after 1
[ -f resumed.h5.partial ] && [ ! -e resumed.h5 ] || fail "killed: expected only resumed.h5.partial"
fem again 2 2 "${sweep[@]}" -output resumed.h5
grep -q "invalid option -output = resumed.h5: .*add -resume" again.err || fail "again: $(cat again.err)"
fem resume 2 0 "${sweep[@]}" -output resumed.h5 -resume
grep -q "2 to run" resume.out || fail "resume: the finished point was not skipped: $(grep 'to run' resume.out)"
same one.h5 resumed.h5
fem resume_other 2 2 "${sweep[@]}" -fem_nx 12 -output resumed.h5 -resume
grep -q "invalid option -resume (continue resumed.h5): it was started with another scene.*-fem_nx: file 10, now 12" resume_other.err ||
  fail "resume_other: $(cat resume_other.err)"
fem resume_sbm 1 2 "${sweep[@]}" -output sbm.h5 -resume
grep -q "invalid option -resume (continue sbm.h5): .*format: file gradfric-sbm-ensemble, now gradfric-fem-sweep" resume_sbm.err ||
  fail "resume_sbm: $(cat resume_sbm.err)"

# Bad input: one message naming the option, exit 2, nothing written (on 2 ranks where the ranks
# matter; the option checks are the same code on every rank).
bad() {  # name, ranks, regex, options...
  local name=$1 ranks=$2 regex=$3; shift 3
  fem "$name" "$ranks" 2 "$@" -output "$name.h5"
  [ "$(grep -c '^gradfric: error:' "$name.err")" -eq 1 ] || fail "$name: not one message: $(cat "$name.err")"
  grep -Eq "$regex" "$name.err" || fail "$name: message does not match $regex: $(cat "$name.err")"
  ! ls "$name".h5* >/dev/null 2>&1 || fail "$name: a file was written"
}
bad ranks 2 "invalid option -fem_sweep_ranks_per_run = 3: allowed a divisor of the number of ranks 2" "${sweep[@]}" -fem_sweep_ranks_per_run 3
bad sigma 2 "invalid option -ensemble_sigma = \(a list\): allowed no sigma sweep in the FEM" "${sweep[@]}" -ensemble_sigma 0,0.1
bad delta_range 1 "invalid option -ensemble_delta = 1: allowed values with \|Delta\| < 1" "${sweep[@]}" -ensemble_delta 0,1
bad no_profile 1 "invalid option -ensemble_delta = \(a list\): allowed only with a grading profile" -ensemble_delta 0,0.2 -fem_nx 10
bad snapshots 1 "invalid option -fem_snapshot_times = \(a list\): allowed none in a sweep" "${sweep[@]}" -fem_snapshot_times 0
bad compare 1 "invalid option -fem_compare_sbm = true: allowed false in a sweep" "${sweep[@]}" -fem_compare_sbm
bad stray 2 "invalid option -ensemble_delta = 0,0.2 -0.2: allowed one value" "${sweep[@]}" -ensemble_delta 0,0.2 -0.2
bad empty 2 "invalid option -ensemble_delta = 0,,0.2: allowed .*\(item 2 is empty\)" "${sweep[@]}" -ensemble_delta 0,,0.2
bad old_resume 2 "invalid option -fem_sweep_resume: renamed.*; use -resume$" "${sweep[@]}" -fem_sweep_resume

# A failing sweep (the blow-up monitor) leaves the earlier result whole.
echo "earlier result" >kept.h5
fem blowup 1 1 "${sweep[@]}" -output kept.h5 -output_overwrite -fem_dt 4e-7 -fem_dt_check false
grep -q "FEM run unstable.*continue with -resume" blowup.err || fail "blowup: $(tail -2 blowup.err)"
[ "$(cat kept.h5)" = "earlier result" ] || fail "a failed sweep replaced kept.h5"

# Pairing in the plotting tool.
plot=("$python" "$source_dir/scripts/gradfric_plot.py")
"${plot[@]}" sbm.h5 --fem one.h5 --out plots >plot.out 2>&1 || fail "plot: $(cat plot.out)"
grep -q "3 FEM point(s) paired" plot.out || fail "plot: no pairs: $(cat plot.out)"
for p in 0 1 2; do grep -q "FEM $p <-> SBM $p " plot.out || fail "plot: FEM $p not paired with SBM $p"; done
[ -s plots/sbm_variation.png ] || fail "plot: no variation figure"
fem other_delta 1 0 "${grading[@]}" -ensemble_delta 0,0.3 -fem_nx 10 -fem_ny 10 -fem_nz 2 -output other.h5
"${plot[@]}" sbm.h5 --fem other.h5 --out plots >unmatched.out 2>&1
[ $? -eq 2 ] || fail "plot: an unmatched sweep was not refused with exit 2"
grep -q "does not match sbm.h5: no spring-block point with the grading, angle and field value of FEM point 1 (Delta=0.3" unmatched.out ||
  fail "unmatched: $(cat unmatched.out)"
fem thick 1 0 "${sweep[@]}" -plate_H 1e-4 -output thick.h5
"${plot[@]}" sbm.h5 --fem thick.h5 --out plots >thick_plot.out 2>&1
[ $? -eq 2 ] || fail "plot: a sweep of another plate was not refused with exit 2"
grep -q "do not describe the same plate: -plate_H" thick_plot.out || fail "thick: $(cat thick_plot.out)"

# A property-field parameter as a sweep axis (-ensemble_field), as the ensemble reads it: the same
# points and layout (field values, per-point maps), paired by the plotting tool on the field value;
# other values or another field are refused.
stripes=(-field_mu_profile stripes -field_mu_period 1e-3 -field_mu_normalise -ensemble_field mu_delta)
fem field 2 0 "${stripes[@]}" -ensemble_field_values 0,0.3 -fem_nx 10 -fem_ny 10 -fem_nz 2 -fem_kn 4e11 -output field.h5
grep -q "2 point(s) (axes: field_mu_delta)" field.out || fail "field: plan line: $(grep 'point(s)' field.out)"
timeout 300 "$sbm_driver" "${stripes[@]}" -ensemble_field_values 0,0.3 -sbm_N 10 -ensemble_realisations 2 \
  -output sbm_field.h5 >sbm_field.out 2>&1 || fail "the spring-block field ensemble failed: $(tail -3 sbm_field.out)"
$python "$source_dir/tests/fem/check_sweep_layout.py" sbm_field.h5 field.h5 || fail "field sweep layout"
$python - field.h5 <<'PY' || fail "field: the per-point maps are not the swept stripes"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
m = f["properties/mu_s_map"][:]  # [point][row][column]; mean-preserving stripes of amplitude 0 and 0.3
base = float(f["scene"].attrs["plate_mu_s"])
assert np.allclose(m[0], base), "point 0 (delta 0) is not uniform"
assert abs(m[1].mean() / base - 1) < 1e-9 and m[1].max() / m[1].min() > 1.2, "point 1 is not the mean-kept stripes"
assert list(f["sweep/reference_point"][:]) == [0, 0], "the uniform point is not the reference"
PY
"${plot[@]}" sbm_field.h5 --fem field.h5 --out plots >field_plot.out 2>&1 || fail "field plot: $(cat field_plot.out)"
grep -q "FEM 1 <-> SBM 1  mu_delta=0.3" field_plot.out || fail "field plot: not paired on the value: $(cat field_plot.out)"
fem field_other 1 0 "${stripes[@]}" -ensemble_field_values 0,0.2 -fem_nx 10 -fem_ny 10 -fem_nz 2 -output field_other.h5
"${plot[@]}" sbm_field.h5 --fem field_other.h5 --out plots >field_other.out 2>&1
[ $? -eq 2 ] || fail "plot: a sweep of other field values was not refused with exit 2"
grep -q "no spring-block point with the grading, angle and field value of FEM point 1 (mu_delta=0.2" field_other.out ||
  fail "field_other: $(cat field_other.out)"
fem field_period 1 0 "${stripes[@]}" -ensemble_field_values 0,0.3 -field_mu_period 2e-3 -fem_nx 10 -fem_ny 10 -fem_nz 2 \
  -output field_period.h5
"${plot[@]}" sbm_field.h5 --fem field_period.h5 --out plots >field_period.out 2>&1
[ $? -eq 2 ] || fail "plot: a sweep of another field was not refused with exit 2"
grep -q "do not describe the same plate: -field_mu_period" field_period.out || fail "field_period: $(cat field_period.out)"
bad field_alone 2 "invalid option -ensemble_field_values = \(not set\): allowed both -ensemble_field and" \
  "${stripes[@]}" -fem_nx 10
bad field_value 2 "invalid option -ensemble_field_values = -1.5 \(-field_mu_delta\): allowed mu_s > 0 everywhere" "${stripes[@]}" \
  -ensemble_field_values 0,-1.5 -fem_nx 10
bad field_name 1 "invalid option -ensemble_field = mu_s_delta" -ensemble_field mu_s_delta -ensemble_field_values 0,0.1 \
  "${stripes[@]:0:5}" -fem_nx 10
echo "fem sweep OK"
