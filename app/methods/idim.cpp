// frictionlab identify idim: inverse dynamic model least squares on a trajectory (EMPS recipe):
// options, run, figures (measured and reconstructed force, friction map, cross-test).
#include <algorithm>
#include <map>
#include <optional>
#include <variant>
#include <cmath>
#include <sstream>

#include "../figure_kit.hpp"
#include "../flag_names.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/io/column_expression.hpp"
#include "frictionlab/io/columns.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "method.hpp"

namespace frictionlab::cli {
namespace {

// The record's columns; the load and temperature columns (--load, --temperature) when given.
// With `loop`, also the closed loop's reference and feedforward (--reference, --feedforward) for
// IDIM-IV; a cross-test's record needs neither.
IdimData idim_data(const Dataset& d, const DataOptions& c, const OptionValues& options, bool loop = true) {
  IdimData x = trajectory_record(d, c, options.text("from"));
  if (options.given("load")) x.load = finite_signal(d, options.text("load"), "--load");
  if (options.given("temperature")) x.temperature = finite_signal(d, options.text("temperature"), "--temperature");
  if (loop && options.given("reference")) x.reference = finite_signal(d, options.text("reference"), "--reference");
  if (loop && options.given("feedforward")) x.feedforward = finite_signal(d, options.text("feedforward"), "--feedforward");
  return x;
}

double sign_of(double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; }

// The controller's gains given as the names of scalars of the data file (--kp kp: a MAT file's
// variable) replaced by their values; `sources` notes each one's name and file.
OptionValues with_file_scalars(const OptionValues& options, const Dataset& d, std::map<std::string, std::string>& sources) {
  OptionValues v = options;
  for (const char* name : {"kp", "kd", "ki", "kv", "drive-gain", "control-limit"}) {
    if (!v.given(name) || !std::isnan(v.number(name))) continue;
    const std::string scalar = v.text(name), flag = std::string("--") + name;
    const double value = resolve_constant(d, scalar, flag);  // unknown: names the file and lists its scalars
    try {
      v.set(name, value, flag);
    } catch (const std::invalid_argument& e) {
      throw InputError(errc::option_out_of_range, d.where() + e.what() + " (the scalar '" + scalar + "' of the file)",
                       ErrorFields{.file = d.file, .column = scalar, .option = flag, .value = format_number(value, 6)});
    }
    sources[name] = flag + " " + scalar + ": scalar of " + file_name(d.file);
  }
  return v;
}

// IDIM-IV's controller from --scenario, read as validate reads a scenario: its data file replaced
// by the identification's, its friction law and inertia by placeholders (IDIM-IV simulates its
// own estimate), so that only the controller and the plant's kind matter.
IdimIvScenario iv_scenario(const std::string& path, const Dataset& d, Axis axis) {
  ScenarioOptions so;
  so.data = std::make_shared<const Dataset>(d);
  so.law = FrictionLaw();
  so.axis = AxisParams{};
  return idim_iv_scenario(load_scenario(path, so), path, axis);
}

// The option values with the EMPS controller's drive gain taken from --gain when neither given
// nor in the scenario (--iv --controller emps-pd): the controller's volts become force through
// the same gain.
OptionValues with_drive_gain(const OptionValues& options, const Dataset& d, const DataOptions& c,
                             const IdimIvScenario* scenario, std::map<std::string, std::string>& sources) {
  OptionValues v = options;
  const bool emps = v.text("controller") == "emps-pd" ||
                    (v.text("controller").empty() && scenario && std::holds_alternative<EmpsPdParams>(scenario->controller));
  if (v.flag("iv") && emps && !v.given("drive-gain") && !scenario && !c.gain.empty()) {
    v.set("drive-gain", resolve_constant(d, c.gain, "gain"), "--gain");
    sources["drive-gain"] = "--gain " + c.gain;
  }
  return v;
}

Result run(const MethodIO& io, const OptionValues& given) {
  const Dataset d = load_data(io.data, io.columns);
  const Axis axis = io.columns.parsed_axis();
  std::map<std::string, std::string> sources;  // the controller's values not given as numbers
  OptionValues options = with_file_scalars(given, d, sources);
  std::optional<IdimIvScenario> scenario;
  if (options.flag("iv") && options.given("scenario")) scenario = iv_scenario(options.text("scenario"), d, axis);
  options = with_drive_gain(options, d, io.columns, scenario ? &*scenario : nullptr, sources);
  IdimOptions o = make_idim_options(options, scenario ? &*scenario : nullptr);
  if (o.iv.enabled)
    for (const auto& [name, source] : sources) o.iv.sources[name] = source;
  o.axis = axis;
  const IdimData data = idim_data(d, io.columns, options);
  Result r = identify_idim(data, o);
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  note_data(r, d);
  if (r.ok() && options.given("validate"))
    r.validation = cross_test(r, idim_data(load_data(options.text("validate"), io.columns), io.columns, options, false), o);
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

// The friction map against velocity and load: the samples of the friction map in three bands of
// |load| (lower, middle and upper third of its range), each with the identified law at the band's
// mean |load|.
Figure idim_load_map(const Result& r) {
  Figure f;
  const auto *v = find(r, "velocity"), *F = find(r, "friction"), *L = find(r, "load");
  const auto *lv = find(r, "law_velocity"), *l0 = find(r, "law_force_zero_load");
  const Parameter* mu = r.find("mu_load");
  if (!v || !F || !L || !mu || L->size() != v->size() || F->size() != v->size()) return f;
  const Axis axis = r.axis;
  f.title = title_for(r, "Friction map against velocity and load");
  f.panel_height = 560;
  FigurePanel p = map_panel(axis);
  const auto [lo_it, hi_it] = std::minmax_element(L->begin(), L->end());
  const double lo = *lo_it, width = std::max((*hi_it - lo) / 3, 1e-300);
  const char* colors[] = {"#0072b2", "#009e73", "#d55e00"};
  const std::string load_unit(unit(Quantity::force, axis));
  for (int b = 0; b < 3; ++b) {
    std::vector<double> x, y;
    double sum = 0;
    for (std::size_t i = 0; i < v->size(); ++i) {
      const int band = std::min(2, static_cast<int>(((*L)[i] - lo) / width));
      if (band != b) continue;
      x.push_back((*v)[i]);
      y.push_back((*F)[i]);
      sum += (*L)[i];
    }
    if (x.empty()) continue;
    const double mean = sum / static_cast<double>(x.size());
    const std::string band = format_number(lo + b * width, 3) + " to " + format_number(lo + (b + 1) * width, 3) + " " + load_unit;
    FigureSeries pts = series("samples at |load| " + band, x, y, SeriesStyle::points, colors[b]);
    pts.point_size = 0.25;
    p.series.push_back(pts);
    if (lv && l0 && l0->size() == lv->size()) {
      std::vector<double> curve(l0->size());
      for (std::size_t i = 0; i < curve.size(); ++i) curve[i] = (*l0)[i] + mu->value * mean * sign_of((*lv)[i]);
      FigureSeries s = gapped_at_zero("identified law at |load| " + format_number(mean, 3) + " " + load_unit, *lv, curve);
      s.color = colors[b];
      s.line_width = 2.2;
      p.series.push_back(s);
    }
  }
  f.panels.push_back(p);
  return f;
}

// The ripple against the position within its period: the fit's residual plus the identified
// ripple at each sample, and the identified ripple.
Figure idim_ripple(const Result& r) {
  Figure f;
  const auto *q = find(r, "ripple_position"), *F = find(r, "ripple_partial");
  const auto *qc = find(r, "ripple_curve_position"), *Fc = find(r, "ripple_curve_force");
  if (!q || !F || !qc || !Fc) return f;
  const Axis axis = r.axis;
  f.title = title_for(r, "Position ripple over one period");
  FigurePanel p;
  p.x_label = label("position within the ripple period", Quantity::displacement, axis);
  p.y_label = label("ripple " + force_name(axis), Quantity::force, axis);
  p.zero_line = true;
  p.key = "top right";
  FigureSeries pts = series("samples: residual + identified ripple", *q, *F, SeriesStyle::points, "#a8a8a8");
  pts.point_size = 0.25;
  p.series.push_back(pts);
  FigureSeries s = series("identified ripple", *qc, *Fc, SeriesStyle::lines, "#d55e00");
  s.line_width = 2.2;
  p.series.push_back(s);
  f.panels.push_back(p);
  return f;
}

// The temperature drift: the logged temperature over time and the viscous coefficient the
// temperature term gives at it, Fv + Fv_per_K (T - T_ref).
Figure idim_temperature(const Result& r) {
  Figure f;
  const auto *t = find(r, "time"), *T = find(r, "temperature"), *fv = find(r, "temperature_viscous");
  if (!t || !T || !fv || T->size() != t->size()) return f;
  const Axis axis = r.axis;
  f.title = title_for(r, "Temperature drift of the viscous coefficient");
  FigurePanel temp = time_panel("temperature (degC or K, as logged)", false);
  temp.series.push_back(series("logged temperature", *t, *T, SeriesStyle::lines, "#d55e00"));
  f.panels.push_back(temp);
  FigurePanel visc = time_panel(label("viscous coefficient", Quantity::viscous, axis), false);
  const auto ref = r.diagnostics.numbers.find("temperature_ref");
  visc.series.push_back(series("Fv + Fv_per_K (T - T_ref)" + (ref != r.diagnostics.numbers.end()
                                                                   ? ", T_ref = " + format_number(ref->second, 4)
                                                                   : std::string()),
                               *t, *fv, SeriesStyle::lines, "#0072b2"));
  f.panels.push_back(visc);
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
           {"load-map",
            "Friction against velocity and load (with the load term): the friction map's samples in three bands of "
            "|load|, each with the identified law at the band's mean |load|.",
            idim_load_map},
           {"ripple",
            "Position ripple (with the ripple term): the fit's residual plus the identified ripple at each sample "
            "against the position within the ripple period, and the identified ripple.",
            idim_ripple},
           {"temperature",
            "Temperature drift (with the temperature term): the logged temperature over time and the viscous "
            "coefficient the temperature term gives at it.",
            idim_temperature},
           {"cross-test",
            "Cross-test: the drive force measured on the second record and the force the model "
            "identified on the first predicts from its position (top), and their difference "
            "(bottom), after the same filtering and decimation.",
            cross_test_figure}},
          nullptr,
          {}};
}

}  // namespace frictionlab::cli
