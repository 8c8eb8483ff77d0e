#pragma once
// Shared by the control tests: runs a compensator as a continuous-time loop would (classic RK4 on
// its own states with a small fixed step, every event function's sign change located by bisection
// and handed to on_event), and compares its Jacobian with central differences.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "frictionlab/control/compensator.hpp"

namespace frictionlab::testing {

/// The compensator's input as a function of time (the plant and the reference, given by the test).
using InputAt = std::function<CompensatorInput(double t)>;

struct Located {
  double t;
  int k;
};

/// Advances z from t0 to t1 in n RK4 steps at the inputs `at`; locates every sign change of the
/// event functions within a step by bisection to `t_tol` seconds, calls on_event there and goes on
/// from the root. Returns the located events.
inline std::vector<Located> run(const Compensator& c, const InputAt& at, std::vector<double>& z, double t0, double t1,
                                long n, double t_tol = 1e-12) {
  const std::size_t m = z.size();
  const int ne = c.num_events();
  std::vector<double> k1(m), k2(m), k3(m), k4(m), tmp(m), g0(static_cast<std::size_t>(ne)),
      g1(static_cast<std::size_t>(ne));
  std::vector<Located> found;
  auto f = [&](double t, const std::vector<double>& y, std::vector<double>& out) { c.derivatives(at(t), y, out); };
  auto rk4 = [&](double t, double h, std::vector<double>& y) {
    f(t, y, k1);
    for (std::size_t j = 0; j < m; ++j) tmp[j] = y[j] + 0.5 * h * k1[j];
    f(t + 0.5 * h, tmp, k2);
    for (std::size_t j = 0; j < m; ++j) tmp[j] = y[j] + 0.5 * h * k2[j];
    f(t + 0.5 * h, tmp, k3);
    for (std::size_t j = 0; j < m; ++j) tmp[j] = y[j] + h * k3[j];
    f(t + h, tmp, k4);
    for (std::size_t j = 0; j < m; ++j) y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  };
  const double h = (t1 - t0) / static_cast<double>(n);
  double t = t0;
  while (t < t1 - 0.5 * h * 1e-9) {
    const double step = std::min(h, t1 - t);
    c.events(at(t), z, g0);
    std::vector<double> y = z;
    rk4(t, step, y);
    c.events(at(t + step), y, g1);
    int first = -1;
    for (int k = 0; k < ne; ++k)
      if ((g0[static_cast<std::size_t>(k)] < 0) != (g1[static_cast<std::size_t>(k)] < 0)) first = first < 0 ? k : first;
    if (first < 0) {
      z = y;
      t += step;
      continue;
    }
    // Bisection on the step length for the earliest root of any changing function.
    double lo = 0, hi = step;
    std::vector<double> g(static_cast<std::size_t>(ne));
    while (hi - lo > t_tol) {
      const double mid = 0.5 * (lo + hi);
      y = z;
      rk4(t, mid, y);
      c.events(at(t + mid), y, g);
      bool changed = false;
      for (int k = 0; k < ne; ++k)
        changed = changed || ((g0[static_cast<std::size_t>(k)] < 0) != (g[static_cast<std::size_t>(k)] < 0));
      (changed ? hi : lo) = mid;
    }
    y = z;
    rk4(t, hi, y);
    c.events(at(t + hi), y, g);
    z = y;
    t += hi;
    for (int k = 0; k < ne; ++k)
      if ((g0[static_cast<std::size_t>(k)] < 0) != (g[static_cast<std::size_t>(k)] < 0)) {
        c.on_event(at(t), z, k);
        found.push_back({t, k});
      }
  }
  return found;
}

/// Checks jacobian() against central differences in (position, velocity, drive, z...).
inline void expect_jacobian_matches(const Compensator& c, const CompensatorInput& in, const std::vector<double>& z,
                                    double rel_tol) {
  const std::size_t n = z.size(), m = 3 + n;
  std::vector<double> dy(m), df(n * m);
  ASSERT_TRUE(c.jacobian(in, z, dy, df));
  auto eval = [&](std::size_t j, double delta, double& y, std::vector<double>& dz) {
    CompensatorInput p = in;
    std::vector<double> zz = z;
    if (j == 0) p.position += delta;
    if (j == 1) p.velocity += delta;
    if (j == 2) p.drive += delta;
    if (j >= 3) zz[j - 3] += delta;
    y = c.output(p, zz);
    dz.assign(n, 0.0);
    c.derivatives(p, zz, dz);
  };
  const double base[3] = {in.position, in.velocity, in.drive};
  for (std::size_t j = 0; j < m; ++j) {
    const double x = j < 3 ? base[j] : z[j - 3];
    const double delta = 1e-6 * std::max(std::abs(x), 1e-6);  // central differences: error ~ delta^2
    double yp, ym;
    std::vector<double> fp, fm;
    eval(j, delta, yp, fp);
    eval(j, -delta, ym, fm);
    const double fd_y = (yp - ym) / (2 * delta);
    EXPECT_NEAR(dy[j], fd_y, rel_tol * std::max(std::abs(fd_y), 1.0)) << "d output / d w[" << j << "]";
    for (std::size_t i = 0; i < n; ++i) {
      const double fd = (fp[i] - fm[i]) / (2 * delta);
      EXPECT_NEAR(df[i * m + j], fd, rel_tol * std::max(std::abs(fd), 1.0)) << "d dz[" << i << "] / d w[" << j << "]";
    }
  }
}

}  // namespace frictionlab::testing
