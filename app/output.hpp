#pragma once
// How a subcommand hands its result to the user: a readable table (stdout, or stderr when the
// JSON goes to stdout) and, with --json, the result as JSON written atomically.

#include <CLI/CLI.hpp>

#include <string>

#include "frictionlab/identify/result.hpp"

namespace frictionlab::cli {

struct OutputOptions {
  std::string json;        ///< file, "-" for stdout, empty for none
  bool overwrite = false;  ///< replace existing output files
};

/// Adds --json and --overwrite to `cmd`.
void add_output_options(CLI::App* cmd, OutputOptions& o);

/// The result as an aligned text table with units, fit figures, validation and warnings.
std::string result_text(const Result& r);

/// Prints the text, writes the JSON, and returns the exit status: 0 when the result is ok, 2
/// when its status is error (the data could not give an answer; the JSON still says why).
int emit(const Result& r, const OutputOptions& o);

/// Refuses early (before any work) an output file that exists without --overwrite.
void check_output_path(const std::string& path, bool overwrite, const std::string& option);

}  // namespace frictionlab::cli
