#pragma once
// Segments of a velocity record: steady constant-velocity runs (for friction-velocity maps),
// motion onset (breakaway) and standstill intervals.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A run of samples [begin, end) and the time it covers, from time(begin) to time(end - 1).
struct IndexRange {
  std::size_t begin = 0;  ///< first sample
  std::size_t end = 0;    ///< one past the last sample
  double t_begin = 0;     ///< s
  double t_end = 0;       ///< s
  std::size_t size() const { return end - begin; }
  double duration() const { return t_end - t_begin; }  ///< s
};

/// Options of steady_segments.
struct SteadySegmentOptions {
  /// Half-width of the velocity band of a steady segment: over the segment
  /// max(v) - min(v) <= 2 * max(velocity_tolerance, relative_tolerance * |mean(v)|).
  /// m/s or rad/s; default 0 (then relative_tolerance must be > 0).
  double velocity_tolerance = 0;
  /// Band half-width relative to the segment's mean speed, dimensionless; default 0.
  double relative_tolerance = 0;
  /// Shortest segment kept, s. Default 0.5 s.
  double min_duration = 0.5;
  /// Segments whose mean |v| is below this are standstill, not steady motion, and are dropped.
  /// m/s or rad/s; default 0 (keep all).
  double min_speed = 0;
};

/// Non-overlapping steady constant-velocity segments, in time order. A segment grows from its
/// first sample while the velocity band holds; when the next sample breaks it, the run is kept
/// if it lasts min_duration, and the search restarts there (otherwise the start slides on).
/// Shapes: time and velocity of equal length N (time in s, strictly increasing).
/// \throws std::invalid_argument on unequal lengths, negative tolerances, or both tolerances zero.
std::vector<IndexRange> steady_segments(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                        const SteadySegmentOptions& options);

/// Standard deviation of white noise on a piecewise-smooth signal, estimated from its
/// sample-to-sample differences: 1.4826 median|x(k+1) - x(k)| / sqrt(2). The median ignores the
/// few large differences of steps and ramps, so a staircase of constant levels with noise gives
/// the noise alone. Unit of x; 0 for fewer than 2 samples.
double difference_noise_std(const Eigen::VectorXd& x);

/// Centred moving average over `window` samples (odd windows centred exactly; shortened at the
/// ends). Shape: as x. \throws std::invalid_argument when window < 1.
Eigen::VectorXd moving_average(const Eigen::VectorXd& x, Eigen::Index window);

/// First sample at or after `start` where |velocity| > threshold (m/s or rad/s, >= 0), or none.
/// \throws std::invalid_argument on a negative threshold.
std::optional<std::size_t> motion_onset(const Eigen::VectorXd& velocity, double threshold, std::size_t start = 0);

/// Maximal runs with |velocity| <= threshold lasting at least min_duration (s), in time order.
/// Shapes: time and velocity of equal length N.
/// \throws std::invalid_argument on unequal lengths or a negative threshold.
std::vector<IndexRange> standstill_intervals(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                             double threshold, double min_duration = 0);

/// Maximal runs with |velocity| > threshold lasting at least min_duration (s): the complement
/// of the standstill runs. Same shapes and throws as standstill_intervals.
std::vector<IndexRange> motion_intervals(const Eigen::VectorXd& time, const Eigen::VectorXd& velocity,
                                         double threshold, double min_duration = 0);

}  // namespace frictionlab
