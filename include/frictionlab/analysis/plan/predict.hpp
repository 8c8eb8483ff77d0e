#pragma once
// Predicting what an experiment will give before it is run: simulate the profile on the prior
// (once: the simulation is deterministic), add the stated sensor noise R times with seeded
// generators, run the method's identification on each noisy copy, and take the spread of the
// estimates (Monte Carlo). For the least-squares methods (idim: linear, sweep: the static fit)
// the Fisher-information std s^2 (J'J)^-1 that each identification reports is averaged too.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "frictionlab/analysis/plan/design.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/simulate/trajectory.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What the rig would record: samples at the profile's rate (SI units, length N each).
struct PlanMeasurement {
  Eigen::VectorXd time;       ///< s
  Eigen::VectorXd position;   ///< m or rad (noise and encoder quantisation added)
  Eigen::VectorXd velocity;   ///< m/s or rad/s (noise added)
  Eigen::VectorXd force;      ///< drive force, N or N m: Kt times the noisy current, or the noisy force
  Eigen::VectorXd reference;  ///< the command at each sample (command unit), exact
  /// The load (N or N m) and the contact's temperature (degC or K) at each sample, as the rig
  /// logs them (exact: the plan's noise is on the motion and force sensors); empty when the run
  /// has no environment.
  Eigen::VectorXd load, temperature;
};

/// Simulates the profile on the rig's plant with friction `law` (the prior's, or a different
/// "true" law for a check), sampled at profile.sample_rate over profile.duration; a profile's
/// load (load-steps) is the contact's load signal (the scenario's environment keeps its
/// temperature or thermal model).
/// \throws std::runtime_error when the integrator fails; std::invalid_argument for bad options.
Trajectory simulate_profile(const ExperimentProfile& profile, const PlanRig& rig, const FrictionLaw& law);

/// One noisy record of a clean simulation: noise drawn from `rng` in the order position,
/// velocity, force (current). A zero std draws nothing.
PlanMeasurement measure(const Trajectory& clean, const PlanRig& rig, const ExperimentProfile& profile,
                        const SensorNoise& noise, std::mt19937_64& rng);

/// The options the plan identifies a sweep record with: a Stribeck fit when the prior has vs,
/// else coulomb-viscous; segments found on `reference` (the set points, m/s or rad/s, length N).
SweepOptions plan_sweep_options(const PlanRig& rig, const Eigen::VectorXd& reference);

/// The options the plan identifies an idim record with: the recipe's cut-off, decimation and
/// skip from the sample rate (idim_rate_defaults), the default terms, and for the effects' plans
/// the term they are for: load-steps "load", warm-up "temperature" (T_ref the prior's, so Fv is
/// the prior's Fv at T_ref), ripple-scan "ripple" (the prior's period and harmonics), and the
/// profile's figure "exclude_below" (m/s or rad/s) when it has one (ripple-scan: rows at rest,
/// where stiction holds the ripple, left out).
IdimOptions plan_idim_options(const PlanRig& rig, PlanMethod method = PlanMethod::idim,
                              const ExperimentProfile* profile = nullptr);

/// The idim data of a measurement: time, position, force, and its load and temperature columns.
IdimData plan_idim_data(const PlanMeasurement& m);

/// The method's identification of a record as a user would run it on the rig's data:
/// breakaway (identify_breakaway, inertia estimated), sweep (identify_sweep with the profile's
/// set points as the reference, a Stribeck fit when the prior has vs, else coulomb-viscous),
/// idim (identify_idim, recipe from the sample rate), lugre (identify_lugre with the rig's inertia).
Result identify_measurement(PlanMethod method, const PlanMeasurement& data, const PlanRig& rig,
                            const ExperimentProfile& profile);

/// The spread of one parameter over the runs.
struct ParameterSpread {
  std::string name;
  std::string unit;
  double prior = 0.0;  ///< the prior's value (NaN when the prior has none), unit
  double mean = 0.0;   ///< mean of the estimates, unit
  /// Sample standard deviation of the estimates (n - 1), unit; NaN when undetermined.
  double std_monte_carlo = 0.0;
  /// Root mean square of the std each identification reported (s^2 (J'J)^-1 with the residual
  /// variance s^2 of each noisy fit), unit; NaN for breakaway and lugre, and when undetermined.
  double std_fisher = 0.0;
  /// The a-priori std (analysis/plan/fisher.hpp: the Fisher information of the noise-free plan
  /// and the stated noise), unit; NaN for breakaway and lugre, and when undetermined. Filled by
  /// plan_experiment, not by monte_carlo_spread.
  double std_a_priori = std::numeric_limits<double>::quiet_NaN();
  int runs = 0;  ///< runs that gave a finite estimate
  bool undetermined = false;
};

/// Result of the Monte Carlo prediction.
struct MonteCarloSpread {
  int runs = 0;    ///< identifications attempted
  int failed = 0;  ///< of which gave no answer (status error)
  std::uint64_t seed = 0;
  std::vector<ParameterSpread> parameters;  ///< in the method's parameter order
  /// breakaway: the spread of the lecture's read-offs (diagnostics.readoff Fs, Fc, Fv).
  std::vector<ParameterSpread> readoff;
  std::vector<std::string> undetermined;  ///< parameters the runs could not determine
  /// Undetermined parameters, failed runs, and biases the spread cannot explain (a mean off the
  /// prior by more than 4 standard errors and 1 %: the method, not the noise, limits it).
  std::vector<std::string> warnings;
  std::string first_failure;  ///< message of the first failed run
  /// The spread of `name`. \throws std::invalid_argument listing the names.
  const ParameterSpread& parameter(const std::string& name) const;
};

/// Called after each run with the run number (1..runs) and the count.
using PlanProgress = std::function<void(int run, int runs)>;

/// Runs `runs` (>= 2) identifications on noisy copies of `clean`; run k uses
/// std::mt19937_64(std::seed_seq{seed, k}), so predictions with different seeds are independent.
/// A parameter is undetermined when most runs report it so (std NaN) or when `profile` names it.
/// \throws std::invalid_argument when runs < 2.
MonteCarloSpread monte_carlo_spread(PlanMethod method, const ExperimentProfile& profile, const PlanRig& rig,
                                    const Trajectory& clean, const SensorNoise& noise, int runs, std::uint64_t seed,
                                    const PlanProgress& progress = {});

}  // namespace frictionlab
