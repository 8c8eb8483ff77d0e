#include "figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <string_view>

#include "frictionlab/format.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "figure_kit.hpp"
#include "methods/method.hpp"

namespace frictionlab::cli {
namespace {

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

}  // namespace

std::string label(std::string_view quantity, Quantity q, Axis axis) {
  return std::string(quantity) + " (" + std::string(unit(q, axis)) + ")";
}

std::string force_name(Axis axis) { return axis == Axis::rotary ? "torque" : "force"; }

const std::vector<double>* find(const Result& r, const std::string& name) {
  const auto it = r.series.find(name);
  return it == r.series.end() || it->second.empty() ? nullptr : &it->second;
}

FigureSeries series(std::string name, std::vector<double> x, std::vector<double> y,
                    SeriesStyle style, std::string color) {
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

FigurePanel time_panel(std::string y_label, bool zero_line) {
  FigurePanel p;
  p.x_label = "time (s)";
  p.y_label = std::move(y_label);
  p.zero_line = zero_line;
  p.tight_x = true;
  return p;
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::string title_for(const Result& r, const std::string& what) {
  return what + (r.data_file.empty() ? "" : " - " + file_name(r.data_file));
}

double parameter(const Result& r, const std::string& name) {
  const Parameter* p = r.find(name);
  return p ? p->value : std::numeric_limits<double>::quiet_NaN();
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

// Measured against simulated, one panel per signal that has both (or at least the measurement).
void add_force_fit_panels(Figure& f, Axis axis, const std::vector<double>& t, const std::vector<double>& measured,
                          const std::vector<double>* model, const std::string& model_name,
                          const std::string& difference, bool thin_model) {
  FigurePanel p = time_panel(label("drive " + force_name(axis), Quantity::force, axis));
  p.series.push_back(series("measured", t, measured, SeriesStyle::lines, "#0072b2"));
  if (model) {
    p.series.push_back(series(model_name, t, *model, SeriesStyle::lines, "#d55e00"));
    if (thin_model) p.series.back().line_width = 1.0;
  }
  f.panels.push_back(p);
  if (!model) return;
  std::vector<double> e(std::min(measured.size(), model->size()));
  for (std::size_t i = 0; i < e.size(); ++i) e[i] = measured[i] - (*model)[i];
  FigurePanel q = time_panel(label("residual", Quantity::force, axis));
  q.series.push_back(series(difference, t, e, SeriesStyle::lines, "#555555"));
  f.panels.push_back(q);
}

Figure compare_figure(const Result& r, const std::string& what, const std::string& force_word,
                      const std::string& file) {
  const Axis axis = r.axis;
  Figure f;
  f.title = what + (file.empty() ? "" : " - " + file_name(file));
  const auto* t = find(r, "time");
  if (!t) return f;
  struct Signal {
    const char* name;
    std::string label;
  };
  const Signal signals[] = {{"position", label("position", Quantity::displacement, axis)},
                            {"velocity", label("velocity", Quantity::velocity, axis)},
                            {"force", label(force_word + " " + force_name(axis),
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
  return p;
}

bool has_data(const Figure& f) {
  for (const auto& p : f.panels)
    for (const auto& s : p.series)
      if (!s.x.empty()) return true;
  return false;
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

std::vector<ReportFigure> result_figures(const Result& r) {
  std::vector<ReportFigure> out;
  const CliMethod* m = find_cli_method(r.method);
  if (!m) {  // a result of no registered method: its measured and simulated signals, if any
    Figure f = compare_figure(r, r.method, "drive", r.data_file);
    if (has_data(f)) out.push_back({"fit", "Signals of the result.", std::move(f)});
    return out;
  }
  for (const auto& mf : m->figures) {
    Figure f = mf.draw(r);
    if (has_data(f)) out.push_back({mf.name, mf.caption, std::move(f)});
  }
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
      a.series.push_back(series(name + " (rms " + format_number(100 * fit.relative_rms, 2) + " %)", tt, yy,
                                SeriesStyle::lines, color));
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
  vel.series.push_back(series("velocity", {t.begin(), t.end()}, {v.begin(), v.end()}, SeriesStyle::lines, "#0072b2"));
  if (r.velocity_threshold > 0 && !t.empty()) {
    vel.series.push_back(series("stuck band |v| <= " + format_number(r.velocity_threshold, 3),
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
