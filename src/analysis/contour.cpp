#include "frictionlab/io/json_text.hpp"
#include "frictionlab/analysis/contour.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr std::size_t kMinSamples = 20;  // five a quadrant at the least: fewer cannot place a glitch
// A reference whose radius varies by more than this (relative) is not a circle: its "radial
// error" would be the path's shape, not the machine's.
constexpr double kReferenceRoundness = 1e-3;

void require_finite(std::span<const double> v, const char* name) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw std::invalid_argument(std::string("contour: ") + name + " sample " + std::to_string(i + 1) +
                                  " is not a finite number");
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double mean_distance(std::span<const double> x, std::span<const double> y, double cx, double cy) {
  double s = 0;
  for (std::size_t i = 0; i < x.size(); ++i) s += std::hypot(x[i] - cx, y[i] - cy);
  return s / static_cast<double>(x.size());
}

// The glitch of the sector within +-45 deg of `reversal_deg`, from the samples `in` of that sector.
QuadrantGlitch glitch_at(double reversal_deg, const std::vector<std::size_t>& in, const ContourResult& r,
                         const std::vector<double>& unwrapped, std::span<const double> t, double fraction) {
  std::vector<double> e;
  e.reserve(in.size());
  for (std::size_t i : in) e.push_back(r.radial_error[i]);
  const double level = median(e);
  std::size_t peak = in.front();
  for (std::size_t i : in)
    if (std::abs(r.radial_error[i] - level) > std::abs(r.radial_error[peak] - level)) peak = i;
  QuadrantGlitch g;
  g.reversal_deg = reversal_deg;
  g.peak_m = r.radial_error[peak] - level;
  g.angle_deg = r.angle_deg[peak];
  g.time = t[peak];
  // The run around the peak above the fraction, with the peak's sign.
  const auto above = [&](std::size_t i) { return (r.radial_error[i] - level) * g.peak_m >= fraction * g.peak_m * g.peak_m; };
  std::size_t lo = peak, hi = peak;
  while (lo > 0 && above(lo - 1)) --lo;
  while (hi + 1 < r.radial_error.size() && above(hi + 1)) ++hi;
  g.extent_deg = std::abs(unwrapped[hi] - unwrapped[lo]);
  return g;
}

// The algebraic least-squares circle {cx, cy, R}, or nothing when the points fix none (collinear,
// coincident). x and y have one length, at least 3.
std::optional<std::array<double, 3>> circle_fit(std::span<const double> x, std::span<const double> y) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  // About the mean point, so that a small circle far from the origin stays well conditioned.
  double mx = 0, my = 0;
  for (Eigen::Index i = 0; i < n; ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(n), my /= static_cast<double>(n);
  // And in units of the points' spread, so that the fit does not depend on the unit: without it a
  // circle of radius 1e48 m had a column of ones 1e-48 of the others and counted as a line, and
  // u^2 + v^2 overflowed for radii beyond 1e154.
  double scale = 0;
  for (Eigen::Index i = 0; i < n; ++i) scale = std::max({scale, std::abs(x[i] - mx), std::abs(y[i] - my)});
  if (!(scale > 0) || !std::isfinite(scale)) return std::nullopt;
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double u = (x[i] - mx) / scale, v = (y[i] - my) / scale;
    A.row(i) << u, v, 1.0;
    b(i) = -(u * u + v * v);
  }
  // Points on a line leave the x and y columns dependent up to roundoff: a pivot below 1e-10 of
  // the largest counts as zero (scaled, a circle's columns have pivots of order 1).
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A.rows(), A.cols());
  qr.setThreshold(1e-10);
  qr.compute(A);
  if (qr.rank() < 3) return std::nullopt;
  const Eigen::Vector3d p = qr.solve(b);
  const double cu = -p(0) / 2, cv = -p(1) / 2, r2 = cu * cu + cv * cv - p(2);
  if (!(r2 > 0)) return std::nullopt;
  return std::array<double, 3>{cu * scale + mx, cv * scale + my, std::sqrt(r2) * scale};
}

}  // namespace

void ContourOptions::validate() const {
  if (centre && (!std::isfinite((*centre)[0]) || !std::isfinite((*centre)[1])))
    throw std::invalid_argument("contour: centre must be finite (m), got (" + format_number((*centre)[0]) + ", " +
                                format_number((*centre)[1]) + ")");
  if (!std::isnan(radius) && !(radius > 0 && std::isfinite(radius)))
    throw std::invalid_argument("contour: radius must be a positive number of m, got " + format_number(radius));
  if (!(extent_fraction > 0 && extent_fraction < 1))
    throw std::invalid_argument("contour: extent fraction must be in (0, 1), got " + format_number(extent_fraction));
}

std::array<double, 3> fit_circle(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size())
    throw std::invalid_argument("fit_circle: x has " + std::to_string(x.size()) + " points but y has " +
                                std::to_string(y.size()));
  if (x.size() < 3) throw std::invalid_argument("fit_circle: needs at least 3 points, got " + std::to_string(x.size()));
  const auto c = circle_fit(x, y);
  if (!c) throw std::invalid_argument("fit_circle: the points are collinear or coincide: no circle");
  return *c;
}


ContourResult analyze_contour(std::span<const double> t, std::span<const double> x, std::span<const double> y,
                              std::span<const double> xr, std::span<const double> yr, const ContourOptions& options) {
  const std::size_t n = t.size();
  if (x.size() != n || y.size() != n)
    throw std::invalid_argument("contour: time, x and y must have one length, got " + std::to_string(n) + ", " +
                                std::to_string(x.size()) + " and " + std::to_string(y.size()));
  const bool reference = !xr.empty() || !yr.empty();
  if (reference && (xr.size() != n || yr.size() != n))
    throw std::invalid_argument("contour: the reference x and y must both have the length of time (" +
                                std::to_string(n) + "), got " + std::to_string(xr.size()) + " and " +
                                std::to_string(yr.size()));
  if (n < kMinSamples)
    throw std::invalid_argument("contour: needs at least " + std::to_string(kMinSamples) + " samples, got " +
                                std::to_string(n));
  require_finite(t, "time");
  require_finite(x, "x");
  require_finite(y, "y");
  require_finite(xr, "reference x");
  require_finite(yr, "reference y");
  for (std::size_t i = 1; i < n; ++i)
    if (!(t[i] > t[i - 1]))
      throw std::invalid_argument("contour: time must increase strictly; sample " + std::to_string(i + 1) + " (" +
                                  format_number(t[i]) + " s) does not");
  options.validate();

  ContourResult r;
  const bool given_radius = !std::isnan(options.radius);
  if (options.centre && given_radius) {
    r.centre_source = "given";
  } else {
    r.centre_source = reference ? "reference" : "fit";
    const std::span<const double> px = reference ? xr : x, py = reference ? yr : y;
    const auto fitted = circle_fit(px, py);
    if (!fitted)
      throw std::invalid_argument(std::string("contour: the ") + (reference ? "reference" : "measured path") +
                                  " lies on a line or a point: no circle to measure against");
    const std::array<double, 3> fit = *fitted;
    if (reference) {
      double dev = 0;
      for (std::size_t i = 0; i < n; ++i) dev = std::max(dev, std::abs(std::hypot(xr[i] - fit[0], yr[i] - fit[1]) - fit[2]));
      if (dev > kReferenceRoundness * fit[2])
        throw std::invalid_argument("contour: the reference is not a circle (its radius varies by " +
                                    format_number(dev) + " m about " + format_number(fit[2]) +
                                    " m); give the centre and radius of the nominal circle");
    }
    if (!options.centre) {
      r.centre_x = fit[0], r.centre_y = fit[1];
      r.radius = given_radius ? options.radius : fit[2];
    } else {
      r.radius = given_radius ? options.radius : mean_distance(px, py, (*options.centre)[0], (*options.centre)[1]);
    }
  }
  if (options.centre) r.centre_x = (*options.centre)[0], r.centre_y = (*options.centre)[1];
  if (given_radius) r.radius = options.radius;

  r.angle_deg.resize(n);
  r.radial_error.resize(n);
  std::vector<double> unwrapped(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - r.centre_x, dy = y[i] - r.centre_y, rad = std::hypot(dx, dy);
    if (!(rad > 1e-9 * r.radius))
      throw std::invalid_argument("contour: measured sample " + std::to_string(i + 1) +
                                  " lies at the centre: its angle is undefined");
    double a = std::atan2(dy, dx) * kDeg;
    if (a < 0) a += 360.0;
    r.angle_deg[i] = a;
    r.radial_error[i] = rad - r.radius;
    if (i == 0) {
      unwrapped[0] = a;
    } else {
      double d = a - r.angle_deg[i - 1];
      d -= 360.0 * std::round(d / 360.0);
      unwrapped[i] = unwrapped[i - 1] + d;
    }
  }
  if (reference) {
    r.x_error.resize(n), r.y_error.resize(n);
    for (std::size_t i = 0; i < n; ++i) r.x_error[i] = x[i] - xr[i], r.y_error[i] = y[i] - yr[i];
  }

  // A closed contour: the angles swept, plus one sample step, reach a full turn.
  const auto [lo, hi] = std::minmax_element(unwrapped.begin(), unwrapped.end());
  std::vector<double> steps(n - 1);
  for (std::size_t i = 1; i < n; ++i) steps[i - 1] = std::abs(unwrapped[i] - unwrapped[i - 1]);
  const double span = *hi - *lo;
  r.turns = span / 360.0;
  if (span + median(steps) < 360.0)
    throw std::invalid_argument("contour: the measured path covers " + format_number(span, 4) +
                                " deg about the centre, less than one turn: not a closed contour");

  std::array<std::vector<std::size_t>, 4> sector;
  for (std::size_t i = 0; i < n; ++i)
    sector[static_cast<std::size_t>(std::lround(r.angle_deg[i] / 90.0)) % 4].push_back(i);
  for (std::size_t k = 0; k < 4; ++k) {
    if (sector[k].empty())
      throw std::invalid_argument("contour: no sample within 45 deg of " + std::to_string(90 * k) +
                                  " deg: the sampling is too coarse for the contour");
    r.glitches[k] = glitch_at(90.0 * static_cast<double>(k), sector[k], r, unwrapped, t, options.extent_fraction);
  }
  const auto [emin, emax] = std::minmax_element(r.radial_error.begin(), r.radial_error.end());
  r.roundness_m = *emax - *emin;
  r.max_radial_error_m = std::max(std::abs(*emin), std::abs(*emax));
  return r;
}

double max_quadrant_glitch(const ContourResult& r) {
  double m = 0.0;
  for (const QuadrantGlitch& g : r.glitches) m = std::max(m, std::abs(g.peak_m));
  return m;
}

std::string contour_json(const ContourResult& r) {
  const auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  nlohmann::json glitches = nlohmann::json::array(), peaks = nlohmann::json::array();
  for (const auto& g : r.glitches) {
    glitches.push_back({{"reversal_deg", g.reversal_deg}, {"peak_m", num(g.peak_m)}, {"angle_deg", num(g.angle_deg)},
                        {"extent_deg", num(g.extent_deg)}, {"time", num(g.time)}});
    peaks.push_back(num(g.peak_m));
  }
  const nlohmann::json j = {{"centre_m", {num(r.centre_x), num(r.centre_y)}},
                            {"radius_m", num(r.radius)},
                            {"centre_from", r.centre_source},
                            {"turns", num(r.turns)},
                            {"roundness_m", num(r.roundness_m)},
                            {"max_radial_error_m", num(r.max_radial_error_m)},
                            {"max_quadrant_glitch_m", num(max_quadrant_glitch(r))},
                            {"quadrant_glitch_m", peaks},
                            {"quadrant_glitches", glitches}};
  return json_text(j);
}

}  // namespace frictionlab
