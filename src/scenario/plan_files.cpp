#include "frictionlab/scenario/plan_files.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/scenario.hpp"

namespace frictionlab {

PlanRig load_plan_rig(const std::string& prior_path, const std::string& scenario_path) {
  const nlohmann::json j = read_model_json(prior_path);
  const FrictionLaw law = j.contains("law") && j["law"].is_object() ? law_from_json(j["law"], prior_path + ": law")
                                                                     : law_from_json(j, prior_path);
  const std::optional<double> inertia = model_inertia(j, prior_path);
  std::optional<Axis> axis;
  if (j.contains("axis")) {
    if (!j["axis"].is_string())
      throw std::invalid_argument(prior_path + ": axis: expected \"linear\" or \"rotary\", got " + j["axis"].dump());
    try {
      axis = parse_axis(j["axis"].get<std::string>());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(prior_path + ": axis: " + e.what());
    }
  }
  ScenarioOptions so;
  so.law = law;
  so.model_source = prior_path;
  const Scenario sc = load_scenario(scenario_path, so);
  return make_plan_rig(sc, law, inertia, axis, scenario_path, prior_path);
}

}  // namespace frictionlab
