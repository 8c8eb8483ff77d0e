#pragma once
// Turning a Dataset into the signals a method needs: column selection, constants given as
// numbers or scalar names, unit scale factors, and checks of the time column.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frictionlab/io/dataset.hpp"

namespace frictionlab {

/// The column `name` of `data`. `role` says what it is used as, for the message (e.g. "time",
/// "--position"). \throws std::invalid_argument "FILE: no column 'NAME' (ROLE); the file has
/// columns: a, b, c (scalars: g)".
const Eigen::VectorXd& select_column(const Dataset& data, const std::string& name, const std::string& role = "");

/// A constant given either as a number ("35.15", "1e-3") or as the name of a scalar in the file
/// ("gtau"). `parameter` names it for messages (e.g. "--gain").
/// \throws std::invalid_argument naming the parameter, the text and the file's scalars when the
///         text is neither a finite number nor a scalar of the file.
double resolve_constant(const Dataset& data, const std::string& text, const std::string& parameter);

/// A parsed "NAME=FACTOR" scale specification.
struct ScaleFactor {
  std::string column;
  double factor = 1.0;
};

/// Parses "NAME=FACTOR" (FACTOR a finite number, e.g. "position=1e-3" for mm to m).
/// \throws std::invalid_argument naming the text and the expected form.
ScaleFactor parse_scale(const std::string& spec);

/// Multiplies each named column by its factor (in place), in order.
/// \throws std::invalid_argument listing the file's columns when a named column is missing, or
///         as parse_scale.
void apply_scales(Dataset& data, const std::vector<std::string>& specs);

/// Options of check_time.
struct TimeCheckOptions {
  /// Largest allowed relative deviation of a step from the median step, |dt_k - dt| / dt.
  /// Default 0.01 (EMPS time stamps jitter by 2.4e-5).
  double regular_tolerance = 0.01;
  /// Check regularity at all. Default true.
  bool require_regular = true;
};

/// Checks a time column (s) and returns its mean step (t(N-1) - t(0)) / (N - 1), s.
/// \throws std::invalid_argument naming the file and the row (data.row_label) of the first
///         non-finite, non-increasing or irregular sample, with the values; or when N < 2.
double check_time(const Dataset& data, const Eigen::VectorXd& time, const TimeCheckOptions& options = {});

}  // namespace frictionlab
