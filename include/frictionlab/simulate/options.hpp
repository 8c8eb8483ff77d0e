#pragma once
// Options of a simulation run: duration, output rate, initial state and the solver.

#include <vector>

#include "frictionlab/simulate/environment.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How the engine integrates.
enum class SolverMode {
  /// Pick by law: dynamic laws -> stiff; static laws with stiction (breakaway > 0) -> hybrid;
  /// continuous static laws (viscous, smooth, zero levels) -> stiff (a plain BDF integration).
  automatic,
  /// Exact stick/slip for static laws: stuck and sliding modes, switches located by root finding.
  /// Refused for dynamic laws.
  hybrid,
  /// CVODE BDF with a dense Newton solver on the full state (plant + law states). For static laws
  /// the friction is the sliding force (no stiction), so it is refused for laws with a breakaway
  /// level > 0: use hybrid or fixed-step.
  stiff,
  /// A controller's discrete loop at rate 1/dt: symplectic Euler for the motion, explicit Euler
  /// for the other plant states, FrictionLaw::force(v, applied) for static laws (the Karnopp band
  /// matters here) and FrictionLaw::step for dynamic ones.
  fixed_step,
};

/// Options of simulate(). Times in s.
struct SimulationOptions {
  /// Simulated time (s), > 0. Default 10.
  double duration = 10.0;
  /// Output samples per second (Hz), > 0: rows at t = k / output_rate, k = 0 .. floor(duration *
  /// output_rate). Default 100. Output does not limit the integrator's steps (it interpolates).
  double output_rate = 100.0;
  /// Initial position (m or rad). Default 0.
  double initial_position = 0.0;
  /// Initial velocity (m/s or rad/s). Default 0. Dynamic laws start at their zero state (z = 0).
  double initial_velocity = 0.0;
  /// Plants with several contacts: initial position and velocity of each contact (one entry per
  /// contact, m or rad, m/s or rad/s); empty (default) = initial_position and initial_velocity
  /// for every contact.
  std::vector<double> initial_positions, initial_velocities;
  /// Solver choice. Default automatic.
  SolverMode mode = SolverMode::automatic;
  /// Relative tolerance of CVODE, > 0. Default 1e-8: tighter costs steps, looser shifts event times.
  double rtol = 1e-8;
  /// Absolute tolerance of CVODE on the plant states (m, m/s, rad, rad/s, A), > 0. Default 1e-10.
  /// Law states (bristle deflections, ~Fc/sigma0) get atol scaled by their size: atol * z_scale
  /// with z_scale = the largest steady-state deflection at 1 m/s, so that 1e-10 resolves them as
  /// finely as a position of 1 m.
  double atol = 1e-10;
  /// Step of the fixed-step mode (s), > 0; 1/output_rate must be a whole multiple of it.
  /// Default 1e-4. Trade-off: the error of the discrete loop is O(dt); large steps chatter
  /// around v = 0 for laws without a Karnopp band.
  double dt = 1e-4;
  /// Largest CVODE step (s); 0 = no limit (default). The engine already stops at every corner of
  /// the input and limits the step for a sine input; set it when the plant has fast features the
  /// integrator could step over while stuck.
  double max_step = 0.0;
  /// Largest number of CVODE steps in the whole run before it gives up (runtime_error). Default 10^7.
  long max_steps = 10'000'000;
  /// The load and temperature each contact works at (environment.hpp), for laws with load or
  /// temperature effects: empty (default) = none (load 0, the laws' T_ref); else one entry per
  /// contact. A contact with an environment records its load and temperature columns.
  std::vector<ContactEnvironment> environments;
};

/// Name of a solver mode as in scenario files ("auto", "hybrid", "stiff", "fixed-step").
const char* solver_mode_name(SolverMode mode);

}  // namespace frictionlab
