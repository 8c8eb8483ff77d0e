#pragma once
// Two-axis contours as input signals: the x and y position references of a two-axis machine
// (simulate/xy_table.hpp), for the circular (ballbar) test or any sampled 2-D path.
//
// A circle of radius R (m) about (cx, cy) (m), run at the feed rate F (m/s, the tangential speed)
// counter-clockwise or clockwise from the start angle theta0 (rad, from +x towards +y):
//   theta(t) = theta0 +/- w t,  w = F / R (rad/s),  x = cx + R cos theta,  y = cy + R sin theta,
// each axis a sine InputSignal (so rate and acceleration, the feedforward's, are exact). The
// references start moving at t = 0 at the full feed (a velocity step, as a machine without a
// lead-in arc); the axes reverse where theta crosses 0, 90, 180 and 270 degrees (quadrant crossings).

#include <array>
#include <span>
#include <string>

#include "frictionlab/core/input.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A circular contour.
struct CircleContour {
  double cx = 0.0;           ///< centre x (m). Default 0.
  double cy = 0.0;           ///< centre y (m). Default 0.
  double radius = 0.01;      ///< R (m), > 0. Default 10 mm (a common ballbar radius is 50-150 mm).
  double feed = 0.01;        ///< tangential speed F (m/s), > 0. Default 10 mm/s.
  bool clockwise = false;    ///< direction of travel; false (default) = counter-clockwise.
  double turns = 1.0;        ///< number of turns (> 0): sets duration(). Default 1.
  double start_angle = 0.0;  ///< theta0 (rad, finite) of the first reference point. Default 0.

  /// \throws std::invalid_argument prefixed by `where`, naming the field, its value and unit.
  void validate(const std::string& where = "circle") const;
  /// Angular speed w = F / R (rad/s).
  double omega() const { return feed / radius; }
  /// Time to run `turns` turns: turns 2 pi R / F (s).
  double duration() const;
  /// The x and y references (m) as sine signals. \throws what validate() throws.
  std::array<InputSignal, 2> inputs() const;
  /// The contour angle theta (rad, unwrapped) at time t (s).
  double angle(double t) const;
};

/// A 2-D path sampled at `times` (s, strictly increasing, >= 2 samples) through points (x, y) (m),
/// as two piecewise-linear table signals (held at the ends). All spans have the same length.
/// \throws std::invalid_argument prefixed by `where` when the lengths differ, there are fewer
///         than 2 samples, or a value is not finite or a time not increasing (naming the 1-based
///         sample).
std::array<InputSignal, 2> path_inputs(std::span<const double> times, std::span<const double> x, std::span<const double> y,
                                       const std::string& where = "path");

}  // namespace frictionlab
