// Compensations named by their spec: see include/frictionlab/control/compensation_spec.hpp.
#include "frictionlab/control/compensation_spec.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace frictionlab {

const std::vector<std::string>& compensation_types() {
  static const std::vector<std::string> types = {"feedforward", "feedback", "lugre-observer", "disturbance-observer"};
  return types;
}

CompensationParams make_compensation(std::string_view type, const std::map<std::string, double>& values,
                                     std::optional<double> model_inertia) {
  CompensationParams c;
  std::vector<std::pair<const char*, double*>> fields;  // the type's parameter names and slots
  if (type == "feedforward") {
    auto& p = c.emplace<FeedforwardParams>();
    fields = {{"band", &p.band}};
  } else if (type == "feedback") {
    auto& p = c.emplace<FeedbackParams>();
    fields = {{"dead_band", &p.dead_band}};
  } else if (type == "lugre-observer") {
    auto& p = c.emplace<LuGreObserverParams>();
    fields = {{"gain", &p.gain}};
  } else if (type == "disturbance-observer") {
    auto& p = c.emplace<DisturbanceObserverParams>();
    p.inertia = model_inertia.value_or(0.0);
    fields = {{"bandwidth", &p.bandwidth}, {"inertia", &p.inertia}};
  } else {
    std::string valid;
    for (const auto& t : compensation_types()) valid += (valid.empty() ? "" : ", ") + t;
    throw std::invalid_argument("compensation '" + std::string(type) + "' is not known; valid types: " + valid);
  }
  for (const auto& entry : values) {
    const auto& name = entry.first;  // not a structured binding: clang (the fuzz build) cannot capture one
    const auto value = entry.second;
    const auto it = std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return name == f.first; });
    if (it == fields.end()) {
      std::string has;
      for (const auto& f : fields) has += (has.empty() ? "" : ", ") + std::string(f.first);
      throw std::invalid_argument("compensation " + std::string(type) + " has no parameter '" + name + "'; it has " + has);
    }
    *it->second = value;
  }
  return c;
}

std::string compensation_type(const CompensationParams& c) {
  if (c.index() == 0) return "";
  return compensation_types()[c.index() - 1];
}

std::shared_ptr<const Compensator> make_compensator(const CompensationParams& params, const FrictionLaw* law) {
  return std::visit(
      [&](const auto& p) -> std::shared_ptr<const Compensator> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, std::monostate>) {
          return nullptr;
        } else if constexpr (std::is_same_v<P, DisturbanceObserverParams>) {
          return std::make_shared<const DisturbanceObserver>(p);
        } else {
          if (!law) throw std::invalid_argument("compensation " + compensation_type(params) + " needs a friction law");
          if constexpr (std::is_same_v<P, FeedforwardParams>) return std::make_shared<const FeedforwardCompensation>(*law, p);
          else if constexpr (std::is_same_v<P, FeedbackParams>) return std::make_shared<const FeedbackCompensation>(*law, p);
          else return std::make_shared<const LuGreObserver>(*law, p);
        }
      },
      params);
}

}  // namespace frictionlab
