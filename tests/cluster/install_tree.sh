#!/usr/bin/env bash
# Installs the build into a temporary prefix and checks what a cluster user gets: the drivers in
# bin (runnable, -help exits 0), the scenes, plotting and slurm scripts in share/gradfric, and no
# path into the build tree left in the installed drivers.
#   install_tree.sh <build-dir> <work-dir>
set -euo pipefail
build=$1
prefix=$2/prefix
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" > "$2/install.log"

fail() { echo "FAIL: $*" >&2; exit 1; }
for f in bin/gradfric bin/gradfric-fem bin/gradfric-study bin/gradfric-design \
         share/gradfric/scripts/gradfric_plot.py share/gradfric/slurm/sbm_ensemble.sbatch \
         share/gradfric/slurm/submit_chain.sh; do
  [ -x "$prefix/$f" ] || fail "$f not installed as an executable"
done
scenes=$(ls "$prefix"/share/gradfric/input/*.opts | wc -l)
sources=$(ls "$(dirname "$0")"/../../input/*.opts | wc -l)
[ "$scenes" -eq "$sources" ] || fail "$scenes scenes installed, $sources in input/"

for driver in gradfric gradfric-fem gradfric-study gradfric-design; do
  # Moved out of the build tree's reach: run from the prefix with a clean working folder.
  (cd "$2" && "$prefix/bin/$driver" -help > "$2/$driver.help" 2>&1) || fail "installed $driver -help exited $?"
  grep -q -- "-grading_delta" "$2/$driver.help" || fail "installed $driver -help does not list -grading_delta"
done
# An installed scene is usable by the installed driver (-help parses the scene, runs nothing).
(cd "$2" && "$prefix/bin/gradfric" -options_file "$prefix/share/gradfric/input/default.opts" -help > /dev/null 2>&1) \
  || fail "installed gradfric refused the installed default scene"
if readelf -d "$prefix/bin/gradfric" | grep -E "R(UN)?PATH" | grep -qF "$(cd "$build" && pwd)"; then
  fail "installed gradfric keeps a run path into the build tree"
fi
echo "install tree OK: $prefix"
