#pragma once
// A plant closed by a controller (control/): the plant's input becomes the controller's output,
// and the scenario's input becomes the reference; an optional friction compensator (control/)
// adds its force to the controller's command. close_loop() composes them; ClosedLoop runs a PID
// (control/pid.hpp), EmpsPdLoop (simulate/emps_pd_loop.hpp) the EMPS controller.

#include <memory>
#include <variant>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/control/emps_pd.hpp"
#include "frictionlab/control/pid.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/simulate/compensation_conditions.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The body a closed loop measures (its controller's and its compensator's position and
/// velocity): the plant's contact (the body the friction acts on; the default), or on a backlash
/// axis (plants/backlash_axis.hpp) its motor or its load by name.
enum class MeasuredBody { contact, motor, load };

/// A PID (control/pid.hpp) closed around `inner` (a 1-DOF plant). States: the inner plant's, then
/// the PID's own (continuous: the integral of the error; sampled: the integral, the applied and
/// the last computed output), then the compensator's own states (none without a compensator).
/// Signals: the inner plant's at the controller output (drive: the force it commands; sampled: at
/// the held output), with reference = r.
///
/// Compensation: the compensator's output (N or N m), times compensation_gain, adds to the PID and
/// feedforward terms BEFORE the saturation, so a saturated loop cannot exceed its limit with it.
/// The loop measures the contact's position and velocity (x[0], x[1]), or on a backlash axis the
/// body measuring() names (a drive's encoder on the motor, a linear scale on the load).
/// The compensator sees the measured position and velocity and, in a position loop,
/// r with its rate and acceleration; in a velocity loop r is its reference velocity (rate r,
/// acceleration dr/dt) and its reference position is the measured one (no position error). Its
/// drive input is the inner plant's drive signal at the saturated output (the force applied).
/// Its event functions are the loop's own (Plant::num_events, events, on_event), so the engine
/// locates its switches. Its initial states come from the initial position and velocity and the
/// reference at t = 0 (initial_extras with the inputs; without them: from rest at x = 0 with a
/// zero reference). In fixed-step mode its states advance by the compensator's own fixed-step
/// update (Compensator::update, what a drive runs, stable at any step), with the drive force held
/// over the step, instead of explicit Euler.
///
/// Sampled PID (Ts > 0): the engine stops at t = j Ts (Plant::sample_period) and the PID computes
/// its output there from the sampled measurement and reference (Pid::sample); the compensator's
/// states are discrete, advanced at every sample by Compensator::update over the step just ended
/// (the drive input: the inner plant's drive at the output held over it), and its output enters
/// the output computed there; no event functions (a drive switches at its samples).
class ClosedLoop : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument as PidParams::validate("controller") (a gain or the limit
  ///         negative or not finite, Kd != 0 in a velocity loop, compensation_gain not > 0, a bad
  ///         Ts or delay), or when `inner` is null, kinematic or not 1-DOF.
  ClosedLoop(std::shared_ptr<const Plant> inner, PidParams c, std::shared_ptr<const Compensator> compensator = nullptr);
  std::string type() const override { return inner_->type(); }
  Axis motion_axis() const override { return inner_->motion_axis(); }
  int num_states() const override { return n_inner_ + n_pid_ + n_comp_; }
  double inertia(int = 0) const override { return inner_->inertia(); }
  void initial_extras(std::span<double> x) const override;
  void initial_extras(std::span<double> x, Inputs u) const override;
  /// True with a compensator that has states (continuous PID only).
  bool has_fixed_step_update() const override { return n_comp_ > 0 && !pid_.sampled(); }
  void fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before, std::span<double> x,
                         Inputs u) const override;
  double applied(double t, std::span<const double> x, const InputValue& r) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& r) const override;
  /// The PID's sample period (s; 0 continuous).
  double sample_period() const override { return pid_.params().Ts; }
  using SingleContactPlant::sample;
  void sample(double t, std::span<double> x, const InputValue& r) const override;
  /// The inner plant's event functions (a backlash's impacts, at the controller output), then the
  /// compensator's (none without one, or with a sampled PID).
  int num_events() const override;
  bool guard_event(int k) const override;
  void events(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
              std::span<double> g) const override;
  /// The same with no friction on the contact (0 N).
  void events(double t, std::span<const double> x, Inputs u, std::span<double> g) const override;
  void on_event(double t, std::span<double> x, Inputs u, int k) const override;

  /// Controller output (plant input unit) at time t (s), state x and reference r (value, rate and
  /// acceleration), saturated, the compensation included; sampled: the output held since the last
  /// sample.
  double control(double t, std::span<const double> x, const InputValue& r) const;
  /// The compensation force (N or N m) at (t, x, r); 0 without a compensator.
  double compensation(double t, std::span<const double> x, const InputValue& r) const;
  const PidParams& controller() const { return pid_.params(); }
  const Plant& inner() const { return *inner_; }
  /// The compensator, or nullptr.
  const Compensator* compensator() const { return compensator_.get(); }
  /// This loop with its compensator given the conditions `c` (replacing any it had).
  std::shared_ptr<const ClosedLoop> with_conditions(CompensationConditions c) const;
  const CompensationConditions& conditions() const { return conditions_; }
  /// This loop measuring `body`'s position and velocity instead of the contact's.
  /// \throws std::invalid_argument "controller.measure: ..." when body is motor or load and the
  ///         inner plant is not a backlash axis (it has one body).
  std::shared_ptr<const ClosedLoop> measuring(MeasuredBody body) const;
  MeasuredBody measured_body() const { return measured_body_; }

 private:
  CompensatorInput measured(double t, std::span<const double> x, const InputValue& r) const;
  PidInput pid_input(std::span<const double> x, const InputValue& r) const;
  double control(std::span<const double> x, const InputValue& r, double compensation) const;
  std::span<const double> own_states(std::span<const double> x) const;

  std::shared_ptr<const Plant> inner_;
  Pid pid_;
  std::shared_ptr<const Compensator> compensator_;
  CompensationConditions conditions_;
  MeasuredBody measured_body_ = MeasuredBody::contact;
  std::size_t pos_ = 0;  ///< state index of the measured position; its velocity is the next one
  int n_inner_;
  int n_pid_;
  int n_comp_;
};

/// A controller for close_loop: a PID or the EMPS controller.
using Controller = std::variant<PidParams, EmpsPdParams>;

/// The plant `plant` (a 1-DOF plant: an axis, a pendulum, a DC motor) closed by `controller`,
/// with an optional friction compensator whose force (N or N m) the controller adds to its
/// command: a ClosedLoop for a PID, an EmpsPdLoop for the EMPS controller. The returned plant's
/// input is the reference (m or rad; m/s or rad/s for a velocity loop).
/// \throws std::invalid_argument what the loop's constructor throws: a parameter out of range
///         (naming it, its value and unit), or a plant that is null, kinematic or not 1-DOF.
std::shared_ptr<const Plant> close_loop(std::shared_ptr<const Plant> plant, const Controller& controller,
                                        std::shared_ptr<const Compensator> compensator = nullptr);

}  // namespace frictionlab
