#pragma once
// Input signals of a simulation: the applied force of an axis, the current or voltage command of
// a motor, the reference of a closed loop, the imposed velocity of a velocity drive.
// A core type (below plants and simulation): plants take InputValues, the engine evaluates
// InputSignals.

#include <span>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The shapes an input signal can take.
enum class InputShape { constant, step, ramp, trapezoid, sine, table };

/// Value and time derivatives of an input at one instant.
struct InputValue {
  double value = 0.0;  ///< u (input unit)
  double rate = 0.0;   ///< du/dt (unit/s)
  double accel = 0.0;  ///< d2u/dt2 (unit/s^2): a closed loop's acceleration feedforward uses it
};

/// The inputs of a plant at one instant, one entry per plant input (Plant::num_inputs()).
using Inputs = std::span<const InputValue>;

/// An input signal u(t), t in seconds. The unit is the unit of what the plant takes as input
/// (N or N m for an axis, A or V for a motor, m or rad for a position reference, m/s or rad/s for
/// a velocity reference or drive). Only the fields of the chosen shape are used.
struct InputSignal {
  InputShape shape = InputShape::constant;

  /// constant: u = value. step: u = initial before `time`, value from `time` on.
  double value = 0.0;
  /// step, ramp, trapezoid: the level before the signal starts moving. Default 0.
  double initial = 0.0;
  /// step: switching time (s). ramp, trapezoid: start time (s). Default 0.
  double time = 0.0;
  /// ramp: slope (unit/s), any sign. trapezoid: rate of the rising edge (unit/s, > 0). Default 0.
  double rate = 0.0;
  /// ramp: optional level where the ramp stops and holds (has_limit). Default: no limit.
  double limit = 0.0;
  bool has_limit = false;
  /// trapezoid: plateau level (unit), reached from `initial` at `rate`. Default 0.
  double level = 0.0;
  /// trapezoid: plateau duration (s, >= 0). Default 0.
  double hold = 0.0;
  /// trapezoid: rate of the falling edge back to `initial` (unit/s, > 0). Default: same as `rate`.
  double rate_down = 0.0;
  /// sine: u = offset + amplitude sin(omega t + phase). amplitude in the input unit, omega in
  /// rad/s (> 0), phase in rad. Defaults 0, 1 rad/s, 0, 0.
  double amplitude = 0.0;
  double omega = 1.0;
  double phase = 0.0;
  double offset = 0.0;
  /// table: sample times (s, strictly increasing) and values; held constant outside the range.
  std::vector<double> times;
  std::vector<double> values;
  /// table: true = piecewise constant (each value held until the next time, a staircase of set
  /// points), false = piecewise linear (default).
  bool hold_steps = false;

  /// Checks the fields of the chosen shape. `where` prefixes messages (e.g. "scenario.yaml: input").
  /// \throws std::invalid_argument naming the field, its value and what is expected.
  void validate(const std::string& where = "input") const;

  /// u(t), du/dt and d2u/dt2 at time t (s). At a jump (step, staircase) or a kink (ramp, trapezoid
  /// and linear-table corners) the values from the right. accel is 0 except for a sine.
  InputValue at(double t) const;

  /// Times in (t_begin, t_end) where u or du/dt is not smooth (kinks and jumps), ascending.
  /// The simulation engine stops and restarts its integrator there.
  std::vector<double> breakpoints(double t_begin, double t_end) const;

  /// Largest integration step (s) that cannot step over a feature of the signal (a sine period /
  /// 8); 0 = no limit needed.
  double max_step() const;

  /// Shape name as in scenario files ("trapezoid").
  static std::string shape_name(InputShape shape);
};

}  // namespace frictionlab
