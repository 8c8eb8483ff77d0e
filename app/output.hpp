#pragma once
// How a subcommand hands its result to the user: a readable table (stdout, or stderr when the
// JSON goes to stdout), with --json the result as JSON written atomically, with --plot the
// method's figure (gnuplot; data and script next to it), with --report DIR a self-contained
// report.html. Long runs show a progress line on stderr when it is a terminal.

#include <CLI/CLI.hpp>

#include <string>

#include "frictionlab/identify/result.hpp"

namespace frictionlab::cli {

struct OutputOptions {
  std::string json;        ///< file, "-" for stdout, empty for none
  std::string plot;        ///< figure file (.svg, .png, .pdf), empty for none
  std::string report;      ///< report directory, empty for none
  bool overwrite = false;  ///< replace existing output files
  CLI::App* command = nullptr;  ///< the subcommand (set by add_output_options), for the report's options
};

/// Adds --json, --plot, --report and --overwrite to `cmd` (identify methods and validate).
void add_output_options(CLI::App* cmd, OutputOptions& o);

/// Adds --plot FILE to `cmd` (simulate, analyze: they have their own other output options).
void add_plot_option(CLI::App* cmd, std::string& plot);

/// Refuses, before any work, outputs that cannot be written: an existing --json file, a --plot
/// path with an unsupported extension (svg, png, pdf) or an existing figure, a --report
/// directory that exists and is not empty, all without --overwrite. Also checks that gnuplot is
/// there when a figure is asked for, and starts the progress line.
/// \throws std::invalid_argument (exit 2) naming the option and path; std::runtime_error when
///         gnuplot is missing ("gnuplot not found: install Debian package gnuplot-nox").
void check_outputs(const OutputOptions& o);

/// The --plot part of check_outputs, for commands with their own output options.
void check_plot(const std::string& plot, bool overwrite);

/// The result as an aligned text table with units, fit figures, validation and warnings.
std::string result_text(const Result& r);

/// Prints the text, writes the JSON, the figure and the report, and returns the exit status: 0
/// when the result is ok, 2 when its status is error (the data could not give an answer; the
/// JSON and the report still say why; no figure is drawn).
int emit(const Result& r, const OutputOptions& o, const std::string& text_override = "");

/// A progress line on stderr for long runs, only when stderr is a terminal (and
/// FRICTIONLAB_NO_PROGRESS is unset): "frictionlab identify idim: fitting ... 3.2 s", shown once
/// a run has taken more than a second and cleared before any other output.
void progress_start(const std::string& task);
/// Changes the stage shown ("drawing figure.svg").
void progress_stage(const std::string& stage);
/// Clears the line and stops.
void progress_stop();

}  // namespace frictionlab::cli
