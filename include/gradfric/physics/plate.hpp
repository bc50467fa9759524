#pragma once
// The physical plate, one record for both models: what the paper's "System parameters" fix
// (size, thickness, material, load, sliding speed and angle, mean local friction). Each model
// adds only its numerics (-sbm_*, -fem_*). PETSc-free; the reader is plate_options.hpp.
#include <cmath>
#include <string>

namespace gradfric {

struct Plate {
  double length = 5e-3;            // L [m], side of the square plate
  double thickness = 5e-5;         // H [m]
  double youngsModulus = 1e7;      // E0 [Pa], reference value the grading scales
  double poissonRatio = 1.0 / 3.0;  // nu
  double density = 1200.0;         // rho [kg/m^3]
  double pressure = 1e4;           // p [Pa] on the top face
  double velocity = 1e-3;          // v [m/s] of the top face (FEM) or slider (SBM)
  double slidingAngle = 0.0;       // theta [degree] between the sliding direction and the grading axis x
  double muStatic = 1.0;           // mean local static friction coefficient (reference of the grading)
  double muKinetic = 0.6;          // mean local kinetic friction coefficient

  double shearModulus(double modulus) const { return modulus / (2.0 * (1.0 + poissonRatio)); }
  double shearModulus() const { return shearModulus(youngsModulus); }
  double area() const { return length * length; }
  double normalForce() const { return pressure * length * length; }  // p L^2 [N] (this order: bitwise as before)
  double angleRadians() const { return slidingAngle * M_PI / 180.0; }
  // Paper Eq. 2: the time for the shear of a layer of height h to reach mu_s p,
  // Delta t_s = mu_s p h / (G v). h = H for the FEM, the lattice's l_z for the SBM.
  double loadingTime(double layerHeight) const {
    return muStatic * pressure * layerHeight / (shearModulus() * velocity);
  }
};

// Why a plate is not the paper's, naming the first field that differs, its value and the paper's
// ("" when it is): the error bars hold only for the plate their studies ran. The sliding angle is
// not compared (each study says which angles it ran); the thickness only where it enters the model.
enum class PlateThickness { Compared, Ignored };
std::string differenceFromPapersPlate(const Plate& plate, PlateThickness thickness);

}  // namespace gradfric
