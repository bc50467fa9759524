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
         share/gradfric/scripts/gradfric_plot.py share/gradfric/scripts/gradfric_plot_data.py share/gradfric/slurm/sbm_ensemble.sbatch \
         share/gradfric/slurm/submit_chain.sh share/gradfric/slurm/fem_sweep.sbatch share/gradfric/slurm/design.sbatch; do
  [ -x "$prefix/$f" ] || fail "$f not installed as an executable"
done
# The scripts import gradfric from the installed share/gradfric/python, so does a user's PYTHONPATH.
refusal=$(/usr/bin/python3 "$prefix/share/gradfric/scripts/plot_accuracy.py" "$2/none.h5" "$2/none.png" 2>&1 || true)
grep -q "none.h5 is not a gradfric accuracy study" <<< "$refusal" || fail "the installed plot_accuracy.py does not run: $refusal"
PYTHONPATH="$prefix/share/gradfric/python" /usr/bin/python3 -c 'import gradfric; print(gradfric.__file__)' |
  grep -qF "$prefix/share/gradfric/python/gradfric/__init__.py" || fail "gradfric not importable from $prefix/share/gradfric/python"
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
# The study tables are installed and read at run time by the installed drivers: a row added to the
# installed table changes the bar with no rebuild (the paper's mesh 100x100x5 has no three-mesh
# ladder until a third mesh of its shape is added).
tables=$prefix/share/gradfric/studies
[ -r "$tables/fem_study.tsv" ] && [ -r "$tables/sbm_study.tsv" ] || fail "the study tables are not installed in $tables"
bar() { (cd "$2" && "$prefix/bin/gradfric-fem" -fem_nz 5 -fem_dry_run 2>&1 | grep "bar point 0 mu_s") || true; }
before=$(bar "$prefix" "$2")
grep -q "not measured" <<< "$before" || fail "the installed gradfric-fem bounds 100x100x5 before the new rows: $before"
printf 'mu_s\t400x400x20\t0.9305\t0\t0\t-\n' >> "$tables/fem_study.tsv"
after=$(bar "$prefix" "$2")
grep -q "ladder 100x100x5:0.936322 200x200x10:0.931691 400x400x20:0.930500" <<< "$after" ||
  fail "the installed gradfric-fem did not read the row added to the installed table: $after"
if readelf -d "$prefix/bin/gradfric" | grep -E "R(UN)?PATH" | grep -qF "$(cd "$build" && pwd)"; then
  fail "installed gradfric keeps a run path into the build tree"
fi
echo "install tree OK: $prefix"
