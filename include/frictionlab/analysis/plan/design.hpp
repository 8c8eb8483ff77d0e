#pragma once
// Designing the excitation of an identification experiment from a prior model and the rig:
//   breakaway  a trapezoid of current or force: a ramp slow against the mechanical time
//              constant tau = M / Fv (its lag biases the stop read-off by rate * tau, kept below
//              lag_fraction Fc), a peak margin * Fs above the prior's breakaway level, a hold of
//              5 tau to settle plus an averaging time for the noise, a ramp down and a rest;
//   sweep      a staircase of velocity set points, log-spaced from below the prior's vs (vs / 5)
//              to the top speed, both directions, each held for the loop's measured settling
//              time (a simulated step on the prior, 1.5 times the 2 % time) plus an averaging
//              time from the force noise;
//   idim       a trapezoidal velocity profile of the position reference: moves out and back
//              over the travel at 1, 1/2 and 1/4 of the top speed, accelerations whose inertia
//              force is comparable to the friction, rests in between (M, Fv, Fc and offset);
//   load-steps the idim moves repeated at loads 0, Lmax / 2 and Lmax (a load column the rig
//              applies, changed while the axis rests): mu_load (and load_gain) by idim's "load"
//              term, the load not following the speed;
//   warm-up    the moves out and back at the top speed and half of it, repeated for 2 thermal
//              time constants (the scenario's environment: {thermal: ...}) while the friction
//              heats the contact: Fv_per_K by idim's "temperature" term, the temperature not
//              following the speed schedule (both speeds in every heat);
//   ripple-scan slow moves out and back over several ripple periods (the prior's ripple_period P)
//              at a speed whose ripple frequency K v / P is 1/20 of idim's low-pass at most, and at
//              half of it: the ripple's harmonics by idim's "ripple" term;
//   lugre      a presliding sine of 0.8 Fs, 1 Hz, 2 cycles (bristle stiffness and damping) then 5 cycles of a sliding sine
//              of margin * Fs, its frequency chosen so that travel and speed stay within limits
//              while the speed passes well over vs.
// Every level is checked against the limits; a limit that leaves no experiment is an error
// naming the limit and what the plan needed.

#include <string>

#include "frictionlab/analysis/plan/limits.hpp"
#include "frictionlab/analysis/plan/noise.hpp"
#include "frictionlab/analysis/plan/profile.hpp"
#include "frictionlab/analysis/plan/rig.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The methods a plan can be made for.
enum class PlanMethod { breakaway, sweep, idim, lugre, load_steps, warm_up, ripple_scan };

/// True for the methods identified by idim (idim and the effects' designs).
inline bool is_idim_plan(PlanMethod m) {
  return m == PlanMethod::idim || m == PlanMethod::load_steps || m == PlanMethod::warm_up || m == PlanMethod::ripple_scan;
}

/// Parses "breakaway", "sweep", "idim", "lugre", "load-steps", "warm-up", "ripple-scan".
/// \throws std::invalid_argument listing them.
PlanMethod parse_plan_method(const std::string& name);
const char* plan_method_name(PlanMethod method);

/// Choices of the design; defaults follow the seeds (the lecture's trapezoid, the paper's 15 speeds).
struct PlanDesignOptions {
  /// breakaway: peak force / prior Fs (default 1.4, the lecture's 0.15 A over 0.1064 A);
  /// lugre: sliding amplitude / Fs (default used there: 2).  Must be > min_margin.
  double margin = 0.0;
  /// Smallest peak / Fs a limit may push the plan to before it is refused. Default 1.1.
  double min_margin = 1.1;
  /// breakaway: the ramp's lag bias at the stop read-off, rate * tau, as a fraction of Fc. Default 0.01.
  double lag_fraction = 0.01;
  /// sweep: speeds per direction (>= 4). Default 15 (the paper).
  int speeds = 15;
  /// Hz of the profile and of the simulated measurement; 0 (default): the scenario's output_rate.
  double sample_rate = 0.0;
  /// load-steps: the largest load the rig applies, Lmax (N or N m, > 0; needed by load-steps).
  double load = 0.0;
  /// warm-up: length of the run (s, > 0); 0 (default): 2 thermal time constants of the scenario's
  /// environment (the temperature rises by 86 % of its way to steady state).
  double warm_up = 0.0;
  /// ripple-scan: ripple periods each move covers (>= 2). Default 4.
  int ripple_periods = 4;
  /// \throws std::invalid_argument naming the option.
  void validate() const;
};

/// Designs the profile of `method` for `rig` within `limits`; `noise` sets averaging times.
/// \throws std::invalid_argument naming the limit that makes the plan impossible (e.g. "--limits
///         current = 0.1 A is below 1.1 Fs / Kt = 0.117 A: the motor would not break away with
///         margin"), a drive the method cannot use (breakaway and lugre need force or current
///         drive, sweep a velocity loop, idim a position loop), or a prior without what the
///         method needs (breakaway: Fv > 0; lugre: a lugre law; ripple-scan: a ripple), naming
///         the prior file, a missing --load (load-steps) or thermal model (warm-up: the scenario's
///         environment), a travel shorter than the ripple periods (ripple-scan).
ExperimentProfile design_experiment(PlanMethod method, const PlanRig& rig, const PlanLimits& limits,
                                    const SensorNoise& noise, const PlanDesignOptions& options = {});

}  // namespace frictionlab
