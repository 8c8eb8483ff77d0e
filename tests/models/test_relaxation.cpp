// The exact relaxation that the LuGre observer and the LuGre fit share (models/relaxation.hpp):
// known values of dz/dt = rate (target - z), LuGre's rate and target at a velocity, and LuGre's
// own step, which is that relaxation.

#include <gtest/gtest.h>

#include <cmath>

#include "frictionlab/models/lugre.hpp"
#include "frictionlab/models/relaxation.hpp"

namespace frictionlab {
namespace {

// One or two roundings of 1 ulp each.
constexpr double kRelTol = 1e-15;

TEST(Relaxation, KnownValues) {
  // From z = 0 toward 2 with decay exp(-1): 2 (1 - e^-1).
  EXPECT_NEAR(relax(0.0, 2.0, std::exp(-1.0)), 2.0 * (1.0 - std::exp(-1.0)), 2.0 * kRelTol);
  EXPECT_EQ(relax(0.5, 2.0, 1.0), 0.5);  // no time: no change
  EXPECT_EQ(relax(0.5, 2.0, 0.0), 2.0);  // infinitely long: the target
}

TEST(Relaxation, LuGreBristlesAndTheirStep) {
  const LuGre law;          // Table I: sigma0 = 1e5 N/m, Fc = 1 N, Fs = 1.5 N, vs = 1 mm/s
  const double v = -0.002;  // m/s: two Stribeck velocities, g = Fc + 0.5 exp(-4)
  const BristleRelaxation<double> r = bristle_relaxation(law, v);
  const double g = 1.0 + 0.5 * std::exp(-4.0);
  // g computed here and by the law differ by the roundings of v / vs (two inexact decimals) and
  // of exp: a few ulp of g.
  constexpr double kLevelRelTol = 1e-14;
  EXPECT_NEAR(r.rate, 1e5 * 0.002 / g, 200.0 * kLevelRelTol);  // 1/s
  EXPECT_NEAR(r.target, -g / 1e5, 1e-5 * kLevelRelTol);        // m
  // LuGre's step over 1 ms from rest is that relaxation, to the bit (the same operations).
  double z[1] = {0.0};
  (void)law.step(z, v, 1e-3);
  EXPECT_EQ(z[0], relax(0.0, r.target, std::exp(-r.rate * 1e-3)));
  EXPECT_EQ(bristle_relaxation(law, 0.0).rate, 0.0);
  EXPECT_EQ(bristle_relaxation(law, 0.0).target, 0.0);
}

}  // namespace
}  // namespace frictionlab
