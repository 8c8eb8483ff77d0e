#include "contour_figure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>

#include "figure_kit.hpp"
#include "frictionlab/format.hpp"

namespace frictionlab::cli {
namespace {

constexpr double kMm = 1e3, kUm = 1e6;  // m to mm and um, the units a circular test is read in

// v times k, element by element (unit changes).
std::vector<double> scaled(std::span<const double> v, double k) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [k](double m) { return m * k; });
  return out;
}

// The largest 1-2-5 number not above `x` (> 0).
double round_down_125(double x) {
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * decade <= x) return m * decade;
  return decade;
}

// The circle of radius `rad` (mm) about the origin, closed.
FigureSeries ring(const std::string& name, double rad, const std::string& color) {
  std::vector<double> x, y;
  for (int i = 0; i <= 360; ++i) {
    const double a = i * std::numbers::pi / 180;
    x.push_back(rad * std::cos(a));
    y.push_back(rad * std::sin(a));
  }
  return series(name, x, y, SeriesStyle::lines, color);
}

// x - xr and y - yr (m) against time, in um.
FigurePanel axis_error_panel(std::span<const double> t, const std::vector<double>& ex, const std::vector<double>& ey) {
  FigurePanel p = time_panel("tracking error (um)");
  p.series.push_back(series("x - x reference", {t.begin(), t.end()}, scaled(ex, kUm), SeriesStyle::lines, "#0072b2"));
  p.series.push_back(series("y - y reference", {t.begin(), t.end()}, scaled(ey, kUm), SeriesStyle::lines, "#009e73"));
  return p;
}

// The polar panel's frame: nominal circle of radius R (mm) and the dashed rings at +-ring_m
// magnified by the scale's factor, with the scale in the title.
FigurePanel polar_panel(double R, const PolarScale& scale) {
  FigurePanel polar;
  polar.title = "radial error x" + format_number(scale.factor) + " about R = " + format_number(R) +
                " mm; dashed rings: +-" + format_number(scale.ring_m * kUm) + " um";
  polar.x_label = "x - centre (mm)";
  polar.y_label = "y - centre (mm)";
  polar.equal_axes = true;
  polar.zero_line = polar.zero_x_line = true;
  polar.series.push_back(ring("nominal circle", R, "#606060"));
  if (scale.ring_m > 0) {
    const double d = scale.factor * scale.ring_m * kMm;
    FigureSeries outer = ring("+-" + format_number(scale.ring_m * kUm) + " um", R + d, "#909090");
    FigureSeries inner = ring("", R - d, "#909090");
    outer.dashed = inner.dashed = true;  // as the title says: the rings are dashed
    polar.series.push_back(std::move(outer));
    polar.series.push_back(std::move(inner));
  }
  return polar;
}

// A path's radial error drawn about the nominal circle of radius R (mm), magnified.
FigureSeries magnified(const std::string& name, const ContourResult& r, double R, const PolarScale& scale,
                       const std::string& color) {
  std::vector<double> px, py;
  for (std::size_t i = 0; i < r.radial_error.size(); ++i) {
    const double a = r.angle_deg[i] * std::numbers::pi / 180, rad = R + scale.factor * r.radial_error[i] * kMm;
    px.push_back(rad * std::cos(a));
    py.push_back(rad * std::sin(a));
  }
  return series(name, px, py, SeriesStyle::lines, color);
}

FigurePanel radial_error_panel() {
  FigurePanel angle;
  angle.x_label = "angle (deg)";
  angle.y_label = "radial error r - R (um)";
  angle.zero_line = true;
  angle.tight_x = true;
  return angle;
}

FigureSeries radial_error_points(const std::string& name, const ContourResult& r, const std::string& color) {
  FigureSeries s = series(name, r.angle_deg, scaled(r.radial_error, kUm), SeriesStyle::points, color);
  s.point_size = 0.25;
  return s;
}

}  // namespace

PolarScale polar_scale(double radius_m, double max_error_m) {
  PolarScale s;
  if (!(max_error_m > 0) || !(radius_m > 0)) return s;
  s.factor = std::max(1.0, round_down_125(0.25 * radius_m / max_error_m));
  s.ring_m = round_down_125(0.5 * max_error_m);
  return s;
}

Figure contour_figure(std::span<const double> t, const ContourResult& r, const std::string& title) {
  Figure f;
  f.title = "Circular test - " + title;
  f.panel_height = 520;
  const PolarScale scale = polar_scale(r.radius, r.max_radial_error_m);
  const double R = r.radius * kMm;

  FigurePanel polar = polar_panel(R, scale);
  polar.series.push_back(magnified("measured", r, R, scale, "#0072b2"));
  std::vector<double> gx, gy;
  for (const QuadrantGlitch& g : r.glitches) {
    const double a = g.angle_deg * std::numbers::pi / 180;
    const double rad = R + scale.factor * r.radial_error[static_cast<std::size_t>(
                                              std::lower_bound(t.begin(), t.end(), g.time) - t.begin())] * kMm;
    gx.push_back(rad * std::cos(a));
    gy.push_back(rad * std::sin(a));
  }
  polar.series.push_back(series("quadrant glitch peaks", gx, gy, SeriesStyle::points, "#d55e00"));
  f.panels.push_back(polar);

  FigurePanel angle = radial_error_panel();
  angle.series.push_back(radial_error_points("radial error", r, "#0072b2"));
  f.panels.push_back(angle);

  if (!r.x_error.empty()) f.panels.push_back(axis_error_panel(t, r.x_error, r.y_error));
  return f;
}

std::optional<Figure> xy_figure(const Trajectory& tr, const std::string& title) {
  const std::vector<std::string> names = tr.names();
  for (const char* c : {"x.position", "y.position", "x.reference", "y.reference"})
    if (std::find(names.begin(), names.end(), c) == names.end()) return std::nullopt;
  const auto& x = tr.column("x.position");
  const auto& y = tr.column("y.position");
  const auto& xr = tr.column("x.reference");
  const auto& yr = tr.column("y.reference");
  try {
    return contour_figure(tr.time, analyze_contour(tr.time, x, y, xr, yr), title);
  } catch (const std::invalid_argument&) {
    // Not a full circle (a path from a CSV, a part turn): the path itself.
  }
  Figure f;
  f.title = "Two-axis path - " + title;
  f.panel_height = 520;
  FigurePanel plane;
  plane.x_label = "x (mm)";
  plane.y_label = "y (mm)";
  plane.equal_axes = true;
  plane.series.push_back(series("reference", scaled(xr, kMm), scaled(yr, kMm), SeriesStyle::lines, "#606060"));
  plane.series.push_back(series("measured", scaled(x, kMm), scaled(y, kMm), SeriesStyle::lines, "#0072b2"));
  f.panels.push_back(plane);
  std::vector<double> ex(x.size()), ey(y.size());
  for (std::size_t i = 0; i < x.size(); ++i) ex[i] = x[i] - xr[i], ey[i] = y[i] - yr[i];
  f.panels.push_back(axis_error_panel(tr.time, ex, ey));
  return f;
}

std::vector<ReportFigure> xy_validation_figures(const Result& r, const std::optional<ContourResult>& measured,
                                                const std::optional<ContourResult>& simulated, const std::string& title) {
  std::vector<ReportFigure> out;
  const std::vector<double>* t = find(r, "time");
  if (!t) return out;
  constexpr const char* kMeasured = "#0072b2";
  constexpr const char* kSimulated = "#d55e00";
  Figure contour;
  contour.panel_height = 520;
  if (measured && simulated) {
    contour.title = "Circular test, measured and simulated - " + title;
    // One magnification for both, from the larger error: the two traces are read against each other.
    const PolarScale scale =
        polar_scale(measured->radius, std::max(measured->max_radial_error_m, simulated->max_radial_error_m));
    const double R = measured->radius * kMm;
    FigurePanel polar = polar_panel(R, scale);
    polar.series.push_back(magnified("measured", *measured, R, scale, kMeasured));
    polar.series.push_back(magnified("simulated", *simulated, R, scale, kSimulated));
    contour.panels.push_back(polar);
    FigurePanel angle = radial_error_panel();
    angle.series.push_back(radial_error_points("measured", *measured, kMeasured));
    angle.series.push_back(radial_error_points("simulated", *simulated, kSimulated));
    contour.panels.push_back(angle);
    out.push_back({"contour",
                   "The circular test: the measured and the simulated radial error about the nominal circle at one "
                   "magnification (polar), and against angle; the quadrant glitches sit at the axis reversals.",
                   std::move(contour)});
  } else {
    contour.title = "Two-axis path, measured and simulated - " + title;
    FigurePanel plane;
    plane.x_label = "x (mm)";
    plane.y_label = "y (mm)";
    plane.equal_axes = true;
    const auto* xr = find(r, "x.reference");
    const auto* yr = find(r, "y.reference");
    if (xr && yr) plane.series.push_back(series("reference", scaled(*xr, kMm), scaled(*yr, kMm), SeriesStyle::lines, "#606060"));
    for (const auto& [name, suffix, color] : {std::tuple{"measured", "", kMeasured}, std::tuple{"simulated", "_sim", kSimulated}}) {
      const auto* x = find(r, std::string("x.position") + suffix);
      const auto* y = find(r, std::string("y.position") + suffix);
      if (x && y) plane.series.push_back(series(name, scaled(*x, kMm), scaled(*y, kMm), SeriesStyle::lines, color));
    }
    contour.panels.push_back(plane);
    out.push_back({"contour", "The measured and the simulated path with the reference, in the plane.", std::move(contour)});
  }

  Figure axes;
  axes.title = "Axes, measured and simulated - " + title;
  axes.panel_height = 260;
  for (const char* a : {"x", "y"}) {
    const std::string p = std::string(a) + ".";
    const auto* ref = find(r, p + "reference");
    FigurePanel err = time_panel(std::string(a) + " - " + a + " reference (um)");
    for (const auto& [name, suffix, color] : {std::tuple{"measured", "", kMeasured}, std::tuple{"simulated", "_sim", kSimulated}}) {
      const auto* q = find(r, p + "position" + suffix);
      if (!q || !ref) continue;
      std::vector<double> e(q->size());
      for (std::size_t i = 0; i < q->size() && i < ref->size(); ++i) e[i] = ((*q)[i] - (*ref)[i]) * kUm;
      err.series.push_back(series(name, *t, e, SeriesStyle::lines, color));
    }
    axes.panels.push_back(err);
    struct Signal {
      const char* name;
      std::string label;
    };
    for (const Signal& sig : {Signal{"velocity", std::string(a) + " " + label("velocity", Quantity::velocity, r.axis)},
                              Signal{"force", std::string(a) + " " + label("drive force", Quantity::force, r.axis)}}) {
      const auto* meas = find(r, p + sig.name);
      const auto* sim = find(r, p + sig.name + "_sim");
      FigurePanel panel = time_panel(sig.label);
      if (meas) panel.series.push_back(series("measured", *t, *meas, SeriesStyle::lines, kMeasured));
      if (sim) panel.series.push_back(series("simulated", *t, *sim, SeriesStyle::lines, kSimulated));
      axes.panels.push_back(panel);
    }
  }
  out.push_back({"axes",
                 "Each axis over time, measured and simulated: the tracking error against the reference, the "
                 "velocity (from the low-passed position) and the drive force (the simulated command; measured when "
                 "the record has it).",
                 std::move(axes)});
  if (measured && simulated) {
    out.push_back({"measured-contour",
                   "The measured circular test: polar error plot with the quadrant glitch peaks marked, radial "
                   "error against angle, and each axis's tracking error.",
                   contour_figure(*t, *measured, "measured - " + title)});
    out.push_back({"simulated-contour", "The same for the simulation of the models.",
                   contour_figure(*t, *simulated, "simulated - " + title)});
  }
  return out;
}

}  // namespace frictionlab::cli
