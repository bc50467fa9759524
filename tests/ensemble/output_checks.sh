#!/usr/bin/env bash
# The results file of the gradfric driver is planned before any work and replaced only on success;
# a refusal or an I/O failure ends every rank with one message and a non-zero exit, never a hang;
# a bad file given to -resume gets one line saying what is wrong with it (exit 2); a
# full disk is exit 1 with one message on every rank (no MPI_ABORT), also when resuming; SIGTERM
# says what the partial file keeps, and resuming it gives the uninterrupted run's file.
#   output_checks.sh <driver> <source-dir> <check>
# checks: refuse_output, overwrite_failed, disk_full, resume_files, resume_disk_full, interrupt.
# Each runs on 1 and 2 ranks where a rank count matters (refusals decided on rank 0, collective
# writes).
set -uo pipefail
driver=$1
src=$2
check=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "$PWD/output_${check}_XXXXXX")
mounted=""
cleanup() {
  [ -n "$mounted" ] && umount "$mounted" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
# A small scene: 3 points x 1 realisation on a 16 x 16 lattice.
scene=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 16 -ensemble_delta -0.3,0,0.3 -ensemble_realisations 1)
# run <ranks> <log-stem> <args...>: the driver with a time limit (a hang fails the check); sets rc.
run() {
  local n=$1 stem=$2
  shift 2
  timeout 300 mpiexec --oversubscribe -n "$n" "$driver" "$@" >"$work/$stem.out" 2>"$work/$stem.err"
  rc=$?
  [ $rc -ne 124 ] || fail "$stem: no exit within 300 s (a hang)"
}
# refused <stem> <expected exit> <message regex>: exactly one gradfric message, no HDF5 error stack.
refused() {
  local stem=$1 code=$2 regex=$3
  [ "$rc" -eq "$code" ] || { cat "$work/$stem.err" >&2; fail "$stem: exit $rc, expected $code"; }
  local lines
  lines=$(grep -c "^gradfric: error:" "$work/$stem.err")
  [ "$lines" -eq 1 ] || { cat "$work/$stem.err" >&2; fail "$stem: $lines error lines, expected one"; }
  grep -Eq "$regex" "$work/$stem.err" || { cat "$work/$stem.err" >&2; fail "$stem: message does not match '$regex'"; }
  ! grep -q "HDF5-DIAG" "$work/$stem.err" || fail "$stem: HDF5 error stack printed"
}
# written <what> <log-stem> <message regex>: a write error: exit 1 on every rank, one gradfric
# message, no HDF5 error stack, no MPI_ABORT, no crash.
written() {
  local what=$1 stem=$2 regex=$3
  [ "$rc" -eq 1 ] || { cat "$work/$stem.err" >&2; fail "$what: exit $rc, expected 1"; }
  local lines
  lines=$(grep -c "^gradfric: error:" "$work/$stem.err")
  [ "$lines" -eq 1 ] || { cat "$work/$stem.err" >&2; fail "$what: $lines error lines, expected one"; }
  grep -Eq "^gradfric: error: $regex" "$work/$stem.err" || { cat "$work/$stem.err" >&2; fail "$what: message does not match '$regex'"; }
  ! grep -q "HDF5-DIAG" "$work/$stem.err" || fail "$what: HDF5 error stack printed"
  ! grep -Eq "MPI_ABORT|Segmentation|signal 11|infinite loop" "$work/$stem.err" "$work/$stem.out" ||
    { cat "$work/$stem.err" >&2; fail "$what: aborted or crashed"; }
}

case "$check" in
refuse_output)
  for n in 1 2; do
    # -output is a directory: refused, the directory and its content untouched.
    mkdir -p "$work/dir$n" && echo keep >"$work/dir$n/inside"
    run "$n" "dir$n" "${scene[@]}" -output "$work/dir$n" -output_overwrite
    refused "dir$n" 2 "invalid option -output = .*dir$n: allowed a file path \(.* is a directory\)"
    [ "$(cat "$work/dir$n/inside")" = keep ] && [ "$(ls "$work/dir$n")" = inside ] || fail "the directory was changed"
    # A missing folder.
    run "$n" "missing$n" "${scene[@]}" -output "$work/no/such/folder/x.h5"
    refused "missing$n" 2 "allowed a path in an existing, writable folder \(.*no/such/folder does not exist\)"
    # An existing file without -output_overwrite: untouched.
    echo earlier >"$work/exists$n.h5"
    run "$n" "exists$n" "${scene[@]}" -output "$work/exists$n.h5"
    refused "exists$n" 2 "exists: add -output_overwrite to replace it, or -resume to continue it"
    [ "$(cat "$work/exists$n.h5")" = earlier ] || fail "the existing file was changed"
    # The temporary cannot be created (a directory stands in its place).
    mkdir -p "$work/temp$n.h5.partial"
    run "$n" "temp$n" "${scene[@]}" -output "$work/temp$n.h5" -output_overwrite
    refused "temp$n" 2 "temporary file .*temp$n.h5.partial is not a directory"
  done
  # A read-only folder (we are root, so permission bits do not stop us: a read-only mount does).
  mkdir -p "$work/ro"
  if mount -t tmpfs -o ro,size=64k tmpfs "$work/ro" 2>/dev/null; then
    mounted="$work/ro"
    for n in 1 2; do
      run "$n" "ro$n" "${scene[@]}" -output "$work/ro/x.h5"
      refused "ro$n" 2 "allowed a path in an existing, writable folder \(cannot write .*ro/x.h5.partial: Read-only file system\)"
    done
    umount "$work/ro" && mounted=""
  else
    echo "note: cannot mount a read-only tmpfs here: read-only folder not checked"
  fi
  [ -z "$(find "$work" -name '*.h5.partial' -type f)" ] || fail "a refused run left a temporary file"
  ;;
overwrite_failed)
  for n in 1 2; do
    run "$n" "good$n" "${scene[@]}" -output "$work/a$n.h5"
    [ "$rc" -eq 0 ] || fail "the first run failed"
    cp "$work/a$n.h5" "$work/a$n.copy"
    # The blow-up monitor stops this run after planning: the earlier file must survive it.
    run "$n" "blowup$n" "${scene[@]}" -output "$work/a$n.h5" -output_overwrite -sbm_dt_check false -sbm_dt 1e-5
    refused "blowup$n" 1 "task \(point [0-9], realisation 0\) failed on rank [0-9]: the spring-block run (became )?unstable"
    cmp -s "$work/a$n.h5" "$work/a$n.copy" || fail "$n ranks: a failed run replaced the earlier result"
  done
  ;;
disk_full)
  # A disk that fills up while the results file is created (collective parallel-HDF5 writes on 2
  # ranks): a tmpfs of 1 MiB for a file of ~5 MB, or, where mounting is not permitted, a file-size
  # limit on the ranks (RLIMIT_FSIZE with SIGXFSZ ignored: write() fails with EFBIG).
  big=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 16 -ensemble_delta -0.3,-0.1,0,0.1,0.3
       -ensemble_realisations 3)
  mkdir -p "$work/full"
  if mount -t tmpfs -o size=1m tmpfs "$work/full" 2>/dev/null; then
    mounted="$work/full"
    echo "disk full: tmpfs of 1 MiB"
    run 2 full "${big[@]}" -output "$work/full/x.h5"
  else
    echo "disk full: RLIMIT_FSIZE of 1 MiB on the ranks"
    timeout 300 mpiexec --oversubscribe -n 2 bash -c 'trap "" XFSZ; ulimit -f 1024; exec "$0" "$@"' "$driver" \
      "${big[@]}" -output "$work/full/x.h5" >"$work/full.out" 2>"$work/full.err"
    rc=$?
    [ $rc -ne 124 ] || fail "disk full: no exit within 300 s (a hang)"
  fi
  written "disk full" full "writing .*full/x.h5.partial failed on rank [01]: .*(No space left on device|File too large)"
  [ ! -e "$work/full/x.h5" ] && [ ! -e "$work/full/x.h5.partial" ] || fail "disk full: a file was left"
  ;;
resume_disk_full)
  # An interrupted run's .partial on a disk that is full when the run is resumed: the resumed run
  # needs room for /run's attributes. Exit 1 on every rank (no hang: the ranks used to wait in
  # H5Fflush, one in MPI_Barrier, the other in MPI_Bcast), the .partial byte for byte as it was.
  small=(-sbm_N 8 -ensemble_realisations 4 -ensemble_history false -friction_observables mu_s)
  mkdir -p "$work/full"
  if mount -t tmpfs -o size=2m tmpfs "$work/full" 2>/dev/null; then
    mounted="$work/full"
    run 2 cut "${small[@]}" -ensemble_abort_after 2 -output "$work/full/res.h5"
    [ -f "$work/full/res.h5.partial" ] || fail "resume disk full: no .partial to resume"
    dd if=/dev/zero of="$work/full/filler" bs=4k 2>/dev/null  # the disk is full now
    cp "$work/full/res.h5.partial" "$work/before.partial"
    run 2 full "${small[@]}" -resume -output "$work/full/res.h5"
  else
    echo "resume disk full: RLIMIT_FSIZE at the size of the .partial on the ranks"
    run 2 cut "${small[@]}" -ensemble_abort_after 2 -output "$work/full/res.h5"
    cp "$work/full/res.h5.partial" "$work/before.partial"
    kib=$(( $(stat -c %s "$work/full/res.h5.partial") / 1024 + 1 ))
    timeout 300 mpiexec --oversubscribe -n 2 bash -c 'trap "" XFSZ; ulimit -f '"$kib"'; exec "$0" "$@"' "$driver" \
      "${small[@]}" -resume -output "$work/full/res.h5" >"$work/full.out" 2>"$work/full.err"
    rc=$?
    [ $rc -ne 124 ] || fail "resume disk full: no exit within 300 s (a hang)"
  fi
  written "resume disk full" full "writing .*full/res.h5.partial failed on rank 0: no room for [0-9]+ more bytes: (No space left on device|File too large) \\(the file is unchanged\\); its finished tasks are kept: continue with -resume once there is room"
  cmp -s "$work/full/res.h5.partial" "$work/before.partial" || fail "resume disk full: the .partial was changed"
  [ ! -e "$work/full/res.h5" ] || fail "resume disk full: a final file was written"
  ;;
interrupt)
  # SIGTERM to mpiexec (as Ctrl-C or a scheduler sends): one line naming the tasks the .partial
  # keeps and the option to continue; resumed, the file is the uninterrupted run's.
  # 20 tasks of ~0.5 s each (more under load): the signal comes after the second.
  slow=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 120 -ensemble_delta -0.3,-0.1,0,0.1,0.3
        -ensemble_realisations 4 -ensemble_monitor)
  run 2 whole "${slow[@]}" -output "$work/whole.h5"
  [ "$rc" -eq 0 ] || fail "interrupt: the uninterrupted run failed"
  # --foreground: timeout passes our SIGTERM to mpiexec alone, once (a second one makes mpiexec
  # kill the ranks at once, before their handlers run).
  timeout --foreground 300 mpiexec --oversubscribe -n 2 "$driver" "${slow[@]}" -output "$work/cut.h5" \
    >"$work/cut.out" 2>"$work/cut.err" &
  launcher=$!
  for _ in $(seq 1 600); do  # until two tasks are done
    sleep 0.05
    grep -q "^\[2/20\]" "$work/cut.out" 2>/dev/null && break
  done
  grep -q "^\[2/20\]" "$work/cut.out" || fail "interrupt: no task finished"
  kill -TERM "$launcher"
  wait "$launcher"
  rc=$?
  [ $rc -ne 124 ] || fail "interrupt: no exit within 300 s"
  [ $rc -ne 0 ] || fail "interrupt: exit status 0"
  [ "$(grep -c "^gradfric: interrupted" "$work/cut.err")" -eq 1 ] ||
    { cat "$work/cut.err" >&2; fail "interrupt: not one notice ($(grep -c '^\[' "$work/cut.out") tasks printed)"; }
  notice="^gradfric: interrupted \(SIGTERM\): ([0-9]+) of 20 tasks are finished and kept in .*cut.h5.partial; continue with the same command and -resume$"
  grep -Eq "$notice" "$work/cut.err" || { cat "$work/cut.err" >&2; fail "interrupt: the notice does not match"; }
  said=$(grep -E "$notice" "$work/cut.err" | sed -E "s/$notice/\\1/")
  kept=$(h5dump -A 0 -y -d /realisations/done "$work/cut.h5.partial" | sed -n '/DATA {/,/}/p' | grep -o '[01]' | grep -c 1 || true)
  [ "$said" -ge 2 ] && [ "$said" -le "$kept" ] || fail "interrupt: the notice says $said tasks, the file keeps $kept"
  [ "$kept" -lt 20 ] || fail "interrupt: the signal came too late to test anything"
  ! grep -q "MPI_ABORT" "$work/cut.err" || fail "interrupt: MPI_ABORT"
  [ ! -e "$work/cut.h5" ] || fail "interrupt: a final file was written"
  run 2 resume "${slow[@]}" -resume -output "$work/cut.h5"
  [ "$rc" -eq 0 ] || { cat "$work/resume.err" >&2; fail "interrupt: the resumed run failed"; }
  grep -q "$kept of 20 tasks already finished" "$work/resume.out" || fail "interrupt: resume did not keep $kept tasks"
  h5diff --exclude-path /run "$work/whole.h5" "$work/cut.h5" >"$work/diff.txt" 2>&1 ||
    { head -5 "$work/diff.txt" >&2; fail "interrupt: the resumed file differs from the uninterrupted one"; }
  if /usr/bin/python3 -c "import h5py" 2>/dev/null; then
    /usr/bin/python3 "$src/tests/ensemble/compare_bytes.py" "$work/whole.h5" "$work/cut.h5" ||
      fail "interrupt: the resumed file's bytes differ from the uninterrupted one's"
  else
    echo "note: no python3 with h5py: byte-level comparison skipped (h5diff comparison done)"
  fi
  ;;
resume_files)
  run 1 good "${scene[@]}" -output "$work/good.h5"
  [ "$rc" -eq 0 ] || fail "the first run failed"
  python=""
  for p in /usr/bin/python3 python3; do
    if command -v "$p" >/dev/null && "$p" -c "import h5py" 2>/dev/null; then python=$p; break; fi
  done
  echo "not a results file" >"$work/text.h5"
  head -c 3000 "$work/good.h5" >"$work/truncated.h5"
  cp "$work/good.h5" "$work/corrupt.h5"  # object headers overwritten with 0xff: HDF5 cannot read them
  head -c 2000 /dev/zero | tr '\0' '\377' | dd of="$work/corrupt.h5" bs=1 seek=800 conv=notrunc 2>/dev/null
  declare -A expect=(
    [text]="it is not an HDF5 file"
    [truncated]="it is truncated or damaged, HDF5 cannot open it \(truncated file"
    [corrupt]="it is (truncated or damaged, HDF5 cannot open it|damaged: )"
    [mismatch]="it was started with another scene .*-sbm_N: file 16, now 18"
  )
  cp "$work/good.h5" "$work/mismatch.h5"
  if [ -n "$python" ]; then
    "$python" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'w'); f['x'] = [1, 2, 3]" "$work/foreign.h5"
    "$python" -c "import h5py, sys; f = h5py.File(sys.argv[1], 'w'); f.attrs['format'] = 'other'" "$work/other.h5"
    expect[foreign]="it is not a gradfric ensemble results file \(no attribute format = gradfric-sbm-ensemble: a file of another program"
    expect[other]="not a gradfric ensemble results file"
  else
    echo "note: no python3 with h5py: foreign HDF5 files not checked"
  fi
  for name in "${!expect[@]}"; do
    extra=()
    [ "$name" = mismatch ] && extra=(-sbm_N 18)
    cp "$work/$name.h5" "$work/$name.before"
    for n in 1 2; do
      run "$n" "$name$n" "${scene[@]}" "${extra[@]}" -output "$work/$name.h5" -resume
      refused "$name$n" 2 "^gradfric: error: invalid option -resume \(continue .*$name.h5\): ${expect[$name]}"
      [ "$(wc -l <"$work/$name$n.err")" -lt 15 ] || fail "$name: more than one message (besides mpiexec's)"
    done
    cmp -s "$work/$name.h5" "$work/$name.before" || fail "$name: the refused file was changed"
  done
  # The same checks for an interrupted run's .partial.
  cp "$work/text.h5" "$work/cut.h5.partial"
  run 2 partial "${scene[@]}" -output "$work/cut.h5" -resume
  refused partial 2 "invalid option -resume \(continue .*cut.h5.partial\): it is not an HDF5 file"
  ;;
*)
  fail "unknown check $check"
  ;;
esac
echo "output check $check: passed"
