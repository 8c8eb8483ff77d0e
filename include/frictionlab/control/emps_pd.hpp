#pragma once
// The EMPS benchmark's discrete position controller (Janot, Gautier, Brunot 2019, "Data Set and
// Reference Models of EMPS"), sampled every dt seconds:
//   qf(k)   = 0.5 q(k) + 0.5 q(k-1)                 (two-tap filtered position, m)
//   qd_m(k) = (qf(k) - qf(k-1)) / dt                 (measured velocity, m/s)
//   v(k)    = sat(kp kv (qg(k) - q(k)) - kv qd_m(k) + c(k)) (drive input, V, |v| <= limit)
//           + pulses(k)                              (V, added after the saturation)
// with c(k) = F / gtau the voltage of an optional friction compensator's force F (N or N m), and
// v(k) applied from sample k + delay on (EMPS: delay = 1), held between samples. The drive turns
// v into the force gtau v (N or N m). Gains and the control law only: the loop that runs it
// around a plant is simulate/closed_loop.hpp.

#include <cstddef>
#include <span>

#include "frictionlab/core/input.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Gains, limits and timing of the EMPS controller (EMPS values in brackets).
struct EmpsPdParams {
  double kp = 0.0;      ///< position-loop gain (1/s), >= 0 [160.18]
  double kv = 0.0;      ///< velocity-loop gain (V/(m/s) or V/(rad/s)), >= 0 [243.45]
  double gtau = 1.0;    ///< drive gain (N/V or N m/V), > 0: plant input = gtau * v [35.15]
  double limit = 10.0;  ///< output saturation |v| <= limit (V), > 0. Default 10.
  double dt = 1e-3;     ///< sample period (s), > 0. Default 1e-3.
  int delay = 1;        ///< samples from computing v(k) to applying it: 0 or 1. Default 1.
  /// Pulses added to the saturated output (V), sampled at the sample instants (EMPS PULSES
  /// file: 0 or 5 V). Default constant 0.
  InputSignal pulses;

  /// \throws std::invalid_argument "controller (emps-pd): kp = -1 must be >= 0 (1/s)" naming the
  ///         parameter, its value and unit when one is out of range, and what InputSignal::validate
  ///         throws for the pulses.
  void validate() const;
};

/// The controller's memory between samples and its held output, in the caller's state vector
/// (EmpsPd::kStates entries, all discrete).
struct EmpsPdState {
  static constexpr std::size_t applied = 0;   ///< output applied since the last sample (V)
  static constexpr std::size_t computed = 1;  ///< last computed output v(k) (V, pulses included)
  static constexpr std::size_t prev_q = 2;    ///< q(k-1) (m or rad)
  static constexpr std::size_t prev_qf = 3;   ///< qf(k-1) (m or rad)
  static constexpr std::size_t primed = 4;    ///< 1 once the first sample was taken, else 0
  static constexpr std::size_t prev_r = 5;    ///< qg(k-1) (m or rad)
};

/// What the controller measured at a sample, before its output: the compensator's inputs.
struct EmpsPdMeasurement {
  bool first = false;           ///< the first sample: the memory started at rest here
  double filtered = 0.0;        ///< qf(k) (m or rad)
  double velocity = 0.0;        ///< qd_m(k) (m/s or rad/s)
  double reference_rate = 0.0;  ///< (qg(k) - qg(k-1)) / dt (m/s or rad/s): the reference is a sampled signal
};

/// The EMPS controller with validated parameters. Immutable; no allocation.
class EmpsPd {
 public:
  static constexpr int kStates = 6;  ///< own states (EmpsPdState), all discrete

  /// \throws std::invalid_argument as EmpsPdParams::validate.
  explicit EmpsPd(EmpsPdParams p);
  const EmpsPdParams& params() const { return p_; }

  /// At a sample: starts the memory at the first one (primed = 0: q(k-1) = qf(k-1) = q, qg(k-1) =
  /// r) and returns the velocity estimate and reference rate there. `s`: the kStates own states;
  /// q the measured position (m or rad), r the reference qg(k) (m or rad).
  EmpsPdMeasurement measure(std::span<double> s, double q, double r) const;
  /// At the same sample, with measure()'s result m: computes v(k) with `compensation` (V, added
  /// inside the saturation) and the pulse at time t (s), applies it now (delay 0) or the one
  /// computed at the previous sample (delay 1), and moves the memory on. Returns v(k) (V).
  double sample(std::span<double> s, double t, double q, double r, const EmpsPdMeasurement& m,
                double compensation) const;
  /// The output applied since the last sample (V).
  static double held(std::span<const double> s) { return s[EmpsPdState::applied]; }
  /// The last computed output v(k) (V).
  static double computed(std::span<const double> s) { return s[EmpsPdState::computed]; }

 private:
  EmpsPdParams p_;
};

}  // namespace frictionlab
