#!/usr/bin/env bash
# gradfric-fem plans its files before any work, on 2 ranks: an existing -output (or its fields
# file) without -output_overwrite and a -output that is a directory are refused with one
# message and exit 2; a run that fails after planning (the blow-up monitor, dt above the limit
# through -fem_dt_check false) with -output_overwrite leaves the earlier history, fields and
# .xmf files exactly as they were, and no temporary.
set -u
driver=$1; source_dir=$2; scratch=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$scratch"; mkdir -p "$scratch/dir"; cd "$scratch"; echo keep >dir/inside
scene=(-options_file "$source_dir/input/fem_fig2_H050_coarse.opts")
fail() { echo "FAILED: $*" >&2; exit 1; }
run() {  # name, expected exit, message regex, options...
  local name=$1 code=$2 regex=$3; shift 3
  timeout 300 mpiexec --oversubscribe -n 2 "$driver" "${scene[@]}" "$@" >"$name.out" 2>"$name.err"
  local rc=$?
  [ $rc -ne 124 ] || fail "$name: no exit within 300 s (a hang)"
  [ $rc -eq "$code" ] || { cat "$name.err" >&2; fail "$name: exit $rc, expected $code"; }
  grep -Eq "$regex" "$name.err" || { cat "$name.err" >&2; fail "$name: message does not match $regex"; }
}
for f in run.h5 run_fields.h5 run_fields.xmf; do echo "earlier $f" >"$f"; done
run exists 2 "invalid option -output = run.h5: allowed a file that does not exist yet \(run.h5 exists: add -output_overwrite" \
  -output run.h5 -fem_snapshot_times 0
[ "$(grep -c '^gradfric: error:' exists.err)" -eq 1 ] || fail "exists: not one message"
rm run.h5
run fields_exist 2 "run_fields.h5 exists: add -output_overwrite" -output run.h5 -fem_snapshot_times 0
echo "earlier run.h5" >run.h5
run directory 2 "invalid option -output = dir: allowed a file path \(dir is a directory\)" -output dir -output_overwrite
[ "$(ls dir)" = inside ] || fail "the directory was changed"
run blowup 1 "FEM run unstable" -output run.h5 -fem_snapshot_times 0 -output_overwrite -fem_dt 3e-7 -fem_dt_check false
for f in run.h5 run_fields.h5 run_fields.xmf; do
  [ "$(cat "$f")" = "earlier $f" ] || fail "a failed run replaced $f"
done
! ls ./*.tmp >/dev/null 2>&1 || fail "temporaries left behind: $(ls ./*.tmp)"
echo "fem output plan OK"
