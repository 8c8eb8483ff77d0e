// The figure series of IDIM's condition terms (load, temperature, ripple): see
// src/identify/idim_internal.hpp. They feed the command line's report figures and Python's
// fl.plot.load_map, ripple and temperature alike.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "frictionlab/models/scalar.hpp"
#include "idim_internal.hpp"

namespace frictionlab::detail {
namespace {

const std::vector<double>* series_of(const Result& r, const char* name) {
  const auto it = r.series.find(name);
  return it == r.series.end() || it->second.empty() ? nullptr : &it->second;
}

}  // namespace

void add_idim_condition_series(Result& r, const IdimData& data, const IdimOptions& o) {
  const auto* t = series_of(r, "time");
  const auto* friction = series_of(r, "friction");
  const auto* friction_model = series_of(r, "friction_model");
  if (!r.ok() || !t || !friction || !friction_model) return;
  // Each fitted sample is a sample of the record: found by its time.
  const Eigen::Index n = data.time.size();
  std::vector<Eigen::Index> at;
  at.reserve(t->size());
  for (const double ti : *t)
    at.push_back(std::clamp<Eigen::Index>(std::lower_bound(data.time.data(), data.time.data() + n, ti) - data.time.data(), 0, n - 1));
  const auto sampled = [&](const Eigen::VectorXd& col) {
    std::vector<double> out;
    out.reserve(at.size());
    for (const auto k : at) out.push_back(col[k]);
    return out;
  };
  if (const Parameter* mu = r.find("mu_load"); mu && data.load.size() == n) {
    r.series["load"] = sampled(data.load.cwiseAbs());
    // law_force is the friction terms at the record's mean |load|: the same at zero load.
    const double mean_load = data.load.cwiseAbs().mean();
    const auto *lv = series_of(r, "law_velocity"), *lF = series_of(r, "law_force");
    if (lv && lF && lv->size() == lF->size()) {
      std::vector<double> zero(lF->size());
      for (std::size_t i = 0; i < zero.size(); ++i) zero[i] = (*lF)[i] - mu->value * mean_load * sgn((*lv)[i]);
      r.series["law_force_zero_load"] = std::move(zero);
    }
  }
  if (r.find("Fv_per_K") && r.find("Fv") && data.temperature.size() == n && r.diagnostics.numbers.count("temperature_ref")) {
    const double Fv = r.value("Fv"), per_K = r.value("Fv_per_K"), ref = r.diagnostics.numbers.at("temperature_ref");
    r.series["temperature"] = sampled(data.temperature);
    std::vector<double> viscous;
    viscous.reserve(at.size());
    for (const double T : r.series["temperature"]) viscous.push_back(Fv + per_K * (T - ref));
    r.series["temperature_viscous"] = std::move(viscous);
  }
  const double P = o.ripple_period;
  if (r.find("ripple_sin_1") && data.position.size() == n && P > 0) {
    std::vector<double> a, b;  // the identified harmonics (N or N m)
    for (int h = 1; r.find("ripple_sin_" + std::to_string(h)); ++h)
      a.push_back(r.value("ripple_sin_" + std::to_string(h))), b.push_back(r.value("ripple_cos_" + std::to_string(h)));
    const auto ripple = [&](double q) {
      double f = 0;
      for (std::size_t h = 0; h < a.size(); ++h) {
        const double w = 2 * std::numbers::pi * static_cast<double>(h + 1) * q / P;
        f += a[h] * std::sin(w) + b[h] * std::cos(w);
      }
      return f;
    };
    // The partial residual: the fit's residual plus the identified ripple, against the position
    // within the period.
    std::vector<double> phase, partial;
    for (std::size_t i = 0; i < at.size(); ++i) {
      const double q = data.position[at[i]];
      phase.push_back(q - P * std::floor(q / P));
      partial.push_back((*friction)[i] - (*friction_model)[i] + ripple(q));
    }
    r.series["ripple_position"] = std::move(phase);
    r.series["ripple_partial"] = std::move(partial);
    constexpr int kCurve = 200;  // points of the identified ripple over one period
    std::vector<double> qc, fc;
    for (int i = 0; i <= kCurve; ++i) qc.push_back(P * i / kCurve), fc.push_back(ripple(qc.back()));
    r.series["ripple_curve_position"] = std::move(qc);
    r.series["ripple_curve_force"] = std::move(fc);
  }
}

}  // namespace frictionlab::detail
