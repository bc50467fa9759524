#!/usr/bin/env bash
# -fem_gravity (src/fem/terms/gravity.cpp) in the driver, on a small plate:
#  1. off (0, the default) is the run without the option bit for bit (every dataset but the run's
#     provenance), and the results file records it (default, or set when given);
#  2. on, the run prints and records it as set, describes the layer among the active effects,
#     settles on p L^2 plus the weight, its history differs, and is the same bits on 2 ranks;
#  3. -help lists it with its unit and default.
set -u
driver=$1; scratch=$2
mkdir -p "$scratch"; cd "$scratch"
fail=0
small="-fem_nx 6 -fem_ny 6 -fem_nz 2 -output_overwrite"
physics="/history /fem /realisations /statistics /properties"

"$driver" $small -output absent.h5 >absent.log 2>&1 || { echo "absent: exit status $?"; fail=1; }
"$driver" $small -fem_gravity 0 -output off.h5 >off.log 2>&1 || { echo "off: exit status $?"; fail=1; }
for group in $physics; do
  h5diff -r absent.h5 off.h5 "$group" >diff.log 2>&1 || { echo "off: $group differs from the run without the option"; fail=1; }
done
for run in absent off; do
  h5dump -a /scene/fem_gravity $run.h5 | grep -q '"0"' || { echo "$run: /scene/fem_gravity is not 0"; fail=1; }
done
h5dump -a /scene/origin/fem_gravity absent.h5 | grep -q '"default"' || { echo "absent: not recorded as default"; fail=1; }
h5dump -a /scene/origin/fem_gravity off.h5 | grep -q '"set"' || { echo "off: not recorded as set"; fail=1; }
if grep -q 'layer gravity' off.log; then echo "off: a gravity layer was built"; fail=1; fi

"$driver" $small -fem_gravity 1e4 -output on.h5 >on.log 2>&1 || { echo "on: exit status $?"; fail=1; }
grep -q -- '-fem_gravity *= 10000 \[m/s^2\]  (set)' on.log || { echo "on: not in the resolved parameters"; fail=1; }
grep -q 'layer gravity: own weight, g 1e+04 m/s^2: rho g H = 600 Pa' on.log || { echo "on: no active effect line"; fail=1; }
grep -q 'step 1 done: .*normal force 1.05[0-9]* p L^2' on.log || { echo "on: step 1 does not carry the weight"; fail=1; }
h5dump -a /scene/fem_gravity on.h5 | grep -q '"10000"' || { echo "on: /scene/fem_gravity is not 10000"; fail=1; }
h5dump -a /scene/origin/fem_gravity on.h5 | grep -q '"set"' || { echo "on: not recorded as set"; fail=1; }
if h5diff -q absent.h5 on.h5 /history >/dev/null 2>&1; then echo "on: the history did not change"; fail=1; fi
mpiexec --oversubscribe -n 2 "$driver" $small -fem_gravity 1e4 -output on2.h5 >on2.log 2>&1 || { echo "on, 2 ranks: exit status $?"; fail=1; }
h5diff -r on.h5 on2.h5 /history >diff.log 2>&1 || { echo "on: 2 ranks differ from 1"; fail=1; }

"$driver" -help fem_gravity >help.log 2>&1
grep -q -- '-fem_gravity <0> \[m/s^2\]: the plate.s own weight' help.log || { echo "help: no -fem_gravity line"; fail=1; }

[ $fail -eq 0 ] && echo "gravity option OK"
