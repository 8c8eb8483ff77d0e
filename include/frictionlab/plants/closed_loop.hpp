#pragma once
// A P/PD/PI/PID controller closed around a plant (axis or motor), with velocity and acceleration
// feedforward and an optional friction compensator: the plant's input becomes the controller
// output, and the scenario's input becomes the reference.

#include <memory>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace FRICTIONLAB_API frictionlab {

/// What the loop controls.
enum class ControlLoop {
  position,  ///< e = r - x;  out = Kp e + Ki int(e) - Kd v + Kvff dr/dt + Kaff d2r/dt2
             ///< (derivative on the measurement: no kick at a step)
  velocity,  ///< e = r - v;  out = Kp e + Ki int(e) + Kvff r + Kaff dr/dt   (Kd must be 0)
};

/// Controller gains and limits. Output unit = the plant's input unit (N, N m, V or amplifier V).
struct ControllerParams {
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
};

/// Closed loop around `inner` (a 1-DOF plant). States: the inner plant's, then the integral of
/// the error, then the compensator's own states (none without a compensator). Signals: the inner
/// plant's at the controller output (drive: the force it commands), with reference = r.
///
/// Compensation: the compensator's output (N or N m), times compensation_gain, adds to the PID and
/// feedforward terms BEFORE the saturation, so a saturated loop cannot exceed its limit with it.
/// The compensator sees the measured position and velocity (x[0], x[1]) and, in a position loop,
/// r with its rate and acceleration; in a velocity loop r is its reference velocity (rate r,
/// acceleration dr/dt) and its reference position is the measured one (no position error). Its
/// drive input is the inner plant's drive signal at the saturated output (the force applied).
/// Its event functions are the loop's own (Plant::num_events, events, on_event), so the engine
/// locates its switches. Its initial states come from the initial position and velocity and the
/// reference at t = 0 (initial_extras with the inputs; without them: from rest at x = 0 with a
/// zero reference). In fixed-step mode its states advance by the compensator's own fixed-step
/// update (Compensator::update, what a drive runs, stable at any step), with the drive force held
/// over the step, instead of explicit Euler.
class ClosedLoop : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when a gain is negative or not finite, Kd != 0 in a velocity
  ///         loop, the limit is negative, compensation_gain is not > 0, or `inner` is null,
  ///         kinematic or not 1-DOF.
  ClosedLoop(std::shared_ptr<const Plant> inner, ControllerParams c,
             std::shared_ptr<const Compensator> compensator = nullptr);
  std::string type() const override { return inner_->type(); }
  int num_states() const override { return n_inner_ + 1 + n_comp_; }
  double inertia(int = 0) const override { return inner_->inertia(); }
  void initial_extras(std::span<double> x) const override;
  void initial_extras(std::span<double> x, Inputs u) const override;
  /// True with a compensator that has states.
  bool has_fixed_step_update() const override { return n_comp_ > 0; }
  void fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before, std::span<double> x,
                         Inputs u) const override;
  double applied(double t, std::span<const double> x, const InputValue& r) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& r) const override;
  /// The compensator's event functions (0 without one).
  int num_events() const override { return compensator_ ? compensator_->num_events() : 0; }
  void events(double t, std::span<const double> x, Inputs u, std::span<double> g) const override;
  void on_event(double t, std::span<double> x, Inputs u, int k) const override;

  /// Controller output (plant input unit) at time t (s), state x and reference r (value, rate and
  /// acceleration), saturated, the compensation included.
  double control(double t, std::span<const double> x, const InputValue& r) const;
  /// The compensation force (N or N m) at (t, x, r); 0 without a compensator.
  double compensation(double t, std::span<const double> x, const InputValue& r) const;
  const ControllerParams& controller() const { return c_; }
  const Plant& inner() const { return *inner_; }
  /// The compensator, or nullptr.
  const Compensator* compensator() const { return compensator_.get(); }

 private:
  CompensatorInput measured(double t, std::span<const double> x, const InputValue& r) const;
  double control(std::span<const double> x, const InputValue& r, double compensation) const;
  std::span<const double> own_states(std::span<const double> x) const;

  std::shared_ptr<const Plant> inner_;
  ControllerParams c_;
  std::shared_ptr<const Compensator> compensator_;
  int n_inner_;
  int n_comp_;
};

}  // namespace frictionlab
