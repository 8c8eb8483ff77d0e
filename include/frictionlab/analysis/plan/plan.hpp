#pragma once
// `frictionlab plan`: design an identification experiment from a prior model and a rig, and
// predict the standard deviation of each parameter before anything is run (analysis/plan/*.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "frictionlab/analysis/plan/design.hpp"
#include "frictionlab/analysis/plan/predict.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct PlanOptions {
  PlanDesignOptions design;
  PlanLimits limits;
  SensorNoise noise;
  /// Monte Carlo runs (>= 2); 0 (default): 40 for breakaway, sweep and idim, 8 for lugre (whose
  /// output-error fit takes about a second per run).
  int runs = 0;
  std::uint64_t seed = 1;  ///< first seed of the runs' generators
  PlanProgress progress;   ///< optional, after each run
};

/// A plan: the profile, what a simulation of it on the prior showed, and the prediction.
struct PlanResult {
  bool ok = true;
  std::string message;  ///< why no prediction could be made (every run failed); empty when ok
  std::string method;
  ExperimentProfile profile;
  MonteCarloSpread prediction;
  /// Figures of the clean simulation on the prior: peak |velocity|, |position - start|, peak
  /// |force| (and |current|), breakaway and stop times where they apply.
  std::vector<PlanFigure> simulated;
  std::vector<std::string> warnings;      ///< the design's and the prediction's
  std::vector<std::string> undetermined;  ///< parameters with std null
  std::string prior_file, scenario_file, drive;
  Axis axis = Axis::linear;
};

/// Designs the profile, simulates it on the prior, checks the simulated speed, force and travel
/// against the limits, and predicts the std by Monte Carlo and, for sweep and idim, a priori
/// (analysis/plan/fisher.hpp); a parameter whose a-priori information is singular is undetermined.
/// \throws std::invalid_argument as design_experiment, and naming the limit when the simulated
///         run exceeds it; std::runtime_error when the simulation fails.
PlanResult plan_experiment(PlanMethod method, const PlanRig& rig, const PlanOptions& options = {});

/// JSON text: {"schema": 1, "status": "ok"|"error", "message", "method", "prior": {"file"},
/// "scenario": {"file", "drive"}, "axis", "profile": {"file" (when given), "columns", "command",
/// "unit", "duration_s", "sample_rate_hz", "samples", "design": {NAME: {"value", "unit", "what"}},
/// "windows": [{"kind", "t_begin_s", "t_end_s", "level"}]}, "simulated": {NAME: {"value",
/// "unit"}}, "noise": {...}, "limits": {...} (null for none), "prediction": {"runs", "failed",
/// "seed", "parameters": {NAME: {"prior", "mean", "bias" (mean - prior), "std", "std_monte_carlo",
/// "std_fisher" (RMS of the std the noisy fits report), "std_a_priori" (Fisher information of the
/// noise-free plan, analysis/plan/fisher.hpp; sweep and idim), "relative_std_percent", "unit", "runs"}}, "readoff": {...} (breakaway)}, "undetermined": [...],
/// "warnings": [...]}. "std" is the Monte Carlo std; null for an undetermined parameter (as are
/// its Fisher and a-priori std and other non-finite numbers).
std::string plan_to_json(const PlanResult& result, const PlanOptions& options, const std::string& profile_file = "",
                         int indent = 2);

}  // namespace frictionlab
