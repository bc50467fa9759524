#pragma once
// The optional FEM terms: each is one source file in src/fem/terms/ (its Layer subclass and the
// FemTerm below, returned by <name>Term()) plus one line GRADFRIC_FEM_TERM(<name>) in
// src/fem/terms/terms.def. That line is the registry: an explicit list, because a static library
// drops an object nothing references, so self-registration from static initialisers would lose
// terms silently. The -fem_ reader, PlateModel and the blow-up monitor loop over it
// (docs/fem.md, "Adding a FEM term"; gravity.cpp is the worked example).
#include "gradfric/core/options.hpp"
#include "gradfric/fem/layer.hpp"
#include "gradfric/fem/parameters.hpp"

#include <memory>
#include <string>
#include <vector>

namespace gradfric::fem {

class PlateMesh;
class PlateProperties;

// What PlateModel has to build a term from.
struct TermInputs {
  const PlateMesh& mesh;
  const LumpedMass& mass;
  const PlateProperties& properties;
  const FemParameters& params;  // the plate (params.plate) and the terms' settings (params.terms)
};

// A load on the plane that does not depend on the state (the blow-up monitor scales with
// p + these): its pressure [Pa] and how the monitor's message names it.
struct TermDeadLoad {
  double (*pressure)(const FemParameters& q) = nullptr;  // null: the term adds none
  const char* symbol = "";                              // "rho g H", in "(p + rho g H)/p"
  const char* share = "";                               // "the weight's share"
};

// Everything the reader, PlateModel and the monitor need of one optional term.
struct FemTerm {
  const char* name = "";  // its layer's name, and its main option's (-fem_<name>)
  // Reads its -fem_ options into q.terms and refuses a bad value naming the option (InputError:
  // exit 2 before any work).
  void (*readOptions)(OptionReader& o, FemParameters& q) = nullptr;
  bool (*wanted)(const FemParameters& q) = nullptr;  // off: not built, no cost
  std::unique_ptr<Layer> (*build)(const TermInputs& in) = nullptr;
  TermDeadLoad deadLoad;
};

// The registered terms in the order of terms.def: the order PlateModel adds their forces in.
const std::vector<FemTerm>& femTerms();
// Every registered term's options, in that order (the -fem_ reader, at their place among the others).
void readFemTermOptions(OptionReader& o, FemParameters& q);

// The wanted terms' dead loads: their pressure summed in the registry's order [Pa] (0: none), and
// for the monitor's message " + <symbol>" each and their shares.
struct DeadLoads {
  double pressure = 0;
  std::string symbols, shares;
};
DeadLoads deadLoadsOf(const FemParameters& q);

}  // namespace gradfric::fem
