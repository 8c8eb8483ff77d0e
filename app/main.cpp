// frictionlab: model, simulate and identify friction. See `frictionlab --help`.
#include <iostream>
#include <stdexcept>
#include <vector>

#include "commands.hpp"
#include "frictionlab/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"frictionlab: model, simulate and identify friction in motion systems (SI units throughout)."};
  app.set_version_flag("--version", std::string("frictionlab ") + frictionlab::kVersion);
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 2 bad input or data that cannot give an answer, 1 any other failure\n"
      "(a simulation that did not converge, a missing program such as gnuplot, an internal error).\n"
      "Run `frictionlab COMMAND --help` for a command's options.");

  std::vector<std::pair<CLI::App*, frictionlab::cli::Handler>> handlers;
  auto add = [&](frictionlab::cli::Handler (*reg)(CLI::App&)) {
    const std::size_t before = app.get_subcommands({}).size();
    auto handler = reg(app);
    handlers.emplace_back(app.get_subcommands({}).at(before), std::move(handler));
  };
  add(frictionlab::cli::register_simulate);
  add(frictionlab::cli::register_identify);
  add(frictionlab::cli::register_validate);
  add(frictionlab::cli::register_analyze);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // usage errors are bad input
  }
  try {
    for (auto& [sub, handler] : handlers)
      if (sub->parsed()) return handler();
  } catch (const std::invalid_argument& e) {
    std::cerr << "frictionlab: error: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {
    // A failure outside the user's input: a simulation that did not converge, a missing
    // program (gnuplot, chromium), an I/O error. The message says which and what to do.
    std::cerr << "frictionlab: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "frictionlab: internal error: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
