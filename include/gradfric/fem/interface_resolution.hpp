#pragma once
// Is the friction law's weakening length D_c resolved by the run? (docs/accuracy_fem.md, "The
// friction law".) Three conditions, checked from the run and printed next to mu_s:
//  - the penalty's elastic slip mu_s p / k_t at most D_c / 10 (kinematic contact: none), so that the
//    contact's compliance does not stand in for D_c;
//  - the largest slip of a node in one step up to the peak at most D_c / 5, so that the time step
//    follows the weakening that decides mu_s;
//  - the process zone (measured up to the peak, physics/process_zone.hpp) spanning a median of at
//    least 4 elements
//    (Day et al. 2005; Dalguer & Day 2007).
// And the flutter: a node that slides with mu(theta) > 1 on the rigid plane is on an ill-posed
// interface (docs/flutter.md), so the onset there depends on the mesh; counted up to the peak.
// With the law's normal-stress memory the interface is well-posed if the mesh resolves it: the
// elements next to those nodes, in-plane and through the thickness, at most lambda_c / 8, and the
// time step at most T / 10.
// Also the regime number kappa = G D_c / (H p (mu_s - mu_k)): the column stiffness of the layer
// against the weakening rate; below 1 the onset is dynamic (fronts), above 1 it is smooth.
#include "gradfric/fem/contact_boundary.hpp"
#include "gradfric/physics/process_zone.hpp"

#include <string>
#include <vector>

namespace gradfric::fem {

class PlateModel;

struct InterfaceResolution {
  bool applies = false;  // a law with a weakening length (the state law)
  double slipLength = 0, kappa = 0;
  double elasticSlip = 0;  // mu_s,max p / k_t [m]; 0 with kinematic contact
  double largestStepSlip = 0;
  double largestStaticCoefficient = 0;  // over the contact nodes: above 1 a node may slide at mu > 1
  SlidingAboveOne aboveOne;              // the nodes that did, before the peak: there sliding flutters
  bool withMemory = false;               // the law's normal-stress memory is on: it bounds that flutter
  // With the memory and nodes sliding at mu > 1: its shortest relaxation time T = L_sigma / (|V| + V*) at
  // their fastest slip rate, and the shortest wavelength that still grows then, 2 pi c_s T / K_c
  // (docs/flutter.md, "With a normal-stress memory"): the mesh must resolve it.
  double memoryTime = 0, cutoffWavelength = 0, baseLayer = 0, timeStep = 0;
  bool randomSurface = false;            // the nodes' mu_s carry a dispersed random surface
  ProcessZone zone;
  std::vector<std::string> violations;  // empty: resolved

  std::string describe() const;  // one line: measures() + ": " + verdict()
  std::string measures() const;  // D_c, kappa and the three measures
  std::string verdict() const;   // "resolved" or "NOT resolved: <each violation>;"
};

// After a run on model (collective); peakTime: of mu_s, after the start of sliding (the process
// zone is measured where weakening started by then: the zone that decides mu_s).
InterfaceResolution checkInterfaceResolution(const PlateModel& model, double peakTime);

}  // namespace gradfric::fem
