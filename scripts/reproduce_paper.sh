#!/usr/bin/env bash
# Runs every scene of the paper (SBM 120 x 120, the paper's resolution; FEM at its converged defaults,
# 100 x 100 x 10, docs/accuracy_fem.md), draws the
# figures into docs/figures/ and records each scene's wall time in results/paper/timings.txt.
#
#   bash scripts/reproduce_paper.sh [sbm] [fem]      (default: both)
#
# Needs the build (scripts/setup.sh). About 50 minutes on 2 idle cores (38 FEM runs of about 65 s on
# 2 ranks, through the kinetic window). NP=ranks (default 2).
# SBM_SCENES overrides the list of SBM scenes; SBM_EXTRA adds options to every SBM run (e.g.
# "-ensemble_realisations 10").
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
np=${NP:-2}
out=$here/results/paper
figures=$here/docs/figures
mkdir -p "$out" "$figures"
timings=$out/timings.txt
parts=${*:-sbm fem}

timed() {  # timed <label> <command...>: runs it, appends "label seconds" to the timings
  local label=$1; shift
  local start=$(date +%s%N)
  "$@" > "$out/$label.log" 2>&1 || { echo "FAILED: $label (see $out/$label.log)"; return 1; }
  local tenths=$(( ($(date +%s%N) - start) / 100000000 ))
  printf "%-28s %6d.%d s\n" "$label" $((tenths / 10)) $((tenths % 10)) | tee -a "$timings"
}

sbm() {
  local scenes=${SBM_SCENES:-sbm_fig2 sbm_fig4 sbm_fig5 sbm_fig6 sbm_fig7 sbm_fig8 sbm_fig9 sbm_fig10 sbm_fig11 sbm_fig12}
  for scene in $scenes; do
    # shellcheck disable=SC2086
    timed "$scene" mpiexec --oversubscribe -n "$np" "$here/build/drivers/gradfric" \
      -options_file "$here/input/$scene.opts" -output "$out/$scene.h5" -output_overwrite ${SBM_EXTRA:-}
  done
}

fem_run() {  # fem_run <label> <scene> [options...]
  local label=$1 scene=$2; shift 2
  timed "$label" mpiexec --oversubscribe -n "$np" "$here/build/drivers/gradfric-fem" \
    -options_file "$here/input/$scene.opts" -output "$out/$label.h5" -output_overwrite "$@"
}

# FEM_DELTAS overrides the Delta values of the FEM points (default -0.4 to 0.4 by 0.1).
fem() {
  local deltas=${FEM_DELTAS:--0.4 -0.3 -0.2 -0.1 0 0.1 0.2 0.3 0.4}
  for h in H025 H050 H100; do fem_run "fem_fig2_$h" "fem_fig2_$h"; done
  for d in $deltas; do
    fem_run "fem_fig4_d$d" fem_fig4_friction -grading_delta "$d"
    fem_run "fem_fig9_d$d" fem_fig9_modulus -grading_delta "$d"
    [ "$d" != 0 ] && fem_run "fem_fig11_d$d" fem_fig11_triangular -grading_delta "$d"
  done
  for d in 0 0.1 0.2 0.3 0.4; do fem_run "fem_fig8_theta90_d$d" fem_fig8_angle -grading_delta "$d"; done
  for d in -0.4 -0.2 0.2 0.4; do  # Figure 11 at 90 degrees: a curve of its own in the plot
    fem_run "fem_fig11_theta90_d$d" fem_fig11_triangular -grading_delta "$d" -plate_theta 90
  done
}

plots() {
  local py=/usr/bin/python3 plot=$here/scripts/gradfric_plot.py
  fems() { ls "$out"/$1 2>/dev/null || true; }
  [ -f "$out/sbm_fig2.h5" ] && $py "$plot" "$out/sbm_fig2.h5" --fem $(fems "fem_fig2_H???.h5") --out "$figures" --prefix fig2
  [ -f "$out/sbm_fig4.h5" ] && $py "$plot" "$out/sbm_fig4.h5" --fem $(fems "fem_fig4_d*.h5") --out "$figures" --prefix fig4_7
  [ -f "$out/sbm_fig5.h5" ] && $py "$plot" "$out/sbm_fig5.h5" --out "$figures" --prefix fig5
  [ -f "$out/sbm_fig6.h5" ] && $py "$plot" "$out/sbm_fig6.h5" --out "$figures" --prefix fig6
  [ -f "$out/sbm_fig8.h5" ] && $py "$plot" "$out/sbm_fig8.h5" --fem $(fems "fem_fig8_theta90_d*.h5") --out "$figures" --prefix fig8
  [ -f "$out/sbm_fig9.h5" ] && $py "$plot" "$out/sbm_fig9.h5" --fem $(fems "fem_fig9_d*.h5") --out "$figures" --prefix fig9_10
  [ -f "$out/sbm_fig11.h5" ] && $py "$plot" "$out/sbm_fig11.h5" --fem $(fems "fem_fig11_d*.h5") $(fems "fem_fig11_theta90_d*.h5") $(fems "fem_fig4_d0.h5") --out "$figures" --prefix fig11
  [ -f "$out/sbm_fig12.h5" ] && $py "$plot" "$out/sbm_fig12.h5" --out "$figures" --prefix fig12
  true
}

for part in $parts; do "$part"; done
plots
echo "figures in $figures, timings in $timings"
