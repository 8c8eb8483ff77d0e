// frictionlab identify idim: inverse dynamic model least squares on a trajectory (EMPS recipe):
// options, run, figures (measured and reconstructed force, friction map, cross-test).
#include <sstream>

#include "../figure_kit.hpp"
#include "../flag_names.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/io/columns.hpp"
#include "method.hpp"

namespace frictionlab::cli {
namespace {

// The record's columns; the load and temperature columns (--load, --temperature) when given.
IdimData idim_data(const Dataset& d, const DataOptions& c, const OptionValues& options) {
  IdimData x = trajectory_record(d, c, options.text("from"));
  if (options.given("load")) x.load = finite_column(d, options.text("load"), "--load");
  if (options.given("temperature")) x.temperature = finite_column(d, options.text("temperature"), "--temperature");
  return x;
}

Result run(const MethodIO& io, const OptionValues& options) {
  IdimOptions o = make_idim_options(options);
  o.axis = io.columns.parsed_axis();
  const Dataset d = load_data(io.data, io.columns);
  const IdimData data = idim_data(d, io.columns, options);
  Result r = identify_idim(data, o);
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  note_data(r, d);
  if (r.ok() && options.given("validate"))
    r.validation = cross_test(r, idim_data(load_data(options.text("validate"), io.columns), io.columns, options), o);
  name_flags(r);
  return r;
}

Figure idim_figure(const Result& r) {
  Figure f;
  f.title = title_for(r, "IDIM least squares: measured and reconstructed " + force_name(r.axis));
  const Axis axis = r.axis;
  const auto *t = find(r, "time"), *y = find(r, "force"), *m = find(r, "force_model");
  if (!t || !y) return f;
  add_force_fit_panels(f, axis, *t, *y, m, "model (M a + friction + offset)", "measured - model");
  return f;
}

// IDIM: the force less the identified inertia and offset terms, against the filtered velocity.
Figure idim_map(const Result& r) {
  const Axis axis = r.axis;
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

// The cross-test: the identified model predicting the drive force of a second record.
Figure cross_test_figure(const Result& r) {
  const Axis axis = r.axis;
  Figure f;
  if (!r.validation) return f;
  const ValidationFigures& val = *r.validation;
  f.title = "Cross-test: measured and predicted " + force_name(axis) + " - " + file_name(val.file) +
            " (relative error " + format_number(val.relative_error_percent, 3) + " %)";
  const auto get = [&](const char* n) -> const std::vector<double>* {
    const auto it = val.series.find(n);
    return it == val.series.end() || it->second.empty() ? nullptr : &it->second;
  };
  const auto *t = get("time"), *y = get("force"), *m = get("force_model");
  if (!t || !y || !m) return f;
  add_force_fit_panels(f, axis, *t, *y, m, "predicted by the identified model", "measured - predicted", true);
  return f;
}

}  // namespace

IdimData trajectory_record(const Dataset& d, const DataOptions& c, const std::string& from) {
  IdimData x;
  x.time = time_column(d, c);
  const bool use_velocity =
      from == "velocity" || (from.empty() && c.velocity_opt->count() > 0 && c.position_opt->count() == 0);
  if (use_velocity) x.velocity = velocity_column(d, c);
  else x.position = position_column(d, c);
  x.force = force_column(d, c);
  x.file = d.file;
  x.sha256 = d.sha256;
  return x;
}

CliMethod idim_method() {
  return {"Inverse dynamic model least squares on a trajectory: force = M qdd + friction(qd) + offset "
          "(EMPS benchmark recipe). Best cross-test on EMPS: --terms inertia,asymmetric,stribeck --delay 1",
          run,
          {{"fit",
            "Measured drive force and the force the identified inverse dynamic model reconstructs from position "
            "(top), and their difference (bottom), on the identification data after filtering and decimation.",
            idim_figure},
           {"friction-map",
            "Friction against velocity: each fitted sample's drive force less the identified inertia and "
            "offset terms (grey), their mean and standard deviation in velocity bins, and the identified "
            "friction law.",
            idim_map},
           {"cross-test",
            "Cross-test: the drive force measured on the second record and the force the model "
            "identified on the first predicts from its position (top), and their difference "
            "(bottom), after the same filtering and decimation.",
            cross_test_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
