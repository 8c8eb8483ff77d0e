#include "frictionlab/identify/diagnostic_units.hpp"

#include <algorithm>
#include <iterator>
#include <nlohmann/json.hpp>

#include "frictionlab/identify/method.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

std::string diagnostic_unit(const Result& r, const std::string& group, const std::string& key) {
  if (group == "relative_error_percent_full_rate" || key.find("relative_error_percent") != std::string::npos) return "%";
  if (group == "iv_controller") {
    if (key == "sample_period") return "s";
    // The controller's values are options of the run (kp, drive_gain -> --kp, --drive-gain): their
    // recorded unit is the run's (OptionValues::unit).
    const auto it = r.json_sections.find("options");
    if (it == r.json_sections.end()) return "";
    const nlohmann::json options = nlohmann::json::parse(it->second, nullptr, false);
    std::string name = key;
    std::replace(name.begin(), name.end(), '_', '-');
    if (!options.is_object() || !options.contains(name) || !options[name].is_object()) return "";
    const auto unit = options[name].find("unit");
    return unit != options[name].end() && unit->is_string() ? unit->get<std::string>() : "";
  }
  if (group == "resampling") return key.rfind("dt", 0) == 0 || key == "max_gap" ? "s" : "";
  if (group == "defaults") return key == "cutoff_hz" ? "Hz" : key == "skip" ? "samples" : "";
  if (group == "adequacy") {
    if (key == "residual_std") return fit_signal_and_unit(r).second;
    if (key == "standstill_speed") return std::string(unit(Quantity::velocity, r.axis));
    return "";
  }
  // Groups of parameter values (not iv_instrument_correlation, whose keys name parameters too).
  static const char* const kEstimates[] = {"readoff", "ls_estimate", "start", "multistart", "static_fit"};
  if (std::find(std::begin(kEstimates), std::end(kEstimates), group) != std::end(kEstimates))
    if (const Parameter* p = r.find(key)) return p->unit;
  return "";
}

}  // namespace frictionlab
