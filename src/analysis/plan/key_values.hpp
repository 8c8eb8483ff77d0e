#pragma once
// KEY=VALUE lists of the plan's --limits and --noise (private to analysis/plan).

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace frictionlab::plan_detail {

/// Each spec a comma-separated list of KEY=NUMBER; keys from `known` (name -> unit phrase).
/// \throws std::invalid_argument naming option, item and expectation.
inline std::map<std::string, double> parse_key_values(const std::vector<std::string>& specs, const std::string& option,
                                                      const std::map<std::string, std::string>& known) {
  auto known_list = [&] {
    std::string s;
    for (const auto& [k, unit] : known) s += (s.empty() ? "" : ", ") + k + " (" + unit + ")";
    return s;
  };
  std::map<std::string, double> out;
  for (const auto& spec : specs) {
    std::size_t start = 0;
    while (start <= spec.size()) {
      const std::size_t comma = spec.find(',', start);
      const std::string item = spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      start = comma == std::string::npos ? spec.size() + 1 : comma + 1;
      const std::size_t eq = item.find('=');
      if (eq == std::string::npos || eq == 0)
        throw std::invalid_argument(option + " '" + item + "': expected KEY=VALUE with KEY one of " + known_list());
      const std::string key = item.substr(0, eq), text = item.substr(eq + 1);
      if (!known.count(key))
        throw std::invalid_argument(option + " '" + item + "': unknown key '" + key + "'; expected one of " + known_list());
      double value = 0;
      std::size_t used = 0;
      try {
        value = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size() || std::isnan(value))
        throw std::invalid_argument(option + " '" + item + "': '" + text + "' is not a number (" + key + " in " +
                                    known.at(key) + ")");
      if (!out.emplace(key, value).second)
        throw std::invalid_argument(option + ": key '" + key + "' given twice");
    }
  }
  return out;
}

}  // namespace frictionlab::plan_detail
