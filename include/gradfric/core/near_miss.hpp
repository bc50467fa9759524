#pragma once
// Telling a misspelt option from a legitimate one that nothing in this run reads.
#include <string>
#include <vector>

namespace gradfric {

// Damerau-Levenshtein distance (optimal string alignment: insert, delete, substitute, swap two
// neighbours, each counts 1).
size_t editDistance(const std::string& a, const std::string& b);

// The known option closest to `name` ("-ouput" -> "-output") if it is a near miss: at most 1 edit
// for names of up to 5 characters, 2 for longer ones; "" otherwise. Names carry their dash.
std::string nearMiss(const std::string& name, const std::vector<std::string>& known);

// An option PETSc itself may read later in the run (-log_view, -ts_monitor, -malloc_debug, ...),
// by the prefixes of PETSc's components. Name without its dash.
bool isPetscOptionName(const std::string& name);

}  // namespace gradfric
