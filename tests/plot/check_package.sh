#!/usr/bin/env bash
# python/ as an installable package: the offline install docs/running.md gives, into a fresh
# virtual environment that uses Debian's h5py, numpy and xarray, then `import gradfric` in that
# venv must load the installed copy (not the checkout), at the project's version, with nothing
# written into the checkout.
#   check_package.sh <source dir> <work dir> <project version>
set -euo pipefail
src=$1 work=$2 version=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
venv=$work/venv
rm -rf "$venv" && mkdir -p "$work"
/usr/bin/python3 -m venv --system-site-packages "$venv"
# The one command of docs/running.md, from the checkout's top level. No PYTHONPATH: it would put the
# checkout ahead of the venv.
unset PYTHONPATH
(cd "$src" && "$venv/bin/python3" -m pip install --no-deps --no-build-isolation ./python) > "$work/pip.log" 2>&1 ||
  { cat "$work/pip.log" >&2; fail "pip install --no-deps --no-build-isolation ./python failed"; }
for left in build gradfric.egg-info; do
  [ ! -e "$src/python/$left" ] || fail "the install wrote $src/python/$left into the checkout"
done
# From a neutral folder (python -c puts the working folder first on sys.path).
cd "$work"
"$venv/bin/python3" - "$venv" "$src" "$version" <<'PY'
import importlib.metadata
import os
import sys

venv, src, version = os.path.realpath(sys.argv[1]), os.path.realpath(sys.argv[2]), sys.argv[3]
import gradfric

where = os.path.realpath(gradfric.__file__)
assert where.startswith(venv + os.sep), f"gradfric imported from {where}, not from the venv {venv}"
assert not where.startswith(os.path.join(src, "python") + os.sep), f"gradfric imported from the checkout: {where}"
assert gradfric.__version__ == version, f"gradfric.__version__ {gradfric.__version__} != project VERSION {version}"
assert importlib.metadata.version("gradfric") == version, importlib.metadata.version("gradfric")
assert callable(gradfric.open) and callable(gradfric.run) and issubclass(gradfric.RunError, RuntimeError)
# Debian's packages, not copies in the venv.
import h5py, numpy, xarray  # noqa: E401
for module in (h5py, numpy, xarray):
    assert not os.path.realpath(module.__file__).startswith(venv + os.sep), module.__file__
print(f"installed gradfric {version} imported from {where}")
PY
echo "gradfric package checks passed"
