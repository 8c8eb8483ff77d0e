// Feedback compensation: the law at the measured velocity, 0 inside the dead band, the band's
// jumps located as events, the fixed-step form, and its error message.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "control/harness.hpp"
#include "error_message.hpp"
#include "frictionlab/control/feedback.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

Stribeck stribeck() { return Stribeck{1.0, 1.5, 0.01, 2.0, 0.4}; }  // N, N, m/s, -, N s/m

TEST(Feedback, LawOutsideZeroInsideTheDeadBand) {
  const FrictionLaw law = stribeck();
  const double db = 2e-3;  // m/s
  const FeedbackCompensation fb(law, {.dead_band = db});
  for (double v : {-0.3, -0.0021, 0.0021, 0.3}) EXPECT_DOUBLE_EQ(fb.force(v), law.sliding(v)) << "v " << v;
  for (double v : {-0.0019, -1e-6, 0.0, 1e-6, 0.0019, db, -db}) EXPECT_EQ(fb.force(v), 0.0) << "v " << v;
  // The jump at the edge is the law's full force there (about Fs here: 1.5 e^-0.04 + 0.4 * 0.002).
  EXPECT_NEAR(fb.force(db * (1 + 1e-9)), law.sliding(db), 1e-6);
  EXPECT_GT(fb.force(db * (1 + 1e-9)), 1.4);
}

TEST(Feedback, JacobianIsTheLawsSlopeOutsideTheDeadBand) {
  // Stribeck (the slope changes sign through vs), an asymmetric law (each side its own) and a
  // table (Hermite segments), both directions, inside and outside the band.
  Asymmetric<Stribeck> asym;
  asym.pos = Stribeck{1.0, 1.5, 0.01, 2.0, 0.4};
  asym.neg = Stribeck{0.8, 1.1, 0.02, 1.0, 0.3};
  const Table table({0.001, 0.01, 0.1}, {1.2, 1.0, 1.3});  // m/s, N (mirrored for v < 0)
  constexpr double kFdRelTol = 1e-6;  // central differences of a smooth curve, step 1e-6 of v: ~1e-9
  for (const FrictionLaw& law : {FrictionLaw(stribeck()), FrictionLaw(asym), FrictionLaw(table)}) {
    const FeedbackCompensation fb(law, {.dead_band = 2e-3});
    for (double v : {-0.3, -0.012, -0.004, -1e-3, 0.0, 5e-4, 0.004, 0.012, 0.3}) {
      SCOPED_TRACE(law.name() + " at v = " + std::to_string(v));
      CompensatorInput in;
      in.velocity = v;
      in.position = 0.02;
      in.drive = 3.0;
      std::vector<double> z(1);
      fb.initial_states(in, z);
      testing::expect_jacobian_matches(fb, in, z, kFdRelTol);
      std::vector<double> dy(4), df(4);
      ASSERT_TRUE(fb.jacobian(in, z, dy, df));
      if (std::abs(v) <= 2e-3) {
        EXPECT_EQ(dy[1], 0.0);  // inside the dead band: the output is 0
      }
    }
  }
  // Outside the band the slope is the law's (Stribeck at 0.3 m/s: Fv plus a vanishing decay term).
  const FeedbackCompensation fb(stribeck(), {.dead_band = 2e-3});
  CompensatorInput in;
  in.velocity = 0.3;
  std::vector<double> z{1.0}, dy(4), df(4);
  ASSERT_TRUE(fb.jacobian(in, z, dy, df));
  EXPECT_NEAR(dy[1], 0.4, 1e-12);
  // A dynamic law's output is its steady-state force, which has no differentiable form here.
  const FeedbackCompensation dynamic(FrictionLaw(LuGre{}), {.dead_band = 2e-3});
  dy.assign(4, -7.0);
  EXPECT_FALSE(dynamic.jacobian(in, z, dy, df));
  EXPECT_EQ(dy[1], -7.0);  // nothing written
}

TEST(Feedback, EventsLocateTheDeadBandEdges) {
  // The measured velocity decelerates linearly through rest: v = 0.01 - 0.02 t (m/s).
  const double db = 1e-3;
  const FeedbackCompensation fb(stribeck(), {.dead_band = db});
  const testing::InputAt at = [](double t) {
    CompensatorInput in;
    in.t = t;
    in.velocity = 0.01 - 0.02 * t;
    return in;
  };
  std::vector<double> z(1);
  fb.initial_states(at(0.0), z);
  EXPECT_EQ(z[0], 1.0);
  const auto events = testing::run(fb, at, z, 0.0, 1.0, 100);
  ASSERT_EQ(events.size(), 2u);
  constexpr double kTimeTol = 1e-10;  // bisection to 1e-12 s
  EXPECT_EQ(events[0].k, 0);
  EXPECT_NEAR(events[0].t, (0.01 - db) / 0.02, kTimeTol);
  EXPECT_EQ(events[1].k, 1);
  EXPECT_NEAR(events[1].t, (0.01 + db) / 0.02, kTimeTol);
  EXPECT_EQ(z[0], -1.0);
  // Just past the second edge the output has the law's negative force; between them, none.
  EXPECT_DOUBLE_EQ(fb.output(at(1.0), z), stribeck().sliding(at(1.0).velocity));
  std::vector<double> inside{0.0};
  EXPECT_EQ(fb.output(at(0.5), inside), 0.0);
}

TEST(Feedback, FixedStepUpdate) {
  const FrictionLaw law = stribeck();
  const FeedbackCompensation fb(law);
  std::vector<double> z{0.0};
  CompensatorInput in;
  in.velocity = -0.02;
  EXPECT_DOUBLE_EQ(fb.update(in, z, 1e-3), law.sliding(-0.02));
  EXPECT_EQ(z[0], -1.0);
  in.velocity = 5e-4;
  EXPECT_EQ(fb.update(in, z, 1e-3), 0.0);
  EXPECT_EQ(z[0], 0.0);
}

TEST(Feedback, RejectsABadDeadBand) {
  EXPECT_EQ(error_of([] { FeedbackCompensation(stribeck(), {.dead_band = 0.0}); }),
            "feedback: dead_band = 0 must be > 0 (m/s or rad/s)");
  EXPECT_EQ(error_of([] { FeedbackCompensation(stribeck(), {.dead_band = std::nan("")}); }),
            "feedback: dead_band = nan must be > 0 (m/s or rad/s)");
}

// A Stribeck law with a two-harmonic ripple of period 0.02 m (a_1 = 0.6, a_2 = 0.15, b_1 = -0.4 N).
FrictionLaw rippled_stribeck() {
  LawEffects e;
  e.ripple = PositionRipple{0.02, {0.6, 0.15}, {-0.4, 0.0}, {}, {}};
  return FrictionLaw(stribeck()).with_effects(e);
}

// r(q) written out in the test, independent of PositionRipple::force.
double ripple_by_hand(double q) {
  const double w = 2 * M_PI * q / 0.02;
  return 0.6 * std::sin(w) + 0.15 * std::sin(2 * w) - 0.4 * std::cos(w);
}

// The feedback adds the ripple at the MEASURED position, outside the dead band and inside it (a
// stuck axis still meets the ripple), in output() and update(); the reference position does not
// enter; the Jacobian's position entry is the ripple's slope dr/dx.
TEST(Feedback, AddsTheRippleAtTheMeasuredPositionInAndOutsideTheDeadBand) {
  const FrictionLaw law = rippled_stribeck();
  const double db = 2e-3;
  const FeedbackCompensation fb(law, {.dead_band = db});
  constexpr double kSumTol = 4e-14;  // a few rounded terms of about 1 N: a few ulps
  // Positions away from 0: the Jacobian check's difference step is relative to |x|.
  for (double x : {-0.013, 0.0009, 0.005, 0.0071, 0.0123, 0.31}) {
    for (double v : {-0.3, -0.0021, -1e-3, 0.0, 1e-6, 0.0019, 0.0021, 0.3}) {
      SCOPED_TRACE("x " + std::to_string(x) + " v " + std::to_string(v));
      CompensatorInput in;
      in.position = x;
      in.velocity = v;
      in.reference = x - 0.004;  // not what the feedback reads
      std::vector<double> z(1);
      fb.initial_states(in, z);
      const double velocity_part = std::abs(v) > db ? law.sliding(v) : 0.0;
      EXPECT_NEAR(fb.output(in, z), velocity_part + ripple_by_hand(x), kSumTol);
      EXPECT_EQ(fb.output(in, z), fb.force(v) + law.ripple(x));  // the same operations
      EXPECT_EQ(fb.update(in, z, 1e-3), fb.force(v) + law.ripple(x));
      constexpr double kFdRelTol = 1e-6;  // central differences of smooth curves, step 1e-6: ~1e-9
      testing::expect_jacobian_matches(fb, in, z, kFdRelTol);
    }
  }
  // At rest, inside the dead band, the output is the ripple alone: a_1 = 0.6 N at x = P/4.
  CompensatorInput in;
  in.position = 0.005;
  std::vector<double> z{0.0}, dy(4), df(4);
  EXPECT_NEAR(fb.output(in, z), 0.6, 1e-12);
  ASSERT_TRUE(fb.jacobian(in, z, dy, df));
  // dr/dx at P/4: 2 pi / P (0.6 cos(pi/2) + 0.3 cos(pi) + 0.4 sin(pi/2)) = 100 pi * 0.1 N/m.
  EXPECT_NEAR(dy[0], 100 * M_PI * (-0.3 + 0.4), 1e-9);
}

}  // namespace
}  // namespace frictionlab
