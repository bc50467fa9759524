#!/bin/bash
# The FEM element and mesh study of docs/studies/fem-element-and-mesh.md: mu_s, the edge
# pressures and the moment balance at the peak for q1 and q1i, in-plane 25/50/100 and through the
# thickness 5/10, non-graded and linear E / friction grading Delta = +-0.2. One run at a time on
# 2 ranks, niced; each run appends one line to the results file.
#   bash scripts/fem_element_study.sh build results/fem_element_study.txt
set -euo pipefail
build=${1:-build}
out=${2:-results/fem_element_study.txt}
mkdir -p "$(dirname "$out")"
study="$build/bench/fem/bench_fem_element_study"
run() { nice -n 10 mpiexec -n 2 "$study" -friction_observables mu_s "$@" | grep '^element' >> "$out"; }
gradings=("E 0.2" "E -0.2" "friction 0.2" "friction -0.2")
for n in 25 50 100; do
  for e in q1 q1i; do run -fem_element $e -fem_nx $n -fem_ny $n -fem_nz 5; done
done
for n in 25 50; do
  for e in q1 q1i; do
    for g in "${gradings[@]}"; do
      set -- $g
      run -fem_element $e -fem_nx $n -fem_ny $n -fem_nz 5 -grading_profile linear -grading_property $1 -grading_delta $2
    done
    run -fem_element $e -fem_nx $n -fem_ny $n -fem_nz 10
  done
done
# The thickness refinement of the paper mesh (~4 x its cost).
run -fem_element q1 -fem_nx 100 -fem_ny 100 -fem_nz 10
