#pragma once
// The files of `frictionlab plan`: the prior model (MODEL.json as `identify --json` writes it, or
// a law file) and the plant scenario, read into the rig a plan is made for (analysis/plan/rig.hpp).

#include <string>

#include "frictionlab/analysis/plan/rig.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Reads the prior (its "law", or the file as a law; parameters.M, when present, replaces an
/// axis plant's inertia; "axis" sets the units) and the scenario (its friction section may be
/// absent: the prior's law replaces it; its input is replaced by the plan's).
/// \throws std::invalid_argument naming the file and key (read_model_json, load_scenario,
///         make_plan_rig).
PlanRig load_plan_rig(const std::string& prior_path, const std::string& scenario_path);

}  // namespace frictionlab
