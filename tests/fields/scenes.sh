#!/usr/bin/env bash
# The field scenes run (reduced: 16 x 16 blocks, 1 realisation) and store their fields; the paper's
# grading said with -field_* gives the -grading_* results bit for bit (SBM on 2 ranks, FEM); the
# shipped HDF5 map of a linear profile gives the profile's results; a field-parameter sweep
# stores its values and compares with its uniform point; an E field along y (per-block springs) gives
# the same numbers on 1 and 2 ranks, and an E map runs; paths inside options files are the file's
# own (the PNG-map scene runs from another folder).
# Usage: scenes.sh <gradfric> <gradfric-fem> <source dir> <scratch folder>
set -u
sbm=$1
fem=$2
source_dir=$3
scratch=$4
mkdir -p "$scratch"
cd "$source_dir" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
small=(-sbm_N 16 -ensemble_realisations 1 -output_overwrite)

for scene in input/field_*.opts; do
  name=$(basename "$scene" .opts)
  if ! "$sbm" -options_file "$scene" "${small[@]}" -output "$scratch/$name.h5" >"$scratch/$name.log" 2>&1; then
    fail "$scene did not run: $(tail -2 "$scratch/$name.log")"; continue
  fi
  grep -q "property field of" "$scratch/$name.log" || fail "$scene: no field in the active effects"
  /usr/bin/python3 - "$scratch/$name.h5" <<'PY' || fail "$scene: fields not stored"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
maps = [n for n in ("E_map", "mu_s_map", "mu_k_map", "p_map") if n in f["properties"]]
assert len(maps) == 4, maps
assert any(np.ptp(f["properties"][n][...]) > 0 for n in maps), "every stored field is uniform"
assert np.isfinite(f["realisations/mu_s"][...]).all()
PY
  echo "ok   $scene"
done

# mu_s, mu_k and the first-slip maps of two results files: equal bit for bit (or within tol).
compare() {
  /usr/bin/python3 - "$@" <<'PY'
import sys, h5py, numpy as np
a, b, tol = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r"), float(sys.argv[3])
for name in ("realisations/mu_s", "realisations/mu_k", "maps/first_slip_time"):
    x, y = a[name][...], b[name][...]
    same = np.array_equal(x, y, equal_nan=True) if tol == 0 else np.allclose(x, y, rtol=tol, atol=0, equal_nan=True)
    if not same:
        sys.exit(f"{name} differs: {x.ravel()[:4]} vs {y.ravel()[:4]}")
print("same", a["realisations/mu_s"][...].ravel())
PY
}
paper=(-sbm_N 20 -ensemble_realisations 2 -output_overwrite)
mpiexec -n 2 "$sbm" "${paper[@]}" -grading_profile triangular -grading_property both -grading_delta -0.3 -grading_bands 7 \
  -output "$scratch/paper_grading.h5" >/dev/null 2>&1 || fail "paper grading run"
mpiexec -n 2 "$sbm" "${paper[@]}" -field_E_profile triangular -field_E_delta -0.3 -field_E_bands 7 \
  -field_mu_profile triangular -field_mu_delta -0.3 -field_mu_bands 7 -output "$scratch/paper_field.h5" >/dev/null 2>&1 ||
  fail "paper grading as fields run"
compare "$scratch/paper_grading.h5" "$scratch/paper_field.h5" 0 && echo "ok   paper grading = fields, bit for bit (SBM, 2 ranks)" ||
  fail "paper grading through fields differs"

"$sbm" "${small[@]}" -field_mu_profile map -field_mu_map input/fields/linear_ramp.h5 -output "$scratch/map.h5" >/dev/null 2>&1 ||
  fail "map run"
"$sbm" "${small[@]}" -field_mu_profile linear -field_mu_delta 0.2 -output "$scratch/linear.h5" >/dev/null 2>&1 || fail "linear run"
compare "$scratch/map.h5" "$scratch/linear.h5" 1e-9 && echo "ok   HDF5 map of a linear profile = the profile" ||
  fail "map of a linear profile differs from the profile"

fem_small=(-fem_nx 8 -fem_ny 8 -fem_nz 2 -friction_observables mu_s -output_overwrite)
"$fem" "${fem_small[@]}" -grading_profile linear -grading_property both -grading_delta 0.2 -output "$scratch/fem_grading.h5" \
  >/dev/null 2>&1 || fail "FEM grading run"
"$fem" "${fem_small[@]}" -field_E_profile linear -field_E_delta 0.2 -field_E_bands 10 -field_mu_profile linear \
  -field_mu_delta 0.2 -field_mu_bands 10 -output "$scratch/fem_field.h5" >/dev/null 2>&1 || fail "FEM field run"
/usr/bin/python3 - "$scratch/fem_grading.h5" "$scratch/fem_field.h5" <<'PY' && echo "ok   FEM paper grading = fields, bit for bit" ||
import sys, h5py, numpy as np
a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
for k in ("realisations/mu_s", "realisations/peak_time", "realisations/steps"):
    assert a[k][0, 0] == b[k][0, 0], (k, a[k][0, 0], b[k][0, 0])
assert a["fem/results"].attrs["settled_normal_force"] == b["fem/results"].attrs["settled_normal_force"]
assert np.array_equal(a["history/mu"][...], b["history/mu"][...], equal_nan=True)  # NaN after the last sample
PY
  fail "FEM grading through fields differs"

"$sbm" "${small[@]}" -field_mu_profile stripes -field_mu_period 1e-3 -field_mu_normalise -ensemble_field mu_delta \
  -ensemble_field_values 0,0.4 -output "$scratch/sweep.h5" >"$scratch/sweep.log" 2>&1 || fail "field sweep run"
/usr/bin/python3 - "$scratch/sweep.h5" <<'PY' && echo "ok   field sweep" || fail "field sweep file"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
s = f["sweep"]
assert s.attrs["axes"] in ("field_mu_delta", b"field_mu_delta"), s.attrs["axes"]
assert list(s["field_value"][...]) == [0.0, 0.4]
assert list(s["reference_point"][...]) == [0, 0]
m = f["properties/mu_s_map"][...]
assert np.ptp(m[0]) == 0 and np.ptp(m[1]) > 0.3
assert abs(m[1].mean() - 1.0) < 1e-12  # mean-preserving: the plate's mu_s
PY

# An E field along y (springs per block): the same numbers on 1 and 2 ranks; an E map runs too.
"$sbm" "${paper[@]}" -field_E_profile linear -field_E_delta 0.3 -field_E_angle 60 -output "$scratch/e60_1.h5" >/dev/null 2>&1 ||
  fail "E at 60 degrees, 1 rank"
mpiexec -n 2 "$sbm" "${paper[@]}" -field_E_profile linear -field_E_delta 0.3 -field_E_angle 60 -output "$scratch/e60_2.h5" \
  >/dev/null 2>&1 || fail "E at 60 degrees, 2 ranks"
compare "$scratch/e60_1.h5" "$scratch/e60_2.h5" 0 && echo "ok   E along y: 1 rank = 2 ranks, bit for bit" || fail "E along y differs with ranks"
"$sbm" "${small[@]}" -field_E_profile map -field_E_map input/fields/pillars.png -output "$scratch/e_map.h5" \
  >"$scratch/e_map.log" 2>&1 && grep -q "per block (E varies along y)" "$scratch/e_map.log" && echo "ok   E map (per block)" ||
  fail "E map run: $(tail -2 "$scratch/e_map.log")"

# Paths inside an options file are the file's own: the shipped PNG-map scene runs from another
# working directory (it names fields/pillars.png), and so does a scene that includes another file
# from its folder, whose map sits beside it; on the command line a path stays the working directory's.
elsewhere=$scratch/elsewhere
mkdir -p "$elsewhere/scene/maps"
cp input/fields/pillars.png "$elsewhere/scene/maps/"
printf -- '-options_file inner.opts  # beside this file\n-sbm_N 16\n' >"$elsewhere/scene/outer.opts"
printf -- '-field_mu_profile map\n-field_mu_map maps/pillars.png\n' >"$elsewhere/scene/inner.opts"
(cd "$elsewhere" && "$sbm" -options_file "$source_dir/input/field_map_png.opts" "${small[@]}" -output png.h5 >png.log 2>&1) &&
  grep -q "map $source_dir/input/fields/pillars.png" "$elsewhere/png.log" &&
  echo "ok   input/field_map_png.opts run from another folder" ||
  fail "the PNG-map scene from another folder: $(tail -2 "$elsewhere/png.log")"
compare "$scratch/field_map_png.h5" "$elsewhere/png.h5" 0 >/dev/null && echo "ok   the same results from either folder" ||
  fail "the PNG-map scene gives other results from another folder"
(cd / && "$sbm" -options_file "$elsewhere/scene/outer.opts" -ensemble_realisations 1 -output_overwrite -output "$elsewhere/nested.h5" \
  >"$elsewhere/nested.log" 2>&1) && grep -q "map $elsewhere/scene/maps/pillars.png" "$elsewhere/nested.log" &&
  echo "ok   a nested options file and its map, from their own folder" ||
  fail "nested options file from another folder: $(tail -2 "$elsewhere/nested.log")"
(cd "$elsewhere" && "$sbm" "${small[@]}" -field_mu_profile map -field_mu_map scene/maps/pillars.png -output cli.h5 >cli.log 2>&1) &&
  echo "ok   a map on the command line: the working directory's" || fail "command-line map path: $(tail -2 "$elsewhere/cli.log")"

if [ $failures -ne 0 ]; then echo "$failures check(s) failed"; exit 1; fi
echo "all field scenes correct"
