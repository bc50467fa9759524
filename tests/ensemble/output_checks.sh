#!/usr/bin/env bash
# The results file of the gradfric driver is planned before any work and replaced only on success;
# a refusal or an I/O failure ends every rank with one message and a non-zero exit, never a hang;
# a bad file given to -resume gets one line saying what is wrong with it (exit 2).
#   output_checks.sh <driver> <source-dir> <check>
# checks: refuse_output, overwrite_failed, disk_full, resume_files. Each runs on 1 and 2 ranks
# where a rank count matters (refusals decided on rank 0, collective writes).
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
  [ "$rc" -ne 0 ] || fail "disk full: exit status 0"
  lines=$(grep -c "^gradfric: error:" "$work/full.err")
  [ "$lines" -eq 1 ] || { cat "$work/full.err" >&2; fail "disk full: $lines error lines, expected one"; }
  grep -q "^gradfric: error: writing .*full/x.h5.partial failed on rank [01]" "$work/full.err" ||
    { cat "$work/full.err" >&2; fail "disk full: the message does not name the file"; }
  ! grep -q "HDF5-DIAG" "$work/full.err" || fail "disk full: HDF5 error stack printed"
  [ ! -e "$work/full/x.h5" ] || fail "disk full: a final file was written"
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
