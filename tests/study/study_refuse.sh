#!/usr/bin/env bash
# Both studies plan their file before any run, on every rank alike: an existing -output, an
# -output that is a directory and a missing folder are refused at once with one message and exit 2
# on 2 ranks (a refusal decided on rank 0 only used to hang -study_model fem), nothing is run and
# the existing file or directory is untouched.
set -u
driver=$1; source_dir=$2; scratch=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$scratch"; mkdir -p "$scratch/dir"; echo keep >"$scratch/dir/inside"
fail() { echo "FAILED: $*" >&2; exit 1; }
check() {  # name, model scene, output, expected message regex
  local name=$1 scene=$2 output=$3 regex=$4
  timeout 300 mpiexec --oversubscribe -n 2 "$driver" -options_file "$source_dir/input/$scene" -output "$output" \
    >"$scratch/$name.out" 2>"$scratch/$name.err"
  local rc=$?
  [ $rc -ne 124 ] || fail "$name: no exit within 300 s (a hang)"
  [ $rc -eq 2 ] || { cat "$scratch/$name.err" >&2; fail "$name: exit $rc, expected 2"; }
  [ "$(grep -c '^gradfric: error:' "$scratch/$name.err")" -eq 1 ] || { cat "$scratch/$name.err" >&2; fail "$name: not one message"; }
  grep -Eq "$regex" "$scratch/$name.err" || { cat "$scratch/$name.err" >&2; fail "$name: message does not match $regex"; }
  ! grep -q "accuracy-cost study" "$scratch/$name.out" || fail "$name: the study ran before refusing"
}
for scene in study_sbm_reduced.opts study_fem_reduced.opts; do
  tag=${scene%.opts}
  echo earlier >"$scratch/$tag.h5"
  check "${tag}_exists" "$scene" "$scratch/$tag.h5" "exists: add -output_overwrite to replace it\)$"
  [ "$(cat "$scratch/$tag.h5")" = earlier ] || fail "$tag: the existing file was changed"
  check "${tag}_dir" "$scene" "$scratch/dir" "allowed a file path \(.*dir is a directory\)"
  [ "$(ls "$scratch/dir")" = inside ] || fail "$tag: the directory was changed"
  check "${tag}_missing" "$scene" "$scratch/no/such/folder/s.h5" "existing, writable folder \(.*no/such/folder does not exist\)"
done
# -pressure_response_select grading without a g for the study's grading: refused before any run.
f="$source_dir/input/fields/pressure_response_fem100_E_+0.2.h5"
timeout 300 mpiexec --oversubscribe -n 2 "$driver" -options_file "$source_dir/input/study_sbm_reduced.opts" \
  -pressure_response fem -pressure_response_select grading -pressure_response_file "$f" -output "$scratch/g.h5" \
  >"$scratch/g.out" 2>"$scratch/g.err"
[ $? -eq 2 ] || { cat "$scratch/g.err" >&2; fail "per-grading g: not exit 2"; }
[ "$(grep -c '^gradfric: error:' "$scratch/g.err")" -eq 1 ] || fail "per-grading g: not one message"
grep -q "invalid option -pressure_response_file = $f: .*the study's scene (friction linear Delta = 0.2" "$scratch/g.err" ||
  { cat "$scratch/g.err" >&2; fail "per-grading g: message"; }
! grep -q "accuracy-cost study" "$scratch/g.out" && [ ! -e "$scratch/g.h5" ] || fail "per-grading g: the study ran or wrote"
echo "study refusals OK"
