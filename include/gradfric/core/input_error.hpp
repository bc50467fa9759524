#pragma once
// Bad input: one clear message naming the option, its value and what is allowed.
#include <stdexcept>
#include <string>

namespace gradfric {

class InputError : public std::runtime_error {
public:
  // option: "-sbm_E"; value: as the user gave it; allowed: "> 0 [Pa]".
  InputError(const std::string& option, const std::string& value, const std::string& allowed)
      : std::runtime_error("invalid option " + option + " = " + value + ": allowed " + allowed),
        option_(option) {}
  // For problems that are not about one option value (a missing file, a conflict).
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
  const std::string& option() const { return option_; }

private:
  std::string option_;
};

}  // namespace gradfric
