#include "frictionlab/identify/method.hpp"

#include <stdexcept>

namespace frictionlab {

const std::vector<MethodInfo>& identification_methods() {
  // One line per method: name, summary, fitted signal and its quantity.
  static const std::vector<MethodInfo> methods = {
      {"idim", "inverse dynamic model least squares on a trajectory", "drive force", Quantity::force},
      {"breakaway", "torque-mode trapezoid experiment: breakaway, Coulomb and viscous levels", "applied force",
       Quantity::force},
      {"sweep", "constant-velocity tests: a friction-velocity map and a fitted static law", "friction force",
       Quantity::force},
      {"decay", "free oscillation: friction from the energy lost per half cycle", "energy lost per half cycle",
       Quantity::energy},
      {"lugre", "LuGre parameters by output error on the position", "position", Quantity::displacement},
      {"validate", "simulation of an identified model against a measured run", "", std::nullopt},
  };
  return methods;
}

const MethodInfo& method_info(std::string_view name) {
  std::string names;
  for (const auto& m : identification_methods()) {
    if (m.name == name) return m;
    names += (names.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument("identification method '" + std::string(name) + "' is not known; expected one of " +
                              names);
}

Result new_result(const MethodInfo& method, const std::string& model, Axis axis) {
  Result r;
  r.method = method.name;
  r.model = model;
  r.axis = axis;
  r.fit.quantity = method.fit_signal;
  if (method.fit_quantity) r.fit.unit = std::string(unit(*method.fit_quantity, axis));
  return r;
}

std::pair<std::string, std::string> fit_signal_and_unit(const Result& r) {
  if (!r.fit.quantity.empty() || !r.fit.unit.empty()) return {r.fit.quantity, r.fit.unit};
  for (const auto& m : identification_methods())
    if (m.name == r.method && m.fit_quantity) return {m.fit_signal, std::string(unit(*m.fit_quantity, r.axis))};
  return {};
}

}  // namespace frictionlab
