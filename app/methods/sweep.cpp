// frictionlab identify sweep: constant-velocity tests to a friction-velocity map and a fitted
// static law: options, run, figure (the map, which is also its fit figure).
#include <string>
#include <vector>

#include "../figure_kit.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "method.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"

namespace frictionlab::cli {
namespace {

Result run(const MethodIO& io, const OptionValues& options) {
  const Dataset d = load_data(io.data, io.columns);
  SweepData x{time_column(d, io.columns), force_column(d, io.columns), velocity_column(d, io.columns), {}};
  SweepOptions o = make_sweep_options(options);
  if (options.given("reference")) o.reference = finite_signal(d, options.text("reference"), "--reference");
  if (options.given("load")) x.load = finite_signal(d, options.text("load"), "--load");
  o.axis = io.columns.parsed_axis();
  Result r = identify_sweep(x, o);
  stamp(r, d);
  return r;
}

Figure sweep_figure(const Result& r) {
  const Axis axis = r.axis;
  Figure f;
  f.title = title_for(r, "Friction map: steady segments and the fitted " + r.model + " law");
  f.panel_height = 520;
  FigurePanel p;
  p.x_label = label("velocity", Quantity::velocity, axis);
  p.y_label = label("friction " + force_name(axis), Quantity::force, axis);
  p.zero_line = true;
  if (const auto *v = find(r, "velocity"), *F = find(r, "force"); v && F) {
    FigureSeries s = series("steady segments (mean +- std)", *v, *F, SeriesStyle::errorbars, "#0072b2");
    if (const auto* sd = find(r, "force_std"); sd && sd->size() == s.y.size()) s.y_error = *sd;
    else s.y_error.assign(s.y.size(), 0.0);
    p.series.push_back(s);
  }
  if (const auto *v = find(r, "law_velocity"), *F = find(r, "law_force"); v && F) {
    const auto at = r.diagnostics.texts.find("law_curve_at");
    p.series.push_back(gapped_at_zero("fitted " + r.model + " law" +
                                          (at != r.diagnostics.texts.end() ? " at " + at->second : std::string()),
                                      *v, *F));
  }
  f.panels.push_back(p);
  return f;
}

}  // namespace

CliMethod sweep_method() {
  return {"Constant-velocity tests: friction-velocity points from steady segments (found on the smoothed "
          "velocity with a noise-aware band, or on --reference) and a fitted law; vs and delta get std "
          "null when no level is slow enough to show the Stribeck part",
          run,
          {{"fit",
            "Friction against velocity: the mean of each steady segment with its standard deviation, and the "
            "fitted law.",
            sweep_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
