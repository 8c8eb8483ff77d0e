// Two-axis validation on a circular test: see include/frictionlab/analysis/contour_validation.hpp.
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/analysis/contour_validation.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace frictionlab {
namespace {

const std::vector<double>& series(const Result& r, const std::string& name) {
  const auto it = r.series.find(name);
  if (it == r.series.end()) throw std::logic_error("validate_contour: validate_axes gave no series " + name);
  return it->second;
}

// 100 ||a - b|| / ||a|| (%), NaN when a is zero.
double relative_error(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0, n = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d += (a[i] - b[i]) * (a[i] - b[i]);
    n += a[i] * a[i];
  }
  return n > 0 ? 100.0 * std::sqrt(d / n) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

ContourValidation validate_contour(const Scenario& scenario, const MultiAxisValidationData& data,
                                   const std::map<std::string, IdentifiedModel>& models,
                                   const ValidateOptions& options) {
  for (const char* axis : {"x", "y"}) {
    bool found = false;
    for (const AxisRecord& a : data.axes) found = found || a.name == axis;
    if (!found)
      throw std::invalid_argument((data.file.empty() ? std::string("validate") : data.file) + ": no " + axis +
                                  " position; a circular test needs both axes, x and y");
  }
  ContourValidation out;
  out.result = validate_axes(scenario, data, models, options);
  Result& r = out.result;
  const std::vector<double>& t = series(r, "time");
  const std::vector<double>&xr = series(r, "x.reference"), &yr = series(r, "y.reference");
  try {
    // Both paths about the reference's centre and radius: the glitches are where the axes reverse.
    out.measured = analyze_contour(t, series(r, "x.position"), series(r, "y.position"), xr, yr);
    out.simulated = analyze_contour(t, series(r, "x.position_sim"), series(r, "y.position_sim"), xr, yr);
  } catch (const std::invalid_argument& e) {
    out.measured.reset();
    out.simulated.reset();
    r.diagnostics.warnings.push_back(std::string("no contour figures (quadrant glitches, roundness): ") + e.what());
    return out;
  }
  const ContourResult &m = *out.measured, &s = *out.simulated;
  nlohmann::json c;
  c["measured"] = nlohmann::json::parse(contour_json(m));
  c["simulated"] = nlohmann::json::parse(contour_json(s));
  c["difference"] = {{"max_quadrant_glitch_m", max_quadrant_glitch(s) - max_quadrant_glitch(m)},
                     {"roundness_m", s.roundness_m - m.roundness_m},
                     {"max_radial_error_m", s.max_radial_error_m - m.max_radial_error_m}};
  const double e = relative_error(m.radial_error, s.radial_error);
  c["relative_error_percent"] = {{"radial_error", std::isfinite(e) ? nlohmann::json(e) : nlohmann::json(nullptr)}};
  r.validation->json_sections["contour"] = json_text(c);
  r.diagnostics.numbers["max_quadrant_glitch_m"] = max_quadrant_glitch(m);
  r.diagnostics.numbers["max_quadrant_glitch_sim_m"] = max_quadrant_glitch(s);
  r.diagnostics.numbers["roundness_m"] = m.roundness_m;
  r.diagnostics.numbers["roundness_sim_m"] = s.roundness_m;
  r.diagnostics.numbers["radial_error_relative_error_percent"] = e;
  return out;
}

}  // namespace frictionlab
