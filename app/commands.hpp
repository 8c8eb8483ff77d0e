#pragma once
// The subcommands of the frictionlab tool. Each lives in app/cmd_<name>.cpp and registers
// itself on the main CLI::App; the handler runs after parsing. The CLI stays thin: it parses,
// calls the library, prints.

#include <CLI/CLI.hpp>

#include <functional>

namespace frictionlab::cli {

/// A parsed subcommand's work; returns the process exit status (0 ok, 2 bad input, 1 internal).
using Handler = std::function<int()>;

/// Each registers a subcommand on `app` and returns the handler to run when it was chosen.
Handler register_simulate(CLI::App& app);
Handler register_identify(CLI::App& app);
Handler register_validate(CLI::App& app);
Handler register_analyze(CLI::App& app);
Handler register_export(CLI::App& app);
Handler register_merge(CLI::App& app);
Handler register_plan(CLI::App& app);
Handler register_help(CLI::App& app);

}  // namespace frictionlab::cli
