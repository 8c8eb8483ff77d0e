#pragma once
// The column options every data-reading subcommand shares (docs/contract.md):
// which column or variable is time, position, velocity, current, force or drive input, the
// constants that turn a drive signal into force, unit scale factors, the axis kind, and how the
// file is read (--format for a file whose name does not say, --names for a file without a header row, --resample and --max-gap for
// irregular time, --drop-invalid).

#include <CLI/CLI.hpp>

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/identify/result.hpp"
#include "frictionlab/io/dataset.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab::cli {

/// How a data file is read: the options of add_read_options.
struct ReadOptions {
  std::string names;     ///< --names a,b,c: names of the columns of a CSV file, in order
  std::string resample;  ///< --resample [DT]: grid step in s ("" = the median step)
  double max_gap = 0;    ///< --max-gap S: longest gap resampling may bridge, s (0 = 10 median steps)
  bool drop_invalid = false;
  std::string format = "auto";  ///< --format csv|mat|auto: the reader, whatever the file's name
  CLI::Option* resample_opt = nullptr;  ///< set by add_read_options; resampling when it was given

  bool resample_given() const { return resample_opt != nullptr && resample_opt->count() > 0; }
};

struct DataOptions {
  std::string time = "time", position = "position", velocity = "velocity", current = "current", force = "force",
              input = "input";
  std::string gain;  ///< number or scalar name: force = gain * input
  std::string kt;    ///< number or scalar name: force = kt * current
  std::vector<std::string> scales;
  std::string axis = "linear";
  ReadOptions read;
  // Which column options the user gave explicitly (they take precedence over defaults).
  CLI::Option *force_opt = nullptr, *input_opt = nullptr, *current_opt = nullptr, *velocity_opt = nullptr,
              *position_opt = nullptr;
  /// The column options whose column the run read, and the column (or expression) each read:
  /// "--velocity" -> "velocity" when the default was taken. Filled by time_column, force_column,
  /// velocity_column and position_column (which take the options const: a record of the run, not
  /// an option), for the report's Options table, which lists a column default only when it was read.
  mutable std::map<std::string, std::string> columns_read;

  Axis parsed_axis() const { return parse_axis(axis); }
};

/// Adds --format --names --resample --max-gap --drop-invalid to `cmd` (group "Data columns"): for
/// commands that name their columns with options of their own (analyze).
void add_read_options(CLI::App* cmd, ReadOptions& o);

/// Adds --time --position --velocity --current --force --input --gain --kt --scale --axis and
/// the read options (add_read_options) to `cmd`. `default_axis` is the axis when --axis is not
/// given: linear for every identification method, so one file never reports N m under one
/// method and N under another.
void add_data_options(CLI::App* cmd, DataOptions& o, const std::string& default_axis = "linear");

/// Reads DATA (CSV with a header row or without one, or MAT): CSV columns named by --names;
/// with --resample, every column put on a uniform grid of `time_column` (repeated time stamps
/// merged, gaps longer than --max-gap or 10 median steps refused).
/// \throws std::invalid_argument naming the file, row, column or option.
Dataset load_data(const std::string& path, const ReadOptions& o, const std::string& time_column);

/// The file read with o.read, the --scale factors applied, then resampled (--resample) on the
/// scaled time column o.time: DT, --max-gap and the resampling report are in s.
Dataset load_data(const std::string& path, const DataOptions& o);

/// The result stamped with the data file, its digest and the data notes (note_data).
void stamp(Result& r, const Dataset& d);

/// Puts what reading did into a result: diagnostics.groups["resampling"] = {dt_min, dt_median,
/// dt_max, dt, max_gap, samples_in, samples_out, merged} (s and sample counts) when the data
/// were resampled, and the data's warnings into diagnostics.warnings.
void note_data(Result& r, const Dataset& d);

/// The same as text lines for commands without a Result (analyze): "" when there is nothing.
std::string data_note(const Dataset& d);

/// The time column, checked strictly increasing and regular (names the row otherwise, and
/// --resample when resampling would help).
Eigen::VectorXd time_column(const Dataset& d, const DataOptions& o);

/// The applied force or torque (N or N m): the --force column if given or present; else --gain
/// times the --input column; else --kt times the --current column. \throws std::invalid_argument
/// saying which columns and constants were looked for and what the file has.
Eigen::VectorXd force_column(const Dataset& d, const DataOptions& o);

/// The velocity column (m/s or rad/s). \throws std::invalid_argument listing the file's columns.
Eigen::VectorXd velocity_column(const Dataset& d, const DataOptions& o);

/// The position column (m or rad). \throws std::invalid_argument listing the file's columns.
Eigen::VectorXd position_column(const Dataset& d, const DataOptions& o);

/// The unit of the value of a data option (add_data_options, add_read_options) on `axis`:
/// "--time" s, "--position" m or rad, "--velocity" m/s or rad/s, "--force" N or N m, "--current" A,
/// "--kt" N m/A, "--gain" "N per unit of --input" (N m on a rotary axis), "--resample" and "--max-gap"
/// s; "" for the others (--input is in the drive's own unit).
std::string data_option_unit(const std::string& flag, Axis axis);

/// Checks every sample of `x` is finite, naming the row and column otherwise.
void require_finite(const Dataset& d, const Eigen::VectorXd& x, const std::string& column);

}  // namespace frictionlab::cli
