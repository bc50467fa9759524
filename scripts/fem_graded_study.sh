#!/bin/bash
# The FEM graded convergence study of docs/studies/fem-graded-convergence-old-law.md, and the FEM
# mu_s runs of docs/reproduction.md: mu_s of the paper's plate (the current defaults: q1,
# penalty 250 G/H, dt_safety 0.6) with linear E or friction grading, Delta = +-0.2 (10 bands
# along x, sliding along x), on 50x50x5, 100x100x5, 100x100x10, 200x200x5 and on 100x100x5 at
# dt_safety 0.3. Each run stops at its confirmed peak (-friction_observables mu_s), on ONE rank,
# niced, one at a time (the machine is shared). Resumable: a run whose tag is already in the
# output file is skipped, so the script can be stopped and started again; each finished run
# appends one line "<tag> | <bench_fem_element_study line> | load".
# Friction memory: -fem_slip_length 0 (no memory, the setting of the study's first runs) unless
# GF_STUDY_SLIP_LENGTH is set (e.g. 1e-8, the current default), which the tag then carries.
#   bash scripts/fem_graded_study.sh build results/fem_graded_study.txt [stage ...]
# Stages (default: m50 m100 dt m100z10 m200 ref repro reprofine):
#   m50, m50z10, m100, dt (100x100x5 at dt_safety 0.3), m100z10, m200: the four gradings
#   (a suffix _E or _friction: that property only, e.g. m200_E);
#   ref: non-graded 100x100x5, 50x50x5, 100x100x10, 200x200x5;
#   repro: the paper-mesh points of docs/reproduction.md (friction and E +-0.4, triangular E
#          +-0.2, friction 0.2 at 90 degrees);
#   n,nz,profile,property,delta[,theta]: one run at dt_safety 0.6, e.g. 100,5,linear,friction,0.2;
#   reprofine: the same points' mesh error bars: 50x50x5 (cheap, for the in-plane order) first,
#          then each point on 200x200x5 (|Delta| 0.4 first, then triangular, 90 deg: the in-plane term
#          is the larger part of the bar), then each on 100x100x10;
#          GF_STUDY_NO_M200_AFTER=HH:MM (UTC) skips 200x200x5 runs that would start later;
#          GF_STUDY_REF_THICKNESS_LAST=1 leaves ref's 100x100x10 to the end of reprofine;
#   pm02mem: the +-0.2 linear gradings (E and friction) again with the friction memory on
#          (slip length 1e-8, the default; whatever GF_STUDY_SLIP_LENGTH says), on 50x50x5, then
#          100x100x5, then 200x200x5, so that every row of the table uses one setting;
#   pm02memz10: the same four points on 100x100x10 (the thickness term of the memory rows).
set -euo pipefail
build=${1:-build}
out=${2:-results/fem_graded_study.txt}
shift $(( $# >= 2 ? 2 : $# ))
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(m50 m100 dt m100z10 m200 ref repro reprofine)
mkdir -p "$(dirname "$out")"
touch "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
study="$build/bench/fem/bench_fem_element_study"
[ -x "$study" ] || { echo "no $study: build first" >&2; exit 2; }

# run <n> <nz> <dt_safety> <profile|none> [property delta [theta]]
run() {
  local n=$1 nz=$2 safety=$3 profile=$4 prop=${5:-none} delta=${6:-0} theta=${7:-0}
  local slip=${stage_slip:-${GF_STUDY_SLIP_LENGTH:-0}}
  local tag="mesh ${n}x${n}x${nz} dt_safety ${safety} grading ${prop} ${delta}"
  [ "$profile" != linear ] && [ "$profile" != none ] && tag+=" ${profile}"
  [ "$theta" != 0 ] && tag+=" theta ${theta}"
  [ "$slip" != 0 ] && tag+=" slip ${slip}"
  if grep -qF "$tag |" "$out"; then echo "skip: $tag"; return; fi
  if [ "$n" = 200 ] && [ -n "${GF_STUDY_NO_M200_AFTER:-}" ] && [[ "$(date -u +%H:%M)" > "$GF_STUDY_NO_M200_AFTER" ]]; then
    echo "late: $tag (not started after $GF_STUDY_NO_M200_AFTER UTC)"; return
  fi
  local args=(-friction_observables mu_s -fem_slip_length "$slip" -fem_element q1 -fem_nx "$n" -fem_ny "$n" -fem_nz "$nz" -fem_dt_safety "$safety")
  [ "$profile" != none ] && args+=(-grading_profile "$profile" -grading_property "$prop" -grading_delta "$delta")
  [ "$theta" != 0 ] && args+=(-plate_theta "$theta")
  echo "run:  $tag  (start $(date -u +%H:%M:%S), load $(cut -d' ' -f1-3 /proc/loadavg))"
  local line
  line=$(nice -n 10 "$study" "${args[@]}" | grep '^element')
  echo "$tag | $line | load $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$out"
}

gradings() {  # linear gradings Delta = +-0.2 on mesh $1 x $1 x $2 at dt_safety $3, property $4 (or both)
  local p
  for p in E friction; do
    [ "$4" = all ] || [ "$4" = "$p" ] || continue
    run "$1" "$2" "$3" linear "$p" 0.2; run "$1" "$2" "$3" linear "$p" -0.2
  done
}

for stage in "${stages[@]}"; do
  stage_slip=  # a stage may fix the friction memory (pm02mem)
  property=all  # a stage name may end in _E or _friction: that property only
  case $stage in *_E) property=E stage=${stage%_E} ;; *_friction) property=friction stage=${stage%_friction} ;; esac
  case $stage in
    m50) gradings 50 5 0.6 $property ;;
    m50z10) gradings 50 10 0.6 $property ;;
    m100) gradings 100 5 0.6 $property ;;
    dt) gradings 100 5 0.3 $property ;;
    m100z10) gradings 100 10 0.6 $property ;;
    m200) gradings 200 5 0.6 $property ;;
    ref) run 100 5 0.6 none; run 200 5 0.6 none; run 50 5 0.6 none
         [ "${GF_STUDY_REF_THICKNESS_LAST:-0}" = 1 ] || run 100 10 0.6 none ;;
    repro)
      for d in 0.4 -0.4; do run 100 5 0.6 linear friction $d; run 100 5 0.6 linear E $d; done
      run 100 5 0.6 triangular E 0.2; run 100 5 0.6 triangular E -0.2
      run 100 5 0.6 linear friction 0.2 90 ;;
    reprofine)
      for d in 0.4 -0.4; do run 50 5 0.6 linear friction $d; run 50 5 0.6 linear E $d; done
      run 50 5 0.6 triangular E 0.2; run 50 5 0.6 triangular E -0.2; run 50 5 0.6 linear friction 0.2 90
      points=("linear E -0.4" "linear E 0.4" "linear friction -0.4" "linear friction 0.4"
              "triangular E 0.2" "triangular E -0.2" "linear friction 0.2 90")
      # shellcheck disable=SC2086
      for point in "${points[@]}"; do run 200 5 0.6 $point; done
      # shellcheck disable=SC2086
      for point in "${points[@]}"; do run 100 10 0.6 $point; done
      run 100 10 0.6 none ;;
    pm02mem) stage_slip=1e-8
         for n in 50 100 200; do gradings "$n" 5 0.6 $property; done ;;
    pm02memz10) stage_slip=1e-8; gradings 100 10 0.6 $property ;;
    *,*) IFS=, read -r -a point <<< "$stage"; run "${point[0]}" "${point[1]}" 0.6 "${point[@]:2}" ;;
    *) echo "unknown stage $stage (m50 m50z10 m100 dt m100z10 m200 ref repro reprofine pm02mem pm02memz10)" >&2; exit 2 ;;
  esac
done
