// Feedforward compensation: the law itself away from rest, continuous through the smoothing band,
// the band's kinks located as events, the fixed-step form, and its error message.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "control/harness.hpp"
#include "error_message.hpp"
#include "frictionlab/control/feedforward.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

// The law's value outside the band is the law's own call: equal to its rounding.
constexpr double kRelTol = 1e-15;

Stribeck stribeck() { return Stribeck{1.0, 1.5, 0.01, 2.0, 0.4}; }  // N, N, m/s, -, N s/m

Asymmetric<CoulombViscous> asymmetric() {
  Asymmetric<CoulombViscous> a;
  a.pos = {2.0, 0.5};   // N, N s/m
  a.neg = {1.2, 0.3};
  return a;
}

TEST(Feedforward, EqualsTheLawAwayFromRest) {
  const FrictionLaw law = stribeck();
  const FeedforwardCompensation ff(law, {.band = 1e-3});
  for (double vr : {-0.5, -0.02, -1.0001e-3, 1.0001e-3, 0.003, 0.02, 0.5}) {
    EXPECT_NEAR(ff.force(vr), law.sliding(vr), kRelTol * std::abs(law.sliding(vr))) << "vr " << vr;
  }
  // Direction-dependent parameters act on their own side.
  const FrictionLaw asym = asymmetric();
  const FeedforwardCompensation ffa(asym, {.band = 1e-3});
  EXPECT_DOUBLE_EQ(ffa.force(0.1), 2.0 + 0.5 * 0.1);
  EXPECT_DOUBLE_EQ(ffa.force(-0.1), -(1.2 + 0.3 * 0.1));
}

TEST(Feedforward, LinearAndContinuousThroughTheBand) {
  const double b = 2e-3;  // m/s
  const FrictionLaw law = stribeck();
  const FeedforwardCompensation ff(law, {.band = b});
  // Symmetric law: odd, 0 at rest, F(b) v / b inside.
  EXPECT_EQ(ff.force(0.0), 0.0);
  EXPECT_NEAR(ff.force(0.5 * b), 0.5 * law.sliding(b), 1e-15);
  EXPECT_NEAR(ff.force(-0.25 * b), -0.25 * law.sliding(b), 1e-15);
  // Continuous at the edges: the jump across +-b is what the law moves over the tiny step.
  for (double edge : {b, -b}) {
    const double below = ff.force(edge * (1 - 1e-12)), above = ff.force(edge * (1 + 1e-12));
    EXPECT_NEAR(above, below, 1e-9) << "edge " << edge;  // slope < 1e3 N/(m/s) times 4e-15 m/s, plus rounding
  }
  // Over a fine grid no neighbours jump by more than the steepest slope (inside: F(b)/b) allows.
  const double dv = b / 1000;
  const double max_slope = law.sliding(b) / b;  // N/(m/s): the band's slope, steeper than the law outside
  for (double v = -3 * b; v < 3 * b; v += dv)
    ASSERT_LE(std::abs(ff.force(v + dv) - ff.force(v)), 1.0001 * max_slope * dv) << "at " << v;
  // Asymmetric law: at rest the mean of the two levels at the band's edges.
  const FrictionLaw asym = asymmetric();
  const FeedforwardCompensation ffa(asym, {.band = b});
  EXPECT_NEAR(ffa.force(0.0), 0.5 * (asym.sliding(b) + asym.sliding(-b)), 1e-15);
}

TEST(Feedforward, StatesAndEventsFollowTheReferenceRate) {
  // A sine of the reference rate through the band: the runner locates each edge crossing, and the
  // output with the event-switched region equals force(vr) everywhere off the edges.
  const double b = 1e-3, A = 5e-3, w = 2.0;  // m/s, m/s, rad/s
  const FeedforwardCompensation ff(stribeck(), {.band = b});
  const testing::InputAt at = [&](double t) {
    CompensatorInput in;
    in.t = t;
    in.reference_rate = A * std::sin(w * t);
    in.reference_accel = A * w * std::cos(w * t);
    return in;
  };
  std::vector<double> z(1);
  ff.initial_states(at(0.0), z);
  EXPECT_EQ(z[0], 0.0);  // vr = 0 at t = 0: inside the band
  const double period = 2 * M_PI / w;
  const auto events = testing::run(ff, at, z, 0.0, period, 2000);
  // Per period vr crosses +b twice and -b twice.
  ASSERT_EQ(events.size(), 4u);
  const double t_edge = std::asin(b / A) / w;  // first crossing of +b (s)
  constexpr double kTimeTol = 1e-9;  // bisection to 1e-12 s; the sine's rounding near the edge
  EXPECT_NEAR(events[0].t, t_edge, kTimeTol);
  EXPECT_EQ(events[0].k, 0);
  EXPECT_NEAR(events[1].t, period / 2 - t_edge, kTimeTol);
  EXPECT_NEAR(events[2].t, period / 2 + t_edge, kTimeTol);
  EXPECT_EQ(events[2].k, 1);
  EXPECT_NEAR(events[3].t, period - t_edge, kTimeTol);
  EXPECT_EQ(z[0], 0.0);  // back inside at the end of the period
  // Between events the output is force(vr): run again, checking at every grid point.
  ff.initial_states(at(0.0), z);
  for (int i = 1; i <= 400; ++i) {
    const double t0 = period * (i - 1) / 400, t1 = period * i / 400;
    testing::run(ff, at, z, t0, t1, 1);
    const CompensatorInput in = at(t1);
    EXPECT_NEAR(ff.output(in, z), ff.force(in.reference_rate), 1e-12) << "t " << t1;
  }
}

TEST(Feedforward, RightBeforeTheFirstEventWhenStartedWithoutTheReference) {
  // A loop that set the states from a zero input (region 0) while the reference already moves at
  // 3b: the output is still the law's, and the first located edge sets the region right.
  const double b = 1e-3;
  const FeedforwardCompensation ff(stribeck(), {.band = b});
  const testing::InputAt at = [&](double t) {
    CompensatorInput in;
    in.reference_rate = 3 * b * std::cos(t);
    in.reference_accel = -3 * b * std::sin(t);
    return in;
  };
  std::vector<double> z(1);
  ff.initial_states(CompensatorInput{}, z);
  ASSERT_EQ(z[0], 0.0);
  EXPECT_DOUBLE_EQ(ff.output(at(0.0), z), stribeck().sliding(3 * b));
  const auto events = testing::run(ff, at, z, 0.0, 1.5, 300);  // vr falls through b at acos(1/3)
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].t, std::acos(1.0 / 3.0), 1e-9);
  EXPECT_EQ(z[0], 0.0);  // inside, and consistent with vr from here on
  EXPECT_NEAR(ff.output(at(1.5), z), ff.force(at(1.5).reference_rate), 1e-15);
}

TEST(Feedforward, EdgesCrossedAtOnce) {
  // A reference rate that jumps from -2b to +2b (a triangle's corner): both edges report at once.
  const double b = 1e-3;
  const FeedforwardCompensation ff(stribeck(), {.band = b});
  std::vector<double> z{-1.0};
  CompensatorInput in;
  in.reference_rate = 2 * b;
  ff.on_event(in, z, 0);
  ff.on_event(in, z, 1);
  EXPECT_EQ(z[0], 1.0);
  // A repeated report of an edge the rate is already far from keeps the region.
  ff.on_event(in, z, 0);
  EXPECT_EQ(z[0], 1.0);
}

TEST(Feedforward, FixedStepUpdate) {
  const FrictionLaw law = stribeck();
  const FeedforwardCompensation ff(law, {.band = 1e-3});
  std::vector<double> z{0.0};
  CompensatorInput in;
  in.reference_rate = 0.05;
  EXPECT_DOUBLE_EQ(ff.update(in, z, 1e-3), law.sliding(0.05));
  EXPECT_EQ(z[0], 1.0);
  in.reference_rate = 4e-4;
  EXPECT_DOUBLE_EQ(ff.update(in, z, 1e-3), ff.force(4e-4));
  EXPECT_EQ(z[0], 0.0);
}

TEST(Feedforward, JacobianIsZero) {
  const FeedforwardCompensation ff(stribeck());
  std::vector<double> dy(4, 7.0), df(4, 7.0), z{1.0};
  CompensatorInput in;
  in.velocity = 0.1;
  in.reference_rate = 0.1;
  ASSERT_TRUE(ff.jacobian(in, z, dy, df));
  for (double d : dy) EXPECT_EQ(d, 0.0);
  for (double d : df) EXPECT_EQ(d, 0.0);
}

TEST(Feedforward, RejectsABadBand) {
  EXPECT_EQ(error_of([] { FeedforwardCompensation(stribeck(), {.band = 0.0}); }),
            "feedforward: band = 0 must be > 0 (m/s or rad/s)");
  EXPECT_EQ(error_of([] { FeedforwardCompensation(stribeck(), {.band = -0.001}); }),
            "feedforward: band = -0.001 must be > 0 (m/s or rad/s)");
  EXPECT_EQ(error_of([] { FeedforwardCompensation(stribeck(), {.band = std::numeric_limits<double>::infinity()}); }),
            "feedforward: band = inf must be > 0 (m/s or rad/s)");
}

}  // namespace
}  // namespace frictionlab

namespace frictionlab {
namespace {

// A Stribeck law with a load term (two coefficients) and a temperature term.
FrictionLaw loaded_stribeck() {
  LawEffects e;
  e.load = LoadDependence{0.08, 0.05};
  TemperatureDependence t;
  t.T_ref = 25.0;
  t.Fc_per_K = -0.005;
  t.Fv_per_K = -0.004;
  e.temperature = t;
  return FrictionLaw(Stribeck{1.0, 1.5, 0.01, 2.0, 0.4}).with_effects(e);
}

// The compensation at the input's load and temperature: the law with its levels moved, outside
// the band and at the band's moved ends; no temperature is T_ref; the Jacobian has no analytic form.
TEST(Feedforward, TakesTheInputsLoadAndTemperature) {
  const FrictionLaw law = loaded_stribeck();
  const double b = 1e-3;
  const FeedforwardCompensation ff(law, {.band = b});
  Conditions c;
  c.load = -30.0;  // N: its magnitude counts
  c.temperature = 40.0;
  for (double vr : {-0.5, -0.02, 0.003, 0.5}) {
    CompensatorInput in;
    in.reference_rate = vr;
    in.load = c.load;
    in.temperature = c.temperature;
    std::vector<double> z(1);
    ff.initial_states(in, z);
    EXPECT_NEAR(ff.output(in, z), law.sliding(vr, c), kRelTol * std::abs(law.sliding(vr, c))) << "vr " << vr;
    EXPECT_GT(std::abs(ff.output(in, z) - law.sliding(vr)), 1.0) << "the load moves the force, vr " << vr;
    EXPECT_NEAR(ff.update(in, z, 1e-3), law.sliding(vr, c), kRelTol * std::abs(law.sliding(vr, c)));
    in.temperature.reset();  // none measured: the law at T_ref, the load still counts
    Conditions at_ref = c;
    at_ref.temperature.reset();
    EXPECT_NEAR(ff.output(in, z), law.sliding(vr, at_ref), kRelTol * std::abs(law.sliding(vr, at_ref)));
  }
  // Inside the band: the straight line between the moved ends.
  EXPECT_NEAR(ff.force(0.5 * b, c), law.sliding(-b, c) + (law.sliding(b, c) - law.sliding(-b, c)) * 0.75, 1e-12);
  std::vector<double> dout(4), dder(4);
  CompensatorInput in;
  EXPECT_FALSE(ff.jacobian(in, std::vector<double>{1.0}, dout, dder));
}

// A Stribeck law with a two-harmonic ripple of period 0.02 m (a_1 = 0.6, a_2 = 0.15, b_1 = -0.4 N).
FrictionLaw rippled_stribeck() {
  LawEffects e;
  e.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  return FrictionLaw(Stribeck{1.0, 1.5, 0.01, 2.0, 0.4}).with_effects(e);
}

// r(q) written out in the test, independent of PositionRipple::force.
double ripple_by_hand(double q) {
  const double w = 2 * M_PI * q / 0.02;
  return 0.6 * std::sin(w) + 0.15 * std::sin(2 * w) - 0.4 * std::cos(w);
}

// The feedforward adds the ripple at the REFERENCE position, outside the band and inside it
// (where the velocity part is the band's straight line), in output() and update(); the measured
// position does not enter, and the Jacobian stays zero (the reference has no entry).
TEST(Feedforward, AddsTheRippleAtTheReferencePosition) {
  const FrictionLaw law = rippled_stribeck();
  const double b = 1e-3;
  const FeedforwardCompensation ff(law, {.band = b});
  // Sums of a few rounded terms: equal to the hand-written ripple to a few ulps of the force.
  constexpr double kSumTol = 1e-14;
  // At q = P/4 the ripple is a_1 = 0.6 N (sin = 1, cos = 0, the second harmonic's sine 0).
  EXPECT_NEAR(ripple_by_hand(0.005), 0.6, 1e-15);
  for (double q : {-0.013, 0.0, 0.005, 0.0071, 0.0123, 0.31}) {
    for (double vr : {-0.5, -0.02, -2e-3, -5e-4, 0.0, 3e-4, 2e-3, 0.5}) {
      SCOPED_TRACE("q " + std::to_string(q) + " vr " + std::to_string(vr));
      CompensatorInput in;
      in.reference = q;
      in.reference_rate = vr;
      in.position = q + 0.004;  // the measured position lags: not what the feedforward reads
      std::vector<double> z(1);
      ff.initial_states(in, z);
      const double velocity_part = std::abs(vr) > b ? law.sliding(vr) : ff.force(vr);
      EXPECT_NEAR(ff.output(in, z), velocity_part + ripple_by_hand(q), kSumTol * 4.0);
      EXPECT_EQ(ff.output(in, z), ff.force(vr) + law.ripple(q));  // the same operations
      EXPECT_EQ(ff.update(in, z, 1e-3), ff.force(vr) + law.ripple(q));
    }
  }
  // The ripple does move the output (a test that passed with it ignored would be none).
  CompensatorInput in;
  in.reference = 0.005;
  std::vector<double> z{0.0};
  EXPECT_NEAR(ff.output(in, z) - ff.force(0.0), 0.6, 1e-12);
  std::vector<double> dout(4, 1.0), dder(4, 1.0);
  ASSERT_TRUE(ff.jacobian(in, z, dout, dder));
  for (double d : dout) EXPECT_EQ(d, 0.0);
}

}  // namespace
}  // namespace frictionlab
