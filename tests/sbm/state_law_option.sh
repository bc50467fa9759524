#!/usr/bin/env bash
# -friction_law state on the spring-block model: listed in -help with -friction_d_c, its kernel and
# regime number printed among the active effects, the law and D_c stored in /scene, and the same
# scene and seed bit for bit on 1 and 2 ranks (every group but /run, which holds the run's timing).
# Usage: state_law_option.sh <gradfric driver> <scratch folder> <mpiexec>
set -u
driver=$1
scratch=$2
mpiexec=$3
mkdir -p "$scratch"
fail() { echo "FAIL: $*"; exit 1; }
help=$("$driver" -help) || fail "-help exited $?"
grep -q -- "-friction_law <coulomb>.*(coulomb, exponential, state)" <<<"$help" || fail "-help does not offer the state law: $(grep -- -friction_law <<<"$help")"
grep -q -- "-friction_d_c" <<<"$help" || fail "-help does not list -friction_d_c"
scene=(-sbm_N 12 -grading_profile linear -grading_property friction -ensemble_delta 0,0.2 -ensemble_realisations 3
       -ensemble_seed 5 -friction_law state -friction_d_c 5e-8)
for ranks in 1 2; do
  rm -f "$scratch/ranks$ranks.h5"
  log=$("$mpiexec" -n $ranks "$driver" "${scene[@]}" -output "$scratch/ranks$ranks.h5" 2>&1) || fail "$ranks rank(s): exit $?: $log"
done
grep -q "Fast kernel, per-block state" <<<"$log" || fail "the active effects do not name the fast kernel"
grep -q "regime number kappa = .* = 0.822 < 1" <<<"$log" || fail "no regime number 0.822 (G D_c / (l_z p (mu_s - mu_k)) at D_c = 5e-8 m): $(grep -i regime <<<"$log")"
h5dump -a /scene/friction_law "$scratch/ranks1.h5" | grep -q '"state"' || fail "/scene/friction_law is not state"
h5dump -a /scene/friction_d_c "$scratch/ranks1.h5" | grep -q '5e-08' || fail "/scene/friction_d_c is not 5e-08"
groups=$(h5ls "$scratch/ranks1.h5" | awk '$1 != "run" {print $1}')
[ -n "$groups" ] || fail "no groups in the results file"
for g in $groups; do
  h5diff "$scratch/ranks1.h5" "$scratch/ranks2.h5" "/$g" "/$g" >/dev/null || fail "/$g differs between 1 and 2 ranks"
done
echo "ok: -friction_law state listed, printed, stored, and bit for bit on 1 and 2 ranks ($(wc -w <<<"$groups") groups)"
