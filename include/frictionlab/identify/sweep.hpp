#pragma once
// Friction from constant-velocity tests (the DC-motor paper's experiment): at constant
// velocity the drive force equals the friction, so each steady segment of a run gives one
// point of the friction-velocity map; a static law is then fitted to the points.

#include <Eigen/Core>
#include <vector>

#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

/// Samples of a sweep run. Shapes: all of length N; time strictly increasing (s).
struct SweepData {
  Eigen::VectorXd time;      ///< s
  Eigen::VectorXd force;     ///< drive force or torque, N or N m (Kt times current)
  Eigen::VectorXd velocity;  ///< m/s or rad/s
};

/// A time window given by the user instead of automatic detection, s.
struct TimeWindow {
  double t_begin = 0;
  double t_end = 0;
};

struct SweepOptions {
  StaticFitOptions fit;  ///< the law to fit (default stribeck, exponent fitted)
  /// A segment is steady while max(v) - min(v) <= 2 max(velocity_tolerance, relative_tolerance |v|).
  /// velocity_tolerance in m/s or rad/s; default 0 (relative only). relative_tolerance default 0.01.
  double velocity_tolerance = 0.0;
  double relative_tolerance = 0.01;
  /// Shortest steady segment kept, s. Default 0.5 (the paper measured after 0.5 s of settling).
  double min_duration = 0.5;
  /// Part of each segment dropped at its start, as a fraction, so that the settling tail of the
  /// previous speed step does not bias the mean. Default 0.2.
  double settle_fraction = 0.2;
  /// Segments slower than this are standstill, not sliding (m/s or rad/s). Default: 1e-3 max |v|.
  double min_speed = -1;
  /// Windows to use instead of automatic detection (empty: detect).
  std::vector<TimeWindow> windows;
  /// Fewer segments than this is an error status. Default: the law's parameter count + 1.
  int min_segments = -1;
  Axis axis = Axis::rotary;
};

/// One point of the friction-velocity map: mean and standard deviation over a steady segment.
struct SweepPoint {
  double velocity = 0, velocity_std = 0;  ///< m/s or rad/s
  double force = 0, force_std = 0;        ///< N or N m
  double t_begin = 0, t_end = 0;          ///< s
  std::size_t samples = 0;
};

/// The points of a sweep, in time order.
/// \throws std::invalid_argument on unequal lengths, non-finite samples, a window outside the record.
std::vector<SweepPoint> sweep_points(const SweepData& data, const SweepOptions& options = {});

/// Identifies the law options.fit.model from the sweep's points: parameters with std, fit
/// figures over the points, diagnostics.lists["points"] with every point, warnings (e.g. "only 4
/// steady segments found", "no negative-velocity segments"). Too few segments, or a fit that
/// cannot be made, gives status "error" with the reason.
/// \throws std::invalid_argument as sweep_points.
Result identify_sweep(const SweepData& data, const SweepOptions& options = {});

}  // namespace frictionlab
