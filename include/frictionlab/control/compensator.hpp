#pragma once
// What a friction compensator (feedforward, feedback, observer) provides to the loop that runs it:
// a force added to the controller's output, computed from the measurement, the reference and the
// compensator's own states, with the states' dynamics and the switches (event functions) at which
// its output changes formula. The control layer depends on models/ only: a closed loop (plants/)
// or a controller's sampled loop (an exported C header) runs a compensator through this interface.
//
// Sign convention (frictionlab's): friction F has the sign of the velocity and is subtracted,
// M a = drive - F. A compensator's output estimates F, so the loop ADDS it to its command.

#include <optional>
#include <span>
#include <string>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The signals a compensator sees at one instant. Units: m, m/s, m/s^2 and N on a linear axis;
/// rad, rad/s, rad/s^2 and N m on a rotary one.
struct CompensatorInput {
  double t = 0.0;                ///< time (s)
  double position = 0.0;         ///< measured position x (m or rad)
  double velocity = 0.0;         ///< measured velocity v (m/s or rad/s)
  double reference = 0.0;        ///< reference position r (m or rad)
  double reference_rate = 0.0;   ///< dr/dt (m/s or rad/s): the feedforward's velocity
  double reference_accel = 0.0;  ///< d2r/dt2 (m/s^2 or rad/s^2)
  /// Force the drive applies to the body (N or N m), this compensator's own output included: the
  /// input of an inverse-model observer. In a sampled loop: the force held over the step just ended.
  double drive = 0.0;
  /// The load the compensated contact transmits (N or N m; its magnitude counts), measured or
  /// estimated by the loop that runs the compensator: it raises the levels of a law with a load
  /// term (mu_load). 0 when the loop knows none.
  double load = 0.0;
  /// The contact's measured temperature (degC or K, the law's scale), for a law with a temperature
  /// term; none = the law's T_ref (no shift: the compensation is the law at its reference).
  std::optional<double> temperature;
};

/// A friction compensator: an immutable object (safe to share between threads and loops) whose
/// states live in the caller's state vector. Per-step calls never allocate.
///
/// Own states z (num_states() entries): continuous ones follow derivatives(); discrete ones (a
/// switching mode) have derivative 0 and change only in on_event() (continuous-time runs) or
/// update() (sampled runs).
///
/// Events: num_events() functions g_k(in, z), continuous in time between events, whose sign changes
/// mark the switches of the output's formula. A continuous-time runner locates every sign change
/// by root finding, stops there, calls on_event(k) once per function that changed sign (in
/// increasing k), and restarts its integrator: a switch is never stepped over, and between events
/// every call is smooth in its arguments.
class Compensator {
 public:
  virtual ~Compensator() = default;

  /// The compensation type as a scenario names it ("feedforward", "feedback", "lugre-observer",
  /// "disturbance-observer").
  virtual std::string type() const = 0;

  /// Number of own states (>= 0). Default 0.
  virtual int num_states() const { return 0; }
  /// Writes the states at the start of a run (num_states() entries of z) from the first input.
  /// Default: nothing (no states).
  virtual void initial_states(const CompensatorInput& in, std::span<double> z) const;

  /// The compensation force (N or N m) at `in` and states z (num_states() entries): the loop adds
  /// it to its command. Never reads in.drive (the drive contains this output), nor do events().
  virtual double output(const CompensatorInput& in, std::span<const double> z) const = 0;
  /// dz/dt (num_states() entries of dz; 0 for discrete states) at `in` and z. Default: zeros.
  virtual void derivatives(const CompensatorInput& in, std::span<const double> z, std::span<double> dz) const;

  /// Number of event functions (>= 0). Default 0.
  virtual int num_events() const { return 0; }
  /// The event functions g (num_events() entries) at `in` and z. Default: nothing.
  virtual void events(const CompensatorInput& in, std::span<const double> z, std::span<double> g) const;
  /// At a located sign change of g[k] (0 <= k < num_events()): rewrites the discrete states in z.
  /// Default: nothing.
  virtual void on_event(const CompensatorInput& in, std::span<double> z, int k) const;

  /// Partial derivatives at (in, z) with respect to the variables w = (position, velocity, drive,
  /// z[0], ..., z[n-1]) (m = 3 + n of them, n = num_states()): doutput (m entries: d output / d w[j])
  /// and dderiv (n * m entries, row-major: dderiv[i * m + j] = d dz[i]/dt / d w[j]). The reference
  /// is a function of time only and has no entry. Returns false, writing nothing, when there is no
  /// analytic form (default): a caller then uses difference quotients.
  virtual bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                        std::span<double> dderiv) const;

  /// The fixed-step form a controller's sampled loop runs (and an exported C header mirrors):
  /// advances z over the step of dt seconds (>= 0) just ended, holding `in` (the latest
  /// measurement and reference, and the drive force held over the step) constant over it, sets
  /// the discrete states from `in`, and returns output(in, z) at the new states (N or N m).
  /// Stable for any dt: each implementation integrates its linear part exactly.
  virtual double update(const CompensatorInput& in, std::span<double> z, double dt) const = 0;
};

}  // namespace frictionlab
