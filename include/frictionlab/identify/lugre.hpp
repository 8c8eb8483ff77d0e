#pragma once
// LuGre identification by output error (Canudas de Wit et al. 1995's model on a rigid axis):
// simulate M x'' = u(t) - F_lugre(z, x') with the measured applied force u(t) as input, compare
// the simulated position with the measured one, and minimise the squared difference over the
// dynamic parameters sigma0, sigma1 (and the static ones Fc, Fs, vs, sigma2 unless given) with
// Ceres (automatic differentiation through the fixed-step simulation of the library's own
// LuGreT<T>, so the fit simulates exactly the law `simulate` does, vd included).
//
// Static part first, unless given: velocity and acceleration of the measured position by central
// differences, friction = u - M a on the sliding samples, a Stribeck fit (fit_static_law) for Fc
// and sigma2. Fs and vs are not seen by the sliding samples of a record driven fast (its vs
// collapses there), so they start from a multi-start: a grid of (Fs, vs) pairs, each simulated
// once over the record, ranked by output error; the fit runs from the best-ranked pairs until one
// reproduces the record to its noise.

#include <Eigen/Core>
#include <functional>
#include <optional>

#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Samples of an experiment on a rigid axis. Shapes: all of length N >= 3, time strictly
/// increasing and regularly sampled. The record should start at rest (bristles unloaded) and
/// contain presliding (forces below the breakaway level) and sliding.
struct LugreData {
  Eigen::VectorXd time;      ///< s
  Eigen::VectorXd force;     ///< applied force or torque u(t) (N or N m), an input
  Eigen::VectorXd position;  ///< m or rad
};

/// Progress of the output-error fit: called after each Ceres iteration with the iteration number
/// (0 = the start), the cost (half the sum of squared position residuals, m^2 or rad^2) and the
/// seconds since the fit began.
using LugreProgress = std::function<void(int iteration, double cost, double elapsed_seconds)>;

struct LugreOptions {
  /// Inertia M (kg or kg m^2), required, > 0.
  double inertia = 0.0;
  /// The static part (Fc, Fs, vs, delta, sigma2 = Fv) when known, e.g. from a sweep. Accepted
  /// laws: stribeck, lugre (its static parameters), static-coulomb-viscous (vs from
  /// `stribeck_velocity`), coulomb-viscous (Fs = Fc). Held fixed in the fit. Absent (default):
  /// identified from the record first and refined in the output error.
  std::optional<FrictionLaw> static_law;
  /// Stribeck exponent delta of the identified law (dimensionless, > 0). Default 2 (Gaussian,
  /// as in Canudas de Wit 1995). Held fixed: output error cannot tell it from vs on usual records.
  double delta = 2.0;
  /// Stribeck velocity (m/s or rad/s) used with a static-coulomb-viscous `static_law`, which has
  /// none. Default 0.001.
  double stribeck_velocity = 0.001;
  /// Damping decay velocity vd (m/s or rad/s, >= 0) of the revisited LuGre damping
  /// sigma1 exp(-(v/vd)^2) (Canudas de Wit 1998); 0 (default) = constant damping sigma1. Held
  /// fixed: the fit simulates with it. A `static_law` of kind lugre with vd > 0 gives its own.
  double vd = 0.0;
  /// Integration substeps per sample interval (>= 1) of the fit's second-order fixed-step
  /// simulation. The bristle-mass resonance sqrt(sigma0/M) (316 rad/s for Table I) and the
  /// reversals need a step well below the sample time of 1 kHz data: 4 substeps keep the
  /// simulation within about 2 um of CVODE over a second of Table I sliding (error ~ 1/substeps^2).
  /// Trade-off: run time grows linearly. Default 4.
  int substeps = 4;
  /// Ceres iteration limit of the output-error fit. Default 50.
  int max_iterations = 50;
  /// Called after each iteration (optional): for progress display.
  LugreProgress progress;
  Axis axis = Axis::linear;  ///< units of the report
};

/// The options of a LuGre fit from the values of its option table (method_info(MethodId::lugre));
/// the table's defaults where a value is not given. The static law (a file or a Python law) and
/// the axis are the caller's to set.
LugreOptions make_lugre_options(const OptionValues& values);

/// Identifies the LuGre parameters of a rigid axis from applied force and position.
/// The output error is taken over windows: from the record's start (at rest, z = 0) to the first
/// velocity peak, then from each peak to the next, each window restarted with the bristles in
/// steady sliding from its own initial position and velocity, fitted with the law (started from
/// the measured ones), so that neither one reversal's error nor the noise of a measured start
/// carries over the record. With the static part identified, each start of the multi-start is
/// fitted jointly, then (if that does not reach the noise) in two stages: sigma0 and sigma1 with
/// the static part held, then all together; at most 4 fits.
/// parameters: sigma0 (N/m), sigma1 (N s/m), sigma2 (N s/m), Fc (N), Fs (N), vs (m/s) with
/// standard deviations from s^2 A^-1 at the solution, A = J'J with the windows' starts eliminated,
/// through identify/uncertainty.hpp: NaN, a flag and a warning for a parameter at a bound of the
/// fit or not determined by the record (near-singular information, or a std above the value);
/// 0 for values held from `static_law`; delta (and vd when > 0) held, std 0.
/// fit: relative error (%) and RMSE (m) of the simulated position.
/// diagnostics: numbers "iterations", "cost_initial", "cost_final" (m^2),
/// "substeps", "windows", "passive" (1 / 0), "static_given" (1 / 0), "presliding_samples", and
/// with the static part identified "fits" and "position_noise_std" (m, from fourth differences);
/// groups "start" (the starting values) and, when identified, "static_fit" (the static Stribeck
/// fit on the sliding samples) and "multistart" (the best-ranked pair); correlation (the six or
/// two fitted parameters), undetermined, at_bound; warnings (among them the passivity verdict
/// when the identified set is not passive, and non-convergence).
/// Adequacy (identify/adequacy.hpp) on the force: u - M a - F_LuGre along the measured motion
/// (the bristle state integrated from z = 0), against velocity, position and time
/// (diagnostics.adequacy, residual_by_*, warnings naming lugre's remedies).
/// law: the lugre LawSpec. series: "time", "position", "position_sim" (the windowed simulation
/// of the identified model), "position_free_run" (the identified model simulated over the whole
/// record from its start; diagnostics "free_run_relative_error_percent"), "force" (length N).
/// A record without sliding (when the static part must be identified) or without any motion gives
/// status "error" with a message saying so.
/// Figures that overflow double precision (values or scales beyond what it holds) give status
/// "error" with code "output.not_finite" naming the figure (finite_or_error,
/// identify/finite_result.hpp), never an ok result with inf in it.
/// \throws std::invalid_argument when options.inertia is not > 0 (naming --inertia and its unit),
///         on unequal lengths, non-finite samples, irregular time, substeps < 1, or a `static_law`
///         of an unsupported kind.
Result identify_lugre(const LugreData& data, const LugreOptions& options);

/// The work budget of identify_lugre on `samples` samples (frictionlab/budget.hpp): samples x
/// options.substeps x (options.max_iterations + 1) simulation steps. identify_lugre checks it
/// first; a caller that must convert or load the samples (Python's arrays, a data file's columns)
/// checks it before that, so a record too large is refused before any work on it.
/// \throws InputError(budget.work, option --substeps) naming the samples, --substeps,
///         --max-iterations, the steps and the budget (and `--budget FACTOR`) when it exceeds it.
void check_lugre_work(double samples, const LugreOptions& options);

}  // namespace frictionlab
