#include "frictionlab/analysis/plan/noise.hpp"

#include <cmath>
#include <stdexcept>

#include "frictionlab/format.hpp"
#include "key_values.hpp"

namespace frictionlab {

void SensorNoise::validate(const std::string& option) const {
  auto check = [&](const char* key, double v, const char* unit) {
    if (!(v >= 0) || !std::isfinite(v))
      throw std::invalid_argument(option + " " + key + " = " + format_number(v) + " " + unit + " must be a finite number >= 0");
  };
  check("position", position, "m or rad");
  check("velocity", velocity, "m/s or rad/s");
  check("current", current, "A");
  check("force", force, "N or N m");
  check("encoder", encoder, "m or rad");
}

SensorNoise parse_sensor_noise(const std::vector<std::string>& specs, const std::string& option) {
  const auto kv = plan_detail::parse_key_values(specs, option,
                                                {{"position", "m or rad"},
                                                 {"velocity", "m/s or rad/s"},
                                                 {"current", "A"},
                                                 {"force", "N or N m"},
                                                 {"encoder", "m or rad per step"}});
  SensorNoise n;
  for (const auto& [k, v] : kv) {
    if (k == "position") n.position = v;
    else if (k == "velocity") n.velocity = v;
    else if (k == "current") n.current = v;
    else if (k == "force") n.force = v;
    else n.encoder = v;
  }
  n.validate(option);
  return n;
}

Eigen::VectorXd add_noise(const Eigen::VectorXd& clean, double std, std::mt19937_64& rng, double step) {
  Eigen::VectorXd out = clean;
  if (std > 0) {
    std::normal_distribution<double> n(0.0, std);
    for (Eigen::Index i = 0; i < out.size(); ++i) out[i] += n(rng);
  }
  if (step > 0) out = (out.array() / step).round() * step;
  return out;
}

}  // namespace frictionlab
