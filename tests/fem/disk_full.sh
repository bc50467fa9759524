#!/usr/bin/env bash
# gradfric-fem when the disk fills, on 2 ranks: the results file, the snapshots, the FEM
# sweep's file and a single run's checkpoint each end the run with exit 1 and one message naming the file and the system's
# reason, on every rank (no crash, no MPI_ABORT, no hang), leave no file under the final name and
# no temporary, and leave an earlier result (-output_overwrite) byte for byte as it was.
# SIGTERM to a FEM sweep says how many points the .partial keeps and how to continue; resumed, the
# file is the uninterrupted sweep's. A full disk is a small tmpfs, or, where mounting is not
# permitted, a file-size limit on the ranks (RLIMIT_FSIZE with SIGXFSZ ignored).
set -u
driver=$1; source_dir=$2; scratch=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mounted=""
cleanup() { [ -n "$mounted" ] && umount "$mounted" 2>/dev/null; }
trap cleanup EXIT
rm -rf "$scratch"; mkdir -p "$scratch/disk"; cd "$scratch"
fail() { echo "FAILED: $*" >&2; exit 1; }
scene=(-options_file "$source_dir/input/fem_fig2_H050_coarse.opts")
limit=""  # KiB of RLIMIT_FSIZE when no tmpfs can be mounted
# disk <KiB>: an empty disk of that size at ./disk.
disk() {
  cleanup; mounted=""; rm -rf disk; mkdir disk
  if mount -t tmpfs -o size="$1k" tmpfs disk 2>/dev/null; then mounted=$PWD/disk; limit=""; else limit=$1; fi
}
fem() {  # name, options...: 2 ranks, a time limit; sets rc
  local name=$1; shift
  if [ -z "$limit" ]; then
    timeout 300 mpiexec -n 2 "$driver" "$@" >"$name.out" 2>"$name.err"
  else
    # (Open MPI's shared-memory transport would exceed the limit itself: TCP between the ranks.)
    OMPI_MCA_btl=self,tcp timeout 300 mpiexec -n 2 bash -c 'trap "" XFSZ; ulimit -f '"$limit"'; exec "$0" "$@"' "$driver" "$@" \
      >"$name.out" 2>"$name.err"
  fi
  rc=$?
  [ $rc -ne 124 ] || fail "$name: no exit within 300 s (a hang)"
}
written() {  # name, message regex: exit 1, one message, no stack, no abort, no crash
  local name=$1 regex=$2
  [ "$rc" -eq 1 ] || { tail -5 "$name.err" >&2; fail "$name: exit $rc, expected 1"; }
  [ "$(grep -c '^gradfric: error:' "$name.err")" -eq 1 ] || { cat "$name.err" >&2; fail "$name: not one message"; }
  grep -Eq "^gradfric: error: $regex" "$name.err" || { cat "$name.err" >&2; fail "$name: message does not match $regex"; }
  ! grep -Eq "HDF5-DIAG|MPI_ABORT|Segmentation|signal 11|infinite loop" "$name.err" "$name.out" ||
    { cat "$name.err" >&2; fail "$name: an HDF5 stack, an abort or a crash"; }
  ! ls disk/*.tmp disk/*.partial >/dev/null 2>&1 || fail "$name: temporaries left: $(ls disk)"
}
full="(No space left on device|File too large)"

# The history file on a full 64 KiB disk (the issue's command): nothing under the final name.
disk 64
if [ -n "$mounted" ]; then dd if=/dev/zero of=disk/filler bs=4k 2>/dev/null; fi
fem history "${scene[@]}" -output disk/fem.h5
written history "writing .*disk/fem.h5.tmp failed on rank 0: .*$full"
[ ! -e disk/fem.h5 ] || fail "history: a file under the final name"

# An earlier result on a disk with no room for the new one: untouched.
disk 64
echo "earlier fem.h5" >disk/fem.h5
fem earlier "${scene[@]}" -output disk/fem.h5 -output_overwrite
written earlier "writing .*disk/fem.h5.tmp failed on rank 0: .*$full"
[ "$(cat disk/fem.h5)" = "earlier fem.h5" ] || fail "earlier: the earlier result was changed"

# Snapshots: room for the first field snapshot, not for all three (nor the history after them);
# the earlier history, fields and .xmf untouched.
disk 1200
for f in run.h5 run_fields.h5 run_fields.xmf; do echo "earlier $f" >"disk/$f"; done
fem snapshots "${scene[@]}" -output disk/run.h5 -output_overwrite -fem_snapshot_times 0,1e-4,2e-4
written snapshots "writing .*disk/run(_fields)?.h5.tmp failed on rank 0: .*$full"
grep -q "no room for snapshot [0-9]" snapshots.err || echo "note: the disk filled before the snapshots: $(cat snapshots.err)"
for f in run.h5 run_fields.h5 run_fields.xmf; do
  [ "$(cat "disk/$f")" = "earlier $f" ] || fail "snapshots: the earlier $f was changed"
done

# The FEM sweep's file on a full disk: refused before any run.
sweep=(-grading_profile linear -grading_property friction -ensemble_delta 0,0.2,-0.2 -fem_nx 10 -fem_ny 10 -fem_nz 2 -fem_kn 4e11)
disk 64
if [ -n "$mounted" ]; then dd if=/dev/zero of=disk/filler bs=4k 2>/dev/null; fi
fem sweep_full "${sweep[@]}" -output disk/sweep.h5
written sweep_full "writing .*disk/sweep.h5.partial failed on rank 0: .*$full"
[ ! -e disk/sweep.h5 ] || fail "sweep_full: a file under the final name"

# A single run's checkpoint on a full disk (written at SIGTERM): exit 1, one message, no
# .partial, and the earlier checkpoint as it was.
disk 64
echo "earlier checkpoint" >disk/ck.checkpoint.h5
fem checkpoint_full "${scene[@]}" -output disk/ck.h5 -output_overwrite -checkpoint_interval 0 -checkpoint_test_signal TERM@200
written checkpoint_full "writing .*disk/ck.checkpoint.h5.partial failed on rank 0: .*$full"
[ "$(cat disk/ck.checkpoint.h5)" = "earlier checkpoint" ] || fail "checkpoint_full: the earlier checkpoint was changed"
cleanup; mounted=""; limit=""

# SIGTERM to a running sweep (2 groups of 1 rank, eight points of ~1 s): the notice, then a resume
# gives the same file.
sweep=(-grading_profile linear -grading_property friction -ensemble_delta 0,0.2,-0.2,0.1,-0.1,0.3,-0.3,0.15
       -fem_nx 32 -fem_ny 32 -fem_nz 2 -fem_kn 4e11)
timeout 300 mpiexec -n 2 "$driver" "${sweep[@]}" -output whole.h5 >whole.out 2>whole.err || fail "whole: $(tail -3 whole.err)"
# --foreground: timeout passes our SIGTERM to mpiexec alone, once (a second one makes mpiexec kill
# the ranks at once, before their handlers run).
timeout --foreground 300 mpiexec -n 2 "$driver" "${sweep[@]}" -output cut.h5 >cut.out 2>cut.err &
launcher=$!
for _ in $(seq 1 3000); do sleep 0.02; grep -q '^\[group [01]\] point' cut.out 2>/dev/null && break; done
grep -q '^\[group [01]\] point' cut.out || fail "interrupt: no point finished: $(cat cut.out cut.err)"
kill -TERM "$launcher"
wait "$launcher"
rc=$?
[ $rc -ne 0 ] && [ $rc -ne 124 ] || fail "interrupt: exit $rc: $(tail -3 cut.out)"
notice="^gradfric: interrupted \(SIGTERM\): ([0-9]+) of 8 points are finished and kept in cut.h5.partial; continue with the same command and -resume$"
[ "$(grep -c '^gradfric: interrupted' cut.err)" -eq 1 ] && grep -Eq "$notice" cut.err || { cat cut.err >&2; fail "interrupt: no notice: $(grep -c '^\[group' cut.out) points printed"; }
said=$(grep -E "$notice" cut.err | sed -E "s/$notice/\1/")
kept=$(h5dump -A 0 -y -d /realisations/done cut.h5.partial | sed -n '/DATA {/,/}/p' | grep -o '[01]' | grep -c 1 || true)
[ "$said" -ge 1 ] && [ "$said" -le "$kept" ] || fail "interrupt: the notice says $said points, the file keeps $kept"
[ "$kept" -lt 8 ] && [ ! -e cut.h5 ] || fail "interrupt: the signal came too late to test anything"
timeout 300 mpiexec -n 2 "$driver" "${sweep[@]}" -output cut.h5 -resume >resume.out 2>resume.err ||
  fail "resume: $(tail -3 resume.err)"
grep -q "$((8 - kept)) to run" resume.out || fail "resume: the $kept finished points were not skipped"
h5diff --exclude-path /run whole.h5 cut.h5 >diff.txt 2>&1 || fail "the resumed sweep differs: $(head -5 diff.txt)"
echo "fem disk full OK"
