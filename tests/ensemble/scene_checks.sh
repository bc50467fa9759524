#!/usr/bin/env bash
# End-to-end checks of the spring-block ensemble through the gradfric driver.
#   scene_checks.sh <driver> <source-dir> <check>
# checks: determinism, kill_resume, refuse, resume_mismatch, single, help, scenes
# (refuse: also stray words and empty list items; single: the reference point's printout)
# Each check fails (exit 1) if what it guards is wrong. Results files are compared with h5diff,
# excluding /run (wall times, which rank ran which task, run-control options): everything else,
# every attribute and dataset, must be equal value for value.
set -euo pipefail
driver=$1
src=$2
check=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d "$PWD/ensemble_${check}_XXXXXX")
trap 'rm -rf "$work"' EXIT
run() {  # run <ranks> <args...>
  local n=$1
  shift
  mpiexec --oversubscribe -n "$n" "$driver" "$@"
}
fail() {
  echo "FAILED: $*" >&2
  exit 1
}
same() {  # same <a.h5> <b.h5>: identical apart from /run
  h5diff --exclude-path /run "$1" "$2" >"$work/diff.txt" 2>&1 || {
    head -20 "$work/diff.txt" >&2
    fail "$1 and $2 differ"
  }
}
# The reduced Figure 4 scene on a smaller lattice (test time); 5 x 3 = 15 tasks.
scene=(-options_file "$src/input/sbm_fig4_reduced.opts" -sbm_N 16 -ensemble_delta -0.3,-0.1,0,0.1,0.3
       -ensemble_realisations 3 -ensemble_monitor)

case "$check" in
determinism)
  for n in 1 2 3; do
    run "$n" "${scene[@]}" -output "$work/np$n.h5" >"$work/np$n.log"
    [ -f "$work/np$n.h5" ] || fail "no results file from $n ranks"
    [ ! -e "$work/np$n.h5.partial" ] || fail "temporary file left behind"
  done
  grep -q "\[15/15\]" "$work/np2.log" || fail "no progress line for the last task"
  same "$work/np1.h5" "$work/np2.h5"
  same "$work/np1.h5" "$work/np3.h5"
  # Who ran what did change (so the comparison above is not vacuous) ...
  h5dump -A 0 -y -d /run/rank "$work/np2.h5" | sed -n '/DATA {/,/}/p' | grep -Eq '(^|[ ,])1(,|$)' ||
    fail "rank 1 ran no task on 2 ranks"
  # ... and h5diff does see a different realisation set: another seed must differ.
  run 2 "${scene[@]}" -ensemble_seed 99 -output "$work/seed.h5" >/dev/null
  if h5diff --exclude-path /run "$work/np1.h5" "$work/seed.h5" >/dev/null 2>&1; then
    fail "a different seed gave the same file"
  fi
  # Byte for byte (NaN payloads, signed zeros), where h5py is available (scripts/setup.sh installs it).
  python=""
  for p in python3 /usr/bin/python3; do
    if command -v "$p" >/dev/null && "$p" -c "import h5py" 2>/dev/null; then python=$p; break; fi
  done
  if [ -n "$python" ]; then
    for n in 2 3; do
      "$python" "$src/tests/ensemble/compare_bytes.py" "$work/np1.h5" "$work/np$n.h5" || fail "np1 and np$n bytes differ"
    done
    if "$python" "$src/tests/ensemble/compare_bytes.py" "$work/np1.h5" "$work/seed.h5" >/dev/null; then
      fail "byte comparison blind to another seed"
    fi
  else
    echo "note: no python3 with h5py: byte-level comparison skipped (h5diff comparison done)"
  fi
  # The static schedule gives the same file too.
  run 2 "${scene[@]}" -ensemble_schedule static -output "$work/static.h5" >/dev/null
  same "$work/np1.h5" "$work/static.h5"
  ;;
kill_resume)
  run 2 "${scene[@]}" -output "$work/full.h5" >"$work/full.log"
  # Every rank exits abruptly (no file close, no MPI_Finalize) once 3 tasks have finished.
  if run 2 "${scene[@]}" -ensemble_abort_after 3 -output "$work/cut.h5" >"$work/cut.log" 2>&1; then
    fail "the interrupted run reported success"
  fi
  [ ! -e "$work/cut.h5" ] || fail "an interrupted run left a file under the final name"
  [ -f "$work/cut.h5.partial" ] || fail "no .partial file after the interruption"
  # The partial file is readable HDF5 and keeps the finished tasks.
  done_count=$(h5dump -A 0 -y -d /realisations/done "$work/cut.h5.partial" | sed -n '/DATA {/,/}/p' | grep -o '[01]' | grep -c 1 || true)
  [ "$done_count" -ge 3 ] || fail "only $done_count finished tasks kept after the interruption"
  [ "$done_count" -le 4 ] || fail "the interruption came too late to test anything ($done_count tasks)"
  h5dump -a /complete "$work/cut.h5.partial" | grep -q "(0): 0" || fail "interrupted file not marked incomplete"
  # Without -resume the interrupted run is not overwritten by accident.
  if run 1 "${scene[@]}" -output "$work/cut.h5" >"$work/refused.log" 2>&1; then fail "started over an interrupted run"; fi
  grep -q -- "-resume" "$work/refused.log" || fail "no hint to -resume"
  run 2 "${scene[@]}" -resume -output "$work/cut.h5" >"$work/resume.log"
  grep -q "$done_count of 15 tasks already finished" "$work/resume.log" || fail "resume did not skip the finished tasks"
  [ ! -e "$work/cut.h5.partial" ] || fail "the .partial file was not renamed"
  same "$work/full.h5" "$work/cut.h5"
  # A real kill: SIGKILL to every rank in the middle of the run. A larger lattice makes the tasks
  # slow enough (about 0.3 s each, 15 on 2 ranks) that the run is still going when the poll below
  # sees its first finished task; at 40 x 40 the whole run could end between two polls under load.
  # Twice the realisations (30 tasks): at load 6 one run of 15 ended before the kill landed.
  big=("${scene[@]}" -sbm_N 96 -ensemble_realisations 6)
  big_tasks=30
  run 2 "${big[@]}" -output "$work/bigfull.h5" >/dev/null
  # On a heavily loaded machine the run can still end before the poll sees a finished task (the
  # poll's h5dump competes for the cores): then it is started again, up to three times.
  killed_run=false
  for attempt in 1 2 3; do
    rm -f "$work/killed.h5.partial"
    mpiexec --oversubscribe -n 2 "$driver" "${big[@]}" -output "$work/killed.h5" >"$work/killed.log" 2>&1 &
    launcher=$!
    finished=0
    for _ in $(seq 1 300); do  # wait until at least one task is in the file
      sleep 0.05
      if [ -f "$work/killed.h5.partial" ]; then
        finished=$(h5dump -A 0 -y -d /realisations/done "$work/killed.h5.partial" 2>/dev/null |
          sed -n '/DATA {/,/}/p' | grep -o '[01]' | grep -c 1 || true)
        [ "$finished" -ge 1 ] && break
      fi
    done
    ranks=$(pgrep -P "$launcher" || true)
    if [ -n "$ranks" ]; then
      kill -KILL $ranks
      wait "$launcher" && fail "the killed run reported success" || true
      killed_run=true
      break
    fi
    wait "$launcher" || true
    echo "attempt $attempt: the run ended before the kill; starting it again" >&2
    rm -f "$work/killed.h5"
  done
  $killed_run || fail "the run to kill had already ended, three times"
  [ -f "$work/killed.h5.partial" ] || fail "no .partial file after SIGKILL"
  kept=$(h5dump -A 0 -y -d /realisations/done "$work/killed.h5.partial" | sed -n '/DATA {/,/}/p' | grep -o '[01]' | grep -c 1 || true)
  [ "$kept" -ge "$finished" ] || fail "SIGKILL lost finished tasks ($kept < $finished)"
  [ "$kept" -lt "$big_tasks" ] || fail "the kill came too late to test anything"
  run 2 "${big[@]}" -resume -output "$work/killed.h5" >"$work/killed_resume.log"
  grep -q "$kept of $big_tasks tasks already finished" "$work/killed_resume.log" || fail "resume after SIGKILL did not skip $kept tasks"
  same "$work/bigfull.h5" "$work/killed.h5"
  # Resuming a finished file runs nothing and keeps it equal.
  run 1 "${scene[@]}" -resume -output "$work/cut.h5" >"$work/again.log"
  grep -q "15 of 15 tasks already finished" "$work/again.log" || fail "a finished file was run again"
  same "$work/full.h5" "$work/cut.h5"
  ;;
refuse)
  run 1 "${scene[@]}" -ensemble_realisations 1 -output "$work/a.h5" >/dev/null
  cp "$work/a.h5" "$work/a.copy"
  if run 1 "${scene[@]}" -ensemble_realisations 1 -output "$work/a.h5" >"$work/b.log" 2>&1; then
    fail "an existing results file was overwritten"
  fi
  grep -q "output_overwrite" "$work/b.log" || fail "no hint to -output_overwrite"
  cmp -s "$work/a.h5" "$work/a.copy" || fail "the refused run modified the existing file"
  run 1 "${scene[@]}" -ensemble_realisations 1 -output "$work/a.h5" -output_overwrite >/dev/null
  if run 1 "${scene[@]}" -output "$work/no/such/folder/x.h5" >"$work/c.log" 2>&1; then fail "wrote into a missing folder"; fi
  grep -q "writable folder" "$work/c.log" || fail "no message about the output folder"
  if run 1 "${scene[@]}" -ensemble_delta 0,1.2 -output "$work/d.h5" >"$work/d.log" 2>&1; then fail "|Delta| >= 1 accepted"; fi
  grep -q "ensemble_delta" "$work/d.log" || fail "the bad option is not named"
  if run 1 -grading_profile none -ensemble_delta 0,0.2 -output "$work/e.h5" >"$work/e.log" 2>&1; then
    fail "a Delta sweep without a grading profile accepted"
  fi
  if run 1 "${scene[@]}" -ensemble_realisatons 2 -output "$work/f.h5" >"$work/f.log" 2>&1; then fail "misspelt option accepted"; fi
  [ ! -e "$work/f.h5" ] && [ ! -e "$work/f.h5.partial" ] || fail "a refused run wrote a file"
  # Stray words, empty list items, the old spellings: exit 2 from both ranks, one line naming the
  # option, nothing written.
  printf -- '-ensemble_theta 0 90\n' >"$work/stray.opts"
  refused=0
  while IFS='|' read -r needle args; do
    status=0
    # shellcheck disable=SC2086  # the arguments are words
    run 2 "${scene[@]}" $args -output "$work/g.h5" </dev/null >"$work/g.log" 2>&1 || status=$?  # mpiexec would read the cases
    [ "$status" = 2 ] || fail "$args: exit $status, expected 2"
    grep -qF -- "$needle" "$work/g.log" || fail "$args: message lacks '$needle': $(cat "$work/g.log")"
    [ "$(grep -c "gradfric: error:" "$work/g.log")" = 1 ] || fail "$args: not one error line"
    [ ! -e "$work/g.h5" ] && [ ! -e "$work/g.h5.partial" ] || fail "$args: a refused run wrote a file"
    refused=$((refused + 1))
  done <<CASES
invalid option -ensemble_delta = 0 0.2: allowed one value|-ensemble_delta 0 0.2
invalid option -ensemble_delta = 0.1,,0.2: allowed a comma-separated list|-ensemble_delta 0.1,,0.2
invalid option -ensemble_theta = 0 90 (in $work/stray.opts line 1)|-options_file $work/stray.opts
invalid option -ensemble_resume: renamed|-ensemble_resume
CASES
  [ "$refused" = 4 ] || fail "only $refused refusal cases ran"
  ;;
resume_mismatch)
  run 1 "${scene[@]}" -ensemble_realisations 1 -ensemble_abort_after 1 -output "$work/m.h5" >/dev/null 2>&1 || true
  [ -f "$work/m.h5.partial" ] || fail "no partial file to resume"
  if run 1 "${scene[@]}" -ensemble_realisations 1 -sbm_N 18 -resume -output "$work/m.h5" >"$work/m.log" 2>&1; then
    fail "resumed with a different lattice"
  fi
  grep -q "sbm_N: file 16, now 18" "$work/m.log" || fail "the differing option is not named"
  # A file of a build before an observable was added (its dataset removed here) is refused with
  # the dataset named (exit 2), not read as damaged.
  /usr/bin/python3 -c 'import h5py, sys; del h5py.File(sys.argv[1], "r+")["realisations/detachment_time"]' "$work/m.h5.partial"
  status=0
  run 1 "${scene[@]}" -ensemble_realisations 1 -resume -output "$work/m.h5" >"$work/old.log" 2>&1 || status=$?
  [ "$status" = 2 ] || fail "a file without /realisations/detachment_time: exit $status, not 2"
  grep -q "it has no /realisations/detachment_time: it was written by an earlier gradfric" "$work/old.log" ||
    fail "the missing observable is not named: $(tail -3 "$work/old.log")"
  ;;
single)
  run 1 -sbm_N 16 -output "$work/s.h5" >"$work/s.log"
  grep -Eq "^Result: mu_s = 0\.[0-9]+, mu_k = 0\.[0-9]+" "$work/s.log" || fail "no 'mu_s = ..., mu_k = ...' line"
  grep -q "results in $work/s.h5" "$work/s.log" || fail "where the results went is not printed"
  # Its discretisation bar: N_b = 16 is in no ladder of the lattice study: NaN stored, "not measured"
  # with the reason, and the printed line is the stored basis.
  basis=$(/usr/bin/python3 -c '
import math, sys, h5py
e = h5py.File(sys.argv[1], "r")["statistics/mu_s_discretisation_error"]
assert math.isnan(e[0]) and e.attrs["basis"].startswith("not measured: mesh 16 "), (e[0], e.attrs["basis"])
print(e.attrs["basis"])' "$work/s.h5") || fail "the single run's stored discretisation bar: $basis"
  grep -qxF "  mu_s: discretisation $basis" "$work/s.log" || fail "no discretisation line for the single run"
  # The printed mu_s is the one in the file.
  printed=$(sed -n 's/^Result: mu_s = \([0-9.]*\),.*/\1/p' "$work/s.log")
  stored=$(h5dump -A 0 -m %.6f -d /statistics/mu_s_mean "$work/s.h5" | sed -n 's/.*(0): \([0-9.]*\).*/\1/p')
  [ "$printed" = "$stored" ] || fail "printed mu_s $printed, file $stored"
  # More ranks than tasks: two of three ranks find nothing to do; same file.
  run 3 -sbm_N 16 -output "$work/s3.h5" >"$work/s3.log"
  grep -q "^Result: mu_s = $printed," "$work/s3.log" || fail "3 ranks printed another mu_s"
  same "$work/s.h5" "$work/s3.h5"
  # No sweep, several realisations: the one point is its own reference, printed as such (not as
  # +0.000 +- 0.000); the file says so with reference_point = 0 (and variation 0). A graded point
  # alone has none: "(no reference)", reference_point = -1, NaN.
  run 1 -sbm_N 12 -ensemble_realisations 2 -output "$work/r.h5" >"$work/r.log"
  grep -Eq "^  0 +single point .* reference +(n/m|\+- [0-9.]+)$" "$work/r.log" || fail "the reference point is not printed as such: $(grep -A2 "^Global" "$work/r.log")"
  ! grep -qF "+0.000 +- 0.000" "$work/r.log" || fail "a relative variation printed for the reference itself"
  run 1 -sbm_N 12 -ensemble_realisations 2 -grading_profile linear -grading_delta 0.2 -output "$work/g.h5" >"$work/g.log"
  grep -Eq "^  0 +single point .* \(no reference\) +(n/m|\+- [0-9.]+)$" "$work/g.log" || fail "no '(no reference)' for a graded point alone"
  for pair in "r.h5 0 0" "g.h5 -1 nan"; do
    read -r name reference relative <<<"$pair"
    ref=$(h5dump -A 0 -d /sweep/reference_point "$work/$name" | sed -n 's/.*(0): \(-*[0-9]*\).*/\1/p')
    rel=$(h5dump -A 0 -d /statistics/mu_s_relative "$work/$name" | sed -n 's/.*(0): \([-a-zA-Z0-9.]*\).*/\1/p' | tr 'A-Z' 'a-z')
    [ "$ref" = "$reference" ] || fail "$name: reference_point $ref, expected $reference"
    [ "$rel" = "$relative" ] || fail "$name: mu_s_relative $rel, expected $relative"
  done
  ;;
help)
  run 1 -help -output "$work/h.h5" >"$work/h.log" 2>&1
  grep -q -- "-ensemble_delta" "$work/h.log" || fail "-help does not list -ensemble_delta"
  grep -q -- "-sbm_N" "$work/h.log" || fail "-help does not list -sbm_N"
  # The observables measured with mu_s, named from the table (physics/observables.hpp).
  grep -q -- "-friction_observables .*peak_time, detachment_time.* come with mu_s" "$work/h.log" ||
    fail "-help does not name the observables that come with mu_s"
  [ ! -e "$work/h.h5" ] && [ ! -e "$work/h.h5.partial" ] || fail "-help ran the scene"
  # -help <prefix>: that prefix's options alone; none listed twice.
  run 1 -help ensemble >"$work/he.log" 2>&1
  grep -q -- "^  -ensemble_delta" "$work/he.log" || fail "-help ensemble does not list -ensemble_delta"
  ! grep -q -- "^  -sbm_N" "$work/he.log" || fail "-help ensemble lists -sbm_N"
  [ -z "$(grep "^  -" "$work/h.log" | awk '{print $1}' | sort | uniq -d)" ] || fail "-help lists an option twice"
  ;;
scenes)
  # Every SBM scene of input/ is valid: read and checked in full (-ensemble_dry_run: no work).
  count=0
  for f in "$src"/input/sbm_*.opts; do
    run 1 -options_file "$f" -ensemble_dry_run -output "$work/dry.h5" >"$work/dry.log" 2>&1 ||
      { cat "$work/dry.log" >&2; fail "scene $f refused"; }
    grep -q "Dry run" "$work/dry.log" || fail "scene $f: no dry-run line"
    ! grep -q "WARNING" "$work/dry.log" || fail "scene $f: unused options"
    count=$((count + 1))
  done
  [ "$count" -ge 20 ] || fail "only $count SBM scenes in input/"
  for fig in 2 4 5 6 7 8 9 10 11 12; do
    [ -f "$src/input/sbm_fig${fig}.opts" ] && [ -f "$src/input/sbm_fig${fig}_reduced.opts" ] ||
      fail "scene of Figure $fig missing"
  done
  ;;
*)
  fail "unknown check $check"
  ;;
esac
echo "ensemble check $check: passed"
