#!/usr/bin/env bash
# The random surface (-surface_ options, -fem_seed) in gradfric-fem, on a small plate:
#  1. zero dispersion given explicitly is the default run bit for bit (every physics dataset), no
#     surface among the active effects, the options recorded (default, or set when given);
#  2. dispersed: an active-effect line, the interface check's local mu_s above 1 from the nodes,
#     the stored node mu_s differs from the means and its values are the same bits on 2 ranks as
#     on 1 (and so is mu(t));
#  3. bad values refused before any work, exit 2, one line naming the option, on 2 ranks too;
#  4. -help lists the options with the FEM's defaults.
set -u
driver=$1; scratch=$2
mkdir -p "$scratch"; cd "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail=0
small="-fem_nx 8 -fem_ny 8 -fem_nz 2 -output_overwrite"
physics="/history /fem /realisations /statistics /properties"

"$driver" $small -output absent.h5 >absent.log 2>&1 || { echo "absent: exit status $?"; fail=1; }
"$driver" $small -surface_sigma_s 0 -surface_sigma_k 0 -output zero.h5 >zero.log 2>&1 || { echo "zero: exit status $?"; fail=1; }
for group in $physics; do
  h5diff -r absent.h5 zero.h5 "$group" >diff.log 2>&1 || { echo "zero: $group differs from the default run"; fail=1; }
done
h5dump -a /scene/origin/surface_sigma_s absent.h5 | grep -q '"default"' || { echo "absent: sigma_s not recorded as default"; fail=1; }
h5dump -a /scene/origin/surface_sigma_s zero.h5 | grep -q '"set"' || { echo "zero: sigma_s not recorded as set"; fail=1; }
h5dump -a /scene/fem_seed absent.h5 | grep -q '"1"' || { echo "absent: /scene/fem_seed is not 1"; fail=1; }
if grep -q 'random surface' absent.log zero.log; then echo "no dispersion: a random surface among the effects"; fail=1; fi

on="-surface_sigma_s 0.05 -surface_sigma_k 0.05 -surface_length 1e-3 -fem_seed 3"
"$driver" $small $on -output on.h5 >on.log 2>&1 || { echo "on: exit status $?"; fail=1; }
grep -q 'random surface: sigma_s = 0.05, sigma_k = 0.05, cells of l_c = 0.001 m (1.6 elements), each node its tributary area.s average (seed 3, realisation 0)' on.log ||
  { echo "on: no active-effect line"; fail=1; }
h5dump -a /scene/surface_length on.h5 | grep -q '"0.001"' || { echo "on: /scene/surface_length is not 0.001"; fail=1; }
# Mean mu_s 1: the surface lifts some nodes above 1, which the interface check names from the nodes,
# with those of them that slid above 1 before the peak (the flutter flag).
grep -A1 'interface resolution' on.log | grep -q 'local mu_s up to 1\.[0-9]* (with the random surface), [0-9]* nodes' ||
  { echo "on: the interface check does not report the nodes' mu_s above 1"; fail=1; }
mpiexec --oversubscribe -n 2 "$driver" $small $on -output on2.h5 >on2.log 2>&1 || { echo "on, 2 ranks: exit status $?"; fail=1; }
for group in /history /fem/properties; do
  h5diff -r on.h5 on2.h5 "$group" >diff.log 2>&1 || { echo "on: $group on 2 ranks differs from 1"; fail=1; }
done
/usr/bin/python3 - absent.h5 on.h5 <<'EOF' || fail=1
import sys, h5py, numpy as np
flat, rough = (h5py.File(name, "r")["fem/properties"] for name in sys.argv[1:])
ms, mk = np.asarray(rough["mu_s"]), np.asarray(rough["mu_k"])
if not (np.all(np.isfinite(ms)) and np.unique(ms).size > 4 and np.all(mk <= ms)):
    sys.exit(f"on: node mu_s not a field: {ms}")
if np.array_equal(ms, np.asarray(flat["mu_s"])):
    sys.exit("on: node mu_s equals the flat plate's")
description = rough["mu_s"].attrs["description"]
if "random surface" not in (description.decode() if isinstance(description, bytes) else description):
    sys.exit("on: the stored mu_s does not say it carries the surface")
EOF

# Refused before any work (no estimate printed, no file), one line naming the option; on 2 ranks
# too (the launcher costs 2 s: one case).
bad() {
  local what=$1 pattern=$2 launcher=(); shift 2
  [ "$what" = "2 ranks" ] && launcher=(mpiexec --oversubscribe -n 2)
  rm -f bad.h5
  "${launcher[@]}" "$driver" $small -output bad.h5 "$@" >bad.log 2>&1
  local status=$?
  [ $status -eq 2 ] || { echo "$what: exit $status, expected 2"; fail=1; }
  grep -q -- "$pattern" bad.log || { echo "$what: no message '$pattern'"; cat bad.log; fail=1; }
  if grep -q 'Estimate:' bad.log || [ -e bad.h5 ]; then echo "$what: work done before the refusal"; fail=1; fi
}
bad "2 ranks" "invalid option -surface_sigma_k = 0.6: allowed 0 <= sigma_k <= 0.5" -surface_sigma_k 0.6
bad "length 0" "invalid option -surface_length = 0: allowed l_c >= L/8192" -surface_length 0
bad "length nan" "invalid option -surface_length = nan" -surface_length nan
bad "sigma_s < 0" "invalid option -surface_sigma_s = -0.1: allowed 0 <= sigma_s <= 0.5" -surface_sigma_s -0.1
bad "blocks" "invalid option -surface_kind = blocks: allowed" -surface_kind blocks
bad "seed < 0" "invalid option -fem_seed = -1" -fem_seed -1
bad "compare seed" "invalid option -fem_compare_seed = 2: .*; use -fem_seed = 2" -fem_compare_seed 2

"$driver" -help surface >help.log 2>&1
grep -q -- '-surface_sigma_s <0> \[1\]' help.log || { echo "help: no -surface_sigma_s line with default 0"; fail=1; }
"$driver" -help fem_seed >help.log 2>&1
grep -q -- '-fem_seed <1> \[1\]: seed of the random surface: a single run takes its realisation 0, realisation r of an ensemble (-ensemble_realisations) its realisation r' help.log || { echo "help: no -fem_seed line"; fail=1; }

[ $fail -eq 0 ] && echo "surface option OK"
