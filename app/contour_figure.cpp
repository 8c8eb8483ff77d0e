#include "contour_figure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
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

  FigurePanel polar;
  polar.title = "radial error x" + format_number(scale.factor) + " about R = " + format_number(R) +
                " mm; dashed rings: +-" + format_number(scale.ring_m * kUm) + " um";
  polar.x_label = "x - centre (mm)";
  polar.y_label = "y - centre (mm)";
  polar.equal_axes = true;
  polar.key = "outside right top";  // the path fills the square: the legend beside it
  polar.zero_line = polar.zero_x_line = true;
  polar.series.push_back(ring("nominal circle", R, "#606060"));
  if (scale.ring_m > 0) {
    const double d = scale.factor * scale.ring_m * kMm;
    polar.series.push_back(ring("+-" + format_number(scale.ring_m * kUm) + " um", R + d, "#b0b0b0"));
    polar.series.push_back(ring("", R - d, "#b0b0b0"));
  }
  std::vector<double> px, py;
  for (std::size_t i = 0; i < r.radial_error.size(); ++i) {
    const double a = r.angle_deg[i] * std::numbers::pi / 180, rad = R + scale.factor * r.radial_error[i] * kMm;
    px.push_back(rad * std::cos(a));
    py.push_back(rad * std::sin(a));
  }
  polar.series.push_back(series("measured", px, py, SeriesStyle::lines, "#0072b2"));
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

  FigurePanel angle;
  angle.x_label = "angle (deg)";
  angle.y_label = "radial error r - R (um)";
  angle.zero_line = true;
  angle.tight_x = true;
  angle.series.push_back(series("radial error", r.angle_deg, scaled(r.radial_error, kUm), SeriesStyle::points, "#0072b2"));
  angle.series.back().point_size = 0.25;
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

}  // namespace frictionlab::cli
