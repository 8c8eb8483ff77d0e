#pragma once
// What every plant provides to the simulation engine: a system in which one or more bodies rub
// ("contacts"), each with the friction force F_k subtracted from the net force on it
// (M_k a_k = applied_k - F_k, the sign convention of frictionlab).
//
// State layout: each contact names the state indices of its position (m or rad) and velocity
// (m/s or rad/s); the other states are the plant's own (motor current, controller integrator,
// held controller output, ...). A 1-DOF plant (SingleContactPlant, every plant but MultiAxis)
// keeps x[0] = position, x[1] = velocity, x[2..] = its other states.

#include <span>
#include <string>

#include "frictionlab/core/input.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

class FrictionLaw;  // models/friction_law.hpp

/// Where one friction contact lives in the plant's state, and its law.
struct Contact {
  std::string name;                  ///< column prefix ("x", "y", "joint2"); "" for the one contact of a 1-DOF plant
  int position = 0;                  ///< state index of the contact's position (m or rad)
  int velocity = 1;                  ///< state index of its velocity (m/s or rad/s)
  const FrictionLaw* law = nullptr;  ///< its law, owned by the plant; nullptr = the law given to simulate()
};

/// Signals of one contact besides the motion, recorded in a trajectory. Zero where a plant has no
/// such signal (current and voltage of an axis).
struct PlantSignals {
  double current = 0.0;    ///< motor current (A)
  double voltage = 0.0;    ///< motor terminal voltage (V)
  double reference = 0.0;  ///< the input signal: reference of a closed loop, command of an open one
                           ///< (spring-base: base position, m)
  double drive = 0.0;      ///< force the drive or controller commands on the contact (N or N m): the
                           ///< input force of an open axis, gtau v of the EMPS loop, Kt i of a motor
};

/// A plant with num_contacts() friction contacts. Implementations are immutable value-like
/// objects, safe to share between threads. Spans: x has num_states() entries, u num_inputs(),
/// friction and force num_contacts().
class Plant {
 public:
  virtual ~Plant() = default;

  /// The scenario-file name of the plant type ("axis", "dc-motor", ...).
  virtual std::string type() const = 0;
  /// How the plant moves, so that results and figures are in its units: rotary (rad, N m) for a
  /// pendulum or a motor, linear (m, N) otherwise. Default linear.
  virtual Axis motion_axis() const { return Axis::linear; }
  /// Number of states (>= 2 num_contacts()).
  virtual int num_states() const = 0;
  /// Number of inputs (>= 1). Default 1.
  virtual int num_inputs() const { return 1; }
  /// Number of friction contacts (>= 1). Default 1.
  virtual int num_contacts() const { return 1; }
  /// Contact i (0 <= i < num_contacts()). Default: the one contact of a 1-DOF plant, at x[0], x[1],
  /// with the law given to simulate().
  virtual Contact contact(int i) const;
  /// Inertia of contact i's body (kg or kg m^2), > 0 (a velocity drive may report 0).
  virtual double inertia(int contact = 0) const = 0;
  /// True when the input imposes the velocity (velocity drive, 1-DOF only): x[1] = u(t), and
  /// `applied` is the force the drive supplies. The engine then never sticks the body.
  virtual bool kinematic() const { return false; }
  /// Sets the initial values of the states that are not a contact's position or velocity (those
  /// are set by the caller). Default 0. The engine calls the overload with the inputs below.
  virtual void initial_extras(std::span<double> x) const;
  /// The same at the start of a run, given what the plant's own states may need to start
  /// consistent with (a controller's or an observer's states: with the measurement and the
  /// reference): x holds every contact's initial position and velocity already, u the inputs at
  /// t = 0 (value, rate and acceleration). The engine calls this one. Default: initial_extras(x).
  virtual void initial_extras(std::span<double> x, Inputs u) const;

  /// Net non-friction force on each contact's body (N or N m) at time t (s), state x and inputs u;
  /// friction balances it while stuck. Contract: contact i obeys M_i dv_i/dt = applied_i - F_i,
  /// with applied_i independent of every friction force (friction enters only its own contact's
  /// equation), so stuck contacts are decided one by one. Writes num_contacts() entries.
  virtual void applied(double t, std::span<const double> x, Inputs u, std::span<double> force) const = 0;

  /// State derivatives dx (num_states() entries) given the friction force on every contact
  /// (N or N m): dx[position_i] = x[velocity_i], dx[velocity_i] = (applied_i - friction_i) / M_i,
  /// the plant's own dynamics for the other states. No allocation (called at every step).
  virtual void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                           std::span<double> dx) const = 0;

  /// Partial derivatives of derivatives() at (t, x, u, friction), for the stiff integrator's
  /// Newton matrix: dfdx (n*n, row-major: dfdx[i * n + j] = d dx[i] / d x[j]) and dfdF
  /// (n * num_contacts(), row-major: dfdF[i * nc + k] = d dx[i] / d F_k). Returns false, writing
  /// nothing, when the plant has no analytic form (default): the engine then uses difference
  /// quotients. No allocation.
  virtual bool jacobian(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                        std::span<double> dfdx, std::span<double> dfdF) const;

  /// Signals of every contact (num_contacts() entries). Default: reference = input i's value
  /// (0 beyond the inputs), the rest 0.
  virtual void signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const;

  /// Sample period (s) of a discrete controller inside the plant (EmpsPdLoop); 0 = none, the
  /// plant is purely continuous (default). With a period Ts > 0 the engine stops at every
  /// t = k Ts (k = 0, 1, ...), calls sample() there, and restarts its integrator from the
  /// updated state, so the held controller output is piecewise constant (zero-order hold).
  virtual double sample_period() const { return 0.0; }

  /// The discrete update at a sample instant t (s): may rewrite the plant's discrete states in x
  /// (controller memory, held output; their derivatives are 0 between samples), never a contact's
  /// position or velocity. `u` are the inputs at t. Default: nothing.
  virtual void sample(double t, std::span<double> x, Inputs u) const;

  /// Number of the plant's own event functions (a compensator's switch at v = 0, an observer's
  /// mode change). Default 0.
  virtual int num_events() const { return 0; }
  /// The event functions g (num_events() entries) at (t, x, u): the engine locates every sign
  /// change of g[k] by root finding, stops there, calls on_event(k) and restarts its integrator,
  /// so a discontinuity of the plant's right-hand side is never stepped over. Default: nothing.
  virtual void events(double t, std::span<const double> x, Inputs u, std::span<double> g) const;
  /// The event functions given the friction force on every contact (num_contacts() entries, N or
  /// N m), for a plant whose events depend on it (the force between two bodies, one of which
  /// rubs). The engine calls this one. Default: events(t, x, u, g).
  virtual void events(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                      std::span<double> g) const;
  /// True when event function k is a guard of the plant's current mode: g[k] >= 0 while the mode
  /// holds, and on_event(k) leaves a mode whose guard is crossing downward (an impact, a
  /// separation). The engine watches only downward crossings of a guard and, right after any
  /// event (and at the start), fires at once each guard that is already negative, so that a mode
  /// entered at an impact that cannot hold is left at the same instant: a guard that was just
  /// reached must therefore not read negative from rounding (the plant allows for it). Default
  /// false (an event function whose every sign change counts).
  virtual bool guard_event(int k) const;
  /// At event k (located at time t): may rewrite the plant's own discrete states in x and, for an
  /// impact, a contact's velocity (never its position): the engine then decides the contact's
  /// mode again (a stuck body struck into motion slides). Default: nothing.
  virtual void on_event(double t, std::span<double> x, Inputs u, int k) const;

  /// True when the plant advances some of its own states by a discrete rule of its own in
  /// fixed-step mode (fixed_step_update). Asked once per run. Default false.
  virtual bool has_fixed_step_update() const { return false; }
  /// Fixed-step mode: the plant's own update over the step of dt seconds that ends at time t (s).
  /// `before` is the state at t - dt and `u_before` the inputs there (what was held over the
  /// step); x is the state at t after the engine's step of every state (symplectic Euler for the
  /// contacts, explicit Euler for the other states) and u the inputs at t. The plant rewrites in
  /// x the states it advances itself, from their values in `before` (a compensator's fixed-step
  /// form, what a drive runs, stable at any dt where explicit Euler is not), never a contact's
  /// position or velocity. Called only when has_fixed_step_update(); before sample() and the
  /// event check at t. Default: nothing.
  virtual void fixed_step_update(double t, double dt, std::span<const double> before, Inputs u_before,
                                 std::span<double> x, Inputs u) const;
};

/// Convenience base of a 1-DOF plant: one contact at x[0], x[1], one input. It implements the
/// span-based Plant methods on top of scalar ones, so a 1-DOF plant reads as a scalar system.
class SingleContactPlant : public Plant {
 public:
  /// Net non-friction force on the body (N or N m) at time t (s), state x and input u.
  virtual double applied(double t, std::span<const double> x, const InputValue& u) const = 0;
  /// dx (num_states() entries) given the friction force (N or N m): dx[0] = x[1],
  /// dx[1] = (applied - friction) / M, dx[2..] the plant's own dynamics. No allocation.
  virtual void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                           std::span<double> dx) const = 0;
  /// dfdx (n*n row-major) and dfdF (n entries); false, writing nothing, when there is no analytic
  /// form (default).
  virtual bool jacobian(double t, std::span<const double> x, const InputValue& u, double friction,
                        std::span<double> dfdx, std::span<double> dfdF) const;
  /// Current, voltage, reference and drive at (t, x, u). Default: reference = u, the rest 0.
  virtual PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const;
  /// The discrete update at a sample instant (see Plant::sample). Default: nothing.
  virtual void sample(double t, std::span<double> x, const InputValue& u) const;

  // The span-based methods, forwarding to the scalar ones with u[0] and friction[0].
  void applied(double t, std::span<const double> x, Inputs u, std::span<double> force) const final {
    force[0] = applied(t, x, u[0]);
  }
  void derivatives(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                   std::span<double> dx) const final {
    derivatives(t, x, u[0], friction[0], dx);
  }
  bool jacobian(double t, std::span<const double> x, Inputs u, std::span<const double> friction,
                std::span<double> dfdx, std::span<double> dfdF) const final {
    return jacobian(t, x, u[0], friction[0], dfdx, dfdF);
  }
  void signals(double t, std::span<const double> x, Inputs u, std::span<PlantSignals> out) const final {
    out[0] = signals(t, x, u[0]);
  }
  void sample(double t, std::span<double> x, Inputs u) const final { sample(t, x, u[0]); }

 protected:
  // Scalar calls into a wrapped 1-DOF plant (the inner plant of a closed loop), whatever its class.
  static double applied_of(const Plant& p, double t, std::span<const double> x, const InputValue& u);
  static void derivatives_of(const Plant& p, double t, std::span<const double> x, const InputValue& u, double friction,
                             std::span<double> dx);
  static PlantSignals signals_of(const Plant& p, double t, std::span<const double> x, const InputValue& u);
  /// The checks of a loop closed around `inner`: it exists, its velocity is not imposed, and it has one
  /// contact and one input.
  /// \throws std::invalid_argument prefixed by `who` ("controller") naming what is wrong.
  static void require_loop_plant(const Plant* inner, const char* who);
};

}  // namespace frictionlab
