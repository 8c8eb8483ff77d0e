#include "frictionlab/analysis/plan/limits.hpp"

#include <cmath>
#include <stdexcept>

#include "frictionlab/format.hpp"
#include "key_values.hpp"

namespace frictionlab {

void PlanLimits::validate(const std::string& option) const {
  auto positive = [&](const char* key, double v, const char* unit) {
    if (!(v > 0)) throw std::invalid_argument(option + " " + key + " = " + format_number(v) + " " + unit + " must be > 0");
  };
  positive("current", current, "A");
  positive("force", force, "N or N m");
  positive("speed", speed, "m/s or rad/s");
  positive("travel", travel, "m or rad");
  if (!(min_speed >= 0) || !std::isfinite(min_speed))
    throw std::invalid_argument(option + " min_speed = " + format_number(min_speed) + " m/s or rad/s must be a finite number >= 0");
  if (min_speed >= speed)
    throw std::invalid_argument(option + " min_speed = " + format_number(min_speed) + " must be below speed = " +
                                format_number(speed) + " (m/s or rad/s)");
}

PlanLimits parse_plan_limits(const std::vector<std::string>& specs, const std::string& option) {
  const auto kv = plan_detail::parse_key_values(specs, option,
                                                {{"current", "A"},
                                                 {"force", "N or N m"},
                                                 {"speed", "m/s or rad/s"},
                                                 {"min_speed", "m/s or rad/s"},
                                                 {"travel", "m or rad"}});
  PlanLimits l;
  for (const auto& [k, v] : kv) {
    if (k == "current") l.current = v;
    else if (k == "force") l.force = v;
    else if (k == "speed") l.speed = v;
    else if (k == "min_speed") l.min_speed = v;
    else l.travel = v;
  }
  l.validate(option);
  return l;
}

}  // namespace frictionlab
