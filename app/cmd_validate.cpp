#include "commands.hpp"

namespace frictionlab::cli {

// Placeholder until the validate work lands: the subcommand exists and says so.
Handler register_validate(CLI::App& app) {
  app.add_subcommand("validate", "(not yet available)");
  return [] {
    throw std::invalid_argument("'validate' is not available in this build yet");
    return 2;
  };
}

}  // namespace frictionlab::cli
