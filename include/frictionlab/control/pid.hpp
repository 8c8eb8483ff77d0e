#pragma once
// The PID controller: P/PD/PI/PID on a position or a velocity, with velocity and acceleration
// feedforward, a friction compensator's force added before an output saturation, continuous or
// sampled (period Ts, the output held between samples, applied at once or one sample later).
// One implementation and one set of checks for every loop that runs a PID: a closed loop around a
// plant (simulate/closed_loop.hpp), each axis of an xy-table (simulate/xy_table.hpp), users' own
// loops. It holds gains and the control law only; its states live in the caller's state vector.

#include <span>
#include <string>
#include <string_view>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What the loop controls.
enum class ControlLoop {
  position,  ///< e = r - x;  out = Kp e + Ki int(e) - Kd v + Kvff dr/dt + Kaff d2r/dt2
             ///< (derivative on the measurement: no kick at a step)
  velocity,  ///< e = r - v;  out = Kp e + Ki int(e) + Kvff r + Kaff dr/dt   (Kd must be 0)
};

/// How the messages of PidParams::validate name the gains' units.
struct PidUnits {
  const char* Kp = "output unit per m, rad, m/s or rad/s";
  const char* Ki = "output unit per m s, rad s, m or rad";
  const char* Kd = "output unit per m/s or rad/s";
  const char* Kvff = "output unit per m/s or rad/s";
  const char* Kaff = "output unit per m/s^2 or rad/s^2";
  const char* limit = "output unit";
  /// A position loop whose output is a force on a linear axis (N, m).
  static PidUnits force_on_linear_axis() { return {"N/m", "N/(m s)", "N/(m/s)", "N/(m/s)", "N/(m/s^2)", "N"}; }
};

/// Gains, limits and timing of a PID. Output unit = the plant's input unit (N, N m, V or amplifier V).
struct PidParams {
  ControlLoop loop = ControlLoop::position;  ///< position (default) or velocity loop
  double Kp = 0.0;     ///< proportional gain (output unit per m, rad, m/s or rad/s), >= 0. Default 0.
  double Ki = 0.0;     ///< integral gain (output unit per (error unit s)), >= 0. Default 0.
  double Kd = 0.0;     ///< velocity feedback gain of the position loop (output unit per m/s or rad/s), >= 0. Default 0.
  /// Output saturation |out| <= limit (output unit); 0 = none (default). The integrator keeps
  /// integrating while saturated (no anti-windup: what a plain PID does).
  double limit = 0.0;
  /// Velocity feedforward gain (output unit per m/s or rad/s), >= 0. Default 0 (none). Multiplies
  /// the reference velocity: dr/dt in a position loop (Kvff = Kd turns the velocity feedback into
  /// feedback on the velocity error), r itself in a velocity loop.
  double Kvff = 0.0;
  /// Acceleration feedforward gain (output unit per m/s^2 or rad/s^2), >= 0. Default 0 (none).
  /// Multiplies the reference acceleration: d2r/dt2 in a position loop, dr/dt in a velocity loop.
  /// On a force-driven body Kaff = M supplies the force the reference's acceleration needs.
  double Kaff = 0.0;
  /// Plant input per unit of the compensator's force (input unit per N or N m), > 0. Default 1: a
  /// plant whose input is a force (axis, pendulum). For a motor give the input that produces one
  /// N m (a current-driven DC motor: 1 / (Ka Kt)).
  double compensation_gain = 1.0;
  /// Sample period (s), >= 0; 0 = continuous controller (default). Sampled: the output is computed
  /// at t = j Ts from the sampled measurement and reference, the integral accumulates Ts e(j)
  /// (rectangle rule, e(j) included), and the output is held until the next sample.
  double Ts = 0.0;
  /// Samples from computing the output to applying it (sampled only): 0 (default) or 1.
  int delay = 0;

  /// The one check of a PID's gains, limit and timing.
  /// \param who  prefix of the messages ("controller", "xy-table: axis x")
  /// \param units  the units the messages quote
  /// \throws std::invalid_argument "WHO: Kp = -1 must be >= 0 (UNIT)" when a gain or the limit is
  ///         negative or not finite, Kd != 0 in a velocity loop, compensation_gain is not > 0, and
  ///         as validate_timing.
  void validate(std::string_view who, const PidUnits& units = {}) const;
  /// The timing's check alone. \throws std::invalid_argument "WHO: Ts = -0.001 must be >= 0 (s; 0 =
  ///         continuous controller)", "WHO: delay = 2 must be 0 or 1 (samples)", "WHO: delay = 1
  ///         needs a sampled controller (Ts > 0 s)".
  void validate_timing(std::string_view who) const;
};

/// The name of PidParams in earlier releases.
using ControllerParams = PidParams;

/// What the PID reads at one instant. Units: m, m/s, m/s^2 on a linear axis; rad, rad/s, rad/s^2
/// on a rotary one.
struct PidInput {
  double position = 0.0;  ///< measured position x
  double velocity = 0.0;  ///< measured velocity v
  /// Position loop: the reference position r, its rate dr/dt and acceleration d2r/dt2. Velocity
  /// loop: the reference velocity r and its rate dr/dt (reference_accel unused).
  double reference = 0.0;
  double reference_rate = 0.0;
  double reference_accel = 0.0;
};

/// A PID with validated parameters. Immutable, safe to share between threads; no allocation.
///
/// Own states (num_states() entries, in the caller's state vector): continuous, the integral of
/// the error (error unit s), whose derivative is error(); sampled, the integral, then the applied
/// (held) output and the last computed output (output unit), all discrete (derivative 0, changed
/// by sample() only).
class Pid {
 public:
  /// \throws std::invalid_argument as PidParams::validate(who, units).
  explicit Pid(PidParams p, std::string_view who = "controller", const PidUnits& units = {});

  const PidParams& params() const { return p_; }
  bool sampled() const { return p_.Ts > 0.0; }
  /// 1 continuous, 3 sampled (see the class comment).
  int num_states() const { return sampled() ? 3 : 1; }

  /// The control error: r - x (position loop) or r - v (velocity loop); the integral's derivative.
  double error(const PidInput& in) const;
  /// The PID and feedforward terms plus compensation_gain times `compensation` (a force, N or
  /// N m), before the saturation (output unit). `integral`: the integral state (error unit s).
  double unsaturated(const PidInput& in, double integral, double compensation) const;
  /// `out` clamped to [-limit, limit] (unchanged without a limit).
  double saturate(double out) const;
  /// d saturate / d out at the unsaturated value `out`: 1 inside the limit (at |out| = limit too,
  /// where clamp is the identity), 0 beyond it.
  double saturation_slope(double out) const;
  /// saturate(unsaturated(in, integral, compensation)): the continuous controller's output.
  double output(const PidInput& in, double integral, double compensation) const {
    return saturate(unsaturated(in, integral, compensation));
  }

  /// Sampled: the update at a sample instant. `s`: the 3 own states (integral, applied, computed);
  /// `in` sampled at the instant; `compensation` the compensator's force there (N or N m). Adds
  /// Ts e to the integral, computes the output, and applies it now (delay 0) or the one computed at
  /// the previous sample (delay 1). Returns the computed output.
  double sample(const PidInput& in, std::span<double> s, double compensation) const;
  /// Sampled: the output held since the last sample (output unit), from the own states.
  static double held(std::span<const double> s) { return s[1]; }

 private:
  PidParams p_;
};

}  // namespace frictionlab
