#include "commands.hpp"

namespace frictionlab::cli {

// Placeholder until the analyze work lands: the subcommand exists and says so.
Handler register_analyze(CLI::App& app) {
  app.add_subcommand("analyze", "(not yet available)");
  return [] {
    throw std::invalid_argument("'analyze' is not available in this build yet");
    return 2;
  };
}

}  // namespace frictionlab::cli
