#pragma once
// Friction from constant-velocity tests (the DC-motor paper's experiment): at constant
// velocity the drive force equals the friction, so each steady segment of a run gives one
// point of the friction-velocity map; a static law is then fitted to the points.

#include <Eigen/Core>
#include <limits>
#include <vector>

#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Samples of a sweep run. Shapes: all of length N; time strictly increasing (s).
struct SweepData {
  Eigen::VectorXd time;      ///< s
  Eigen::VectorXd force;     ///< drive force or torque, N or N m (Kt times current)
  Eigen::VectorXd velocity;  ///< m/s or rad/s
  /// The load the contact transmits (N or N m), optional (empty: none; else length N). When
  /// given, each point carries its segment's mean |load| and identify_sweep fits mu_load: the
  /// law's Coulomb and static levels grow by mu_load |load| (models/law_effects.hpp).
  Eigen::VectorXd load;
};

/// A time window given by the user instead of automatic detection, s.
struct TimeWindow {
  double t_begin = 0;
  double t_end = 0;
};

struct SweepOptions {
  StaticFitOptions fit;  ///< the law to fit (default stribeck, exponent fitted)
  /// Segments are found on the velocity smoothed by a centred moving average over
  /// smoothing_fraction * min_duration (at least 1 sample). A segment is steady while the
  /// smoothed velocity's max - min <= 2 max(velocity_tolerance, relative_tolerance |v|,
  /// noise_band * sigma_s), where sigma_s is the measured noise of the smoothed velocity: the
  /// raw noise sigma (1.4826 median |dv| / sqrt 2, from sample-to-sample differences, robust to
  /// the speed steps) divided by sqrt(window). So a slow level in noise is found as well as a
  /// fast one. velocity_tolerance in m/s or rad/s; default 0. relative_tolerance default 0.01.
  double velocity_tolerance = 0.0;
  double relative_tolerance = 0.01;
  /// Half-width of the noise band in smoothed-noise std; default 5 (the range of a few hundred
  /// smoothed samples of Gaussian noise stays within +-5 std).
  double noise_band = 5.0;
  /// Moving-average window as a fraction of min_duration; default 0.1.
  double smoothing_fraction = 0.1;
  /// Shortest steady segment kept, s. Default 0.5 (the paper measured after 0.5 s of settling).
  double min_duration = 0.5;
  /// Part of each segment dropped at its start, as a fraction, so that the settling tail of the
  /// previous speed step does not bias the mean. Default 0.2.
  double settle_fraction = 0.2;
  /// Segments slower than this are standstill, not sliding (m/s or rad/s). Default: 1e-6 max |v|
  /// (of the reference when given); a segment whose mean is within its band of zero is
  /// standstill too. Two segments in a row at the same speed (within the band) are one level
  /// when less than min_duration lies between them, or when the velocity stayed within half
  /// that speed in between.
  double min_speed = -1;
  /// Commanded velocity (m/s or rad/s, length N of the data), optional: when given, steady
  /// segments are found on it instead of on the measured velocity; the points still average the
  /// measured velocity and force.
  Eigen::VectorXd reference;
  /// Windows to use instead of automatic detection (empty: detect).
  std::vector<TimeWindow> windows;
  /// Fewer segments than this is an error status. Default: the law's parameter count + 1.
  int min_segments = -1;
  /// Units of the report. Default linear, as every method (Axis::rotary for a motor).
  Axis axis = Axis::linear;
};

/// The options of a sweep from the values of its option table (method_info(MethodId::sweep),
/// identify/options.hpp): the table's defaults where a value is not given. The reference column
/// and the axis are the caller's to set.
/// \throws std::invalid_argument for a --segment that is not T_BEGIN:T_END in seconds.
SweepOptions make_sweep_options(const OptionValues& values);

/// One point of the friction-velocity map: mean and standard deviation over a steady segment.
struct SweepPoint {
  double velocity = 0, velocity_std = 0;  ///< m/s or rad/s
  double force = 0, force_std = 0;        ///< N or N m
  double t_begin = 0, t_end = 0;          ///< s
  std::size_t samples = 0;
  double load = std::numeric_limits<double>::quiet_NaN();  ///< mean |load| over the segment, N or N m (NaN: no load column)
};

/// The points of a sweep, in time order.
/// \throws std::invalid_argument on unequal lengths (the load's included), non-finite samples, a window
///         outside the record.
std::vector<SweepPoint> sweep_points(const SweepData& data, const SweepOptions& options = {});

/// Identifies the law options.fit.model from the sweep's points: parameters with std (NaN for
/// parameters at a bound or not determined, e.g. vs and delta when fewer than 3 points lie below
/// vs or the slowest is above 2 vs), fit figures over the points, diagnostics.lists["points"]
/// with every point and lists["levels"] (speed, duration, samples), diagnostics.numbers
/// "velocity_noise_std" and "smoothing_samples", diagnostics.correlation, warnings (e.g. "only 4
/// steady segments found", "no negative-velocity segments", "the slowest segment is above 2
/// vs"). Too few segments, or a fit that cannot be made, gives status "error" with the reason.
/// With data.load: the model is law(v) + mu_load |load| sign(v) (one coefficient raises the
/// Coulomb and the static level together), so the law's levels are those at zero load; mu_load
/// (dimensionless) is found by minimising the points' residual over it (the law refitted at each
/// trial value; exact for coulomb-viscous, where the problem is linear), its std from the
/// curvature of that residual (s^2 2 / RSS''(mu)), and the law's std widened by how the law moves
/// with mu_load (std^2 + (d theta / d mu)^2 std_mu^2). result.law carries mu_load; each point
/// lists its "load"; diagnostics.numbers "load_min"/"load_max" (mean |load| of the points). Loads
/// that hardly differ between the points (max - min within 1 % of the largest) give status
/// "error": mu_load cannot be told from the levels.
/// \throws std::invalid_argument as sweep_points.
Result identify_sweep(const SweepData& data, const SweepOptions& options = {});

}  // namespace frictionlab
