#pragma once
// What a FEM run at a design point says about the flutter (docs/flutter.md): its bottom nodes that
// slid at mu > 1 before the peak and their share of the area. There the onset depends on the
// mesh. One record for the evaluations, the verification, the FEM evaluator's runs and the runs
// taken from earlier design files. PETSc-free.

namespace gradfric::design {

struct FlutterExposure {
  long nodes = -1;            // -1: not measured (not a FEM run, or a law without D_c)
  double areaFraction = 0.0;  // their share of the contact area
};

}  // namespace gradfric::design
