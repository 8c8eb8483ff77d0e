#pragma once
// How a subcommand hands its result to the user: a readable table (stdout, or stderr when the
// JSON goes to stdout), with --json the result as JSON written atomically, with --plot the
// method's figure (gnuplot; data and script next to it), with --report DIR a self-contained
// report.html. Long runs show a progress line on stderr when it is a terminal.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "report/report.hpp"

namespace frictionlab::cli {

struct DataOptions;

struct OutputOptions {
  std::string json;        ///< file, "-" for stdout, empty for none
  std::string plot;        ///< figure file (.svg, .png, .pdf), empty for none
  std::string report;      ///< report directory, empty for none
  bool overwrite = false;  ///< replace existing output files
  CLI::App* command = nullptr;  ///< the subcommand (set by add_output_options), for the report's options
  /// The method's option values (identify sets them before emit): the report lists an option of
  /// the method's table that was not given only when it has a default and applies to the run
  /// (OptionSpec::applies_if). Null: such options are listed only when given.
  const OptionValues* values = nullptr;
  /// The run's data options (set before emit): the report lists a data column option not given
  /// only when the run read its column (DataOptions::columns_read), with the column taken. Null:
  /// the column defaults are listed as declared.
  const DataOptions* data = nullptr;
};

/// Adds --json, --plot, --report and --overwrite to `cmd` (identify methods and validate), and
/// registers --json with register_json_output (method: the subcommand's name).
void add_output_options(CLI::App* cmd, OutputOptions& o);

/// Registers `cmd`'s --json option (owned by the subcommand) so that a failed run still prints
/// its error JSON: `method` gives the "method" the JSON names (called when the error is reported;
/// it may read parsed positionals). This registry lets fail() build the error JSON in one place.
void register_json_output(CLI::App* cmd, CLI::Option* json, std::function<std::string()> method);

/// The one place a failed run is reported (main's catch blocks; emit prints the same line for a
/// result whose data gave no answer): one line "frictionlab: error: MESSAGE" (or "internal
/// error" when `internal`) on stderr; and when the subcommand that ran was given `--json -`, the
/// JSON {"schema": 2, "status": "error", "message": MESSAGE, "method": ...} as one line on stdout.
/// The JSON also has "error": {"code": CODE, "message": MESSAGE, and the fields that apply: file,
/// row, column, key, option, value, other_file, other_option} (codes: frictionlab/error.hpp; an
/// empty `code` is input.invalid for status 2, internal otherwise). Bytes that are not UTF-8 are
/// escaped as \xNN. A --json FILE is not written: a run that failed leaves no file behind. Never
/// throws. Returns `status`.
int fail(const std::string& message, int status, bool internal = false, const std::string& code = "",
         const ErrorFields& fields = {});

/// fail() with the message, code and fields of `e` (error_code and error_fields of error.hpp).
int fail(const std::exception& e, int status, bool internal = false);

/// The error line alone: "frictionlab: error: MESSAGE" on stderr (the progress line cleared).
void print_error(const std::string& message, bool internal = false);

/// Refuses an output file before any work (check_output_path of io/atomic_write.hpp), the
/// message naming `option`: a directory, an existing regular file without --overwrite, a
/// missing directory, a block device or socket. "-" (stdout) and "" (none) pass. Devices and
/// FIFOs pass: they are written through, never replaced.
/// \throws std::invalid_argument "OPTION PATH ...".
void check_output_file(const std::string& path, bool overwrite, const std::string& option);

/// Refuses two outputs of one run that are the same file (--json and --plot, or a figure's
/// .dat/.gp): the second would fail after the first was written. `paths` pairs option and path.
/// \throws std::invalid_argument naming both options.
void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& paths);

/// A file a run reads or writes: the option or role that names it ("--json", "DATA", "scenario
/// data:") and its path. An output is a file, a figure (--plot: FILE, FILE.dat and FILE.gp) or a
/// report directory (--report: DIR/report.html and its figures).
struct RunFile {
  enum class Kind { file, figure, report };
  std::string option;
  std::string path;
  Kind kind = Kind::file;
};

/// Declares `opt` an output option of its subcommand, of `kind` (every option that names a file the
/// run writes is declared through this: one list). command_inputs leaves output options out of the
/// inputs, and `frictionlab help --commands` lists them, so a property test reaches every output of
/// every command (tests/cli/outputs_never_inputs.py). Returns `opt`.
CLI::Option* output_option(CLI::Option* opt, RunFile::Kind kind = RunFile::Kind::file);

/// The kind of output `opt` was declared with by output_option, or nothing for an input or setting.
const RunFile::Kind* output_kind(const CLI::Option* opt);

/// Every subcommand of `app` that runs (the leaves: `simulate`, `identify sweep`, ...) with its
/// positional arguments and options, as JSON: {"schema": 1, "commands": [{"command": "identify
/// sweep", "positionals": ["DATA"], "options": [{"name": "--json", "output": "file"}, {"name":
/// "--kt"}, ...]}]}; "output" (file, figure or report) marks output options (output_option).
std::string commands_json(const CLI::App& app);

/// The one rule for a run's outputs, applied before any work: every command hands it all its
/// inputs (the files it reads, including those a scenario or a model names) and all its outputs.
/// In this order (an output at an input is named as that, whatever else is wrong with it):
///  - each output is compared with every input, then with every other output, by device and
///    inode after resolving links (an output that does not exist yet: its directory's device and
///    inode and its name; a report directory that is an input file too); a match is refused with
///    or without `overwrite`, naming both (hard links count). Outputs written in place (a device,
///    a FIFO: never replaced) are compared with the inputs only when they lead to a regular file;
///  - each output path must be able to take an output (check_output_path of io/atomic_write.hpp:
///    not a directory, block device or socket; its directory exists); "-" and "" pass;
///  - an existing regular file or symbolic link (a dangling one too) is replaced only with `overwrite`;
///  - the directory that will receive a new or replaced file must be writable;
///  - a figure's extension and its gnuplot, a report directory (check_plot, check_report_dir).
/// \throws InputError (exit 2) with code output.is_input, output.duplicate, output.exists or
///         output.not_writable, naming the option and path (and the other file); std::runtime_error
///         when gnuplot is missing.
void check_run_files(const std::vector<RunFile>& inputs, const std::vector<RunFile>& outputs, bool overwrite);

/// The files a scenario names (its data files, its compensations' model files), read as
/// load_scenario reads them; what was found before a failure when the scenario cannot be read
/// (the command reports that failure itself later).
std::vector<RunFile> scenario_inputs(const std::string& scenario);

/// The inputs a parsed subcommand names: its positional arguments and every option value that
/// is an existing file (a folder's files are the batch's own inputs), except the output options
/// (output_option). A method's own input files (--validate, --static) are found this way.
std::vector<RunFile> command_inputs(const CLI::App* cmd);

/// Adds --plot FILE to `cmd` (simulate, analyze: they have their own other output options).
void add_plot_option(CLI::App* cmd, std::string& plot);

/// Refuses, before any work, outputs that cannot be written: an existing --json file, a --plot
/// path with an unsupported extension (svg, png, pdf) or an existing figure, a --report
/// directory that exists and is not empty, all without --overwrite; a --json or --plot path that
/// is a directory (with or without --overwrite); two outputs that are the same file. Also checks
/// that gnuplot is there when a figure is asked for, and starts the progress line.
/// \throws std::invalid_argument (exit 2) naming the option and path; std::runtime_error when
///         gnuplot is missing ("gnuplot not found: install Debian package gnuplot-nox").
/// `inputs` are the run's input files (command_inputs of the subcommand, and what its scenario
/// names), `extra` its other outputs: check_run_files applies to all of them.
void check_outputs(const OutputOptions& o, const std::vector<RunFile>& inputs = {}, const std::vector<RunFile>& extra = {});

/// The --plot part of check_outputs, for commands with their own output options: also refuses
/// a figure, .dat or .gp path that exists and is not a regular file (a figure is three files
/// renamed into place: a device or directory there is never replaced).
void check_plot(const std::string& plot, bool overwrite);

/// The result as an aligned text table with units, fit figures, validation and warnings.
std::string result_text(const Result& r);

/// Prints the text, writes the figure, the report and the JSON (in that order: the JSON, the
/// simplest to write, last, so that a failed figure leaves no JSON saying ok), and returns the
/// exit status: 0 when the result is ok, 2 when its status is error (the data could not give an
/// answer: one error line on stderr as fail() prints it; the JSON and the report still say why;
/// no figure is drawn).
/// The figures are the method's (result_figures of figures.hpp: the first, "fit", is what --plot
/// draws), or `figures` when given (analyze draws its own from the analysis result, validate on a
/// two-axis plant the circular test's; --plot draws the first of them).
/// This is the one output path of identify, validate and analyze.
int emit(const Result& r, const OutputOptions& o, const std::string& text_override = "",
         const std::vector<ReportFigure>* figures = nullptr);

/// A progress line on stderr for long runs, only when stderr is a terminal (and
/// FRICTIONLAB_NO_PROGRESS is unset): "frictionlab identify idim: fitting ... 3.2 s", shown once
/// a run has taken more than a second and cleared before any other output.
void progress_start(const std::string& task);
/// Changes the stage shown ("drawing figure.svg").
void progress_stage(const std::string& stage);
/// Clears the line and stops.
void progress_stop();

/// The check of a --shard value: K/N, never empty (an empty --shard "" would otherwise read as
/// "no sharding" and run every job).
inline CLI::Validator shard_text_check() {
  return CLI::Validator(
      [](std::string& s) { return s.empty() ? std::string("empty; expected K/N (shard K of N, 1 <= K <= N)") : std::string(); },
      "K/N");
}

}  // namespace frictionlab::cli
