#!/usr/bin/env bash
# Installs what gradfric needs from Debian's packages (only what is missing) and builds it.
# Usage: scripts/setup.sh [--tests] [--target NAME] [build-dir]   (default: build)
#   --tests        also installs what only the test suite needs: ParaView (pvbatch) with Xvfb to
#                  check and render the FEM's .xmf headless, xarray + h5netcdf to read the results
#                  files the way users do, Lmod to load the installed modulefile, and Slurm
#                  (slurmctld, slurmd, slurm-client) with munge to run slurm/ on a one-node local
#                  cluster (scripts/slurm_local_cluster.sh) (about 150 MB to download, 800 MB
#                  installed, ~2-3 min).
#   --target NAME  builds only that CMake target and what it links (run-default.sh: gradfric_driver,
#                  the driver `gradfric`); by default everything: drivers, tests and benchmarks.
# Environment: GRADFRIC_NATIVE=ON builds with -march=native (faster, not portable across nodes).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
with_tests=0
target=()
while [ $# -gt 0 ]; do
  case $1 in
    --tests) with_tests=1; shift ;;
    --target) [ $# -ge 2 ] || { echo "gradfric setup: --target needs a target name" >&2; exit 2; }
              target=(--target "$2"); shift 2 ;;
    *) break ;;
  esac
done
build=${1:-$here/build}

packages=(build-essential cmake pkg-config petsc-dev openmpi-bin libopenmpi-dev libhdf5-openmpi-dev
          libmetis-dev librandom123-dev libyaml-dev libpng-dev googletest libgtest-dev libbenchmark-dev
          python3 python3-h5py python3-matplotlib python3-numpy hdf5-tools
          python3-setuptools python3-pip python3-venv)
test_packages=(paraview python3-paraview xvfb xauth python3-xarray python3-h5netcdf lmod
               slurmctld slurmd slurm-client munge)
[ "$with_tests" = 1 ] && packages+=("${test_packages[@]}")
# python/gradfric (gradfric.open, used by the plotting scripts) returns xarray Datasets;
# python3-setuptools, -pip, -venv install it offline (pip install --no-deps --no-build-isolation ./python).
packages+=(python3-xarray)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "gradfric setup: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then echo "gradfric setup: run as root (or install: ${missing[*]})" >&2; exit 1; fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# python/gradfric is not put on any global path: the repository's scripts and tests find the
# checkout's python/ themselves; a user installs it into a virtual environment or a prefix
# (docs/running.md, "Reading results in Python"). A gradfric.pth an earlier setup.sh wrote into a
# site folder (pointing `import gradfric` of every python3 at one checkout) is removed.
/usr/bin/python3 - <<'PY'
import os, site
for folder in site.getsitepackages() + [site.getusersitepackages()]:
    stale = os.path.join(folder, "gradfric.pth")
    if os.path.isfile(stale):
        try:
            os.remove(stale)
            print(f"gradfric setup: removed {stale} (a global path into one checkout)")
        except OSError as e:
            print(f"gradfric setup: cannot remove {stale} ({e.strerror}): remove it to stop python3 importing that checkout")
PY
PYTHONPATH="$here/python" /usr/bin/python3 -c 'import gradfric' ||
  { echo "gradfric setup: python3 cannot import this checkout's python/gradfric (h5py, numpy, xarray?)" >&2; exit 1; }

# Open MPI refuses to run as root without these; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# GRADFRIC_REQUIRE_ALL: everything above is installed, so a missing test dependency is an error.
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGRADFRIC_NATIVE="${GRADFRIC_NATIVE:-OFF}" -DGRADFRIC_REQUIRE_ALL=ON >/dev/null
cmake --build "$build" -j "$(nproc)" "${target[@]}"
