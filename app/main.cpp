// frictionlab: model, simulate and identify friction. See `frictionlab --help`.
#include <iostream>
#include <new>
#include <stdexcept>
#include <vector>

#include "commands.hpp"
#include "output.hpp"
#include "frictionlab/budget.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"frictionlab: model, simulate and identify friction in motion systems (SI units throughout)."};
  app.set_version_flag("--version", std::string("frictionlab ") + frictionlab::kVersion);
  app.require_subcommand(1);
  // The one option of the work and memory budget (frictionlab/budget.hpp), before or after the
  // command's name (fallthrough): every command checks its sizes against it before any work.
  double budget = 1.0;
  app.add_option("--budget", budget,
                 "Factor on the work and memory budget (default 1: 1e9 work units, i.e. samples, solver steps, "
                 "runs or bytes, and half the memory this process may use; memory never beyond all of it)")
      ->type_name("FACTOR");
  app.fallthrough();
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
  add(frictionlab::cli::register_export);
  add(frictionlab::cli::register_plan);
  add(frictionlab::cli::register_merge);
  add(frictionlab::cli::register_help);

  // Every failure goes through fail() (app/output.hpp): one line on stderr, and the error JSON
  // when the chosen subcommand was asked for --json.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return frictionlab::cli::fail(std::string(e.what()) + " (run with --help for the options)", 2, false,
                                  frictionlab::errc::option_invalid);
  }
  try {
    frictionlab::set_budget_factor(budget);
    for (auto& [sub, handler] : handlers)
      if (sub->parsed()) return handler();
  } catch (const std::invalid_argument& e) {
    return frictionlab::cli::fail(e, 2);
  } catch (const std::length_error&) {
    return frictionlab::cli::fail("out of memory: the data or the result is larger than a container can hold", 1);
  } catch (const std::bad_alloc&) {
    // Sizes the readers can foresee (a scenario's output rows) are refused before allocating;
    // this is what is left: a data set or result larger than the memory there is.
    return frictionlab::cli::fail("out of memory: the data or the result is larger than the memory available", 1);
  } catch (const std::runtime_error& e) {
    // A failure outside the user's input: a simulation that did not converge, a missing
    // program (gnuplot, chromium), an I/O error. The message says which and what to do.
    return frictionlab::cli::fail(e, 1);
  } catch (const std::exception& e) {
    return frictionlab::cli::fail(e, 1, true);
  }
  return 1;
}
