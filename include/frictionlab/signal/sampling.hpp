#pragma once
// Sampling of a time column: the one regular-sampling check every reader and method uses
// (finite, strictly increasing, every step within a tolerance of the median step), and the
// resampling of an irregular record onto a uniform grid (repeated time stamps merged, long gaps
// refused, every column interpolated linearly).

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Names sample k (0-based) in messages, e.g. "line 17" for a CSV row or "sample 18".
using RowLabeller = std::function<std::string(Eigen::Index)>;

/// "sample K" with K = k + 1: the labeller used when the caller gives none.
std::string sample_label(Eigen::Index k);

/// The steps t(k) - t(k-1) of a time column, s.
struct TimeSteps {
  double min = std::numeric_limits<double>::quiet_NaN();     ///< smallest step, s
  double median = std::numeric_limits<double>::quiet_NaN();  ///< median step (upper median for an even count), s
  double max = std::numeric_limits<double>::quiet_NaN();     ///< largest step, s
  double mean = std::numeric_limits<double>::quiet_NaN();    ///< (t(N-1) - t(0)) / (N - 1), s
};

/// Steps of `time` (length N >= 2, any values). NaN figures when N < 2.
TimeSteps time_steps(const Eigen::VectorXd& time);

/// What check_regular_sampling found wrong, so a caller can add its own advice (a command line
/// names --resample for `repeated` and `irregular`).
enum class SamplingProblem {
  too_few,     ///< fewer than min_samples samples
  not_finite,  ///< a time stamp is NaN or infinite
  repeated,    ///< a time stamp equals the previous one
  backwards,   ///< a time stamp is before the previous one
  irregular,   ///< a step differs from the median step by more than the tolerance
  gap,         ///< (resampling) a step longer than the largest allowed gap
};

/// The error of check_regular_sampling and UniformResampler: a std::invalid_argument whose
/// message names the row (through the caller's labeller), the values and what was expected.
class SamplingError : public std::invalid_argument {
 public:
  SamplingError(SamplingProblem problem, const std::string& message) : std::invalid_argument(message), problem_(problem) {}
  SamplingProblem problem() const { return problem_; }

 private:
  SamplingProblem problem_;
};

/// Options of check_regular_sampling.
struct RegularSamplingCheck {
  /// Largest allowed relative deviation of a step from the median step, |dt_k - median| / median.
  /// Default 0.01 (1 %: EMPS time stamps jitter by 2.4e-5; a 100 Hz controller log jittering
  /// between 10 and 12 ms does not pass and needs resampling).
  double tolerance = 0.01;
  /// Check regularity at all (finiteness and increase are always checked). Default true.
  bool require_regular = true;
  /// Fewest samples accepted. Default 2.
  Eigen::Index min_samples = 2;
  /// Prefix of every message, e.g. "run.csv: " or "decay: ". Default "".
  std::string where;
  /// Names sample k (0-based) in messages. Default sample_label ("sample k+1").
  RowLabeller row_label;
  /// End of the irregular-step message: what needs regular data. Default
  /// "expected regularly sampled data".
  std::string requirement = "expected regularly sampled data";
};

/// Checks a time column (s): at least min_samples samples, every one finite, strictly
/// increasing, and (require_regular) every step within `tolerance` of the median step. Messages
/// name the first offending sample, e.g. "run.csv: line 17: time step 0.012 s differs from the
/// median step 0.01 s by more than 1 % (steps from 0.01 to 0.012 s); expected regularly sampled
/// data". Returns the mean step (t(N-1) - t(0)) / (N - 1), s; time_steps gives the others.
/// \throws SamplingError (a std::invalid_argument) saying which rule failed.
double check_regular_sampling(const Eigen::VectorXd& time, const RegularSamplingCheck& check = {});

/// Options of UniformResampler.
struct ResampleOptions {
  /// Step of the uniform grid, s. 0 (default): the median step of the record (after repeated
  /// time stamps are merged). Must be finite and >= 0.
  double dt = 0;
  /// Longest step between two samples that may be interpolated over, s. 0 (default): 10 median
  /// steps. A longer gap is refused: interpolation would invent data there.
  double max_gap = 0;
  /// Prefix of every message, e.g. "run.csv: ". Default "".
  std::string where;
  /// Names sample k (0-based, of the record as given) in messages. Default sample_label.
  RowLabeller row_label;
  /// How the caller's user sets dt and max_gap, for messages: e.g. "--resample" and "--max-gap"
  /// on the command line, "resample" and "max_gap" in Python. Defaults "dt" and "max_gap".
  std::string dt_name = "dt";
  std::string max_gap_name = "max_gap";
};

/// What resampling did: the record's jitter and the grid it was put on.
struct ResampleReport {
  double dt_min = 0;     ///< smallest step of the record (after merging repeated time stamps), s
  double dt_median = 0;  ///< median step, s
  double dt_max = 0;     ///< largest step, s
  double dt = 0;         ///< step of the uniform grid, s
  double max_gap = 0;    ///< largest gap that was allowed, s
  Eigen::Index samples_in = 0;   ///< samples of the record as given
  Eigen::Index samples_out = 0;  ///< samples of the uniform grid
  Eigen::Index merged = 0;       ///< samples removed by merging repeated time stamps
  /// One sentence each: repeated time stamps merged, a grid coarser than the record, ...
  std::vector<std::string> warnings;
};

/// Puts a record sampled at irregular times onto a uniform grid: built once from the time
/// column (which it checks), then applied to each column. Rows with the same time stamp are
/// merged into their mean (with a warning naming the first such row); the grid runs from the
/// first time stamp in steps of dt up to the last; each column is interpolated linearly between
/// the two neighbouring (merged) samples. Linear interpolation does not low-pass filter: a grid
/// coarser than the record aliases what lies above its Nyquist frequency (a warning says so).
class UniformResampler {
 public:
  /// \param time time stamps, s (N >= 2, finite, never decreasing).
  /// \throws SamplingError naming the row for a non-finite or decreasing time stamp, fewer than 2
  ///         distinct time stamps, or a gap longer than max_gap (naming both rows, the gap in s and
  ///         in median steps, and the option that allows it); std::invalid_argument naming
  ///         dt_name / max_gap_name for a negative or non-finite dt or max_gap, a dt longer
  ///         than the record, or one that would make more than 1e8 grid samples.
  UniformResampler(const Eigen::VectorXd& time, const ResampleOptions& options = {});

  /// The uniform time grid, s (length report().samples_out).
  const Eigen::VectorXd& time() const { return grid_; }
  const ResampleReport& report() const { return report_; }

  /// `column` (same length as the time column given to the constructor) on the grid.
  /// \throws std::invalid_argument naming the row and `name` for a non-finite value, or the
  ///         length when it differs from the time column's.
  Eigen::VectorXd apply(const Eigen::VectorXd& column, const std::string& name) const;

 private:
  std::string label(Eigen::Index k) const;

  ResampleOptions options_;
  Eigen::Index n_in_ = 0;
  std::vector<Eigen::Index> group_start_;  // first row of each distinct time stamp, plus n_in_ at the end
  std::vector<Eigen::Index> left_;         // per grid point: index of the merged sample at or before it
  std::vector<double> weight_;             // per grid point: weight of the next merged sample
  Eigen::VectorXd grid_;
  ResampleReport report_;
};

}  // namespace frictionlab
