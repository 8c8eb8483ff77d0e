#pragma once
// What every plant provides to the simulation engine: a 1-DOF system in which one body (the
// "friction body") rubs, with the friction force F subtracted from the net force on it
// (M a = applied - F, the sign convention of frictionlab).
//
// State layout, shared by all plants: x[0] = position (m or rad), x[1] = velocity (m/s or rad/s),
// x[2..] = the plant's other states (motor current, controller integrator, ...).

#include <span>
#include <string>

#include "frictionlab/simulate/input.hpp"

namespace frictionlab {

/// Plant signals besides the motion, recorded in a trajectory. Zero where a plant has no such
/// signal (current and voltage of an axis).
struct PlantSignals {
  double current = 0.0;    ///< motor current (A)
  double voltage = 0.0;    ///< motor terminal voltage (V)
  double reference = 0.0;  ///< the input signal: reference of a closed loop, command of an open one
                           ///< (spring-base: base position, m)
};

/// A 1-DOF plant. Implementations are immutable value-like objects, safe to share between threads.
class Plant {
 public:
  virtual ~Plant() = default;

  /// The scenario-file name of the plant type ("axis", "dc-motor", ...).
  virtual std::string type() const = 0;
  /// Number of states (>= 2; see the layout above).
  virtual int num_states() const = 0;
  /// Inertia of the friction body (kg or kg m^2), > 0 (a velocity drive may report 0).
  virtual double inertia() const = 0;
  /// True when the input imposes the velocity (velocity drive): x[1] = u(t), and `applied` is the
  /// force the drive supplies. The engine then never sticks the body.
  virtual bool kinematic() const { return false; }
  /// Sets the initial values of states x[2..] (x[0] and x[1] are set by the caller). Default 0.
  virtual void initial_extras(std::span<double> x) const;

  /// Net non-friction force on the friction body (N or N m) at time t (s), state x (num_states()
  /// entries) and input u. Friction balances it while stuck.
  virtual double applied(double t, std::span<const double> x, const InputValue& u) const = 0;

  /// State derivatives dx (num_states() entries) given the friction force (N or N m):
  /// dx[0] = x[1], dx[1] = (applied - friction) / M, dx[2..] the plant's own dynamics.
  /// No allocation (called at every integrator step).
  virtual void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                           std::span<double> dx) const = 0;

  /// Partial derivatives of derivatives() at (t, x, u, friction), for the stiff integrator's
  /// Newton matrix: dfdx (num_states()^2 entries, row-major: dfdx[i * n + j] = d dx[i] / d x[j])
  /// and dfdF (num_states() entries: d dx[i] / d friction). Returns false, writing nothing, when
  /// the plant has no analytic form (default): the engine then uses difference quotients.
  /// No allocation.
  virtual bool jacobian(double t, std::span<const double> x, const InputValue& u, double friction,
                        std::span<double> dfdx, std::span<double> dfdF) const;

  /// Current, voltage and reference at (t, x, u).
  virtual PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const;

  /// Sample period (s) of a discrete controller inside the plant (EmpsPdLoop); 0 = none, the
  /// plant is purely continuous (default). With a period Ts > 0 the engine stops at every
  /// t = k Ts (k = 0, 1, ...), calls sample() there, and restarts its integrator from the
  /// updated state, so the held controller output is piecewise constant (zero-order hold).
  virtual double sample_period() const { return 0.0; }

  /// The discrete update at a sample instant t (s): may rewrite the plant's discrete states in
  /// x[2..] (controller memory, held output; their derivatives are 0 between samples), never
  /// x[0] or x[1]. `u` is the input (reference) at t. Default: nothing.
  virtual void sample(double t, std::span<double> x, const InputValue& u) const;
};

}  // namespace frictionlab
