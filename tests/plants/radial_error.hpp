#pragma once
// Shared by the circular-test tests: the radial error of an xy-table run against angle, split by
// the angle's distance to the nearest axis reversal (0, 90, 180, 270 degrees).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "frictionlab/simulate/trajectory.hpp"

namespace frictionlab::testing {

struct RadialError {
  double near[4] = {0, 0, 0, 0};  // largest |r - R| (m) within `near_deg` of reversal k (at k 90 degrees)
  double elsewhere = 0.0;         // largest |r - R| (m) farther than `far_deg` from every reversal
};

/// Over the rows with time >= t_from (s), about the centre (cx, cy) and radius R (m).
inline RadialError radial_error(const Trajectory& tr, double cx, double cy, double R, double t_from, double near_deg,
                                double far_deg) {
  const auto& t = tr.column("time");
  const auto& x = tr.column("x.position");
  const auto& y = tr.column("y.position");
  RadialError out;
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    if (t[i] < t_from) continue;
    const double e = std::abs(std::hypot(x[i] - cx, y[i] - cy) - R);
    double deg = std::atan2(y[i] - cy, x[i] - cx) * 180.0 / std::numbers::pi;
    if (deg < 0) deg += 360.0;
    const int k = static_cast<int>(std::lround(deg / 90.0)) % 4;  // nearest reversal
    const double d = std::abs(std::remainder(deg - 90.0 * k, 360.0));
    if (d <= near_deg) out.near[k] = std::max(out.near[k], e);
    if (d >= far_deg) out.elsewhere = std::max(out.elsewhere, e);
  }
  return out;
}

}  // namespace frictionlab::testing
