#!/usr/bin/env bash
# scripts/setup.sh leaves no global path into a checkout: after it ran (here on a fresh build folder,
# building only the `help` target: nothing is compiled), no site folder of the system's python3
# (nor of the python3 on PATH) holds a gradfric.pth or any .pth naming a folder with a gradfric
# package, a stale gradfric.pth planted before (as an earlier setup.sh wrote) is gone, and python3
# without PYTHONPATH does not import the checkout.
#   check_setup_pth.sh <source dir> <work dir>
set -euo pipefail
src=$1 work=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
unset PYTHONPATH
mkdir -p "$work"
cd "$work"
pythons=(/usr/bin/python3)
on_path=$(command -v python3 || true)
[ -n "$on_path" ] && [ "$(realpath "$on_path")" != "$(realpath /usr/bin/python3)" ] && pythons+=("$on_path")
user_site=$(/usr/bin/python3 -c 'import site; print(site.getusersitepackages())')
planted=$user_site/gradfric.pth
mkdir -p "$user_site"
trap 'rm -f "$planted"' EXIT
echo "/nonexistent/gradfric-checkout/python" > "$planted"

bash "$src/scripts/setup.sh" --target help "$work/setup_build" > "$work/setup.log" 2>&1 ||
  { tail -20 "$work/setup.log" >&2; fail "scripts/setup.sh failed"; }

for python in "${pythons[@]}"; do
  "$python" - "$src" <<'PY' || fail "$python: a global path into a checkout"
import glob
import os
import site
import sys

src = os.path.realpath(sys.argv[1])
folders = [f for f in site.getsitepackages() + [site.getusersitepackages()] if os.path.isdir(f)]
found = []
for folder in folders:
    for pth in glob.glob(os.path.join(folder, "*.pth")):
        if os.path.basename(pth) == "gradfric.pth":
            found.append(pth)
            continue
        with open(pth, errors="replace") as text:
            for line in text:
                line = line.strip()
                if line and not line.startswith(("#", "import")) and os.path.isfile(os.path.join(line, "gradfric", "__init__.py")):
                    found.append(f"{pth} -> {line}")
assert not found, f"{sys.executable}: {found}"
try:
    import gradfric
except ImportError:
    where = None
else:
    where = os.path.realpath(gradfric.__file__)
assert where is None or not where.startswith(src + os.sep), f"{sys.executable} imports the checkout: {where}"
print(f"{sys.executable}: no gradfric.pth in {', '.join(folders)}; import gradfric -> {where}")
PY
done
echo "no global gradfric.pth"
