// The registry of the command line's identification methods: one line per method.
#include "method.hpp"

namespace frictionlab::cli {

const std::vector<CliMethod>& cli_methods() {
  static const std::vector<CliMethod> methods = {
      idim_method(),
      breakaway_method(),
      sweep_method(),
      decay_method(),
      lugre_method(),
      validate_method(),
  };
  return methods;
}

const CliMethod* find_cli_method(const std::string& name) {
  for (const auto& m : cli_methods())
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace frictionlab::cli
