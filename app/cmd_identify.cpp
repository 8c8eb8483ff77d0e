#include "commands.hpp"

namespace frictionlab::cli {

// Placeholder until the identify work lands: the subcommand exists and says so.
Handler register_identify(CLI::App& app) {
  app.add_subcommand("identify", "(not yet available)");
  return [] {
    throw std::invalid_argument("'identify' is not available in this build yet");
    return 2;
  };
}

}  // namespace frictionlab::cli
