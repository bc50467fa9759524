#!/usr/bin/env bash
# -sbm_spring: listed in -help with its default and choices, printed among the active effects,
# stored in the results file, and a bad value refused naming the option (exit 2).
# Usage: spring_option.sh <gradfric driver> <scratch folder>
set -u
driver=$1
scratch=$2
mkdir -p "$scratch"
out="$scratch/small_strain.h5"
rm -f "$out"
fail() { echo "FAIL: $*"; exit 1; }
help=$("$driver" -help) || fail "-help exited $?"
grep -q -- "-sbm_spring <exact>.*(exact, small_strain)" <<<"$help" || fail "-help does not list -sbm_spring: $(grep -- -sbm_spring <<<"$help")"
log=$("$driver" -sbm_N 8 -ensemble_realisations 1 -sbm_spring small_strain -output "$out" 2>&1) || fail "run exited $?: $log"
grep -q "small-strain springs" <<<"$log" || fail "the active effects do not name the small-strain springs"
stored=$(h5dump -a /scene/sbm_spring "$out") || fail "no /scene/sbm_spring in $out"
grep -q '"small_strain"' <<<"$stored" || fail "stored value is not small_strain: $stored"
message=$("$driver" -sbm_spring linear -output "$scratch/refused.h5" 2>&1 >/dev/null)
status=$?
[ $status -eq 2 ] || fail "-sbm_spring linear exited $status, expected 2"
grep -q -- "-sbm_spring" <<<"$message" || fail "the refusal does not name -sbm_spring: $message"
[ ! -e "$scratch/refused.h5" ] || fail "the refused run left a file"
echo "ok: -sbm_spring listed, printed, stored (small_strain) and checked"
