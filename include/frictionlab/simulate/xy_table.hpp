#pragma once
// A two-axis (x-y) table: two independent linear axes, each a carriage on a ball screw driven by its
// own servo drive under its own PID position loop with velocity and acceleration feedforward. The
// plant of a circular (ballbar) test: as one axis reverses, static friction holds it for a moment
// while the other moves on, and the contour shows a glitch at each of the four quadrant crossings.
//
// Axis k (k = x, y), force-driven (the drive's force on the carriage, N), its PID the one of
// control/pid.hpp:
//   M_k a_k = u_k + offset_k - F_k(v_k)          (M_k: equivalent mass, F_k: its own law, offset_k a constant force)
//   u_k = sat_k(Kp e + Ki int(e) - Kd v + Kvff dr/dt + Kaff d2r/dt2 + c_k),  e = r_k - x_k
// with c_k an optional friction compensator's force (control/compensator.hpp), added before the
// saturation |u_k| <= limit_k. Continuous (Ts = 0): exactly ClosedLoop's position loop per axis.
// Sampled (Ts > 0): u_k is computed at t = j Ts from the sampled position, velocity and reference,
// the integral accumulates Ts e(j) (rectangle rule, e(j) included), and u_k is held until the next
// sample (delay 0) or applied one sample later (delay 1), as the EMPS loop (simulate/emps_pd_loop.hpp).

#include <memory>
#include <optional>
#include <string>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/control/pid.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// One axis of an XyTable: body, friction, drive and controller gains.
struct XyAxis {
  /// Moving mass (kg, >= 0): carriage and what rides on it. Default 0.
  double mass = 0.0;
  /// Rotating inertia (kg m^2, >= 0): motor rotor, screw, coupling, seen through the screw. Default 0.
  double inertia = 0.0;
  /// Screw lead (m/rev, > 0 when inertia > 0): carriage travel per screw revolution. Default 0.
  double lead = 0.0;
  /// Its friction law, a force (N) on the carriage against its velocity (m/s); empty (default) =
  /// the law given to simulate().
  std::optional<FrictionLaw> law;
  /// Position-loop gains in N: Kp (N/m), Ki (N/(m s)), Kd (N/(m/s)), Kvff (N/(m/s)), Kaff
  /// (N/(m/s^2)) and the drive's force limit `limit` (N, 0 = none): the saturation. `loop` must be
  /// position and compensation_gain 1 (the drive takes a force); Ts and delay stay 0 (the timing
  /// is XyTiming's, shared by both axes). Defaults: all 0.
  PidParams gains;
  /// Constant force on the carriage (N), added to the drive's: a cable chain's pull, gravity on
  /// an inclined axis, or an identified model's offset. Default 0.
  double offset = 0.0;
  /// Friction compensator (N) added to the command before the saturation; null = none (default).
  std::shared_ptr<const Compensator> compensator;

  /// Equivalent mass (kg) the drive moves: mass + inertia (2 pi / lead)^2, the rotating inertia
  /// reflected through the screw (a screw turning at 2 pi / lead rad per m of travel).
  double equivalent_mass() const;
};

/// The controller's timing, shared by both axes.
struct XyTiming {
  /// Sample period (s, >= 0); 0 = continuous controller (default).
  double Ts = 0.0;
  /// Samples from computing u(j) to applying it (sampled only): 0 (default) or 1.
  int delay = 0;
};

/// Two-axis table. Contacts "x" (states 0, 1: position m, velocity m/s) and "y" (states 2, 3), each
/// with its own law; inputs 0 and 1: the x and y position references (m), whose rate and
/// acceleration feed the feedforward terms. Then each axis's own states, x's block before y's:
/// the integral of the position error (m s), then, when sampled, the applied and the last computed
/// command (N), then its compensator's states. Signals of axis k: reference = r_k (m), drive = the
/// force the drive applies to the carriage (N: the held command when sampled; without the axis's
/// offset, which `applied` includes), current = voltage = 0.
///
/// Compensation (continuous, as ClosedLoop): the compensator's states are plant states following
/// Compensator::derivatives, its event functions are the plant's (x's first, then y's), its drive
/// input is the saturated command. Sampled: its states are discrete, advanced at every sample by
/// Compensator::update over the step just ended (the drive input is the command held over it),
/// and its output enters the command computed there; no event functions (a drive switches at its
/// samples). Its initial states come from rest at x = 0 with a zero reference, as in ClosedLoop.
class XyTable : public Plant {
 public:
  /// \throws std::invalid_argument naming the axis, the parameter, its value and unit when a mass,
  ///         inertia, lead or gain is negative or not finite, an offset is not finite, the equivalent mass is not > 0, an
  ///         inertia is given without a lead, a gain set is not a position loop with
  ///         compensation_gain 1 or has a Ts or delay of its own, Ts is negative or not finite, or
  ///         delay is not 0 or 1 (1 only when sampled).
  XyTable(XyAxis x, XyAxis y, XyTiming timing = {});

  std::string type() const override { return "xy-table"; }
  int num_states() const override { return 4 + own_[0] + own_[1]; }
  int num_inputs() const override { return 2; }
  int num_contacts() const override { return 2; }
  Contact contact(int i) const override;
  /// Equivalent mass of axis i (kg). \throws std::out_of_range unless i is 0 or 1.
  double inertia(int contact = 0) const override;
  void initial_extras(std::span<double> x) const override;
  void applied(double t, std::span<const double> x, Inputs u, std::span<double> force) const override;
  void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                   std::span<double> dx) const override;
  /// Analytic partials of derivatives() (the stiff engine's Newton matrix; layout as
  /// Plant::jacobian: dfdx num_states()^2 and dfdF num_states() x 2, row-major). Continuous: each
  /// axis's PID terms through the saturation (slope 1 while |command| <= limit, 0 beyond it), the
  /// compensator's partials from Compensator::jacobian (its output into the command, its state
  /// equations through the measured position, velocity and the saturated command). Sampled: the
  /// held command is a state and the discrete states do not move between samples. The axes do not
  /// couple: the x block never depends on y's states. Returns false, writing nothing, when a
  /// compensator of a continuous loop has no analytic partials (Compensator::jacobian returns
  /// false: a feedback compensation of a dynamic law): the engine then uses difference quotients.
  /// No allocation for compensators of up to 8 states.
  bool jacobian(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                std::span<double> dfdx, std::span<double> dfdF) const override;
  void signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const override;
  double sample_period() const override { return timing_.Ts; }
  void sample(double t, std::span<double> x, Inputs u) const override;
  /// The compensators' event functions (continuous controller only).
  int num_events() const override { return events_[0] + events_[1]; }
  void events(double t, std::span<const double> x, Inputs u, std::span<double> g) const override;
  void on_event(double t, std::span<double> x, Inputs u, int k) const override;

  /// The drive force of axis i (N) at (t, x, r): continuous, the saturated command with its
  /// compensation; sampled, the command held from the last sample.
  double command(int i, double t, std::span<const double> x, const InputValue& r) const;
  const XyAxis& axis(int i) const;
  const XyTiming& timing() const { return timing_; }

 private:
  bool sampled() const { return timing_.Ts > 0.0; }
  std::size_t block(int i) const { return static_cast<std::size_t>(i == 0 ? 4 : 4 + own_[0]); }
  std::size_t comp_offset() const { return sampled() ? 3 : 1; }
  CompensatorInput measured(int i, double t, std::span<const double> x, const InputValue& r) const;
  PidInput pid_input(int i, std::span<const double> x, const InputValue& r) const;
  double integral(int i, std::span<const double> x) const { return x[block(i)]; }

  XyAxis axes_[2];
  Pid pids_[2];
  XyTiming timing_;
  double mass_[2];
  int own_[2];
  int events_[2];
};

}  // namespace frictionlab
