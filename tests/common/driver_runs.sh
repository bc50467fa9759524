# Sourced by the campaign tests (tests/fem/sweep.sh, ensemble.sh); needs $driver and fail().
# fem <name> <ranks> <expected exit> <options...>: runs the driver on that many ranks into
# <name>.out and <name>.err, fails on a hang (300 s) or another exit status.
fem() {
  local name=$1 ranks=$2 code=$3; shift 3
  timeout 300 mpiexec -n "$ranks" "$driver" "$@" >"$name.out" 2>"$name.err"
  local rc=$?
  [ $rc -ne 124 ] || fail "$name: no exit within 300 s (a hang)"
  [ $rc -eq "$code" ] || { tail -5 "$name.err" >&2; fail "$name: exit $rc, expected $code"; }
}
# same <a.h5> <b.h5>: the two results files are equal value for value apart from /run.
same() { h5diff --exclude-path /run "$1" "$2" >/dev/null || fail "$1 and $2 differ: $(h5diff --exclude-path /run "$1" "$2" | head -5)"; }
