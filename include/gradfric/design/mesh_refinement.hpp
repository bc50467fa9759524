#pragma once
// The coarse-to-fine FEM design (-design_model fem -design_coarse_mesh, docs/design.md): the root
// finder searches on the coarse mesh; its design is then run on the -fem_* mesh and moved by
// secant steps, the first with the coarse search's slope, each later one with the slope of the
// last two fine runs, until a fine run holds the target within the tolerance or
// -design_fine_evaluations runs are spent. A coarse search that does not find ends the design
// with its own outcome, said to be the coarse mesh's.
#include "gradfric/design/search.hpp"

namespace gradfric::design {

// Collective (through the runs). fine: the FEM on the -fem_* mesh.
SearchResult refineOnFineMesh(DesignModel& fine, const Problem& problem, SearchLog& log, const SearchResult& coarse);

}  // namespace gradfric::design
