#include "commands.hpp"

namespace frictionlab::cli {

// Placeholder until the simulate work lands: the subcommand exists and says so.
Handler register_simulate(CLI::App& app) {
  app.add_subcommand("simulate", "(not yet available)");
  return [] {
    throw std::invalid_argument("'simulate' is not available in this build yet");
    return 2;
  };
}

}  // namespace frictionlab::cli
