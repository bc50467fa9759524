# Sourced by the refusal batteries. expect <ranks> <driver> <output option> <needle>... -- <args>...
# runs the driver on that many ranks and requires, before any work: exit 2, every needle in the
# message, one "gradfric: error:" line (or one per rank), and no results file "$out" or
# "$out.partial" left behind. Counts failures in $failures.
expect() {
  local ranks=$1 driver=$2 outopt=$3; shift 3
  local needles=()
  while [ "$1" != "--" ]; do needles+=("$1"); shift; done
  shift
  rm -f "$out" "$out.partial"
  local message status
  if [ "$ranks" = 1 ]; then
    message=$(timeout 120 "$driver" "$outopt" "$out" "$@" 2>&1 >/dev/null)
  else
    message=$(timeout 120 mpiexec -n "$ranks" "$driver" "$outopt" "$out" "$@" 2>&1 >/dev/null)
  fi
  status=$?
  if [ $status -ne 2 ]; then
    echo "FAIL ($*): exit $status, expected 2: $message"; failures=$((failures + 1)); return
  fi
  for needle in "${needles[@]}"; do
    if ! grep -qF -- "$needle" <<<"$message"; then
      echo "FAIL ($*): message lacks '$needle': $message"; failures=$((failures + 1)); return
    fi
  done
  local lines; lines=$(grep -c 'gradfric: error:' <<<"$message")
  if [ "$lines" -ne "$ranks" ] && [ "$lines" -ne 1 ]; then
    echo "FAIL ($*): not one error line: $message"; failures=$((failures + 1)); return
  fi
  if [ -e "$out" ] || [ -e "$out.partial" ]; then
    echo "FAIL ($*): left $out behind"; failures=$((failures + 1)); return
  fi
  echo "ok   ($*): $(head -1 <<<"$message")"
}
