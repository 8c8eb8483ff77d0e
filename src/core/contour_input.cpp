// Two-axis contours as input signals: see include/frictionlab/core/contour_input.hpp.
#include "frictionlab/core/contour_input.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

void require(bool ok, const std::string& where, const char* name, double value, const char* rule) {
  if (!ok) throw std::invalid_argument(where + ": " + name + " = " + format_number(value) + " must be " + rule);
}

}  // namespace

void CircleContour::validate(const std::string& where) const {
  require(std::isfinite(cx), where, "centre x", cx, "finite (m)");
  require(std::isfinite(cy), where, "centre y", cy, "finite (m)");
  require(std::isfinite(radius) && radius > 0, where, "radius", radius, "> 0 (m)");
  require(std::isfinite(feed) && feed > 0, where, "feed", feed, "> 0 (m/s)");
  require(std::isfinite(turns) && turns > 0, where, "turns", turns, "> 0");
  require(std::isfinite(start_angle), where, "start angle", start_angle, "finite (rad)");
}

double CircleContour::duration() const { return turns * 2.0 * std::numbers::pi * radius / feed; }

double CircleContour::angle(double t) const { return start_angle + (clockwise ? -1.0 : 1.0) * omega() * t; }

std::array<InputSignal, 2> CircleContour::inputs() const {
  validate();
  // x = cx + R cos(theta) = cx + R sin(theta + pi/2); y = cy + R sin(theta). Clockwise,
  // theta = theta0 - w t: cos is even, and sin(theta0 - w t) = sin(w t - theta0 + pi).
  const double w = omega(), s = clockwise ? -1.0 : 1.0;
  InputSignal x, y;
  x.shape = y.shape = InputShape::sine;
  x.amplitude = y.amplitude = radius;
  x.omega = y.omega = w;
  x.offset = cx;
  y.offset = cy;
  x.phase = s * start_angle + std::numbers::pi / 2;
  y.phase = clockwise ? std::numbers::pi - start_angle : start_angle;
  return {x, y};
}

std::array<InputSignal, 2> path_inputs(std::span<const double> times, std::span<const double> x, std::span<const double> y,
                                       const std::string& where) {
  if (times.size() != x.size() || times.size() != y.size())
    throw std::invalid_argument(where + ": time, x and y must have the same number of samples, got " + std::to_string(times.size()) +
                                ", " + std::to_string(x.size()) + " and " + std::to_string(y.size()));
  if (times.size() < 2)
    throw std::invalid_argument(where + ": a path needs at least 2 samples, got " + std::to_string(times.size()));
  for (std::size_t k = 0; k < times.size(); ++k) {
    const std::string at = where + ": sample " + std::to_string(k + 1);
    if (!std::isfinite(times[k])) throw std::invalid_argument(at + ": time " + format_number(times[k]) + " is not a finite number (s)");
    if (!std::isfinite(x[k])) throw std::invalid_argument(at + ": x " + format_number(x[k]) + " is not a finite number (m)");
    if (!std::isfinite(y[k])) throw std::invalid_argument(at + ": y " + format_number(y[k]) + " is not a finite number (m)");
    if (k > 0 && !(times[k] > times[k - 1]))
      throw std::invalid_argument(at + ": time " + format_number(times[k]) + " s must be greater than the previous sample's " +
                                  format_number(times[k - 1]) + " s");
  }
  std::array<InputSignal, 2> out;
  for (int i = 0; i < 2; ++i) {
    InputSignal& s = out[static_cast<std::size_t>(i)];
    s.shape = InputShape::table;
    s.times.assign(times.begin(), times.end());
    const auto v = i == 0 ? x : y;
    s.values.assign(v.begin(), v.end());
  }
  return out;
}

}  // namespace frictionlab
