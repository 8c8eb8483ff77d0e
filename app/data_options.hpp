#pragma once
// The column options every data-reading subcommand shares (DESIGN.md's command-line contract):
// which column or variable is time, position, velocity, current, force or drive input, the
// constants that turn a drive signal into force, unit scale factors, and the axis kind.

#include <CLI/CLI.hpp>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/io/dataset.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab::cli {

struct DataOptions {
  std::string time = "time", position = "position", velocity = "velocity", current = "current", force = "force",
              input = "input";
  std::string gain;  ///< number or scalar name: force = gain * input
  std::string kt;    ///< number or scalar name: force = kt * current
  std::vector<std::string> scales;
  std::string axis = "linear";
  bool drop_invalid = false;
  // Which column options the user gave explicitly (they take precedence over defaults).
  CLI::Option *force_opt = nullptr, *input_opt = nullptr, *current_opt = nullptr, *velocity_opt = nullptr,
              *position_opt = nullptr;

  Axis parsed_axis() const { return parse_axis(axis); }
};

/// Adds --time --position --velocity --current --force --input --gain --kt --scale --axis
/// --drop-invalid to `cmd`. `default_axis` is the axis when --axis is not given.
void add_data_options(CLI::App* cmd, DataOptions& o, const std::string& default_axis = "linear");

/// Reads DATA (CSV or MAT), applies --scale factors. \throws std::invalid_argument naming the file.
Dataset load_data(const std::string& path, const DataOptions& o);

/// The time column, checked strictly increasing and regular (names the row otherwise).
Eigen::VectorXd time_column(const Dataset& d, const DataOptions& o);

/// The applied force or torque (N or N m): the --force column if given or present; else --gain
/// times the --input column; else --kt times the --current column. \throws std::invalid_argument
/// saying which columns and constants were looked for and what the file has.
Eigen::VectorXd force_column(const Dataset& d, const DataOptions& o);

/// The velocity column (m/s or rad/s). \throws std::invalid_argument listing the file's columns.
Eigen::VectorXd velocity_column(const Dataset& d, const DataOptions& o);

/// The position column (m or rad). \throws std::invalid_argument listing the file's columns.
Eigen::VectorXd position_column(const Dataset& d, const DataOptions& o);

/// Checks every sample of `x` is finite, naming the row and column otherwise.
void require_finite(const Dataset& d, const Eigen::VectorXd& x, const std::string& column);

}  // namespace frictionlab::cli
