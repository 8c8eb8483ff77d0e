#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <string_view>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab::cli {
namespace {

std::string label(std::string_view quantity, Quantity q, Axis axis) {
  return std::string(quantity) + " (" + std::string(unit(q, axis)) + ")";
}

std::string force_name(Axis axis) { return axis == Axis::rotary ? "torque" : "force"; }

const std::vector<double>* find(const Result& r, const std::string& name) {
  const auto it = r.series.find(name);
  return it == r.series.end() || it->second.empty() ? nullptr : &it->second;
}

FigureSeries series(std::string name, std::vector<double> x, std::vector<double> y,
                    SeriesStyle style = SeriesStyle::lines, std::string color = {}) {
  FigureSeries s;
  s.name = std::move(name);
  const std::size_t n = std::min(x.size(), y.size());
  x.resize(n);
  y.resize(n);
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  s.color = std::move(color);
  return s;
}

FigurePanel time_panel(std::string y_label, bool zero_line = true) {
  FigurePanel p;
  p.x_label = "time (s)";
  p.y_label = std::move(y_label);
  p.zero_line = zero_line;
  p.tight_x = true;
  return p;
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::string title_for(const Result& r, const std::string& what) {
  // A validation is drawn against its own run, not the identification data the model came from.
  const std::string& file = r.method == "validate" && r.validation ? r.validation->file : r.data_file;
  return what + (file.empty() ? "" : " - " + file_name(file));
}

double parameter(const Result& r, const std::string& name) {
  const ParameterEstimate* p = r.find(name);
  return p ? p->value : std::numeric_limits<double>::quiet_NaN();
}

// Value of one fitted envelope model at time t (s). decay_envelope fits the linear model in
// absolute time and the exponential ones in time since the first peak time.
double fit_at(const EnvelopeResult& e, const EnvelopeFit& f, bool linear, double t) {
  if (linear) return f.q + f.slope * t;
  const double t0 = e.peak_times.empty() ? 0.0 : e.peak_times.front();
  return f.p * std::exp(-f.lambda * (t - t0)) + f.q;
}

// The chosen envelope model at time t.
double envelope_at(const EnvelopeResult& e, double t) {
  switch (e.kind) {
    case DecayKind::linear: return fit_at(e, e.linear, true, t);
    case DecayKind::exponential: return fit_at(e, e.exponential, false, t);
    case DecayKind::mixed: return fit_at(e, e.mixed, false, t);
    case DecayKind::none: break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

std::string kind_words(DecayKind k) {
  switch (k) {
    case DecayKind::linear: return "linear (Coulomb)";
    case DecayKind::exponential: return "exponential (viscous)";
    case DecayKind::mixed: return "mixed (Coulomb + viscous)";
    case DecayKind::none: break;
  }
  return "none";
}

// The position signal with its turning points and the fitted envelope drawn as +-A(t) about the
// centre of the oscillation (the mean of the midpoints of consecutive turning points).
FigurePanel position_with_envelope(std::span<const double> t, std::span<const double> x,
                                   const std::vector<double>& peak_t, const std::vector<double>& peak_x,
                                   const std::optional<EnvelopeResult>& env, const std::string& y_label) {
  FigurePanel p = time_panel(y_label);
  p.series.push_back(series("measured", {t.begin(), t.end()}, {x.begin(), x.end()}, SeriesStyle::lines, "#0072b2"));
  if (!peak_t.empty()) p.series.push_back(series("turning points", peak_t, peak_x, SeriesStyle::points, "#d55e00"));
  if (env && env->kind != DecayKind::none && !t.empty() && !env->peak_times.empty()) {
    double centre = 0;
    if (peak_x.size() >= 2) {
      for (std::size_t i = 1; i < peak_x.size(); ++i) centre += 0.5 * (peak_x[i] + peak_x[i - 1]);
      centre /= static_cast<double>(peak_x.size() - 1);
    }
    const double t0 = t.front(), t1 = env->peak_times.back();
    std::vector<double> tt, up, lo;
    constexpr int kPoints = 300;
    for (int i = 0; i < kPoints; ++i) {
      const double ti = t0 + (t1 - t0) * i / (kPoints - 1);
      // A fitted half swing at t_k is the mean of the swings ending at t_(k-1) and t_k: the
      // amplitude of the signal half a half period earlier.
      const double a = std::max(0.0, envelope_at(*env, ti + 0.5 * env->half_period));
      tt.push_back(ti);
      up.push_back(centre + a);
      lo.push_back(centre - a);
    }
    p.series.push_back(series("fitted envelope: " + kind_words(env->kind), tt, up, SeriesStyle::lines, "#009e73"));
    p.series.push_back(series("", tt, lo, SeriesStyle::lines, "#009e73"));
  }
  return p;
}

Figure idim_figure(const Result& r) {
  Figure f;
  f.title = title_for(r, "IDIM least squares: measured and reconstructed " + force_name(result_axis(r)));
  const Axis axis = result_axis(r);
  const auto *t = find(r, "time"), *y = find(r, "force"), *m = find(r, "force_model");
  if (!t || !y) return f;
  FigurePanel p = time_panel(label("drive " + force_name(axis), Quantity::force, axis));
  p.series.push_back(series("measured", *t, *y, SeriesStyle::lines, "#0072b2"));
  if (m) p.series.push_back(series("model (M a + friction + offset)", *t, *m, SeriesStyle::lines, "#d55e00"));
  f.panels.push_back(p);
  if (m) {
    std::vector<double> e(std::min(y->size(), m->size()));
    for (std::size_t i = 0; i < e.size(); ++i) e[i] = (*y)[i] - (*m)[i];
    FigurePanel q = time_panel(label("residual", Quantity::force, axis));
    q.series.push_back(series("measured - model", *t, e, SeriesStyle::lines, "#555555"));
    f.panels.push_back(q);
  }
  return f;
}

// A law's curve, v ascending: discontinuous at v = 0, so a gap there (a NaN, which gnuplot leaves
// undrawn), not a vertical line through the origin.
FigureSeries gapped_at_zero(const std::string& name, const std::vector<double>& v, const std::vector<double>& F) {
  FigureSeries s = series(name, {}, {}, SeriesStyle::lines, "#d55e00");
  for (std::size_t i = 0; i < std::min(v.size(), F.size()); ++i) {
    if (i > 0 && (v[i - 1] < 0) != (v[i] < 0)) {
      s.x.push_back(std::numeric_limits<double>::quiet_NaN());
      s.y.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    s.x.push_back(v[i]);
    s.y.push_back(F[i]);
  }
  return s;
}

Figure sweep_figure(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Friction map: steady segments and the fitted " + r.model + " law");
  f.panel_height = 520;
  FigurePanel p;
  p.x_label = label("velocity", Quantity::velocity, axis);
  p.y_label = label("friction " + force_name(axis), Quantity::force, axis);
  p.zero_line = true;
  p.key = "top left";
  if (const auto *v = find(r, "velocity"), *F = find(r, "force"); v && F) {
    FigureSeries s = series("steady segments (mean +- std)", *v, *F, SeriesStyle::errorbars, "#0072b2");
    if (const auto* sd = find(r, "force_std"); sd && sd->size() == s.y.size()) s.y_error = *sd;
    else s.y_error.assign(s.y.size(), 0.0);
    p.series.push_back(s);
  }
  if (const auto *v = find(r, "law_velocity"), *F = find(r, "law_force"); v && F) {
    p.series.push_back(gapped_at_zero("fitted " + r.model + " law", *v, *F));
  }
  f.panels.push_back(p);
  return f;
}

Figure breakaway_figure(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Breakaway experiment: applied " + force_name(axis) + " and velocity");
  const auto *t = find(r, "time"), *F = find(r, "force"), *v = find(r, "velocity");
  if (!t) return f;
  if (F) {
    FigurePanel p = time_panel(label("applied " + force_name(axis), Quantity::force, axis));
    p.key = "top left";
    p.series.push_back(series("applied", *t, *F, SeriesStyle::lines, "#0072b2"));
    const auto tb = r.diagnostics.numbers.find("breakaway_time");
    const double Fs = parameter(r, "Fs"), Fc = parameter(r, "Fc");
    if (tb != r.diagnostics.numbers.end() && std::isfinite(Fs))
      p.series.push_back(series("breakaway (Fs)", {tb->second}, {Fs}, SeriesStyle::points, "#d55e00"));
    if (std::isfinite(Fc))
      p.series.push_back(series("Coulomb level Fc", {t->front(), t->back()}, {Fc, Fc}, SeriesStyle::lines, "#009e73"));
    f.panels.push_back(p);
  }
  if (v) {
    FigurePanel p = time_panel(label("velocity", Quantity::velocity, axis));
    p.key = "top left";
    p.series.push_back(series("measured", *t, *v, SeriesStyle::lines, "#0072b2"));
    f.panels.push_back(p);
  }
  return f;
}

Figure decay_figure(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Free decay: turning points and the fitted envelope");
  const auto *t = find(r, "time"), *x = find(r, "position");
  if (!t || !x) return f;
  std::optional<EnvelopeResult> env;
  try {
    env = decay_envelope(*t, *x);
  } catch (const std::invalid_argument&) {  // too few swings for an envelope: the signal alone
  }
  const auto* pt = find(r, "peak_time");
  const auto* px = find(r, "peak_position");
  f.panels.push_back(position_with_envelope(*t, *x, pt ? *pt : std::vector<double>{}, px ? *px : std::vector<double>{},
                                            env, label("position", Quantity::displacement, axis)));
  return f;
}

// Measured against simulated, one panel per signal that has both (or at least the measurement).
Figure compare_figure(const Result& r, const std::string& what) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, what);
  const auto* t = find(r, "time");
  if (!t) return f;
  struct Signal {
    const char* name;
    std::string label;
  };
  const Signal signals[] = {{"position", label("position", Quantity::displacement, axis)},
                            {"velocity", label("velocity", Quantity::velocity, axis)},
                            {"force", label((r.method == "lugre" ? "applied " : "drive ") + force_name(axis),
                                            Quantity::force, axis)}};
  for (const auto& s : signals) {
    const auto* meas = find(r, s.name);
    const auto* sim = find(r, std::string(s.name) + "_sim");
    if (!meas && !sim) continue;
    FigurePanel p = time_panel(s.label);
    if (meas) p.series.push_back(series("measured", *t, *meas, SeriesStyle::lines, "#0072b2"));
    if (sim) p.series.push_back(series("simulated", *t, *sim, SeriesStyle::lines, "#d55e00"));
    f.panels.push_back(p);
  }
  return f;
}

// Velocities for drawing a law over [-vmax, vmax]: dense near zero, where Stribeck laws bend;
// a NaN between the two signs so that the jump at v = 0 is a gap, not a vertical line.
// Only the sides the record covers: lo < 0 draws [lo, 0), hi > 0 draws (0, hi].
std::vector<double> law_grid(double lo, double hi) {
  constexpr int kPerSide = 150;
  std::vector<double> v;
  if (lo < 0)
    for (int i = kPerSide; i >= 1; --i) v.push_back(lo * std::pow(static_cast<double>(i) / kPerSide, 2.0));
  if (lo < 0 && hi > 0) v.push_back(std::numeric_limits<double>::quiet_NaN());
  if (hi > 0)
    for (int i = 1; i <= kPerSide; ++i) v.push_back(hi * std::pow(static_cast<double>(i) / kPerSide, 2.0));
  return v;
}

// The identified law's sliding (steady-state for dynamic laws) force over +-vmax; empty when the
// result has no law or it cannot be built.
std::optional<FigureSeries> law_curve(const Result& r, double lo, double hi, const std::string& name) {
  if (!r.law || !(lo < 0 || hi > 0)) return std::nullopt;
  try {
    const FrictionLaw law = FrictionLaw::from_spec(*r.law);
    FigureSeries s = series(name, {}, {}, SeriesStyle::lines, "#d55e00");
    s.x = law_grid(lo, hi);
    s.y.resize(s.x.size());
    for (std::size_t i = 0; i < s.x.size(); ++i)
      s.y[i] = std::isfinite(s.x[i]) ? law.sliding(s.x[i]) : std::numeric_limits<double>::quiet_NaN();
    s.line_width = 2.2;
    return s;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, std::abs(x));
  return m;
}

// Friction samples binned by velocity, each sign on its own (friction jumps at v = 0): the mean
// and the standard deviation of each bin holding enough samples for them to mean something.
FigureSeries binned(const std::vector<double>& v, const std::vector<double>& F, double vmax) {
  constexpr int kBinsPerSide = 16;
  constexpr std::size_t kMinSamples = 5;  // fewer: a std of little worth
  FigureSeries s = series("mean +- std per velocity bin", {}, {}, SeriesStyle::errorbars, "#0072b2");
  for (int side : {-1, 1}) {
    std::vector<double> n(kBinsPerSide, 0.0), sum(kBinsPerSide, 0.0), sum2(kBinsPerSide, 0.0), vsum(kBinsPerSide, 0.0);
    for (std::size_t i = 0; i < std::min(v.size(), F.size()); ++i) {
      if (!(side * v[i] > 0) || !std::isfinite(F[i])) continue;
      const int b = std::min(kBinsPerSide - 1, static_cast<int>(std::abs(v[i]) / vmax * kBinsPerSide));
      n[b] += 1;
      sum[b] += F[i];
      sum2[b] += F[i] * F[i];
      vsum[b] += v[i];
    }
    for (int b0 = 0; b0 < kBinsPerSide; ++b0) {
      const int b = side < 0 ? kBinsPerSide - 1 - b0 : b0;  // increasing velocity
      if (n[b] < kMinSamples) continue;
      const double mean = sum[b] / n[b];
      s.x.push_back(vsum[b] / n[b]);
      s.y.push_back(mean);
      s.y_error.push_back(std::sqrt(std::max(0.0, (sum2[b] - n[b] * mean * mean) / (n[b] - 1))));
    }
  }
  return s;
}

FigurePanel map_panel(Axis axis) {
  FigurePanel p;
  p.x_label = label("velocity", Quantity::velocity, axis);
  p.y_label = label("friction " + force_name(axis), Quantity::force, axis);
  p.zero_line = true;
  p.zero_x_line = true;
  p.key = "top left";
  return p;
}

// IDIM: the force less the identified inertia and offset terms, against the filtered velocity.
Figure idim_map(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Friction map: identified friction " + force_name(axis) + " against velocity");
  f.panel_height = 560;
  const auto *v = find(r, "velocity"), *F = find(r, "friction");
  if (!v || !F) return f;
  FigurePanel p = map_panel(axis);
  const bool inertia = r.find("M") != nullptr, offset = r.find("offset") != nullptr;
  const std::string less = inertia && offset ? " - M a - offset" : inertia ? " - M a" : offset ? " - offset" : "";
  FigureSeries pts = series("samples: drive " + force_name(axis) + less, *v, *F, SeriesStyle::points, "#a8a8a8");
  pts.point_size = 0.25;
  p.series.push_back(pts);
  const double vmax = max_abs(*v);
  p.series.push_back(binned(*v, *F, vmax));
  if (auto law = law_curve(r, -vmax, vmax, "identified law (" + (r.law ? r.law->name : r.model) + ")")) {
    p.series.push_back(*law);
  } else if (const auto *lv = find(r, "law_velocity"), *lF = find(r, "law_force"); lv && lF) {
    // No law to simulate (e.g. Fs below Fc): the identified friction terms as they are.
    FigureSeries s = gapped_at_zero("identified friction terms (" + r.model + ")", *lv, *lF);
    s.line_width = 2.2;
    p.series.push_back(s);
  }
  f.panels.push_back(p);
  return f;
}

// Breakaway: the applied force against velocity over the experiment, the breakaway force at rest
// with its std, and the identified static law.
Figure breakaway_map(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Friction map: applied " + force_name(axis) + " against velocity");
  f.panel_height = 520;
  const auto *v = find(r, "velocity"), *F = find(r, "force");
  if (!v || !F) return f;
  FigurePanel p = map_panel(axis);
  p.y_label = label("applied " + force_name(axis), Quantity::force, axis);
  FigureSeries pts = series("samples (applied, includes M a while accelerating)", *v, *F, SeriesStyle::points, "#7f7f7f");
  pts.point_size = 0.3;
  p.series.push_back(pts);
  if (const ParameterEstimate* Fs = r.find("Fs"); Fs && std::isfinite(Fs->value)) {
    FigureSeries b = series("breakaway Fs +- std", {0.0}, {Fs->value}, SeriesStyle::errorbars, "#0072b2");
    b.y_error = {std::isfinite(Fs->std) ? Fs->std : 0.0};
    b.point_size = 1.4;
    p.series.push_back(b);
  }
  // The law on the sides the experiment moved in only (a breakaway test pushes one way).
  const double lo = std::min(0.0, *std::min_element(v->begin(), v->end()));
  const double hi = std::max(0.0, *std::max_element(v->begin(), v->end()));
  if (auto law = law_curve(r, lo, hi, "identified law (" + (r.law ? r.law->name : r.model) + ")")) {
    // Drawn for sliding only: a static law's value at rest is its breakaway level, marked above.
    p.series.push_back(*law);
  }
  f.panels.push_back(p);
  return f;
}

// LuGre: the identified law's steady state (the force while sliding at constant velocity) over
// the velocities the record reached (from the simulated position, which is smooth).
Figure lugre_map(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  f.title = title_for(r, "Friction map: steady-state friction of the identified LuGre law");
  f.panel_height = 420;
  const auto *t = find(r, "time"), *x = find(r, "position_sim");
  double vmax = 0;
  if (t && x && t->size() >= 2 && x->size() == t->size())
    for (std::size_t i = 1; i < t->size(); ++i)
      if ((*t)[i] > (*t)[i - 1]) vmax = std::max(vmax, std::abs(((*x)[i] - (*x)[i - 1]) / ((*t)[i] - (*t)[i - 1])));
  const double vs = parameter(r, "vs");
  if (std::isfinite(vs)) vmax = std::max(vmax, 5 * vs);  // a record that stayed slow: still the Stribeck part
  const std::string name = "steady state Fc + (Fs - Fc) exp(-|v/vs|^delta) + sigma2 v";
  auto law = law_curve(r, -vmax, vmax, name);
  if (!law) return f;
  FigurePanel p = map_panel(axis);
  p.title = "over the velocities of the record";
  p.series.push_back(*law);
  f.panels.push_back(p);
  // The Stribeck region is often a small fraction of the record's speed: drawn again, near zero.
  if (std::isfinite(vs) && vs < 0.2 * vmax) {
    FigurePanel z = map_panel(axis);
    z.title = "near zero velocity: |v| <= 10 vs";
    z.series.push_back(*law_curve(r, -10 * vs, 10 * vs, name));
    const FrictionLaw lg = FrictionLaw::from_spec(*r.law);
    z.series.push_back(series("v = +-vs", {-vs, vs}, {lg.sliding(-vs), lg.sliding(vs)}, SeriesStyle::points, "#009e73"));
    z.series.back().point_size = 1.2;
    f.panels.push_back(z);
  }
  return f;
}

// The cross-test: the identified model predicting the drive force of a second record.
Figure cross_test_figure(const Result& r) {
  const Axis axis = result_axis(r);
  Figure f;
  if (!r.validation) return f;
  const ValidationFigures& val = *r.validation;
  char err[64];
  std::snprintf(err, sizeof err, " (relative error %.3g %%)", val.relative_error_percent);
  f.title = "Cross-test: measured and predicted " + force_name(axis) + " - " + file_name(val.file) + err;
  const auto get = [&](const char* n) -> const std::vector<double>* {
    const auto it = val.series.find(n);
    return it == val.series.end() || it->second.empty() ? nullptr : &it->second;
  };
  const auto *t = get("time"), *y = get("force"), *m = get("force_model");
  if (!t || !y || !m) return f;
  FigurePanel p = time_panel(label("drive " + force_name(axis), Quantity::force, axis));
  p.series.push_back(series("measured", *t, *y, SeriesStyle::lines, "#0072b2"));
  p.series.push_back(series("predicted by the identified model", *t, *m, SeriesStyle::lines, "#d55e00"));
  p.series.back().line_width = 1.0;  // thinner, so that the measurement shows where they differ
  f.panels.push_back(p);
  std::vector<double> e(std::min(y->size(), m->size()));
  for (std::size_t i = 0; i < e.size(); ++i) e[i] = (*y)[i] - (*m)[i];
  FigurePanel q = time_panel(label("residual", Quantity::force, axis));
  q.series.push_back(series("measured - predicted", *t, e, SeriesStyle::lines, "#555555"));
  f.panels.push_back(q);
  return f;
}

bool has_data(const Figure& f) {
  for (const auto& p : f.panels)
    for (const auto& s : p.series)
      if (!s.x.empty()) return true;
  return false;
}

}  // namespace

Axis result_axis(const Result& r) {
  for (const auto& p : r.parameters)
    if (p.unit.find("rad") != std::string::npos || p.unit.find("N m") != std::string::npos ||
        p.unit.find("kg m^2") != std::string::npos)
      return Axis::rotary;
  return Axis::linear;
}

std::optional<Figure> result_figure(const Result& r) {
  Figure f;
  if (r.method == "idim") f = idim_figure(r);
  else if (r.method == "sweep") f = sweep_figure(r);
  else if (r.method == "breakaway") f = breakaway_figure(r);
  else if (r.method == "decay") f = decay_figure(r);
  else if (r.method == "validate") f = compare_figure(r, "Validation: measured and simulated");
  else if (r.method == "lugre") f = compare_figure(r, "LuGre identification: measured and simulated");
  else f = compare_figure(r, r.method);
  if (!has_data(f)) return std::nullopt;
  return f;
}

std::optional<Figure> friction_map_figure(const Result& r) {
  Figure f;
  if (r.method == "idim") f = idim_map(r);
  else if (r.method == "sweep") f = sweep_figure(r);
  else if (r.method == "breakaway") f = breakaway_map(r);
  else if (r.method == "lugre") f = lugre_map(r);
  if (!has_data(f)) return std::nullopt;
  return f;
}

std::vector<ReportFigure> report_extra_figures(const Result& r) {
  std::vector<ReportFigure> out;
  if (!r.ok()) return out;
  // sweep's fit figure is its friction map already.
  if (r.method != "sweep")
    if (auto map = friction_map_figure(r)) {
      std::string caption;
      if (r.method == "idim")
        caption = "Friction against velocity: each fitted sample's drive force less the identified inertia and "
                  "offset terms (grey), their mean and standard deviation in velocity bins, and the identified "
                  "friction law.";
      else if (r.method == "breakaway")
        caption = "Applied force against velocity over the experiment, the breakaway force at rest with its "
                  "standard deviation, and the identified static law while sliding.";
      else
        caption = "Steady-state friction of the identified LuGre law (the force while sliding at constant "
                  "velocity) over the velocities of the record and, where the Stribeck part is narrow, near zero "
                  "velocity.";
      out.push_back({"friction-map", caption, *map});
    }
  const Figure cross = cross_test_figure(r);
  if (has_data(cross))
    out.push_back({"cross-test", "Cross-test: the drive force measured on the second record and the force the model "
                                 "identified on the first predicts from its position (top), and their difference "
                                 "(bottom), after the same filtering and decimation.",
                   cross});
  return out;
}

Figure trajectory_figure(const Trajectory& tr, Axis axis, const std::string& title) {
  Figure f;
  f.title = "Simulation - " + title;
  f.panel_height = 300;
  FigurePanel pos = time_panel(label("position", Quantity::displacement, axis));
  pos.series.push_back(series("position", tr.position.empty() ? std::vector<double>{} : tr.time, tr.position,
                              SeriesStyle::lines, "#0072b2"));
  FigurePanel vel = time_panel(label("velocity", Quantity::velocity, axis));
  vel.series.push_back(series("velocity", tr.time, tr.velocity, SeriesStyle::lines, "#0072b2"));
  FigurePanel force = time_panel(label(force_name(axis), Quantity::force, axis));
  force.series.push_back(series("applied (net non-friction)", tr.time, tr.applied, SeriesStyle::lines, "#0072b2"));
  force.series.push_back(series("friction", tr.time, tr.friction, SeriesStyle::lines, "#d55e00"));
  f.panels = {pos, vel, force};
  const bool motor = std::any_of(tr.current.begin(), tr.current.end(), [](double c) { return c != 0.0; });
  if (motor) {
    FigurePanel cur = time_panel("current (A)");
    cur.series.push_back(series("motor current", tr.time, tr.current, SeriesStyle::lines, "#009e73"));
    f.panels.push_back(cur);
  }
  return f;
}

Figure envelope_figure(std::span<const double> t, std::span<const double> x, const EnvelopeResult& r,
                       const std::string& title) {
  Figure f;
  f.title = "Decay envelope - " + title;
  // The extremes: the first sample's turning point is not in peak_times; the signal value at
  // each peak time is interpolated from the record.
  std::vector<double> pt, px;
  for (double tp : r.peak_times) {
    const auto it = std::lower_bound(t.begin(), t.end(), tp);
    if (it == t.end()) continue;
    const std::size_t i = static_cast<std::size_t>(it - t.begin());
    double xi = x[i];
    if (i > 0 && t[i] != tp) xi = x[i - 1] + (x[i] - x[i - 1]) * (tp - t[i - 1]) / (t[i] - t[i - 1]);
    pt.push_back(tp);
    px.push_back(xi);
  }
  f.panels.push_back(position_with_envelope(t, x, pt, px, r, "position (m or rad)"));
  FigurePanel a;
  a.x_label = "time (s)";
  a.y_label = "half-swing amplitude (m or rad)";
  a.key = "top right";
  a.series.push_back(series("half swings", r.peak_times, r.amplitudes, SeriesStyle::points, "#0072b2"));
  if (!r.peak_times.empty()) {
    const double t0 = r.peak_times.front(), t1 = r.peak_times.back();
    auto curve = [&](const EnvelopeFit& fit, bool linear, const std::string& name, const char* color) {
      std::vector<double> tt, yy;
      for (int i = 0; i < 200; ++i) {
        const double ti = t0 + (t1 - t0) * i / 199.0;
        tt.push_back(ti);
        yy.push_back(fit_at(r, fit, linear, ti));
      }
      char rms[32];
      std::snprintf(rms, sizeof rms, "%.2g", 100 * fit.relative_rms);
      a.series.push_back(series(name + " (rms " + rms + " %)", tt, yy, SeriesStyle::lines, color));
    };
    curve(r.linear, true, "linear fit", "#d55e00");
    curve(r.exponential, false, "exponential fit", "#009e73");
    curve(r.mixed, false, "mixed fit", "#cc79a7");
  }
  a.title = "chosen: " + kind_words(r.kind);
  f.panels.push_back(a);
  return f;
}

Figure stick_slip_figure(std::span<const double> t, std::span<const double> v, std::span<const double> force,
                         const StickSlipResult& r, const std::string& title) {
  Figure f;
  f.title = "Stick-slip - " + title;
  FigurePanel vel = time_panel("velocity (m/s or rad/s)");
  vel.key = "top left";  // stick-slip records start stuck: the upper left corner is free
  vel.series.push_back(series("velocity", {t.begin(), t.end()}, {v.begin(), v.end()}, SeriesStyle::lines, "#0072b2"));
  if (r.velocity_threshold > 0 && !t.empty()) {
    char band[48];
    std::snprintf(band, sizeof band, "stuck band |v| <= %.3g", r.velocity_threshold);
    vel.series.push_back(series(band,
                                {t.front(), t.back()}, {r.velocity_threshold, r.velocity_threshold},
                                SeriesStyle::lines, "#999999"));
    vel.series.push_back(series("", {t.front(), t.back()}, {-r.velocity_threshold, -r.velocity_threshold},
                                SeriesStyle::lines, "#999999"));
  }
  std::vector<double> starts, zeros;
  for (const auto& s : r.slip) {
    starts.push_back(s.start);
    zeros.push_back(0.0);
  }
  vel.series.push_back(series("slip starts", starts, zeros, SeriesStyle::points, "#d55e00"));
  f.panels.push_back(vel);
  if (!force.empty() && !t.empty()) {
    FigurePanel fp = time_panel("friction force (N or N m)");
    fp.key = "top left";
    fp.series.push_back(series("friction", {t.begin(), t.end()}, {force.begin(), force.end()}, SeriesStyle::lines,
                               "#0072b2"));
    // Complete slips (started after the record's start, ended before its end) carry the forces.
    std::vector<double> tb, tr;
    for (const auto& s : r.slip)
      if (s.start > t.front() && s.end < t.back()) {
        tb.push_back(s.start);
        tr.push_back(s.end);
      }
    if (tb.size() == r.breakaway_force.size()) {
      fp.series.push_back(series("breakaway", tb, r.breakaway_force, SeriesStyle::points, "#d55e00"));
      fp.series.push_back(series("re-stick", tr, r.restick_force, SeriesStyle::points, "#009e73"));
    }
    f.panels.push_back(fp);
  }
  return f;
}

}  // namespace frictionlab::cli
