// frictionlab identify lugre: LuGre parameters by output error: options, run, figures (measured
// and simulated signals, the identified law's steady state).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "../figure_kit.hpp"
#include "../flag_names.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "method.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/scenario/law_file.hpp"

namespace frictionlab::cli {
namespace {

Result run(const MethodIO& io, const OptionValues& options) {
  LugreOptions o = make_lugre_options(options);
  o.axis = io.columns.parsed_axis();
  if (options.given("static")) o.static_law = load_law(options.text("static"));
  const Dataset d = load_data(io.data, io.columns);
  check_lugre_work(static_cast<double>(d.rows()), o);  // before the columns are formed and checked
  LugreData x{time_column(d, io.columns), force_column(d, io.columns), position_column(d, io.columns)};
  o.progress = [](int iteration, double cost, double) {
    progress_stage("output-error fit, iteration " + std::to_string(iteration) + ", cost " + std::to_string(cost) + " m^2");
  };
  Result r = identify_lugre(x, o);
  stamp(r, d);
  name_flags(r);
  return r;
}

Figure lugre_figure(const Result& r) {
  return compare_figure(r, "LuGre identification: measured and simulated", "applied", r.data_file);
}

// LuGre: the identified law's steady state (the force while sliding at constant velocity) over
// the velocities the record reached (from the simulated position, which is smooth).
Figure lugre_map(const Result& r) {
  const Axis axis = r.axis;
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

}  // namespace

CliMethod lugre_method() {
  return {"LuGre parameters by output error: simulate the axis with the measured force, compare positions, "
          "Ceres least squares. From one record that starts at rest and breaks away both ways (presliding, "
          "sliding, reversals), all six: sigma0, sigma1 and the static part Fc, Fs, vs, sigma2 (started "
          "from the sliding samples and a grid of Fs and vs), unless --static gives the static part. A "
          "parameter the record cannot determine, or that ends at a bound, has std null (nan) and a warning",
          run,
          {{"fit", "Measured and simulated position and force of the identified LuGre model.", lugre_figure},
           {"friction-map",
            "Steady-state friction of the identified LuGre law (the force while sliding at constant "
            "velocity) over the velocities of the record and, where the Stribeck part is narrow, near zero "
            "velocity.",
            lugre_map}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
