#pragma once
// One identification method of the command line, declared in one file under app/methods/: its
// `frictionlab identify NAME` subcommand (help, default axis, its own options and how it runs)
// and its figures with their captions (--plot draws the first; --report shows them all). The
// library's side of a method (name, summary, fitted signal, option table) is identify/method.hpp;
// the method's flags are made from its option table (add_table_options). Adding a method:
// app/methods/NAME.cpp defining NAME_method(), and its line in FRICTIONLAB_METHODS.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "../batch_identify.hpp"
#include "../data_options.hpp"
#include "../output.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/method.hpp"
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

/// Identifies from the data file io.data with the method's option values (given on the command
/// line over the table's defaults, already checked against the table): the Result
/// (status error when the data could not give an answer). The caller checks and writes the
/// outputs (one file: emit; several: the batch table of batch_identify.hpp), so the same run
/// serves one file and a batch, from several threads at once (it reads only its arguments).
/// \throws std::invalid_argument for bad input (an option, the file, a column), as emit's callers expect.
using MethodRun = std::function<Result(const MethodIO& io, const OptionValues& options)>;

/// One figure of a method's result.
struct MethodFigure {
  std::string name;     ///< report file stem: "fit", "friction-map", "cross-test"
  std::string caption;  ///< one sentence under it in the report
  std::function<Figure(const Result&)> draw;  ///< an empty figure (no series) is left out
};

struct CliMethod {
  std::string help;          ///< the subcommand's help text
  /// Runs the method on one file. Empty for a method with a command of its own (validate).
  MethodRun run;
  std::vector<MethodFigure> figures;  ///< the first is the fit figure
  /// The library's side (name, option table), set by the registry from FRICTIONLAB_METHODS.
  const MethodInfo* info = nullptr;
  std::string name;  ///< info->name: the subcommand and Result::method
};

#define FRICTIONLAB_CLI_METHOD_DECL(method) CliMethod method##_method();
FRICTIONLAB_METHODS(FRICTIONLAB_CLI_METHOD_DECL)
#undef FRICTIONLAB_CLI_METHOD_DECL

/// The option values a parsed subcommand was given (checked against the table).
using GivenOptions = std::function<OptionValues()>;

/// Adds one flag per option of `info`'s table to `cmd`: `--NAME`, its help with unit, default
/// and valid values, required when the table says so; repeatable lists take one item each time.
/// Returns what reads the given flags after parsing, each checked by the table (parse_option).
/// \throws std::invalid_argument from the returned function: "--NAME 'TEXT': expected ...".
GivenOptions add_table_options(CLI::App* cmd, const MethodInfo& info);

/// A trajectory record of `d` for the methods that fit one (idim, auto): time, force, and the
/// position, or the velocity when `from` is "velocity" or only --velocity was given (`from` is the
/// methods' --from: "", "position" or "velocity"); the file's name and digest.
/// \throws std::invalid_argument naming the file and column, as the column readers.
IdimData trajectory_record(const Dataset& d, const DataOptions& c, const std::string& from);

/// Records the options that shaped `r` (options_json: name, value, unit, given) in its JSON.
void record_options(Result& r, const OptionValues& options);

/// Every method, in the order of `frictionlab identify --help`.
const std::vector<CliMethod>& cli_methods();
/// The method named `name`, or nullptr.
const CliMethod* find_cli_method(const std::string& name);

}  // namespace frictionlab::cli
