// frictionlab identify sweep: constant-velocity tests to a friction-velocity map and a fitted
// static law: options, run, figure (the map, which is also its fit figure).
#include <string>
#include <vector>

#include "../figure_kit.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "method.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace frictionlab::cli {
namespace {

struct SweepArgs {
  std::string model = "stribeck";
  double fixed_delta = 0;
  double relative_tolerance = 0.01, min_duration = 0.5;
  std::vector<std::string> segments;
  std::string reference;  // commanded-velocity column to segment on
};

Result run(const SweepArgs& a, const MethodIO& io) {
  const Dataset d = load_data(io.data, io.columns);
  SweepData x{time_column(d, io.columns), force_column(d, io.columns), velocity_column(d, io.columns)};
  SweepOptions o;
  if (!a.reference.empty()) {
    DataOptions ref = io.columns;
    ref.velocity = a.reference;
    o.reference = velocity_column(d, ref);
  }
  o.fit.model = parse_static_fit_model(a.model);
  o.fit.fixed_delta = a.fixed_delta;
  o.relative_tolerance = a.relative_tolerance;
  o.min_duration = a.min_duration;
  o.axis = io.columns.parsed_axis();
  for (const auto& s : a.segments) {
    const auto colon = s.find(':');
    try {
      if (colon == std::string::npos) throw std::invalid_argument("");
      o.windows.push_back({std::stod(s.substr(0, colon)), std::stod(s.substr(colon + 1))});
    } catch (const std::exception&) {
      throw std::invalid_argument("--segment '" + s + "': expected T_BEGIN:T_END in seconds, e.g. 2.5:4.0");
    }
  }
  Result r = identify_sweep(x, o);
  stamp(r, d);
  return r;
}

MethodRun add_options(CLI::App* sweep) {
  auto a = std::make_shared<SweepArgs>();
  sweep->add_option("--model", a->model, "Law to fit: coulomb-viscous, coulomb-viscous-asymmetric, stribeck, stribeck-asymmetric")
      ->capture_default_str();
  sweep->add_option("--delta", a->fixed_delta, "Hold the Stribeck exponent at this value (default: fitted)");
  sweep->add_option("--tolerance", a->relative_tolerance, "Relative velocity band of a steady segment")->capture_default_str();
  sweep->add_option("--min-duration", a->min_duration, "Shortest steady segment (s)")->capture_default_str();
  sweep->add_option("--segment", a->segments, "T_BEGIN:T_END (s) of a steady segment, instead of detection (repeatable)");
  sweep->add_option("--reference", a->reference,
                    "Column of the commanded velocity: steady segments are found on it instead of on the measured "
                    "velocity (which is smoothed, with a band that covers its measured noise)");
  return [a](const MethodIO& io, const CLI::App&) { return run(*a, io); };
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

}  // namespace

CliMethod sweep_method() {
  return {"sweep",
          "Constant-velocity tests: friction-velocity points from steady segments (found on the smoothed "
          "velocity with a noise-aware band, or on --reference) and a fitted law; vs and delta get std "
          "null when no level is slow enough to show the Stribeck part",
          "rotary",
          add_options,
          {{"fit",
            "Friction against velocity: the mean of each steady segment with its standard deviation, and the "
            "fitted law.",
            sweep_figure}}};
}

}  // namespace frictionlab::cli
