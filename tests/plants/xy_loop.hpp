#pragma once
// Shared by the two-axis table's tests: the position loop they tune each axis with, and the
// comparison of two runs' columns.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "frictionlab/simulate/closed_loop.hpp"

namespace frictionlab::testing {

/// A 40 Hz PID position loop (damping 0.7) with velocity and acceleration feedforward for a body
/// of mass M (kg): Kp = M w^2 (N/m), Kd = Kvff = 1.4 w M (N s/m), Ki = Kp w / 10 (N/(m s)),
/// Kaff = M (kg), force limit `limit` (N, 0 = none).
inline ControllerParams gains_for(double M, double limit = 400.0) {
  const double w = 2.0 * std::numbers::pi * 40.0;
  ControllerParams c;
  c.Kp = M * w * w;
  c.Kd = 1.4 * w * M;
  c.Ki = c.Kp * w / 10.0;
  c.Kvff = c.Kd;
  c.Kaff = M;
  c.limit = limit;
  return c;
}

/// Largest |a - b| over the columns, relative to b's largest magnitude (a size mismatch fails).
inline double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double scale = 1e-300, diff = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    scale = std::max(scale, std::abs(b[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

}  // namespace frictionlab::testing
