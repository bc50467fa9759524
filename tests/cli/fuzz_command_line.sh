#!/usr/bin/env bash
# A fuzz-style battery of bad and extreme command lines for the drivers. Every
# case must: exit 2 (0 for -help/-version), print exactly one stderr line "gradfric: error: ..."
# naming the option, show no PETSc banner/traceback, leave no file behind, finish within 60 s.
# Usage: fuzz_command_line.sh <drivers folder> <scratch folder> <group: sbm|fem|study|mpi> [mpiexec]
set -u
bin=$(cd "$1" && pwd)
scratch=$2
group=$3
mpiexec=${4:-mpiexec}
G=$bin/gradfric
F=$bin/gradfric-fem
S=$bin/gradfric-study
C=$bin/gradfric-calibrate
D=$bin/gradfric-design
# The plate's physical options (one record for both models since the rename).
SP=-plate_
FP=-plate_

# A single process needs no Open MPI daemon: starts faster.
export OMPI_MCA_ess_singleton_isolated=1
rm -rf "$scratch/$group"
mkdir -p "$scratch/$group/inputs"
in=$scratch/$group/inputs
mkdir -p "$in/folder"
printf -- '-sbm_N 5\0\x01\x02binary' > "$in/binary.opts"
echo "-options_file $in/self.opts" > "$in/self.opts"
echo "-options_file $in/b.opts" > "$in/a.opts"
echo "-sbm_N 8  # comment" > "$in/b.opts"; echo "-options_file $in/a.opts" >> "$in/b.opts"
printf 'a: [1, 2\nb: }\n' > "$in/bad.yaml"
printf 'just a sentence\n' > "$in/scalar.yaml"
printf -- '-sbm_N 5 \xe9t\xe9\n' > "$in/latin1.opts"
printf 'sbm_N 5\n' > "$in/nodash.opts"
mkdir -p "$in/home"; echo "-sbm_N 8 9" > "$in/home/.petscrc"  # a petscrc with a stray word
: > "$in/empty.opts"
echo "-options_file $in/no_such_inner.opts" > "$in/outer.opts"
echo "-sbm_N 5" > "$in/good.opts"
printf -- '-sbm_N 5\n-ensemble_delta 0 0.2\n' > "$in/stray.opts"
printf -- '-sbm_N 5 # comment\n-grading_profile "linear"\n' > "$in/quoted.opts"

cases=0
failures=0
n=0
# run <expected exit> <regex the error line / stdout must match> <driver> [args...]
# Environment: RANKS (default 1), ABSENT (a regex stderr must not match).
run() {
  local expected=$1 named=$2 driver=$3; shift 3
  n=$((n + 1)); cases=$((cases + 1))
  local dir=$scratch/$group/case_$n
  rm -rf "$dir"; mkdir -p "$dir"
  local out=-output  # every driver names its results file so
  local launcher=()
  [ "${RANKS:-1}" -gt 1 ] && launcher=("$mpiexec" -n "$RANKS" --oversubscribe --quiet)  # --quiet: no launcher notice
  (cd "$dir" && timeout 60 "${launcher[@]}" "$driver" "$out" "$dir/out.h5" "$@" >"$dir.stdout" 2>"$dir.stderr")
  local status=$?
  local stderr; stderr=$(cat "$dir.stderr")
  local problem=""
  if [ $status -eq 124 ]; then problem="timed out (60 s)"
  elif [ $status -ne "$expected" ]; then problem="exit $status, expected $expected"
  elif [ -n "$(ls -A "$dir")" ]; then problem="left files behind: $(ls -A "$dir" | tr '\n' ' ')"
  elif grep -qiE "PETSC ERROR|traceback|segmentation|signal|MPI_ABORT|-----" "$dir.stderr"; then problem="noise on stderr"
  elif [ "$expected" -eq 2 ]; then
    if [ "$(wc -l <"$dir.stderr")" -ne 1 ]; then problem="stderr has $(wc -l <"$dir.stderr") lines, expected 1"
    elif ! grep -qE "^gradfric: error: .*($named)" "$dir.stderr"; then problem="error line does not name $named"
    fi
  elif ! grep -qE -- "$named" "$dir.stdout"; then problem="stdout does not match $named"
  elif [ -s "$dir.stderr" ]; then problem="unexpected stderr"
  fi
  if [ -n "${ABSENT:-}" ] && grep -qE -- "$ABSENT" "$dir.stderr"; then problem="stderr mentions $ABSENT"; fi
  if [ -n "$problem" ]; then
    failures=$((failures + 1))
    echo "FAIL [$n] $(basename "$driver") $*: $problem"
    echo "     stderr: $(head -c 400 "$dir.stderr")"
  else
    echo "ok   [$n] $(basename "$driver") $*: $(head -n 1 "$dir.stderr")"
  fi
  rm -rf "$dir" "$dir.stdout" "$dir.stderr"
}

case $group in
sbm)
  # Integers: wrap-around, signs, junk, overflow, empty.
  run 2 -sbm_N "$G" -sbm_N 4294967304
  run 2 -sbm_N "$G" -sbm_N -5
  run 2 -sbm_N "$G" -sbm_N 1e3
  run 2 -sbm_N "$G" -sbm_N 0x10
  run 2 -sbm_N "$G" -sbm_N 99999999999999999999
  run 2 -sbm_N "$G" -sbm_N ""
  run 2 -sbm_N "$G" -sbm_N 4097
  run 2 -ensemble_realisations "$G" -ensemble_realisations 4294967297
  run 2 -ensemble_realisations "$G" -ensemble_realisations 0
  run 2 -ensemble_realisations "$G" -ensemble_realisations -1
  run 2 -ensemble_seed "$G" -ensemble_seed -1
  run 2 -ensemble_seed "$G" -ensemble_seed 2147483648
  run 2 -ensemble_abort_after "$G" -ensemble_abort_after -3
  run 2 -grading_bands "$G" -grading_profile linear -grading_delta 0.2 -grading_bands 1
  run 2 -grading_bands "$G" -grading_profile linear -grading_delta 0.2 -grading_bands 4294967306
  # Reals: inf, nan, -inf, overflow, subnormal, empty, junk; absurd but finite values.
  run 2 -sbm_dt "$G" -sbm_dt inf
  run 2 -sbm_dt "$G" -sbm_dt nan
  run 2 -sbm_dt "$G" -sbm_dt -inf
  run 2 -sbm_dt "$G" -sbm_dt 1e308
  run 2 -sbm_dt "$G" -sbm_dt 1e-320
  run 2 -sbm_dt "$G" -sbm_dt 1e-300
  run 2 -sbm_dt "$G" -sbm_dt 1e999
  run 2 -sbm_dt "$G" -sbm_dt ""
  run 2 -sbm_dt "$G" -sbm_dt 1e-6x
  run 2 -sbm_t_max "$G" -sbm_t_max 1e10
  run 2 -sbm_t_max "$G" -sbm_t_max nan
  run 2 -sbm_t_end "$G" -sbm_t_end 1e300
  run 2 -sbm_t_end "$G" -sbm_t_end -1
  run 2 -friction_history_interval "$G" -friction_history_interval -1e-300
  run 2 -friction_muk_width "$G" -friction_muk_width inf
  run 2 -sbm_dt_safety "$G" -sbm_dt_safety 0
  run 2 -sbm_dt_safety "$G" -sbm_dt_safety nan
  run 2 -friction_peak_drop "$G" -friction_peak_drop 2
  run 2 -surface_sigma_s "$G" -surface_sigma_s inf
  run 2 -surface_length "$G" -surface_length nan
  # The state law on the blocks: 0 < D_c <= H, D_c only with -friction_law state.
  run 2 -friction_d_c "$G" -friction_law state -friction_d_c 0
  run 2 -friction_d_c "$G" -friction_law state -friction_d_c 1e-3
  run 2 -friction_d_c "$G" -friction_law state -friction_d_c nan
  run 2 "-friction_d_c = 1e-08: allowed only with -friction_law state" "$G" -friction_d_c 1e-8
  run 2 -sbm_gamma "$G" -sbm_gamma 1e300
  run 2 -grading_delta "$G" -grading_profile linear -grading_delta nan
  run 2 -grading_delta "$G" -grading_profile linear -grading_delta inf
  run 2 -grading_delta "$G" -grading_profile linear -grading_delta 1e-320
  run 2 -grading_profile "$G" -grading_delta 0.2
  # Physical values of the plate: non-finite, and finite values that make the run endless.
  run 2 ${SP}rho "$G" ${SP}rho inf
  run 2 ${SP}E "$G" ${SP}E inf
  run 2 ${SP}E "$G" ${SP}E 1e300
  run 2 ${SP}mu_s "$G" ${SP}mu_s 1e300
  run 2 ${SP}v "$G" ${SP}v 1e-300
  run 2 ${SP}v "$G" ${SP}v 1e300
  run 2 ${SP}rho "$G" ${SP}rho 1e-300
  run 2 ${SP}theta "$G" ${SP}theta -inf
  run 2 ${SP}p "$G" ${SP}p 1e300
  run 2 -plate_nu "$G" -plate_nu 0.3
  run 2 "-sbm_E = 1e7: .*use -plate_E" "$G" -sbm_E 1e7
  run 2 "did you mean -plate_mu_s" "$G" -plate_mus 0.6
  # Lists and choices.
  run 2 -ensemble_delta "$G" -grading_profile linear -ensemble_delta 0,inf
  run 2 -ensemble_delta "$G" -grading_profile linear -ensemble_delta 0,,x
  run 2 -ensemble_theta "$G" -ensemble_theta 0,nan
  run 2 -ensemble_sigma "$G" -ensemble_sigma 0,1e308
  run 2 -sbm_snapshot_times "$G" -sbm_snapshot_times 1e-4,nan
  run 2 -ensemble_property "$G" -grading_profile linear -ensemble_property E,bogus
  run 2 -friction_observables "$G" -friction_observables mu_s,bogus
  run 2 -sbm_integrator "$G" -sbm_integrator euler
  run 2 -grading_profile "$G" -grading_profile ""
  run 2 "-model = fem: gradfric runs the spring-block model only; the finite-element model is the driver gradfric-fem" "$G" -model fem
  run 2 -ensemble_schedule "$G" -ensemble_schedule random
  run 2 -ensemble_history "$G" -ensemble_history maybe
  # Stray words after a value and empty list items: refused, not ignored (PETSc skips them).
  run 2 "-ensemble_delta = 0 0.2: allowed one value .*0,0.2" "$G" -grading_profile linear -ensemble_delta 0 0.2
  run 2 "-ensemble_delta = -0.1 -0.2: allowed one value" "$G" -grading_profile linear -ensemble_delta -0.1 -0.2
  # The same from the other sources PETSc reads: the environment and the petscrc files.
  PETSC_OPTIONS="-ensemble_delta 0 0.2" run 2 "-ensemble_delta = 0 0.2 \\(in the environment's PETSC_OPTIONS\\): allowed one value" "$G" -grading_profile linear
  HOME=$in/home run 2 "-sbm_N = 8 9 \\(in $in/home/.petscrc line 1\\): allowed one value" "$G"
  run 2 "-sbm_N = 5 6 7: allowed one value \\(the stray words 6 7" "$G" -sbm_N 5 6 7
  run 2 "-output_overwrite = true yes: allowed one value" "$G" -output_overwrite true yes
  run 2 "-ensemble_delta = 0 0.2 \\(in $in/stray.opts line 2\\): allowed one value" "$G" -options_file "$in/stray.opts"
  run 2 "-ensemble_delta = 0.1,,0.2: .*\\(item 2 is empty\\)" "$G" -grading_profile linear -ensemble_delta 0.1,,0.2
  run 2 "-ensemble_theta = 0,90,: .*\\(item 3 is empty\\)" "$G" -ensemble_theta 0,90,
  run 2 "-ensemble_property = ,E: .*\\(item 1 is empty\\)" "$G" -grading_profile linear -ensemble_property ,E
  run 2 "-friction_observables = mu_s,: .*item 2 is empty" "$G" -friction_observables mu_s,
  run 2 "-sbm_N = 4294967304" "$G" -options_file "$in/quoted.opts" -sbm_N 4294967304
  # The renamed run-control options: refused with the new spelling.
  run 2 "-ensemble_resume: renamed.*; use -resume$" "$G" -ensemble_resume
  run 2 "-fem_output = x.h5: renamed.*; use -output = x.h5" "$G" -fem_output x.h5
  # Options files.
  run 2 "-options_file = $in/folder: a directory" "$G" -options_file "$in/folder"
  run 2 "-options_file = $in/binary.opts: binary" "$G" -options_file "$in/binary.opts"
  run 2 "includes itself" "$G" -options_file "$in/self.opts"
  run 2 "includes itself \\($in/a.opts -> $in/b.opts -> $in/a.opts" "$G" -options_file "$in/a.opts"
  run 2 "-options_file = $in/missing.opts: No such file" "$G" -options_file "$in/missing.opts"
  run 2 "-options_file_yaml = $in/bad.yaml: not valid YAML" "$G" -options_file_yaml "$in/bad.yaml"
  run 2 "-options_file_yaml = $in/scalar.yaml: .*mapping" "$G" -options_file_yaml "$in/scalar.yaml"
  run 2 "-options_file_yaml = $in/binary.opts: binary" "$G" -options_file_yaml "$in/binary.opts"
  run 2 "-options_file_yaml = $in/folder" "$G" -options_file_yaml "$in/folder"
  run 2 "-options_file = $in/latin1.opts: not UTF-8" "$G" -options_file "$in/latin1.opts"
  run 2 "-options_file = $in/nodash.opts: line 1" "$G" -options_file "$in/nodash.opts"
  run 2 "-options_file = $in/no_such_inner.opts \\(in $in/outer.opts line 1\\)" "$G" -options_file "$in/outer.opts"
  run 2 "-options_file: no file name" "$G" -options_file
  run 2 -sbm_N "$G" -options_file "$in/empty.opts" -sbm_N 1
  run 2 -sbm_N "$G" -options_file "$in/good.opts" -sbm_N 4294967298
  # Misspellings: near misses of known options, double dashes.
  run 2 "-ouput \\(did you mean -output\\?\\)" "$G" -ouput x.h5
  run 2 "-outptu \\(did you mean -output\\?\\)" "$G" -outptu x.h5
  run 2 "did you mean -ensemble_realisations" "$G" -ensmble_realisations 3
  run 2 "did you mean -plot_dir" "$G" -plot_dri figures
  run 2 "-sbm_dealta" "$G" -sbm_dealta 0.1
  run 2 "did you mean -grading_profile" "$G" -grading_profil linear
  run 2 -sbm_N "$G" --sbm_N 1
  run 2 -sbm_N "$G" --sbm_N=9
  ABSENT=log_view run 2 -sbm_N "$G" -log_view -sbm_N 1
  # Combinations: the first problem is reported, alone.
  run 2 "-sbm_N|-sbm_dt" "$G" -sbm_N 4294967304 -sbm_dt nan
  run 2 "-sbm_N|-options_file" "$G" -sbm_N 0 -options_file "$in/self.opts"
  # Help and version stop before any work.
  run 0 "-sbm_N" "$G" --help
  run 0 "-sbm_N" "$G" -h
  run 0 "-ensemble_realisations" "$G" -help
  run 0 "^gradfric [0-9.]+ \\(commit [^)]+\\)$" "$G" -version
  run 0 "^gradfric [0-9.]+ \\(commit" "$G" --version -sbm_N 4294967304
  ;;
fem)
  run 2 -fem_nx "$F" -fem_nx 4294967297
  # The mesh graded toward the edges: ratio, band and the mesh's unit (12 cells at ratio 4).
  run 2 -fem_edge_ratio "$F" -fem_edge_ratio 0.5
  run 2 -fem_edge_ratio "$F" -fem_edge_ratio nan
  run 2 -fem_edge_ratio "$F" -fem_edge_ratio 17
  run 2 -fem_edge_band "$F" -fem_edge_ratio 4 -fem_edge_band -5e-4
  run 2 -fem_edge_band "$F" -fem_edge_ratio 4 -fem_edge_band 2.5e-3
  run 2 -fem_ny "$F" -fem_edge_ratio 4 -fem_nx 24 -fem_ny 25
  run 2 -fem_nx "$F" -fem_nx 0
  run 2 -fem_nz "$F" -fem_nz -1
  run 2 -fem_nx "$F" -fem_nx 100000 -fem_ny 100000
  run 2 -friction_muk_steady_tol "$F" -friction_muk_steady_tol 2
  run 2 -friction_muk_latest_delay "$F" -friction_muk_latest_delay 1e-6
  run 2 -fem_ny "$F" -fem_ny 1.5
  run 2 -fem_monitor_every "$F" -fem_monitor_every 0
  run 2 -fem_history_every "$F" -fem_history_every 99999999999
  run 2 -fem_dt "$F" -fem_dt 1e-300
  run 2 -fem_dt "$F" -fem_dt inf
  run 2 -fem_dt "$F" -fem_dt 1
  run 2 -fem_dt_safety "$F" -fem_dt_safety nan
  run 2 -fem_slide_time "$F" -fem_slide_time 1e10
  run 2 -fem_ramp_time "$F" -fem_ramp_time inf
  run 2 -fem_kn "$F" -fem_kn 1e300
  run 2 -fem_kt "$F" -fem_kt -1
  run 2 -friction_v_c "$F" -friction_v_c nan
  run 2 -friction_d_c "$F" -friction_d_c 0
  run 2 -friction_d_c "$F" -friction_d_c 1e-3
  run 2 -friction_d_c "$F" -friction_law exponential -friction_d_c 1e-8
  run 2 -fem_slip_length "$F" -fem_slip_length 1e-8
  run 2 -fem_v_c "$F" -fem_v_c 1e-4
  run 2 -fem_monitor_factor "$F" -fem_monitor_factor inf
  run 2 -fem_snapshot_times "$F" -fem_snapshot_times 0,inf
  run 2 -fem_partitioner "$F" -fem_partitioner parmetis
  run 2 -fem_contact "$F" -fem_contact sometimes
  run 2 ${FP}theta "$F" ${FP}theta nan
  run 2 ${FP}E "$F" ${FP}E inf
  run 2 ${FP}E "$F" ${FP}E 1e300
  run 2 ${FP}mu_s "$F" ${FP}mu_s 1e300
  run 2 ${FP}H "$F" ${FP}H 1e-300
  run 2 ${FP}nu "$F" ${FP}nu 0.5
  run 2 "-fem_H = 0.1: .*use -plate_H" "$F" -fem_H 0.1
  run 2 "did you mean -plate_L" "$F" -plat_L 0.1
  run 2 -grading_profile "$F" -grading_delta 0.2
  run 2 -grading_bands "$F" -grading_profile linear -grading_delta 0.1 -grading_bands 0
  run 2 -fem_seed "$F" -fem_seed -1
  run 2 "-fem_compare_seed = 1: .*; use -fem_seed = 1" "$F" -fem_compare_seed 1
  run 2 "-fem_nxx" "$F" -fem_nxx 3
  run 2 "did you mean -output\\?" "$F" -outptu x.h5
  run 2 "-output_overwrit \\(did you mean -output_overwrite" "$F" -output_overwrit
  run 2 "-fem_output = f.h5: renamed.*; use -output = f.h5" "$F" -fem_output f.h5
  run 2 "-fem_output_overwrite: renamed.*; use -output_overwrite$" "$F" -fem_output_overwrite
  run 2 "-fem_sweep_resume: renamed.*; use -resume$" "$F" -fem_sweep_resume
  run 2 "-fem_snapshot_times = 0 1e-5: allowed one value" "$F" -fem_snapshot_times 0 1e-5
  run 2 "-ensemble_delta = 0.1,,0.2: .*item 2 is empty" "$F" -grading_profile linear -ensemble_delta 0.1,,0.2
  run 2 "-ensemble_theta = 0 90: allowed one value" "$F" -ensemble_theta 0 90
  run 2 -fem_nx "$F" --fem_nx 0
  run 2 "-options_file_yaml = $in/bad.yaml" "$F" -options_file_yaml "$in/bad.yaml"
  run 2 "includes itself" "$F" -options_file "$in/a.opts"
  run 0 "-fem_nx" "$F" --help
  run 0 "^  -fem_nx" "$F" -help fem
  run 0 "No option of this driver starts with -zzz" "$F" -help zzz
  # -help <prefix> lists that prefix alone; gradfric-fem's -friction_ options (read by both
  # models) once each, every section once.
  cases=$((cases + 1))
  ( cd "$scratch/$group" && "$F" -help fem >help_fem.txt 2>&1 && "$F" -help >help_all.txt 2>&1 ) || true
  problem=""
  grep -q "^  -fem_nx" "$scratch/$group/help_fem.txt" || problem="-help fem lacks -fem_nx"
  grep -qE "^  -(plate|friction|grading|field|sbm|ensemble|output)" "$scratch/$group/help_fem.txt" && problem="-help fem lists other prefixes"
  [ "$(grep -c "^  -friction_law " "$scratch/$group/help_all.txt")" = 1 ] || problem="-friction_law not listed once"
  [ -z "$(grep "^  -" "$scratch/$group/help_all.txt" | awk '{print $1}' | sort | uniq -d)" ] || problem="an option listed twice"
  [ -z "$(grep -E "^[A-Z].*:$" "$scratch/$group/help_all.txt" | grep -v "Options" | sort | uniq -d)" ] || problem="a section listed twice"
  if [ -n "$problem" ]; then failures=$((failures + 1)); echo "FAIL [help] $problem"; else echo "ok   [help] gradfric-fem -help fem: only -fem_; -friction_ once"; fi
  run 0 "^gradfric [0-9.]+ \\(commit" "$F" -version
  ;;
study)
  run 2 -study_model "$S" -study_model bogus
  run 2 -study_dt "$S" -study_dt 1e-300
  run 2 -study_dt "$S" -study_dt 0,nan
  run 2 -study_N "$S" -study_N 4294967304
  run 2 -study_N "$S" -study_N 2.5
  run 2 -study_R_max "$S" -study_R_max 4294967298
  run 2 -study_dt_realisations "$S" -study_dt_realisations 0
  run 2 -study_seed "$S" -study_seed -1
  run 2 -study_knobs "$S" -study_knobs dt,bogus
  run 2 -study_meshes "$S" -study_model fem -study_meshes 100000x100000x10
  run 2 -study_meshes "$S" -study_model fem -study_meshes 4294967304x1x1
  run 2 -study_penalty_factors "$S" -study_model fem -study_penalty_factors 1e300
  run 2 -study_mesh_estimate_steps "$S" -study_model fem -study_mesh_estimate_steps 4294967296
  run 2 -sbm_N "$S" -sbm_N 4294967304
  run 2 "includes itself" "$S" -options_file "$in/self.opts"
  run 2 "did you mean -study_model" "$S" -study_mdoel fem
  run 2 "-study_meshes = 6x6x1.5: .*'6x6x1.5' is not one" "$S" -study_model fem -study_meshes 6x6x1.5
  run 2 "-study_meshes = 25x25x1,,50x50x2: .*an empty item" "$S" -study_model fem -study_meshes 25x25x1,,50x50x2
  run 2 "-study_meshes = 25x25x1,: .*an empty item" "$S" -study_model fem -study_meshes 25x25x1,
  run 2 "-study_dt = 1e-8 3e-8: allowed one value" "$S" -study_dt 1e-8 3e-8
  run 2 "-study_N = 30,,60: .*item 2 is empty" "$S" -study_N 30,,60
  run 2 "unknown option -resume" "$S" -resume
  # The other drivers: the same vocabulary and refusals.
  run 2 -friction_d_c "$S" -friction_law state -friction_d_c -1
  run 2 -friction_d_c "$C" -friction_law state -friction_d_c 1
  run 2 -friction_d_c "$D" -grading_profile linear -design_parameters grading_delta -design_lower 0 -design_upper 0.5 -design_target 0.9 -friction_law state -friction_d_c 0
  run 2 "-calibrate_output = c.opts: renamed.*; use -output = c.opts" "$C" -calibrate_output c.opts
  run 2 "-calibrate_output_overwrite: renamed.*; use -output_overwrite$" "$C" -calibrate_output_overwrite
  run 2 "-calibrate_window = 0.2 0.6: allowed one value" "$C" -calibrate_window 0.2 0.6
  run 2 "-design_parameters = grading_delta,: .*none empty" "$D" -grading_profile linear -design_parameters grading_delta, -design_lower 0 -design_upper 0.5 -design_target 0.9
  run 2 "-design_lower = 0,,1: .*item 2 is empty" "$D" -design_lower 0,,1
  run 2 "-ensemble_resume: renamed.*; use -resume$" "$D" -ensemble_resume
  run 0 "-study_knobs" "$S" --help
  run 0 "^gradfric [0-9.]+ \\(commit" "$S" -version
  ;;
mpi)
  # The same refusals on 2 ranks: one message, exit 2 from mpiexec, no rank left waiting.
  export RANKS=2
  run 2 -sbm_N "$G" -sbm_N 4294967304
  run 2 -sbm_dt "$G" -sbm_dt nan
  run 2 -sbm_dt "$G" -sbm_dt 1e-300
  run 2 "binary" "$G" -options_file "$in/binary.opts"
  run 2 "includes itself" "$G" -options_file "$in/a.opts"
  run 2 "not valid YAML" "$G" -options_file_yaml "$in/bad.yaml"
  run 2 "did you mean -output" "$G" -ouput x.h5
  run 2 -grading_profile "$G" -grading_delta 0.2
  run 2 -fem_nx "$F" -fem_nx 4294967297
  run 2 -study_dt "$S" -study_dt 1e-300
  run 2 "-ensemble_delta = 0 0.2: allowed one value" "$G" -grading_profile linear -ensemble_delta 0 0.2
  run 2 "-ensemble_delta = 0.1,,0.2: .*item 2 is empty" "$G" -grading_profile linear -ensemble_delta 0.1,,0.2
  run 2 "-fem_output = f.h5: renamed.*; use -output = f.h5" "$F" -fem_output f.h5
  run 2 "-study_meshes = 6x6x1.5" "$S" -study_model fem -study_meshes 6x6x1.5
  run 0 "^gradfric [0-9.]+ \\(commit" "$G" -version
  ;;
*) echo "unknown group $group"; exit 1 ;;
esac
echo "command-line battery ($group): $cases cases, $((cases - failures)) passed, $failures failed"
exit $((failures > 0))
