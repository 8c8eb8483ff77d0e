// frictionlab identify breakaway: torque-mode trapezoid experiment (ramp up, hold, ramp down):
// options, run, figures (applied force and velocity over time, friction map).
#include <algorithm>
#include <cmath>
#include <limits>

#include "../figure_kit.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "method.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"

namespace frictionlab::cli {
namespace {

Result run(const MethodIO& io, const OptionValues& options) {
  const Dataset d = load_data(io.data, io.columns);
  BreakawayData x{time_column(d, io.columns), force_column(d, io.columns), velocity_column(d, io.columns), {}};
  if (options.given("load")) x.load = finite_signal(d, options.text("load"), "--load");
  BreakawayOptions o = make_breakaway_options(options);
  o.axis = io.columns.parsed_axis();
  Result r = identify_breakaway(x, o);
  stamp(r, d);
  return r;
}

Figure breakaway_figure(const Result& r) {
  const Axis axis = r.axis;
  Figure f;
  f.title = title_for(r, "Breakaway experiment: applied " + force_name(axis) + " and velocity");
  const auto *t = find(r, "time"), *F = find(r, "force"), *v = find(r, "velocity");
  if (!t) return f;
  if (F) {
    FigurePanel p = time_panel(label("applied " + force_name(axis), Quantity::force, axis));
    p.series.push_back(series("applied", *t, *F, SeriesStyle::lines, "#0072b2"));
    const auto tb = r.diagnostics.numbers.find("breakaway_time");
    const double Fs = parameter(r, "Fs"), Fc = parameter(r, "Fc");
    const auto starts = r.diagnostics.lists.find("breakaways");
    if (starts != r.diagnostics.lists.end()) {  // with a load: every start's breakaway force at its load
      std::vector<double> ts, fs;
      for (const auto& b : starts->second) ts.push_back(b.at("time")), fs.push_back(b.at("force"));
      p.series.push_back(series("breakaways (at each start's load)", ts, fs, SeriesStyle::points, "#d55e00"));
    } else if (tb != r.diagnostics.numbers.end() && std::isfinite(Fs)) {
      p.series.push_back(series("breakaway (Fs)", {tb->second}, {Fs}, SeriesStyle::points, "#d55e00"));
    }
    if (std::isfinite(Fc))
      p.series.push_back(series(starts != r.diagnostics.lists.end() ? "Coulomb level Fc at zero load" : "Coulomb level Fc",
                                {t->front(), t->back()}, {Fc, Fc}, SeriesStyle::lines, "#009e73"));
    f.panels.push_back(p);
  }
  if (v) {
    FigurePanel p = time_panel(label("velocity", Quantity::velocity, axis));
    p.series.push_back(series("measured", *t, *v, SeriesStyle::lines, "#0072b2"));
    f.panels.push_back(p);
  }
  return f;
}

// Breakaway: the applied force against velocity over the experiment, the breakaway force at rest
// with its std, and the identified static law.
Figure breakaway_map(const Result& r) {
  const Axis axis = r.axis;
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
  if (const Parameter* Fs = r.find("Fs"); Fs && std::isfinite(Fs->value)) {
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

}  // namespace

CliMethod breakaway_method() {
  return {"Torque-mode trapezoid experiment (ramp up, hold, ramp down): Fs, Fc, Fv (and M) from "
          "time, torque (or current with --kt) and velocity",
          run,
          {{"fit",
            "Applied force and velocity over the experiment; the point marks the breakaway (Fs), the line the "
            "identified Coulomb level.",
            breakaway_figure},
           {"friction-map",
            "Applied force against velocity over the experiment, the breakaway force at rest with its "
            "standard deviation, and the identified static law while sliding.",
            breakaway_map}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
