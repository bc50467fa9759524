#include "gradfric/fem/term_registry.hpp"

namespace gradfric::fem {

// terms.def, once as the declarations of the terms' functions, once as the table: the table
// references every term's function, so the linker keeps each term's object file.
#define GRADFRIC_FEM_TERM(name) FemTerm name##Term();
#include "terms/terms.def"
#undef GRADFRIC_FEM_TERM

const std::vector<FemTerm>& femTerms() {
  static const std::vector<FemTerm> terms = {
#define GRADFRIC_FEM_TERM(name) name##Term(),
#include "terms/terms.def"
#undef GRADFRIC_FEM_TERM
  };
  return terms;
}

void readFemTermOptions(OptionReader& o, FemParameters& q) {
  for (const FemTerm& term : femTerms()) term.readOptions(o, q);
}

DeadLoads deadLoadsOf(const FemParameters& q) {
  DeadLoads loads;
  for (const FemTerm& term : femTerms()) {
    if (!term.deadLoad.pressure || !term.wanted(q)) continue;
    loads.pressure += term.deadLoad.pressure(q);
    loads.symbols += std::string(" + ") + term.deadLoad.symbol;
    loads.shares += std::string(loads.shares.empty() ? "" : " and ") + term.deadLoad.share;
  }
  return loads;
}

}  // namespace gradfric::fem
