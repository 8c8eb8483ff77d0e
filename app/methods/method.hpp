#pragma once
// One identification method of the command line, declared in one file under app/methods/: its
// `frictionlab identify NAME` subcommand (help, default axis, its own options and how it runs)
// and its figures with their captions (--plot draws the first; --report shows them all). The
// library's side of a method (name, summary, fitted signal) is identify/method.hpp. Adding a
// method: app/methods/NAME.cpp defining NAME_method(), and one line in methods.cpp.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "../batch_identify.hpp"
#include "../data_options.hpp"
#include "../output.hpp"
#include "frictionlab/identify/result.hpp"
#include "report/figure.hpp"

namespace frictionlab::cli {

/// The data file, column, output and batch options of one method subcommand (each has its own,
/// so that "was --force given?" is asked of the method the user chose).
struct MethodIO {
  std::string data;                 ///< the file a run reads (one of `inputs`)
  std::vector<std::string> inputs;  ///< the DATA arguments: files or folders
  DataOptions columns;
  OutputOptions output;
  BatchOptions batch;
};

/// Identifies from the data file io.data with a parsed method subcommand's options: the Result
/// (status error when the data could not give an answer). The caller checks and writes the
/// outputs (one file: emit; several: the batch table of batch_identify.hpp), so the same run
/// serves one file and a batch, from several threads at once (it reads only its arguments).
/// \throws std::invalid_argument for bad input (an option, the file, a column), as emit's callers expect.
using MethodRun = std::function<Result(const MethodIO& io, const CLI::App& cmd)>;

/// One figure of a method's result.
struct MethodFigure {
  std::string name;     ///< report file stem: "fit", "friction-map", "cross-test"
  std::string caption;  ///< one sentence under it in the report
  std::function<Figure(const Result&)> draw;  ///< an empty figure (no series) is left out
};

struct CliMethod {
  std::string name;          ///< subcommand and Result::method: "idim", "sweep", ...
  std::string help;          ///< the subcommand's help text
  std::string default_axis;  ///< --axis default: "linear" or "rotary"
  /// Adds the method's own options to its subcommand (after DATA, the column and the output
  /// options) and returns what runs it. Empty for a method with a command of its own (validate).
  std::function<MethodRun(CLI::App* cmd)> add_options;
  std::vector<MethodFigure> figures;  ///< the first is the fit figure
};

CliMethod idim_method();
CliMethod breakaway_method();
CliMethod sweep_method();
CliMethod decay_method();
CliMethod lugre_method();
CliMethod validate_method();

/// Every method, in the order of `frictionlab identify --help`.
const std::vector<CliMethod>& cli_methods();
/// The method named `name`, or nullptr.
const CliMethod* find_cli_method(const std::string& name);

}  // namespace frictionlab::cli
