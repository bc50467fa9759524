#!/usr/bin/env bash
# FEM ensembles (docs/fem.md, "Ensembles"): realisations of the random surface as a campaign
# dimension of gradfric-fem, on a coarse 10 x 10 x 2 plate, Delta 0 and 0.2 of friction grading:
#  - determinism: 3 realisations per point on 1 rank, on 2 groups of 1 rank and on 1 group of 2
#    ranks write the same file value for value (h5diff without /run);
#  - realisation 0 of a point is the single run of the same seed (mu_s, mu_k bit for bit), the
#    realisations differ, and every point's realisation r has the same surface (the per-run
#    coefficients of a run are not stored, so: the same realisation-to-realisation ordering);
#  - statistics: the stored mean, standard error, 95 % interval and paired relative variation
#    recomputed here from /realisations with numpy;
#  - resume: a sweep killed after its first run, re-run with -resume, writes the same file;
#  - extend: 2 realisations, extended to 3 with -ensemble_extend, equal the 3-realisation file;
#  - target: -ensemble_target runs batches until the half-width is met or the cap reached, and
#    stores what each point reached;
#  - bad input: realisations or a target without a random surface, exit 2 on 2 ranks, one
#    message, nothing written.
set -u
driver=$1; source_dir=$2; scratch=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
python=/usr/bin/python3
rm -rf "$scratch"; mkdir -p "$scratch"; cd "$scratch"
fail() { echo "FAILED: $*" >&2; exit 1; }
surface=(-surface_sigma_s 0.05 -surface_sigma_k 0.05 -surface_length 5e-4 -fem_seed 5)
plate=(-fem_nx 10 -fem_ny 10 -fem_nz 2 -fem_kn 4e11 -grading_profile linear -grading_property friction)
ensemble=("${plate[@]}" "${surface[@]}" -ensemble_delta 0,0.2)
source "$source_dir/tests/common/driver_runs.sh"  # fem, same

# Determinism over rank counts and groups.
fem one 1 0 "${ensemble[@]}" -ensemble_realisations 3 -output one.h5
grep -q "2 point(s) (axes: delta), 3 realisation(s) per point, 6 to run, on 1 group(s) of 1 rank(s)" one.out ||
  fail "one: plan line missing: $(grep 'FEM sweep:' one.out)"
grep -q "realisation r: the random surface r of seed 5 at every point" one.out || fail "one: the surface line is missing"
[ "$(grep -c '^\[group 0\] point [01] (Delta=0\(.2\)\?) realisation [012]:' one.out)" -eq 6 ] || fail "one: not six runs"
grep -Eq "^  1 +Delta=0.2 +0\.[0-9]{6}\+-0\.[0-9]{6} .* [-+][0-9.]+\+-[0-9.]+ .*\(3 runs\)" one.out ||
  fail "one: the table has no means with half-widths: $(grep -A3 'FEM sweep results' one.out)"
fem two 2 0 "${ensemble[@]}" -ensemble_realisations 3 -output two.h5
grep -q '^\[group 1\] point' two.out || fail "two: group 1 ran nothing"
same one.h5 two.h5
fem pair 2 0 "${ensemble[@]}" -ensemble_realisations 3 -fem_sweep_ranks_per_run 2 -output pair.h5
same one.h5 pair.h5

# Realisation 0 is the single run of the seed; the statistics recomputed.
fem single 1 0 "${plate[@]}" "${surface[@]}" -grading_delta 0.2 -output single.h5
"$python" - one.h5 single.h5 <<'PY' || fail "statistics or realisation 0"
import sys
import h5py, numpy as np
ens, single = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
mu = ens["realisations/mu_s"][...]
assert mu.shape == (2, 3), mu.shape
for name in ("mu_s", "mu_k"):
    a, b = ens["realisations/" + name][1, 0], single["realisations/" + name][0, 0]
    assert a == b, f"{name}: realisation 0 of Delta 0.2 {a!r} != the single run {b!r}"
assert len(set(mu[0])) == 3 and len(set(mu[1])) == 3, f"realisations not distinct: {mu}"
st = ens["statistics"]
t95 = 4.302652729911275  # Student t(0.975, 2)
for p in range(2):
    x = mu[p]
    assert np.isclose(st["mu_s_mean"][p], x.mean(), rtol=1e-14, atol=0)
    assert np.isclose(st["mu_s_stderr"][p], x.std(ddof=1) / np.sqrt(3), rtol=1e-12, atol=0)
    assert np.isclose(st["mu_s_ci95_high"][p] - st["mu_s_mean"][p], t95 * x.std(ddof=1) / np.sqrt(3), rtol=1e-6, atol=0)
# Paired variation (common surfaces): z_r = x_r / m0 - m y_r / m0^2.
x, y = mu[1], mu[0]
m, m0 = x.mean(), y.mean()
z = x / m0 - m * y / m0**2
assert np.isclose(st["mu_s_relative"][1], m / m0 - 1, rtol=1e-12, atol=1e-15)
assert np.isclose(st["mu_s_relative_ci95"][1], t95 * z.std(ddof=1) / np.sqrt(3), rtol=1e-6, atol=0), \
    (st["mu_s_relative_ci95"][1], t95 * z.std(ddof=1) / np.sqrt(3))
print("statistics OK")
PY

# Resume after a kill: the same file.
fem killed 2 86 "${ensemble[@]}" -ensemble_realisations 3 -fem_sweep_abort_after 1 -output resumed.h5
[ -e resumed.h5.partial ] && [ ! -e resumed.h5 ] || fail "killed: no .partial left or a result written"
fem resumed 1 0 "${ensemble[@]}" -ensemble_realisations 3 -output resumed.h5 -resume
grep -Eq "^[1-5] of 6 runs already finished" resumed.out || fail "resumed: no finished run kept: $(grep 'already' resumed.out)"
same one.h5 resumed.h5

# Extend: 2 realisations, then 3.
fem short 2 0 "${ensemble[@]}" -ensemble_realisations 2 -output extended.h5
fem extend 2 0 "${ensemble[@]}" -ensemble_realisations 3 -ensemble_extend -output extended.h5
grep -q "4 runs kept from extended.h5" extend.out || fail "extend: the 4 runs were not kept: $(grep kept extend.out)"
grep -q "2 to run" extend.out || fail "extend: not 2 runs to add"
h5diff --exclude-path /run --exclude-path /scene one.h5 extended.h5 >/dev/null ||
  fail "extended file differs: $(h5diff --exclude-path /run --exclude-path /scene one.h5 extended.h5 | head -5)"
fem extend_sigma 1 2 "${ensemble[@]}" -surface_sigma_s 0.06 -ensemble_realisations 4 -ensemble_extend -output extended.h5
grep -q "surface_sigma_s" extend_sigma.err || fail "extend with another surface: not refused by name: $(cat extend_sigma.err)"

# A precision target: batches of realisations until met or capped.
fem target 2 0 "${ensemble[@]}" -ensemble_target 0.002 -ensemble_target_min 2 -ensemble_target_max 4 -output target.h5
grep -q "^Target batch 0: 4 task(s) to run; realisations per point: 2 2" target.out || fail "target: no first batch"
"$python" - target.h5 <<'PY' || fail "target columns"
import sys
import h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
st = f["statistics"]
n = st["finished"][...]
reached, met = st["target_half_width"][...], st["target_met"][...]
for p in range(2):
    assert 2 <= n[p] <= 4, n
    assert bool(met[p]) == (reached[p] <= 0.002), (reached, met)
    assert met[p] or n[p] == 4, f"point {p}: neither met nor capped ({n[p]} runs)"
    half = st["mu_s_ci95_high"][p] - st["mu_s_mean"][p]
    assert np.isclose(half, reached[p], rtol=1e-12), (half, reached[p])
print("target OK", n, reached)
PY

# Bad input: exit 2 before any work on both ranks, one message naming the option.
bad() {  # name, the message, options...
  local name=$1 message=$2; shift 2
  fem "$name" 2 2 "$@" -output "$name.h5"
  [ "$(grep -c '^gradfric: error:' "$name.err")" -eq 1 ] && grep -q "$message" "$name.err" ||
    fail "$name: not one message naming the option: $(cat "$name.err")"
  [ ! -e "$name.h5" ] && [ ! -e "$name.h5.partial" ] || fail "$name: a file was written"
}
bad flat "invalid option -ensemble_realisations = 3: allowed 1 without a random surface" "${plate[@]}" -ensemble_realisations 3
bad flat_target "invalid option -ensemble_target = 0.01: allowed 0 without a random surface" "${plate[@]}" -ensemble_target 0.01
bad one_first "invalid option -ensemble_realisations = 1: allowed at least 2 under -ensemble_target" "${ensemble[@]}" -ensemble_realisations 1 -ensemble_target 0.01
echo "fem ensemble OK"
