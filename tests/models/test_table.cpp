// Tabulated friction-velocity map: exact at the points, monotone (Fritsch-Carlson) between them,
// held below the first point, extrapolated along the last segment, mirrored when one-sided.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/models/static_law.hpp"
#include "frictionlab/models/table.hpp"

namespace frictionlab {
namespace {

// Hermite polynomials evaluated by hand differ from the library's only by rounding (a few ulps).
constexpr double kRelTol = 1e-13;

void expect_rel(double got, double want) { EXPECT_NEAR(got, want, kRelTol * std::abs(want)) << "want " << want; }

std::string error_of(std::vector<double> v, std::vector<double> f) {
  try {
    Table t(std::move(v), std::move(f));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no std::invalid_argument>";
}

TEST(Table, ExactAtThePoints) {
  const Table t({0.01, 0.1, 0.5, 1.0}, {1.2, 0.9, 1.0, 1.3});
  EXPECT_EQ(t.sliding(0.01), 1.2);
  EXPECT_EQ(t.sliding(0.1), 0.9);
  EXPECT_EQ(t.sliding(0.5), 1.0);
  EXPECT_EQ(t.sliding(1.0), 1.3);
}

TEST(Table, HermiteValueByHand) {
  // v = [1, 2, 3], F = [1, 2, 4]: secants d = [1, 2]; slopes m0 = d0 = 1, m2 = d1 = 2,
  // m1 = (d0 + d1)/2 = 1.5 (same sign; Fritsch-Carlson r = a^2 + b^2 <= 9 so no limiting).
  const Table t({1.0, 2.0, 3.0}, {1.0, 2.0, 4.0});
  // At v = 1.5 (t = 0.5, h = 1): H = h00 f0 + h10 m0 + h01 f1 + h11 m1
  //   = 0.5 * 1 + 0.125 * 1 + 0.5 * 2 - 0.125 * 1.5 = 1.4375
  expect_rel(t.sliding(1.5), 1.4375);
  // At v = 2.5: 0.5 * 2 + 0.125 * 1.5 + 0.5 * 4 - 0.125 * 2 = 2.9375
  expect_rel(t.sliding(2.5), 2.9375);
}

TEST(Table, LinearDataIsReproducedExactly) {
  // F = 0.5 + 2 v: all secants and slopes are 2, so the cubic is the line itself.
  const Table t({0.1, 0.2, 0.4, 0.8}, {0.7, 0.9, 1.3, 2.1});
  for (double v : {0.15, 0.3, 0.55, 0.79}) expect_rel(t.sliding(v), 0.5 + 2.0 * v);
}

TEST(Table, HeldBelowFirstPointAndExtrapolatedBeyondLast) {
  const Table t({1.0, 2.0, 3.0}, {1.0, 2.0, 4.0});
  EXPECT_EQ(t.sliding(0.5), 1.0);    // held at F(1)
  EXPECT_EQ(t.sliding(1e-12), 1.0);  // also the breakaway level
  EXPECT_EQ(t.breakaway_positive(), 1.0);
  // Beyond v = 3: last secant slope (4 - 2)/(3 - 2) = 2: F(4) = 4 + 2 * 1 = 6
  expect_rel(t.sliding(4.0), 6.0);
  expect_rel(t.sliding(10.0), 18.0);
}

TEST(Table, NoOvershootBetweenPoints) {
  // A step in the data: a cubic spline would overshoot, the monotone Hermite does not.
  const Table t({0.1, 0.2, 0.3, 0.4, 0.5}, {1.0, 1.0, 2.0, 2.0, 2.0});
  double previous = t.sliding(0.1);
  for (int i = 1; i <= 400; ++i) {
    const double v = 0.1 + 0.4 * i / 400.0;
    const double f = t.sliding(v);
    EXPECT_GE(f, 1.0) << v;
    EXPECT_LE(f, 2.0) << v;
    EXPECT_GE(f, previous) << "monotone data gives a monotone curve at v = " << v;
    previous = f;
  }
  // A falling (Stribeck-like) branch stays within each interval's end values.
  const Table s({0.01, 0.02, 0.05, 0.1, 1.0}, {1.5, 1.1, 1.0, 1.02, 1.4});
  for (int i = 0; i <= 1000; ++i) {
    const double v = 0.01 + 0.99 * i / 1000.0;
    const auto& vv = s.velocity();
    const auto& ff = s.force();
    std::size_t k = 0;
    while (k + 2 < vv.size() && vv[k + 1] < v) ++k;
    const double lo = std::min(ff[k], ff[k + 1]), hi = std::max(ff[k], ff[k + 1]);
    EXPECT_GE(s.sliding(v), lo) << v;
    EXPECT_LE(s.sliding(v), hi) << v;
  }
}

TEST(Table, OneSidedTableIsMirrored) {
  const Table t({1.0, 2.0, 3.0}, {1.0, 2.0, 4.0});
  for (double v : {0.5, 1.0, 1.5, 2.5, 3.0, 7.0}) EXPECT_EQ(t.sliding(-v), -t.sliding(v)) << v;
  EXPECT_EQ(t.breakaway_negative(), 1.0);
  EXPECT_EQ(t.sliding(0.0), 0.0);
  // Only negative velocities: mirrored the other way.
  const Table n({-3.0, -2.0, -1.0}, {-4.0, -2.0, -1.0});
  for (double v : {0.5, 1.5, 2.5, 7.0}) EXPECT_EQ(n.sliding(v), t.sliding(v)) << v;
}

TEST(Table, TwoBranches) {
  // Negative branch |v| = [1, 2], |F| = [2, 3] (linear: F = 1 + |v|); positive F = 0.5 + 0.5 v.
  const Table t({-2.0, -1.0, 1.0, 2.0}, {-3.0, -2.0, 1.0, 1.5});
  expect_rel(t.sliding(-1.5), -2.5);
  expect_rel(t.sliding(1.5), 1.25);
  EXPECT_EQ(t.breakaway_positive(), 1.0);
  EXPECT_EQ(t.breakaway_negative(), 2.0);
  expect_rel(t.sliding(-4.0), -5.0);  // extrapolated with slope 1
}

TEST(Table, StictionUpToTheFirstPoint) {
  const Table t({-2.0, -1.0, 1.0, 2.0}, {-3.0, -2.0, 1.0, 1.5});
  EXPECT_EQ(friction_force(t, 0.0, 0.5), 0.5);
  EXPECT_EQ(friction_force(t, 0.0, 1.0), 1.0);
  EXPECT_EQ(friction_force(t, 0.0, 5.0), 1.0);
  EXPECT_EQ(friction_force(t, 0.0, -1.9), -1.9);
  EXPECT_EQ(friction_force(t, 0.0, -5.0), -2.0);
  EXPECT_EQ(friction_force(t, 1.5, 100.0), t.sliding(1.5));
}

TEST(Table, DefaultIsValid) {
  const Table t;
  EXPECT_NO_THROW(t.validate());
  EXPECT_EQ(t.sliding(0.5), 1.0);
}

// One test per rule, with the message.
TEST(TableValidation, UnequalLengths) {
  EXPECT_EQ(error_of({0.1, 0.2, 0.3}, {1.0, 1.0}), "table: velocity has 3 points but force has 2; they must be equal");
}

TEST(TableValidation, NonFinite) {
  EXPECT_EQ(error_of({0.1, 0.2}, {1.0, NAN}), "table: point 1 (velocity 0.2, force nan) must be finite");
  EXPECT_EQ(error_of({0.1, INFINITY}, {1.0, 1.0}), "table: point 1 (velocity inf, force 1) must be finite");
}

TEST(TableValidation, ZeroVelocity) {
  EXPECT_EQ(error_of({0.0, 0.2, 0.3}, {0.0, 1.0, 1.0}),
            "table: velocity[0] = 0 must be nonzero (the force at rest is the breakaway level, taken from the smallest |v|)");
}

TEST(TableValidation, NotStrictlyIncreasing) {
  EXPECT_EQ(error_of({0.1, 0.3, 0.2}, {1.0, 1.0, 1.0}),
            "table: velocity[2] = 0.2 must be > velocity[1] = 0.3 (strictly increasing, m/s or rad/s)");
  EXPECT_EQ(error_of({0.1, 0.1}, {1.0, 1.0}),
            "table: velocity[1] = 0.1 must be > velocity[0] = 0.1 (strictly increasing, m/s or rad/s)");
}

TEST(TableValidation, ForceSignDiffersFromVelocity) {
  EXPECT_EQ(error_of({-0.2, -0.1, 0.1, 0.2}, {-1.0, 1.0, 1.0, 1.0}),
            "table: force[1] = 1 must have the sign of velocity[1] = -0.1");
}

TEST(TableValidation, BranchWithOnePoint) {
  EXPECT_EQ(error_of({-0.1, 0.1, 0.2}, {-1.0, 1.0, 1.0}),
            "table: each direction needs at least 2 points (has 2 positive, 1 negative)");
  EXPECT_EQ(error_of({0.1}, {1.0}), "table: each direction needs at least 2 points (has 1 positive, 0 negative)");
  EXPECT_EQ(error_of({}, {}), "table: each direction needs at least 2 points (has 0 positive, 0 negative)");
}

}  // namespace
}  // namespace frictionlab
