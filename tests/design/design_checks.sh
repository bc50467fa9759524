#!/usr/bin/env bash
# End-to-end checks of gradfric-design on reduced plates (check_design.py reads the files).
#   design_checks.sh <gradfric-design> <gradfric> <source-dir> <check> [<gradfric-fem>]
# checks: known_answer, missed, unreachable, ranks, tao, refuse, fem, fem_model, variants
set -euo pipefail
design=$1
driver=$2
src=$3
check=$4
fem=${5:-}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "$PWD/design_${check}_XXXXXX")
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3
checker="$src/tests/design/check_design.py"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
run() {  # run <expected exit> <ranks> <log> <args...>
  local expected=$1 n=$2 log=$3
  shift 3
  local status=0
  if [ "$n" -eq 1 ]; then  # a singleton: no mpiexec start-up
    "$design" "$@" >"$log" 2>&1 || status=$?
  else
    mpiexec --oversubscribe -n "$n" "$design" "$@" >"$log" 2>&1 || status=$?
  fi
  [ "$status" -eq "$expected" ] || { cat "$log" >&2; fail "exit $status, not $expected, for: $*"; }
}
refused() {  # refused <ranks> <option named> <args...>: exit 2, the option named, no file
  local n=$1 option=$2
  shift 2
  run 2 "$n" "$work/bad.log" "${scene[@]}" -output "$work/bad.h5" "$@"
  grep -q "gradfric: error: .*$option" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "$option not named for: $*"; }
  [ "$(grep -c 'gradfric: error' "$work/bad.log")" -eq 1 ] || fail "not one error line for: $*"
  ! grep -q "gradfric-design parameters" "$work/bad.log" || fail "parameters printed before the refusal of: $*"
  [ ! -e "$work/bad.h5" ] && [ ! -e "$work/bad.h5.partial" ] || fail "a refused run wrote a file: $*"
}
# The paper's linear friction grading (Figure 4) on a reduced plate.
scene=(-options_file "$src/input/design_friction_delta.opts" -sbm_N 24)

case "$check" in
known_answer)
  # mu_s(Delta) measured by a small gradfric sweep (independent streams); a target inside it;
  # the design must recover the sweep's Delta within the two uncertainties.
  mpiexec --oversubscribe -n 2 "$driver" -grading_profile linear -grading_property friction -grading_bands 10 \
    -sbm_N 24 -ensemble_delta -0.2,-0.15 -ensemble_realisations 12 -ensemble_seed 11 \
    -friction_observables mu_s -ensemble_history false -ensemble_monitor false -output "$work/sweep.h5" >"$work/sweep.log" 2>&1 ||
    { cat "$work/sweep.log" >&2; fail "the sweep"; }
  target=$("$python" -c "import h5py,sys; m=h5py.File(sys.argv[1])['statistics/mu_s_mean'][()]; print(round(0.5*(m[0]+m[1]),4))" "$work/sweep.h5")
  run 0 2 "$work/d.log" "${scene[@]}" -design_target "$target" -output "$work/d.h5"
  grep -q "Design (root, found)" "$work/d.log" || fail "no design line"
  "$python" "$checker" status "$work/d.h5" found || fail "status"
  "$python" "$checker" meets "$work/d.h5" "$target" 0.002 || fail "the design does not meet the target"
  "$python" "$checker" uncertainty "$work/d.h5" || fail "the sources' intervals"
  "$python" "$checker" known "$work/d.h5" "$work/sweep.h5" "$target" || fail "known answer"
  "$python" "$src/scripts/plot_design.py" "$work/d.h5" --out "$work/plots" >/dev/null || fail "plot of a one-parameter search"
  [ -s "$work/plots/d_search.png" ] || fail "no search plot"
  ;;
missed)
  # A found search whose verification (fresh streams) misses the target: its own outcome, exit 6,
  # the design file written with that status (the tutorial's scene, seed 1: measured to miss).
  run 6 2 "$work/m.log" -options_file "$src/input/design_friction_delta.opts" -sbm_N 40 -design_seed 1 -output "$work/m.h5"
  grep -q "Design (root, not_verified)" "$work/m.log" || fail "not reported not_verified"
  grep -q "the verification's CI misses it" "$work/m.log" || fail "no verification line"
  "$python" "$checker" status "$work/m.h5" not_verified || fail "status"
  # The same search with the verification off ends found (nothing to contradict it).
  run 0 2 "$work/m0.log" -options_file "$src/input/design_friction_delta.opts" -sbm_N 40 -design_seed 1 -design_verify false \
    -output "$work/m0.h5"
  "$python" "$checker" status "$work/m0.h5" found || fail "status without verification"
  ;;
unreachable)
  # Above the non-graded plate's mu_s: no Delta in [-0.4, 0] reaches it; the closest is Delta = 0.
  run 4 2 "$work/u.log" "${scene[@]}" -design_target 0.99 -design_scan_points 1 -output "$work/u.h5"
  grep -q "unreachable" "$work/u.log" || fail "not reported unreachable"
  "$python" "$checker" status "$work/u.h5" unreachable || fail "status"
  "$python" "$checker" unreachable "$work/u.h5" 0.99 0 || fail "closest attainable value"
  # A relative variation beyond the family's reach: -60 % (Delta = -0.4 gives about -28 %).
  run 4 1 "$work/v.log" "${scene[@]}" -design_target_type variation -design_target -0.6 -design_tolerance 0.005 \
    -design_scan_points 0 -design_verify false -output "$work/v.h5"
  "$python" "$checker" unreachable "$work/v.h5" -0.6 -0.4 || fail "closest attainable variation"
  ;;
ranks)
  # The same seed gives the same design file on 1 and 2 ranks: a property-field parameter under a
  # relative-variation target (paired streams with the non-graded plate).
  for n in 1 2; do
    run 0 "$n" "$work/r$n.log" -options_file "$src/input/design_mu_field_variation.opts" -sbm_N 20 -output "$work/r$n.h5"
  done
  "$python" "$checker" status "$work/r1.h5" found || fail "status"
  "$python" "$checker" meets "$work/r1.h5" -0.12 0.004 || fail "the variation design does not meet the target"
  "$python" "$checker" same "$work/r1.h5" "$work/r2.h5" || fail "1 and 2 ranks differ"
  ;;
tao)
  # Two free parameters (E and mu amplitudes) with TAO's pounders on a reduced plate.
  run 0 2 "$work/t.log" -options_file "$src/input/design_E_mu_tao.opts" -sbm_N 20 -design_tao_type pounders -output "$work/t.h5"
  grep -q "Design (tao pounders, found)" "$work/t.log" || { cat "$work/t.log" >&2; fail "no TAO design"; }
  "$python" "$checker" status "$work/t.h5" found || fail "status"
  "$python" "$checker" meets "$work/t.h5" 0.85 0.003 || fail "the TAO design does not meet the target"
  # TAO takes the same steps on 1 rank: the same file.
  run 0 1 "$work/t1.log" -options_file "$src/input/design_E_mu_tao.opts" -sbm_N 20 -design_tao_type pounders -output "$work/t1.h5"
  "$python" "$checker" same "$work/t1.h5" "$work/t.h5" || fail "TAO: 1 and 2 ranks differ"
  "$python" "$src/scripts/plot_design.py" "$work/t.h5" --out "$work/plots" >/dev/null || fail "plot of a TAO search"
  [ -s "$work/plots/t_search.png" ] || fail "no search plot"
  ;;
fem)
  # -design_verify_fem on a tiny mesh: the design's surface in the FEM, beside the spring blocks;
  # the FEM too finds the graded plate's mu_s below its uniform plate's.
  run 0 1 "$work/f.log" "${scene[@]}" -sbm_N 12 -design_verify_fem -fem_nx 8 -fem_ny 8 -fem_nz 1 -output "$work/f.h5"
  grep -q "^  FEM " "$work/f.log" || { cat "$work/f.log" >&2; fail "no FEM line"; }
  "$fem" -fem_nx 8 -fem_ny 8 -fem_nz 1 -friction_observables mu_s -output "$work/u.h5" >"$work/u.log" 2>&1 ||
    { cat "$work/u.log" >&2; fail "the uniform FEM run"; }
  uniform=$(sed -n 's/^  mu_s (global) *\([0-9.]*\).*/\1/p' "$work/u.log")
  "$python" - "$work/f.h5" "$uniform" <<'PY' || fail "FEM verification"
import math, sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    mu, confirmed = f["fem_verification/mu_s"][0], f["fem_verification/peak_confirmed"][0]
uniform = float(sys.argv[2])
print(f"FEM mu_s: design {mu:.4f}, uniform plate {uniform:.4f}")
assert math.isfinite(mu) and confirmed == 1, (mu, confirmed)
assert mu < uniform - 0.01, "the graded design does not lower the FEM's mu_s"
PY
  "$python" "$checker" uncertainty "$work/f.h5" || fail "the model-form interval"
  # A variation target: the FEM's variation is against its own non-graded plate, the same run as
  # gradfric-fem's uniform one, bit for bit.
  run 0 1 "$work/v.log" "${scene[@]}" -sbm_N 12 -design_target_type variation -design_target -0.15 -design_verify_fem \
    -fem_nx 8 -fem_ny 8 -fem_nz 1 -output "$work/v.h5"
  grep -q "^  FEM, uniform " "$work/v.log" && grep -q "^    model form      \[" "$work/v.log" || { cat "$work/v.log" >&2; fail "no uniform FEM or model form line"; }
  "$python" "$checker" uncertainty "$work/v.h5" || fail "the model-form interval of a variation"
  "$python" - "$work/v.h5" "$work/u.h5" <<'PY' || fail "the FEM's reference plate"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f, h5py.File(sys.argv[2], "r") as u:
    reference, uniform = f["fem_verification/reference_mu_s"][0], u["realisations/mu_s"][0, 0]
    assert f["fem_verification/reference_peak_confirmed"][0] == 1
print(f"FEM non-graded: design's reference {reference!r}, gradfric-fem {uniform!r}")
assert reference == uniform, "the design's FEM reference is not gradfric-fem's uniform plate"
PY
  ;;
fem_model)
  # -design_model fem: every evaluation one gradfric-fem run (8 x 8 x 1). The root finder meets the
  # target within the tolerance; the design's mu_s is gradfric-fem's at that Delta, bit for bit;
  # 1 and 2 ranks write the same file; the spring blocks give the model-form interval.
  fem_args=(-design_model fem -fem_nx 8 -fem_ny 8 -fem_nz 1)
  fem_at_design() {  # design.h5 nx ny nz target [most fine runs]: gradfric-fem at the design's Delta
    local delta
    delta=$("$python" -c "import h5py,sys; print(repr(float(h5py.File(sys.argv[1])['design/x_grading_delta'][0])))" "$1")
    "$fem" -fem_nx "$2" -fem_ny "$3" -fem_nz "$4" -grading_profile linear -grading_property friction -grading_bands 10 \
      -grading_delta "$delta" -friction_observables mu_s -output "$1.fem.h5" >"$1.fem.log" 2>&1 || { cat "$1.fem.log" >&2; return 1; }
    "$python" "$checker" femrun "$1" "$1.fem.h5" "$5" "${6:-0}"
  }
  run 0 2 "$work/m.log" "${scene[@]}" -sbm_N 12 "${fem_args[@]}" -design_target 0.86 -output "$work/m.h5"
  grep -q "Design (root, found)" "$work/m.log" && grep -q "^  no verification ensemble: a FEM run is deterministic" "$work/m.log" ||
    { cat "$work/m.log" >&2; fail "no FEM design"; }
  "$python" "$checker" status "$work/m.h5" found || fail "status"
  "$python" "$checker" uncertainty "$work/m.h5" || fail "the FEM design's intervals"
  fem_at_design "$work/m.h5" 8 8 1 0.86 || fail "the FEM design against gradfric-fem"
  run 0 1 "$work/m1.log" "${scene[@]}" -sbm_N 12 "${fem_args[@]}" -design_target 0.86 -output "$work/m1.h5"
  "$python" "$checker" same "$work/m1.h5" "$work/m.h5" || fail "FEM design: 1 and 2 ranks differ"
  # Beyond the family (the 8 x 8 x 1 plate reaches 0.81 at Delta -0.4): unreachable, exit 4.
  run 4 1 "$work/u4.log" "${scene[@]}" -sbm_N 12 "${fem_args[@]}" -design_target 0.7 -output "$work/u4.h5"
  "$python" "$checker" unreachable "$work/u4.h5" 0.7 -0.4 || fail "FEM design: the closest value"
  # Two parameters with TAO (pounders).
  run 0 2 "$work/t.log" -options_file "$src/input/design_E_mu_tao.opts" -sbm_N 12 "${fem_args[@]}" -design_tao_type pounders \
    -output "$work/t.h5"
  grep -q "Design (tao pounders, found)" "$work/t.log" || { cat "$work/t.log" >&2; fail "no FEM TAO design"; }
  "$python" -c "import h5py,sys; v=h5py.File(sys.argv[1])['design/value'][0]; sys.exit(int(abs(v-0.85) > 0.003))" "$work/t.h5" ||
    fail "the FEM TAO design is not within the tolerance of 0.85"
  # Coarse to fine: the search on 8 x 8 x 1, then secant steps on 16 x 16 x 2; the design's
  # mu_s is gradfric-fem's on the fine mesh at that Delta, and at most -design_fine_evaluations
  # runs were made there.
  run 0 2 "$work/c.log" "${scene[@]}" -sbm_N 12 "${fem_args[@]}" -fem_nx 16 -fem_ny 16 -fem_nz 2 -design_coarse_mesh 8,8,1 \
    -design_target 0.88 -output "$work/c.h5"
  grep -q "found on the coarse mesh 8x8x1, confirmed on the -fem_\* mesh" "$work/c.log" || { cat "$work/c.log" >&2; fail "no coarse-to-fine design"; }
  fem_at_design "$work/c.h5" 16 16 2 0.88 4 || fail "the coarse-to-fine design against gradfric-fem"
  # A design whose FEM run has nodes sliding at mu > 1 before the peak (the high-friction edge
  # trailing, Delta about -0.39 on 10 x 10 x 2) says that its onset depends on the mesh; the count
  # is gradfric-fem's at that Delta.
  run 0 1 "$work/f.log" "${scene[@]}" -sbm_N 12 "${fem_args[@]}" -fem_nx 10 -fem_ny 10 -fem_nz 2 -design_target 0.78 \
    -output "$work/f.h5"
  grep -q "^  flutter: [1-9][0-9]* FEM nodes ([0-9.]* % of the area) slid at mu > 1 before the peak at the design" "$work/f.log" ||
    { cat "$work/f.log" >&2; fail "no flutter line"; }
  fem_at_design "$work/f.h5" 10 10 2 0.78 || fail "the flutter count against gradfric-fem"
  # -design_reuse: the FEM runs of an earlier design file are taken, not run again, and change
  # nothing. A design of another target (-0.06) from one of -0.08 takes the runs they share (the
  # bracket's ends, the non-graded plates on both meshes) and equals its own fresh design, bit for
  # bit; the runs taken plus those made are the fresh design's.
  reuse_args=("${scene[@]}" -sbm_N 12 "${fem_args[@]}" -fem_nx 16 -fem_ny 16 -fem_nz 2 -design_coarse_mesh 8,8,1
              -design_target_type variation)
  run 0 1 "$work/r1.log" "${reuse_args[@]}" -design_target -0.08 -output "$work/r1.h5"
  run 5 1 "$work/r2.log" "${reuse_args[@]}" -design_target -0.06 -design_reuse "$work/r1.h5" -output "$work/r2.h5"
  run 5 1 "$work/r3.log" "${reuse_args[@]}" -design_target -0.06 -output "$work/r3.h5"
  grep -q "more taken from -design_reuse" "$work/r2.log" || { cat "$work/r2.log" >&2; fail "no run reused"; }
  "$python" "$checker" reused "$work/r2.h5" "$work/r3.h5" || fail "a design with reused runs differs from its fresh run"
  # -design_reuse of a study table: rows of gradfric-fem's own runs (6 decimals, as the study
  # writes them) stand for the runs of their scene; a row of another scene (plate_E) is passed
  # over. The design takes the bracket's end -0.4, Delta 0 and the non-graded plates on both meshes
  # and follows the fresh design to the 6th decimal. A spring-block design's FEM check takes its
  # non-graded plate from the same table.
  fem_mu_s() {  # nx ny nz [options]: gradfric-fem's mu_s with 6 decimals
    local nx=$1 ny=$2 nz=$3
    shift 3
    "$fem" -fem_nx "$nx" -fem_ny "$ny" -fem_nz "$nz" -friction_observables mu_s "$@" -output "$work/row.h5" \
      -output_overwrite >"$work/row.log" 2>&1 || { cat "$work/row.log" >&2; fail "gradfric-fem for a table row"; }
    "$python" -c "import h5py,sys; print('%.6f' % h5py.File(sys.argv[1])['realisations/mu_s'][0, 0])" "$work/row.h5"
  }
  graded=(-grading_profile linear -grading_property friction -grading_delta -0.4)
  {
    printf '# a study table of the test\n'
    printf 'mu_s\t8x8x1\t%s\t0\t0\tgrading_delta=-0.4,grading_profile=linear,grading_property=friction\n' "$(fem_mu_s 8 8 1 "${graded[@]}")"
    printf 'mu_s\t8x8x1\t%s\t0\t0\t-\n' "$(fem_mu_s 8 8 1)"
    printf 'mu_s\t16x16x2\t%s\t0\t0\t-\n' "$(fem_mu_s 16 16 2)"
    printf 'mu_s\t8x8x1\t0.5\t0\t0\tgrading_delta=-0.4,grading_profile=linear,grading_property=friction,plate_E=2e7\n'
  } >"$work/table.tsv"
  run 5 1 "$work/r4.log" "${reuse_args[@]}" -design_target -0.06 -design_reuse "$work/table.tsv" -output "$work/r4.h5"
  grep -q "4 more taken from -design_reuse" "$work/r4.log" || { cat "$work/r4.log" >&2; fail "not 4 rows taken"; }
  "$python" "$checker" table_reused "$work/r4.h5" "$work/r3.h5" "$work/table.tsv" || fail "a design with table rows"
  # A variation's discretisation is looked up as the ladder of the variation at the design's Delta.
  grep -q "^    discretisation  not measured: no mu_s row of the study has this scene (grading_delta=-0.09" "$work/r4.log" ||
    { cat "$work/r4.log" >&2; fail "the variation's study bar not looked up at the design"; }
  run 0 1 "$work/v.log" "${scene[@]}" -sbm_N 12 -design_target_type variation -design_target -0.06 -design_verify_fem \
    -fem_nx 16 -fem_ny 16 -fem_nz 2 -design_reuse "$work/table.tsv" -output "$work/v.h5"
  uniform16=$(awk -F'\t' '$2 == "16x16x2" && $6 == "-" {print $3}' "$work/table.tsv")
  grep -q "^  FEM, uniform .* $uniform16   (the FEM's non-graded plate, taken from -design_reuse)" "$work/v.log" ||
    { cat "$work/v.log" >&2; fail "the FEM check's non-graded plate not taken from the table"; }
  "$python" -c "import h5py,sys; t=h5py.File(sys.argv[1])['fem_verification']; sys.exit(int(not (t['reference_reused'][0] == 1 and t['reused'][0] == 0)))" \
    "$work/v.h5" || fail "the FEM check's record of what it took"
  # A file of another scene, of the spring blocks, or not a design file: refused, naming what differs.
  refused 1 -design_reuse "${reuse_args[@]}" -design_target -0.06 -design_reuse "$work/r1.h5" -plate_E 2e7
  grep -q "was run with -plate_E = " "$work/bad.log" || { cat "$work/bad.log" >&2; fail "the differing option not named"; }
  refused 1 -design_reuse "${scene[@]}" -design_target 0.86 -design_reuse "$work/r1.h5"
  refused 1 -design_reuse "${reuse_args[@]}" -design_target -0.06 -design_reuse "$work/r1.h5.log"
  refused 1 -design_reuse "${reuse_args[@]}" -design_target -0.06 -design_reuse "$src/input/design_friction_delta.opts"
  grep -q "neither a design file (HDF5) nor a study table" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "a log taken for a table"; }
  refused 1 -design_reuse -options_file "$src/input/design_E_mu_tao.opts" -sbm_N 12 "${fem_args[@]}" -design_reuse "$work/table.tsv"
  grep -q "serve a design of grading_delta alone" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "a table for two parameters"; }
  # Refused before any work: the FEM checking itself, a dispersed surface, a verification that
  # would repeat the same run, a coarse mesh without the FEM, of two numbers, or with TAO.
  refused 1 -design_verify_fem "${fem_args[@]}" -design_target 0.86 -design_verify_fem
  refused 1 -surface_sigma_s "${fem_args[@]}" -design_target 0.86 -surface_sigma_s 0.02
  refused 1 -design_verify "${fem_args[@]}" -design_target 0.86 -design_verify false
  refused 1 -design_coarse_mesh -design_target 0.86 -design_coarse_mesh 8,8,1
  refused 1 -design_coarse_mesh "${fem_args[@]}" -design_target 0.86 -design_coarse_mesh 8,8
  refused 1 -design_fine_evaluations "${fem_args[@]}" -design_target 0.86 -design_fine_evaluations 3
  ;;
variants)
  # The spring-block variants a designer names, run at the design on the verification's streams:
  # the scene itself (an option at its default), a calibration's scene file (its -ensemble_* are
  # reported unused) and the state law. Their spread is the design's variant interval.
  printf -- '-sbm_integrator verlet\n' >"$work/scene.opts"
  printf -- '# gradfric-calibrate wrote\n-sbm_lz 5.0482e-05\n-ensemble_realisations 2\n' >"$work/calibrated.opts"
  printf -- '-friction_law state\n' >"$work/state.opts"
  run 0 2 "$work/v.log" "${scene[@]}" -design_variants "$work/scene.opts,$work/calibrated.opts,$work/state.opts" \
    -output "$work/v.h5"
  grep -q "^    variants  *\[" "$work/v.log" || { cat "$work/v.log" >&2; fail "no variants interval"; }
  grep -q "ensemble_realisations not used" "$work/v.log" || fail "the calibration's ensemble options not reported"
  grep -q "statistical + variants, added" "$work/v.log" || fail "the combination leaves out the variants"
  "$python" "$checker" variants "$work/v.h5" 0 2 || fail "the variants"
  "$python" "$checker" uncertainty "$work/v.h5" || fail "the sources' intervals with variants"
  # Refused before any work, on every rank alike: a missing file, an option that is not the
  # spring blocks', one nothing reads, a malformed line (PETSc's reader would stop rank 0 alone),
  # a bad value, the FEM as the design's model.
  printf -- '-design_target 0.7\n' >"$work/design.opts"
  printf -- '-sbm_lzz 1e-4\n' >"$work/misspelt.opts"
  printf -- 'sbm_lz 1e-4\n' >"$work/malformed.opts"
  printf -- '-friction_law state\n-friction_memory_length 4\n' >"$work/memory.opts"
  refused 2 -design_variants -design_variants "$work/missing.opts"
  refused 2 -design_variants -design_variants "$work/design.opts"
  refused 2 -design_variants -design_variants "$work/state.opts,$work/misspelt.opts"
  refused 2 -design_variants -design_variants "$work/malformed.opts"
  refused 2 -friction_memory_length -design_variants "$work/memory.opts"
  refused 1 -design_variants -design_model fem -fem_nx 8 -fem_ny 8 -fem_nz 1 -design_variants "$work/state.opts"
  ;;
refuse)
  refused 1 -design_parameters -design_parameters ""
  refused 1 -design_parameters -design_parameters mu_width
  refused 1 -design_parameters -design_parameters grading_delta,grading_delta -design_lower -0.4,-0.4 -design_upper 0,0
  refused 1 -design_lower -design_lower -0.4,-0.2
  refused 1 -design_upper -design_upper -0.5
  refused 1 -design_upper -design_upper 1.5
  refused 1 -design_target -design_target 0
  refused 1 -design_target -design_target_type variation -design_target -1.5
  refused 1 -design_tolerance -design_tolerance 0
  refused 1 -design_coarse -design_coarse 0.001
  refused 1 -design_max_realisations -design_min_realisations 20 -design_max_realisations 10
  refused 1 -design_max_evaluations -design_max_evaluations 0
  refused 1 -design_method -design_method simplex
  refused 1 -design_tolerance -design_tolerance nan
  refused 1 -design_tolernce -design_tolernce 0.001  # a misspelling
  refused 1 -fem_nx -design_verify_fem -fem_nx 0     # the FEM's options, checked before any work
  refused 1 -output -output "$work/missing/d.h5"     # a missing folder
  # On 2 ranks: one line, exit 2, every rank (no hang).
  refused 2 -design_upper -design_upper 1.5
  # grading_delta without a grading profile; two parameters under the root finder; a field
  # parameter whose bound makes the plate invalid (mu_s < 0).
  refused 1 -design_parameters -grading_profile none
  refused 1 -design_method -options_file "$src/input/design_E_mu_tao.opts" -design_method root
  refused 1 -design_upper -options_file "$src/input/design_E_mu_tao.opts" -design_upper 0.5,1.5
  # TAO reads its options with the prefix design_: a bad type, and the unprefixed spelling.
  refused 1 -design_tao_type -options_file "$src/input/design_E_mu_tao.opts" -design_tao_type simplex
  refused 2 -tao_type -options_file "$src/input/design_E_mu_tao.opts" -tao_type pounders
  # A g per grading cannot follow a grading that moves with every evaluation.
  refused 2 -pressure_response_select -pressure_response fem -pressure_response_select grading \
    -pressure_response_file "$src/input/fields/pressure_response_fem100.h5"
  ;;
*)
  fail "unknown check $check"
  ;;
esac
echo "design check $check: passed"
