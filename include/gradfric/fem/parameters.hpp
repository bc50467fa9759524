#pragma once
// Parameters of the 3D finite-element plate model (all -fem_ options) and their reader.
#include "gradfric/core/options.hpp"
#include "gradfric/fem/hex_element.hpp"
#include "gradfric/physics/friction_history.hpp"
#include "gradfric/physics/plate.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

// A FrictionMeasurement whose times are all derived (negative placeholders, see resolveDerived).
FrictionMeasurement derivedMeasurement();

struct FemParameters {
  // Mesh and geometry
  int nx = 100, ny = 100, nz = 5;
  ElementType element = ElementType::Trilinear;  // -fem_element q1 | q1i (docs/fem.md)
  // The physical plate (-plate_ options, shared with the spring-block model): size L, thickness
  // H, material, pressure, sliding speed and angle, mean local mu_s and mu_k (graded by -grading_).
  Plate plate;
  // Friction law (paper Eq. 1)
  double vC = 1e-4;      // critical velocity v_c [m/s]
  bool contact = true;   // false: free bottom face (testing)
  double kn = 0, kt = 0;  // penalty stiffnesses [Pa/m]; 0 = derived E/hz
  // Damping (mass-proportional, [1/s]) in the pressure phase and in the sliding phase;
  // stiffness-proportional (Rayleigh beta, [s]) in both.
  double settleDamping = -1;  // < 0: derived c_s/H
  double slideDamping = 0;
  double stiffnessDamping = 0;
  // Time stepping
  double dt = 0;            // 0: safety * stable step
  double dtSafety = 0.6;  // docs/accuracy_fem.md: 0.9 gave 1 % mu_s error on the paper mesh and instability with stiffer penalties
  bool dtCheck = true;  // false (testing only): a dt above the stable step is accepted, to test the monitor
  // Blow-up monitor: non-finite mu(t) or normal force any step; every monitorEvery steps, a
  // non-finite state or kinetic + elastic energy above monitorFactor x (energy put in + reference).
  int monitorEvery = 25;
  double monitorFactor = 10.0;
  double rampTime = -1;     // < 0: derived 20 H/c_s
  double settleTime = -1;   // < 0: derived 10 H/c_s
  double slideTime = -1;    // < 0: derived 3 * Eq. 2 estimate (upper bound; stops earlier)
  // How friction is measured: the shared rule of both models (-friction_ options). Negative
  // times: derived from the Eq. 2 loading time as readFrictionMeasurement does (for code that
  // builds parameters without options).
  FrictionMeasurement measurement = derivedMeasurement();
  bool stopWhenKnown = true;  // false: slide for slideTime whatever the observer knows
  // Parallel
  std::string partitioner = "metis";
  // Output
  std::string output;  // "" = no output file
  bool overwrite = false;
  std::vector<double> snapshotTimes;  // times after the start of sliding [s]
  int historyEvery = 1;
  bool verbose = true;

  double shearModulus() const { return plate.shearModulus(); }
  double shearWaveSpeed() const;
  // Paper Eq. 2: Delta t_s = mu_s p H / (G v).
  double eq2PeakTime() const { return plate.loadingTime(plate.thickness); }
  // Fill the derived defaults (negative or zero placeholders) from the others.
  void resolveDerived();
};

// Reads and validates every -fem_ option (derived defaults recorded as such).
FemParameters readFemParameters(MPI_Comm comm, RunParameters* record, const Plate& plate);

}  // namespace gradfric::fem
