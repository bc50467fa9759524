#!/usr/bin/env bash
# The spring-block lattice ladder at a fixed random surface converges by the verification
# procedure; with one draw per block (l_c following the block) it does not. A coarse lattice:
# l_c = L/16, N_b = 16, 32, 64, the same seed on every rung (paired realisations), judged by
# gradfric-study -study_judge on the rows scripts/sbm_study_rows.py makes (docs/verification.md).
# l_z = 1 mm: the slider springs carry a block's load over sqrt(2) l_z, which these lattices
# resolve with h / (sqrt(2) l_z) = 0.22, 0.11, 0.055, as N_b = 240, 480, 960 do at the default
# l_z (docs/studies/sbm-surface-ladder.md).
# Usage: surface_ladder.sh <gradfric> <gradfric-study> <source dir> <scratch folder>
set -eu
driver=$1 study=$2 src=$3 scratch=$4
rm -rf "$scratch" && mkdir -p "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ladder() {  # ladder <kind> <extra options...>: the judged table's mu_s line
  local kind=$1; shift
  local files=()
  for n in 16 32 64; do
    mpiexec --oversubscribe -n 2 "$driver" -plot false -sbm_N $n -ensemble_realisations 24 -ensemble_seed 5 \
      -ensemble_history false -ensemble_monitor false -friction_observables mu_s -surface_kind "$kind" "$@" \
      -output "$scratch/$kind$n.h5" > "$scratch/$kind$n.log" 2>&1 || { cat "$scratch/$kind$n.log"; exit 1; }
    files+=("$scratch/$kind$n.h5")
  done
  { printf '# observable\tmesh\tvalue\tstd_error\tsamples\tscene\n'
    /usr/bin/python3 "$src/scripts/sbm_study_rows.py" "${files[@]}" 2>"$scratch/$kind.pairs"; } > "$scratch/$kind.tsv"
  cat "$scratch/$kind.pairs" >&2
  "$study" -study_judge "$scratch/$kind.tsv" | grep "^| mu_s "
}
cells=$(ladder cells -surface_length 3.125e-4 -sbm_lz 1e-3)
blocks=$(ladder blocks -sbm_lz 1e-3)
echo "cells:  $cells"
echo "blocks: $blocks"
# A bar for every member (a number, not n/b) at the fixed surface ...
grep -Eq '\| (monotone|oscillatory) \|' <<<"$cells" || { echo "FAIL: the fixed-surface ladder does not converge"; exit 1; }
grep -q 'n/b' <<<"$cells" && { echo "FAIL: a fixed-surface member has no bar"; exit 1; }
# ... and none when the surface follows the lattice.
grep -Eq 'slow convergence|diverge' <<<"$blocks" || { echo "FAIL: the per-block draws should not converge"; exit 1; }
echo "surface ladder OK"
