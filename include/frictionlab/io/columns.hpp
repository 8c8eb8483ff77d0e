#pragma once
// Turning a Dataset into the signals a method needs: column selection, constants given as
// numbers or scalar names, unit scale factors, the check of the time column, and resampling an
// irregularly sampled record onto a uniform grid.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frictionlab/io/dataset.hpp"
#include "frictionlab/signal/sampling.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The column `name` of `data`. `role` says what it is used as, for the message (e.g. "time",
/// "--position"). \throws std::invalid_argument "FILE: no column 'NAME' (ROLE); the file has
/// columns: a, b, c (scalars: g)", or, when NAME is a scalar or a MAT variable of the wrong
/// shape or type, "FILE: variable 'NAME' (ROLE) is a 3x4 matrix; expected ..."
/// (Dataset::missing_column_message); or the reader's error for a column with a cell that is not
/// a finite number (Dataset::invalid_cells: "FILE: line 102, column 4 'NAME': 'nan'; expected ...").
const Eigen::VectorXd& select_column(const Dataset& data, const std::string& name, const std::string& role = "");

/// select_column, and every sample finite. The one check of a loaded column's presence, shape,
/// type and values that commands use.
/// \throws std::invalid_argument as select_column, or "FILE: line 17, column 'NAME': value is
///         not a finite number" (row named by data.row_label).
const Eigen::VectorXd& finite_column(const Dataset& data, const std::string& name, const std::string& role = "");

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
ScaleFactor parse_scale(const std::string& spec, const std::string& option = "scale");

/// Multiplies each named column by its factor (in place), in order.
/// \throws std::invalid_argument listing the file's columns when a named column is missing, or
///         as parse_scale.
void apply_scales(Dataset& data, const std::vector<std::string>& specs, const std::string& option = "scale");

/// Options of check_time.
struct TimeCheckOptions {
  /// Largest allowed relative deviation of a step from the median step, |dt_k - dt| / dt.
  /// Default 0.01 (EMPS time stamps jitter by 2.4e-5).
  double regular_tolerance = 0.01;
  /// Check regularity at all. Default true.
  bool require_regular = true;
};

/// Checks a time column (s) with check_regular_sampling (signal/sampling.hpp), rows named by
/// data.row_label, and returns its mean step (t(N-1) - t(0)) / (N - 1), s.
/// \throws SamplingError (a std::invalid_argument) naming the file and the row of the first
///         non-finite, non-increasing or irregular sample, with the values and the min, median
///         and max step; or when N < 2.
double check_time(const Dataset& data, const Eigen::VectorXd& time, const TimeCheckOptions& options = {});

/// Puts every column of `data` on a uniform time grid (UniformResampler of signal/sampling.hpp:
/// repeated time stamps merged into their mean, gaps longer than options.max_gap refused, linear
/// interpolation), in place. The time column becomes the grid; data.resampling records the
/// jitter and the samples in and out; its warnings are appended to data.warnings; data.lines is
/// cleared (rows are grid samples from then on). Rows in messages are the file's (data.row_label
/// before resampling). options.where and options.row_label are filled in from `data`.
/// \throws std::invalid_argument as select_column for a missing time column, as
///         UniformResampler (naming the file, rows and the options' names), or when the
///         resampled columns would take more than 8 GB.
void resample_dataset(Dataset& data, const std::string& time_column, ResampleOptions options = {});

}  // namespace frictionlab
