#include "frictionlab/analysis/plan/profile.hpp"

#include <cmath>
#include <stdexcept>

#include "frictionlab/format.hpp"

namespace frictionlab {


double ExperimentProfile::figure(const std::string& name) const {
  std::string names;
  for (const auto& f : figures) {
    if (f.name == name) return f.value;
    names += (names.empty() ? "" : ", ") + f.name;
  }
  throw std::invalid_argument("plan " + method + ": no figure '" + name + "'; the figures are " + names);
}

std::vector<std::string> ExperimentProfile::column_names() const {
  std::string unit = command_unit;
  for (auto& c : unit)
    if (c == ' ' || c == '/') c = '_';
  std::vector<std::string> names{"time_s", command + "_" + unit};
  if (load) {
    std::string lu = load_unit;
    for (auto& c : lu)
      if (c == ' ') c = '_';
    names.push_back("load_" + lu);
  }
  return names;
}

void ExperimentProfile::samples(std::vector<double>& time, std::vector<double>& command_values) const {
  const auto n = static_cast<std::size_t>(std::floor(duration * sample_rate + 1e-9)) + 1;
  time.resize(n);
  command_values.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    time[k] = static_cast<double>(k) / sample_rate;
    command_values[k] = signal.at(time[k]).value;
  }
}

std::string ExperimentProfile::to_csv() const {
  std::vector<double> t, u;
  samples(t, u);
  const auto names = column_names();
  std::string out = names[0] + "," + names[1] + (load ? "," + names[2] : std::string()) + "\n";
  out.reserve(out.size() + t.size() * (load ? 36 : 24));
  for (std::size_t k = 0; k < t.size(); ++k)
    out += format_exact(t[k]) + "," + format_exact(u[k]) + (load ? "," + format_exact(load->at(t[k]).value) : std::string()) + "\n";
  return out;
}

}  // namespace frictionlab
