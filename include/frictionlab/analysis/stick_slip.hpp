#pragma once
// Stick-slip detection: the stick and slip intervals of a motion record, its period, the peak
// slip velocity, and the friction force at breakaway and at re-stick.

#include <span>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of detect_stick_slip.
struct StickSlipOptions {
  /// |v| at or below this counts as stuck (m/s or rad/s). Default 0 = automatic: exactly 0 when
  /// at least 5 % of the samples have v == 0 exactly (an exact hybrid simulation), else 1 % of
  /// the largest |v| (dynamic laws and measurements creep or are noisy while "stuck").
  double velocity_threshold = 0.0;
  /// Slips shorter than this are merged into the surrounding stick (s). Default 0.
  double min_slip_duration = 0.0;
};

/// A time interval [start, end] (s).
struct TimeInterval {
  double start = 0.0;
  double end = 0.0;
};

/// Result of detect_stick_slip. Forces are in the unit of the force signal (N or N m).
struct StickSlipResult {
  std::vector<TimeInterval> stick;  ///< stuck intervals, in time order
  std::vector<TimeInterval> slip;   ///< sliding intervals, in time order (the last may be open: ends at the record's end)
  double velocity_threshold = 0.0;  ///< the threshold used
  /// Mean time between successive slip starts (s); the first interval is left out when there
  /// are at least three starts (it starts from the initial state, not from the limit cycle).
  /// NaN with fewer than two slips.
  double period = 0.0;
  double peak_slip_velocity = 0.0;  ///< largest |v| during slips (m/s or rad/s)
  double mean_slip_duration = 0.0;  ///< s, over complete slips
  /// Force at each breakaway (the larger in magnitude of the last two stuck samples before a
  /// slip: a sample at the switch instant may already show the sliding level) and at each
  /// re-stick (the first stuck sample after a slip); complete slips only; empty without a force.
  std::vector<double> breakaway_force;
  std::vector<double> restick_force;
  double mean_breakaway_force = 0.0;
  double mean_restick_force = 0.0;
  double mean_force_drop = 0.0;  ///< mean (breakaway - re-stick) over complete slips
  /// Why the record shows no stick-slip, empty when it does: "no slip found: velocity never
  /// exceeded ..." (never moved) or "no slip from stick found: ..." (slides from the start and
  /// never sticks then slips again). The figures are then not meaningful (period NaN).
  std::string message;
  bool found() const { return message.empty(); }
};

/// Detects stick and slip in a record.
/// \param t velocity and force: equal lengths (force may be empty), t strictly increasing (s).
/// \throws std::invalid_argument when lengths differ, fewer than 3 samples, t not increasing
///         (naming the sample), or a negative threshold.
StickSlipResult detect_stick_slip(std::span<const double> t, std::span<const double> v, std::span<const double> force,
                                  const StickSlipOptions& options = {});

}  // namespace frictionlab
