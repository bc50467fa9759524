#!/usr/bin/env bash
# End-to-end checks of precision on demand (-ensemble_target) and file extension (-ensemble_extend)
# through the gradfric driver.
#   target_checks.sh <driver> <source-dir> <check>
# checks: target_met, target_determinism, target_refuse, extend
# Files are compared byte for byte outside /run (compare_bytes.py); targets are checked from the
# raw realisations (check_target.py), not from the statistics the run wrote.
set -euo pipefail
driver=$1
src=$2
check=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "$PWD/target_${check}_XXXXXX")
trap 'rm -rf "$work"' EXIT
python=/usr/bin/python3
run() {  # run <ranks> <args...>
  local n=$1
  shift
  mpiexec --oversubscribe -n "$n" "$driver" "$@"
}
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
same() {  # same <a.h5> <b.h5>: byte for byte apart from /run
  "$python" "$src/tests/ensemble/compare_bytes.py" "$1" "$2" || fail "$1 and $2 differ"
}
refused() {  # refused <option named> <args...>: exit 2, one line naming the option, no file
  local option=$1
  shift
  local status=0
  run 1 "${scene[@]}" "$@" -output "$work/bad.h5" >"$work/bad.log" 2>&1 || status=$?
  [ "$status" -eq 2 ] || { cat "$work/bad.log" >&2; fail "exit $status, not 2, for: $*"; }
  grep -q "gradfric: error: .*$option" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "$option not named for: $*"; }
  [ ! -e "$work/bad.h5" ] && [ ! -e "$work/bad.h5.partial" ] || fail "a refused run wrote a file: $*"
}
# The reduced Figure 4 scene on a small lattice (test time).
# l_c = the block (L/16): the 16 x 16 plate keeps the paper's per-block dispersion, so the
# points' variances differ and the target needs batches.
scene=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 16 -surface_length 3.125e-4 -ensemble_monitor)

case "$check" in
target_met)
  # Absolute: every point's CI half-width of mean mu_s at most 0.0015, counts where the variance is.
  run 2 "${scene[@]}" -ensemble_delta -0.3,0,0.3 -ensemble_target 0.0015 -output "$work/a.h5" >"$work/a.log"
  grep -q "Target met" "$work/a.log" || fail "no 'Target met' line"
  "$python" "$src/tests/ensemble/check_target.py" "$work/a.h5" 0.0015 absolute --distinct-counts || fail "absolute target"
  # The relative variation against the non-graded point, with paired streams (its default).
  run 2 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_target 0.003 -ensemble_target_type variation \
    -output "$work/v.h5" >"$work/v.log"
  grep -q "paired differences" "$work/v.log" || fail "variation target without paired streams"
  "$python" "$src/tests/ensemble/check_target.py" "$work/v.h5" 0.003 variation || fail "variation target"
  # A cap below what the target needs: the run completes, says so, and the file says which points missed.
  run 2 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_target 0.0001 -ensemble_realisations 3 -ensemble_target_max 4 \
    -output "$work/c.h5" >"$work/c.log"
  grep -q "NOT met" "$work/c.log" || fail "no warning for a target missed at the cap"
  "$python" "$src/tests/ensemble/check_target.py" "$work/c.h5" 0.0001 absolute || fail "capped run"
  "$python" - "$work/c.h5" <<'PY' || fail "capped run: counts or target_met wrong"
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    assert list(f["statistics/finished"][()]) == [4, 4], f["statistics/finished"][()]
    assert list(f["statistics/target_met"][()]) == [0, 0]
PY
  ;;
target_determinism)
  t=(-ensemble_delta 0,0.3 -ensemble_target 0.004 -ensemble_realisations 4)
  for n in 1 2 3; do run "$n" "${scene[@]}" "${t[@]}" -output "$work/np$n.h5" >"$work/np$n.log"; done
  same "$work/np1.h5" "$work/np2.h5"
  same "$work/np1.h5" "$work/np3.h5"
  grep -q "Target batch 1" "$work/np2.log" || fail "the target needed one batch only: nothing adaptive tested"
  # Killed in the second batch (the first has 8 tasks), resumed: the same file.
  if run 2 "${scene[@]}" "${t[@]}" -ensemble_abort_after 10 -output "$work/cut.h5" >"$work/cut.log" 2>&1; then
    fail "the interrupted run reported success"
  fi
  [ -f "$work/cut.h5.partial" ] || fail "no .partial after the interruption"
  run 3 "${scene[@]}" "${t[@]}" -resume -output "$work/cut.h5" >"$work/resume.log"
  grep -Eq "1[0-9] of [0-9]+ tasks already finished" "$work/resume.log" || fail "resume did not keep the finished tasks"
  same "$work/np1.h5" "$work/cut.h5"
  # A scene without a target stores none of the target options (its files stay as they were).
  run 1 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_realisations 2 -output "$work/fixed.h5" >/dev/null
  h5dump -A "$work/fixed.h5" >"$work/fixed.txt"
  h5dump -A "$work/np1.h5" >"$work/np1.txt"
  ! grep -q "ensemble_target" "$work/fixed.txt" || fail "target options stored by a fixed-count run"
  grep -q "ensemble_target_type" "$work/np1.txt" || fail "the target is not stored in /scene"
  ;;
target_refuse)
  scene+=(-ensemble_delta 0,0.3)
  refused "-ensemble_target" -ensemble_target -0.01
  refused "-ensemble_target" -ensemble_target 1.5
  refused "-ensemble_target_type" -ensemble_target 0.01 -ensemble_target_type median
  refused "-ensemble_target_min" -ensemble_target_min 4
  refused "-ensemble_target_min" -ensemble_target 0.01 -ensemble_target_min 1
  refused "-ensemble_target_min" -ensemble_target 0.01 -ensemble_target_min 50 -ensemble_target_max 20
  refused "-ensemble_realisations" -ensemble_target 0.01 -ensemble_realisations 1
  refused "-ensemble_target_type" -ensemble_delta 0.3 -ensemble_target 0.01 -ensemble_target_type variation
  ;;
extend)
  scene+=(-ensemble_monitor false)
  # More realisations and an appended point equal a run that asked for them from the start.
  run 2 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_realisations 2 -output "$work/x.h5" >/dev/null
  run 2 "${scene[@]}" -ensemble_delta 0,0.3,-0.3 -ensemble_realisations 3 -output "$work/full.h5" >/dev/null
  cp "$work/x.h5" "$work/x.orig"
  # Refused extensions leave the file as it was: another lattice, a sweep whose first points are
  # not the file's, fewer realisations, no file, together with -output_overwrite.
  for bad in "-sbm_N 18 -ensemble_delta 0,0.3 -ensemble_realisations 3" \
    "-ensemble_delta 0.3,0 -ensemble_realisations 3" "-ensemble_delta 0,0.3 -ensemble_realisations 1"; do
    status=0
    # shellcheck disable=SC2086
    run 2 "${scene[@]}" $bad -ensemble_extend -output "$work/x.h5" >"$work/bad.log" 2>&1 || status=$?
    [ "$status" -eq 2 ] && grep -q "ensemble_extend" "$work/bad.log" || { cat "$work/bad.log" >&2; fail "extension $bad not refused"; }
    cmp -s "$work/x.h5" "$work/x.orig" && [ ! -e "$work/x.h5.partial" ] || fail "a refused extension touched the file"
  done
  status=0
  run 1 "${scene[@]}" -ensemble_extend -output "$work/none.h5" >"$work/bad.log" 2>&1 || status=$?
  [ "$status" -eq 2 ] && grep -q "does not exist" "$work/bad.log" || fail "extension of a missing file not refused"
  status=0
  run 1 "${scene[@]}" -ensemble_extend -output_overwrite -output "$work/x.h5" >"$work/bad.log" 2>&1 || status=$?
  [ "$status" -eq 2 ] || fail "-ensemble_extend with -output_overwrite not refused"
  # Interrupted in the middle of the extension: the file stays whole, running it again finishes it.
  if run 2 "${scene[@]}" -ensemble_delta 0,0.3,-0.3 -ensemble_realisations 3 -ensemble_extend \
    -ensemble_abort_after 2 -output "$work/x.h5" >"$work/cut.log" 2>&1; then
    fail "the interrupted extension reported success"
  fi
  grep -q "4 tasks kept" "$work/cut.log" || fail "the extension did not keep the file's 4 tasks"
  cmp -s "$work/x.h5" "$work/x.orig" || fail "an interrupted extension changed the finished file"
  run 2 "${scene[@]}" -ensemble_delta 0,0.3,-0.3 -ensemble_realisations 3 -ensemble_extend \
    -output "$work/x.h5" >"$work/again.log"
  grep -q "Resuming" "$work/again.log" || fail "the interrupted extension was not continued"
  same "$work/full.h5" "$work/x.h5"
  # A target run extended with a tighter target meets it, keeping what it had.
  run 2 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_target 0.006 -ensemble_realisations 4 -output "$work/t.h5" >/dev/null
  run 2 "${scene[@]}" -ensemble_delta 0,0.3 -ensemble_target 0.003 -ensemble_realisations 4 -ensemble_extend \
    -output "$work/t.h5" >"$work/t.log"
  grep -Eq "[1-9][0-9]* tasks kept" "$work/t.log" || fail "the target extension kept nothing"
  "$python" "$src/tests/ensemble/check_target.py" "$work/t.h5" 0.003 absolute || fail "tighter target not met"
  # A file from before the random surface (-sbm_sigma_s, -sbm_sigma_k in /scene, no -surface_kind)
  # extends with its model and streams, -surface_kind blocks -ensemble_common_streams false, into
  # the file of the scene asked for from the start; without them it is refused.
  before=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 16 -ensemble_monitor false
    -surface_kind blocks -ensemble_common_streams false -ensemble_delta 0,0.3)
  run 2 "${before[@]}" -ensemble_realisations 2 -output "$work/old.h5" >/dev/null
  run 2 "${before[@]}" -ensemble_realisations 3 -output "$work/old_full.h5" >/dev/null
  "$python" - "$work/old.h5" <<'PYTHON'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:  # the /scene of a file written before the surface
    for group in (f["scene"], f["scene/origin"], f["scene/units"]):
        for now, before in (("surface_sigma_s", "sbm_sigma_s"), ("surface_sigma_k", "sbm_sigma_k")):
            group.attrs[before] = group.attrs[now]
            del group.attrs[now]
        del group.attrs["surface_kind"]
PYTHON
  status=0
  run 2 "${before[@]:0:6}" -ensemble_delta 0,0.3 -ensemble_realisations 3 -ensemble_extend -output "$work/old.h5" \
    >"$work/bad.log" 2>&1 || status=$?
  [ "$status" -eq 2 ] && grep -q "surface_kind: file blocks, now cells" "$work/bad.log" ||
    { cat "$work/bad.log" >&2; fail "an old file extended with the random surface was not refused"; }
  run 2 "${before[@]}" -ensemble_realisations 3 -ensemble_extend -output "$work/old.h5" >/dev/null
  same "$work/old_full.h5" "$work/old.h5"
  ;;
*)
  fail "unknown check $check"
  ;;
esac
echo "target check $check: passed"
