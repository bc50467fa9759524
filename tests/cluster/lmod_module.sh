#!/usr/bin/env bash
# Installs the build into a temporary prefix and uses the installed Lmod modulefile with the real
# Lmod (Debian's package `lmod`; scripts/setup.sh --tests installs it), in a clean shell that has no
# path into the build tree: `module use P/share/modulefiles`, `module load gradfric`, the drivers,
# a small scene of the installed tree and the Python reader come from P; `module help`/`whatis`
# work; `module unload` takes it all away again.
#   lmod_module.sh <build-dir> <work-dir> [<modulefile-dir under the prefix> [<version>]]
set -euo pipefail
build=$1
work=$2
module_dir=${3:-share/modulefiles}
version=${4:-0.1.0}
prefix=$work/prefix
rm -rf "$prefix" "$work/run"
mkdir -p "$work/run"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"

fail() { echo "FAIL: $*" >&2; exit 1; }
modulefile=$prefix/$module_dir/gradfric/$version.lua
[ -r "$modulefile" ] || fail "cmake --install wrote no modulefile $modulefile"

# Lmod's shell set-up: the one of a running Lmod (LMOD_PKG), else Debian's.
init=""
for candidate in "${LMOD_PKG:+$LMOD_PKG/init/bash}" /usr/share/lmod/lmod/init/bash; do
  if [ -n "$candidate" ] && [ -r "$candidate" ]; then init=$candidate; break; fi
done
if [ -z "$init" ] && command -v dpkg > /dev/null; then
  init=$(dpkg -L lmod 2>/dev/null | grep -m1 '/init/bash$' || true)
fi
[ -n "$init" ] && [ -r "$init" ] || fail "Lmod not found (apt-get install lmod; scripts/setup.sh --tests installs it)"

# A clean login-like shell: no PATH, PYTHONPATH or module state inherited from the build.
env -i HOME="$work" TMPDIR="${TMPDIR:-/tmp}" PATH=/usr/local/bin:/usr/bin:/bin LANG=C.UTF-8 \
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    INIT="$init" PREFIX="$prefix" MODULES="$prefix/$module_dir" VERSION="$version" RUN="$work/run" \
    bash --noprofile --norc -c '
set -uo pipefail
fail() { echo "FAIL: $*" >&2; exit 1; }
. "$INIT" || fail "sourcing $INIT failed"
type module > /dev/null 2>&1 || fail "$INIT defined no module command"
command -v gradfric > /dev/null && fail "gradfric is on PATH before module load: $(command -v gradfric)"

module use "$MODULES"
avail=$(module -t avail gradfric 2>&1)
grep -q "^gradfric/$VERSION" <<< "$avail" || fail "module avail does not list gradfric/$VERSION: $avail"
whatis=$(module whatis gradfric 2>&1)
grep -q "Version: $VERSION" <<< "$whatis" && grep -q "Description: " <<< "$whatis" ||
  fail "module whatis gradfric: $whatis"
help=$(module help gradfric 2>&1)
grep -q "GRADFRIC_DATA" <<< "$help" && grep -qF "Installed in: $PREFIX" <<< "$help" ||
  fail "module help gradfric: $help"

# In this shell, not in $(...): module changes the environment of the shell it runs in.
module load gradfric 2> "$RUN/load.log" || fail "module load gradfric: $(cat "$RUN/load.log")"
[ ! -s "$RUN/load.log" ] || fail "module load gradfric printed: $(cat "$RUN/load.log")"
module -t list 2>&1 | grep -q "^gradfric/$VERSION" || fail "gradfric/$VERSION not in module list after load"
[ "$(command -v gradfric)" = "$PREFIX/bin/gradfric" ] || fail "gradfric resolves to $(command -v gradfric || echo nothing), not $PREFIX/bin/gradfric"
[ "$(command -v gradfric-fem)" = "$PREFIX/bin/gradfric-fem" ] || fail "gradfric-fem resolves to $(command -v gradfric-fem || echo nothing)"
[ "${GRADFRIC_ROOT:-}" = "$PREFIX" ] || fail "GRADFRIC_ROOT=${GRADFRIC_ROOT:-unset}, expected $PREFIX"
[ "${GRADFRIC_DATA:-}" = "$PREFIX/share/gradfric" ] || fail "GRADFRIC_DATA=${GRADFRIC_DATA:-unset}"
py=$(cd "$RUN" && python3 -c "import gradfric; print(gradfric.__file__)" 2>&1) || fail "import gradfric: $py"
[ "$py" = "$PREFIX/share/gradfric/python/gradfric/__init__.py" ] || fail "import gradfric resolves to $py"

# A scene of the installed tree, shrunk to seconds: 8 x 8 blocks, one realisation per point.
cd "$RUN"
out=$(gradfric -options_file "$GRADFRIC_DATA/input/default.opts" -sbm_N 8 -ensemble_realisations 1 \
      -plot false -output "$RUN/default.h5" 2>&1) || fail "installed gradfric on the installed default scene: $out"
grep -q "Global static friction mu_s" <<< "$out" && grep -qF "results in $RUN/default.h5" <<< "$out" ||
  fail "gradfric printed no result: $out"
[ -s "$RUN/default.h5" ] || fail "gradfric wrote no results file $RUN/default.h5"
format=$(python3 -c "import gradfric, sys; print(gradfric.open(sys.argv[1]).attrs[\"format\"])" "$RUN/default.h5" 2>&1) ||
  fail "the installed reader cannot open the results: $format"
[ "$format" = "gradfric-sbm-ensemble" ] || fail "the installed reader reads format $format"

module unload gradfric
command -v gradfric > /dev/null && fail "gradfric still on PATH after module unload: $(command -v gradfric)"
[ -z "${GRADFRIC_ROOT:-}" ] || fail "GRADFRIC_ROOT still set after module unload"
case ":${PYTHONPATH:-}:" in *"$PREFIX"*) fail "PYTHONPATH keeps $PREFIX after module unload";; esac
echo "lmod: load, run, unload OK"
' || fail "in the Lmod shell (above)"
echo "lmod module OK: $modulefile"
