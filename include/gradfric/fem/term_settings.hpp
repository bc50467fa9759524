#pragma once
// The settings of the optional FEM terms (term_registry.hpp), by option name without its prefix
// ("gravity" for -fem_gravity): each term reads, checks and uses its own, so FemParameters needs no
// member per term. They travel with the parameters (a sweep's points copy them), tests set them
// directly, and the -fem_ reader prints and records them as every other option.
#include <map>
#include <string>

namespace gradfric::fem {

class TermSettings {
public:
  void set(const std::string& name, double value) { values_[name] = value; }
  // The value set (by the reader or a test), else the term's default.
  double get(const std::string& name, double fallback) const {
    const auto found = values_.find(name);
    return found == values_.end() ? fallback : found->second;
  }

private:
  std::map<std::string, double> values_;
};

}  // namespace gradfric::fem
