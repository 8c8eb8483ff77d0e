#pragma once
// Maps over scenario grids: a grid of values of scenario keys (`--vary KEY=START:STOP:N`), each
// point simulated (simulate_batch, several threads) and its motion classified after a transient:
// converged (to rest or to the setpoint), steady sliding, stick-slip, hunting (a limit cycle about
// a point, with sticking), or oscillating (a limit cycle without sticking), with the cycle's
// amplitude and period; and, where theory gives one, the predicted class beside it (the
// linearised sliding stability of a spring-block on a Stribeck law, analysis/sliding_stability.hpp;
// the describing-function hunting cycle of a PID loop with Coulomb and static friction,
// analysis/describing_function.hpp). Building the scenario of each point from a file is the io
// layer's (scenario/scenario_grid.hpp); the table and its sharding, fleet/shard.hpp's.

#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/simulate/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// One varied key: `count` values from `start` to `stop`, evenly spaced (or log-spaced).
struct MapAxis {
  std::string key;   ///< dotted path into the scenario, e.g. plant.k or controller.Kp
  double start = 0;  ///< first value (unit of the key)
  double stop = 0;   ///< last value
  std::size_t count = 1;  ///< number of values, >= 1 (1: start only)
  bool log = false;  ///< log spacing (start and stop > 0)
  /// The values, start first. \throws std::invalid_argument as parse_map_axis.
  std::vector<double> values() const;
  /// "KEY=START:STOP:N" or "KEY=log:START:STOP:N" (numbers in their shortest exact form).
  std::string text() const;
};

/// Parses "KEY=START:STOP:N" (linear) or "KEY=log:START:STOP:N" (log-spaced).
/// \throws std::invalid_argument "--vary 'TEXT': ..." naming what is wrong: no '=', an empty key,
///         not three numbers, N not an integer >= 1, a value that is not finite, N = 1 with
///         START != STOP, log spacing with a value <= 0.
MapAxis parse_map_axis(const std::string& text, const std::string& option = "--vary");

/// The grid: every combination of the axes' values, the first axis varying slowest (row-major),
/// so point i of a 2-D grid is (values0[i / n1], values1[i % n1]).
struct MapGrid {
  std::vector<MapAxis> axes;
  std::size_t size() const;  ///< product of the counts (0 without axes)
  std::vector<double> point(std::size_t i) const;  ///< the axes' values at point i
  /// \throws std::invalid_argument for no axis, a key given twice, or more than 1e7 points.
  void validate() const;
};

/// The motion's kind.
enum class MotionClass { converged, steady_sliding, stick_slip, hunting, oscillating, failed };

/// "converged", "steady-sliding", "stick-slip", "hunting", "oscillating", "failed".
const char* motion_class_name(MotionClass c);

/// Options of classify_motion.
struct MotionOptions {
  /// Time discarded from the start (s): the motion from the initial state is not the map's
  /// answer. NaN (default): half of the record.
  double transient = std::numeric_limits<double>::quiet_NaN();
  /// A velocity oscillation (half peak-to-peak over the last third of the kept record) below this
  /// fraction of the record's largest |v| counts as none (steady or at rest). Default 0.01.
  double tolerance = 0.01;
  /// \throws std::invalid_argument for a negative transient or a tolerance outside (0, 1).
  void validate() const;
};

/// What classify_motion finds. Units of the signals (m, m/s; rad, rad/s on a rotary axis).
struct MotionSummary {
  MotionClass kind = MotionClass::failed;
  /// Half peak-to-peak of the position about its mean drift (m): the cycle's amplitude; that of
  /// what is left of the motion when converged or steady.
  double amplitude = std::numeric_limits<double>::quiet_NaN();
  /// Mean time between upward crossings of the drift-free position through its mid-range (s);
  /// NaN without two such crossings (no cycle).
  double period = std::numeric_limits<double>::quiet_NaN();
  double mean_velocity = std::numeric_limits<double>::quiet_NaN();       ///< net displacement / time (m/s)
  double velocity_amplitude = std::numeric_limits<double>::quiet_NaN();  ///< half peak-to-peak of v (m/s)
  double stuck_fraction = std::numeric_limits<double>::quiet_NaN();      ///< of the kept time stuck (detect_stick_slip)
  double transient = std::numeric_limits<double>::quiet_NaN();           ///< the time discarded (s)
  std::string message;  ///< why it failed (simulation error), else empty
};

/// Classifies a record (t strictly increasing, s; x position; v velocity; equal lengths). After
/// the transient: an oscillation is sustained when the velocity's half peak-to-peak over the last
/// third exceeds tolerance * max|v| (whole record); the motion drifts when its net displacement
/// is more than half its total travel. Not sustained: steady-sliding when the mean velocity
/// exceeds tolerance * max|v|, else converged (at rest, or creeping into the setpoint). Sustained: with sticking (detect_stick_slip finds stuck time) stick-slip when it
/// drifts, hunting when not; without sticking oscillating when it drifts, hunting when not.
/// \throws std::invalid_argument for unequal lengths, fewer than 8 samples after the transient,
///         or bad options.
MotionSummary classify_motion(std::span<const double> t, std::span<const double> x, std::span<const double> v,
                              const MotionOptions& options = {});

/// What theory predicts at a grid point, when it applies.
struct MapTheory {
  /// "spring-block" (SpringBase plant with a stribeck, coulomb-viscous, static-coulomb-viscous,
  /// viscous or coulomb law: linearised sliding stability), "pid-hunting" (a position PID loop
  /// around an axis, no compensation, with coulomb or static-coulomb-viscous friction with Fv =
  /// 0: describing function), or "" (none applies).
  std::string kind;
  std::string predicted;  ///< motion_class_name of the prediction ("" when none)
  /// spring-block: c + dF/dv(V0) (N s/m; < 0: stick-slip); else NaN.
  double margin = std::numeric_limits<double>::quiet_NaN();
  double amplitude = std::numeric_limits<double>::quiet_NaN();  ///< pid-hunting: predicted A (m)
  double period = std::numeric_limits<double>::quiet_NaN();     ///< pid-hunting: predicted T (s)
  std::string message;  ///< why no prediction, when kind is set but predicted is empty
};

/// The theory of a scenario (see MapTheory), for its first contact (both theories are of 1-DOF
/// plants). Never throws for a scenario that simulates.
MapTheory map_theory(const Scenario& scenario);

/// The contact a map classifies, by `which`: a contact's name (Contact::name: "x", "y" of an
/// xy-table), or its index from 0 (Plant::contact order); "" is the first contact (index 0). A name
/// is matched before an index (a contact named "1" is that contact).
/// \returns the index, 0 <= index < plant->num_contacts().
/// \throws std::invalid_argument "OPTION 'WHICH': ..." for a name or index the plant does not have,
///         listing its contacts as INDEX NAME ("0 x, 1 y"; "0 (unnamed)" for a 1-DOF plant), or a
///         scenario without a plant.
int map_contact(const Scenario& scenario, const std::string& which, const std::string& option = "--contact");

/// Options of run_map.
struct MapOptions {
  MotionOptions motion;
  int threads = 0;  ///< as BatchOptions::threads (0: all cores)
  /// The contact classified (index from 0, map_contact); every scenario's plant must have it.
  int contact = 0;
  /// Called after each point (thread-safe): points finished so far, of `scenarios.size()`.
  std::function<void(std::size_t finished, std::size_t total)> progress;
};

/// Simulates each scenario (simulate_batch, trajectories reduced as they finish) and classifies
/// the motion of contact options.contact (the first by default). A failed simulation gives
/// MotionClass::failed with its message; the others go on.
/// \throws std::invalid_argument when options.contact is not a contact of every scenario's plant
///         (before anything is simulated; a scenario without a plant is a failed row), or for bad
///         motion options.
std::vector<MotionSummary> run_map(const std::vector<Scenario>& scenarios, const MapOptions& options = {});

}  // namespace frictionlab
