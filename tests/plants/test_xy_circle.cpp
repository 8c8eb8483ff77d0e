// Circular contours (core/contour_input.hpp) and the circular test of examples/xy_circle.yaml: the
// quadrant glitches at the four axis reversals, and their absence without friction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "radial_error.hpp"
#include "frictionlab/core/contour_input.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;
using frictionlab::testing::radial_error;
using frictionlab::testing::RadialError;

namespace {

constexpr double kPi = std::numbers::pi;

std::string example(const std::string& name) { return std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name; }

}  // namespace

TEST(ContourInput, CircleReferencesRunTheCircleAtTheFeed) {
  constexpr double kRelTol = 1e-13;  // sine and cosine of the same angle: a few roundoffs of R
  for (bool cw : {false, true}) {
    SCOPED_TRACE(cw ? "clockwise" : "counter-clockwise");
    CircleContour c;
    c.cx = 0.1;
    c.cy = -0.05;
    c.radius = 0.02;
    c.feed = 0.03;
    c.clockwise = cw;
    c.turns = 1.5;
    c.start_angle = 0.3;
    const auto in = c.inputs();
    EXPECT_NEAR(c.duration(), 1.5 * 2 * kPi * 0.02 / 0.03, 1e-15);
    for (double t : {0.0, 0.1, 0.77, 3.1}) {
      const double th = 0.3 + (cw ? -1.0 : 1.0) * (0.03 / 0.02) * t;
      EXPECT_NEAR(c.angle(t), th, kRelTol);
      const InputValue x = in[0].at(t), y = in[1].at(t);
      EXPECT_NEAR(x.value, 0.1 + 0.02 * std::cos(th), kRelTol * 0.1);
      EXPECT_NEAR(y.value, -0.05 + 0.02 * std::sin(th), kRelTol * 0.1);
      EXPECT_NEAR(std::hypot(x.rate, y.rate), 0.03, kRelTol);                    // the feed, m/s
      EXPECT_NEAR(std::hypot(x.accel, y.accel), 0.03 * 0.03 / 0.02, kRelTol);   // F^2 / R, m/s^2
      // Direction: the cross product of radius and velocity is + counter-clockwise.
      const double cross = (x.value - 0.1) * y.rate - (y.value + 0.05) * x.rate;
      EXPECT_EQ(cross > 0, !cw);
    }
  }
}

TEST(ContourInput, BadCircleAndPathAreRefusedNamingTheValue) {
  CircleContour c;
  c.radius = 0.0;
  EXPECT_EQ(error_of([&] { c.validate("s.yaml: input"); }), "s.yaml: input: radius = 0 must be > 0 (m)");
  c.radius = 0.01;
  c.feed = -1;
  EXPECT_EQ(error_of([&] { c.inputs(); }), "circle: feed = -1 must be > 0 (m/s)");
  const std::vector<double> t = {0.0, 1.0, 1.0}, x = {0, 1, 2}, y = {0, 1, 2};
  EXPECT_EQ(error_of([&] { path_inputs(t, x, y, "p.csv"); }),
            "p.csv: sample 3: time 1 s must be greater than the previous sample's 1 s");
  const std::vector<double> short_y = {0, 1};
  EXPECT_NE(error_of([&] { path_inputs(t, x, short_y); }).find("same number of samples, got 3, 3 and 2"), std::string::npos);
  const std::vector<double> t2 = {0.0, 0.5}, x2 = {0.0, 0.01}, y2 = {0.0, -0.02};
  const auto in = path_inputs(t2, x2, y2);
  constexpr double kRelTol = 1e-15;  // one linear interpolation
  EXPECT_NEAR(in[0].at(0.25).value, 0.005, kRelTol);
  EXPECT_NEAR(in[1].at(0.25).rate, -0.04, kRelTol);
}

// examples/xy_circle.yaml: static friction makes a glitch in the radial error at each of the four
// axis reversals, far above the error elsewhere; with frictionless axes the glitches vanish.
TEST(XyCircle, QuadrantGlitchesAtTheFourReversalsVanishWithoutFriction) {
  const Scenario sc = load_scenario(example("xy_circle.yaml"));
  ASSERT_EQ(sc.plant->type(), "xy-table");
  ASSERT_EQ(sc.inputs.size(), 2u);
  constexpr double R = 0.01;       // m, the example's radius
  constexpr double kFrom = 0.2;    // s: past the start transient at 45 degrees (loop settles in ~0.1 s)
  constexpr double kNear = 15.0;   // degrees: a glitch lasts some ms after the reversal at 0.02 m/s on R = 10 mm
  constexpr double kFar = 30.0;    // degrees
  // "Much larger": a glitch is the stuck axis's lag (tens of micrometres here); elsewhere the
  // integral and feedforward hold the radius to a small fraction of that (measured: ratio ~160).
  constexpr double kGlitchRatio = 5.0;
  const Trajectory tr = simulate(sc);
  const RadialError with = radial_error(tr, 0.0, 0.0, R, kFrom, kNear, kFar);
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(with.near[k], kGlitchRatio * with.elsewhere) << "no glitch at " << 90 * k << " degrees";
  }
  std::printf("with friction: glitches %.3g %.3g %.3g %.3g um, elsewhere %.3g um\n", 1e6 * with.near[0],
              1e6 * with.near[1], 1e6 * with.near[2], 1e6 * with.near[3], 1e6 * with.elsewhere);

  const auto& table = dynamic_cast<const XyTable&>(*sc.plant);
  XyAxis x = table.axis(0), y = table.axis(1);
  x.law = Viscous{0.0};
  y.law = Viscous{0.0};
  const XyTable frictionless(x, y, table.timing());
  const Trajectory free = simulate(frictionless, sc.law, sc.inputs, sc.options);
  const RadialError without = radial_error(free, 0.0, 0.0, R, kFrom, kNear, kFar);
  // Without friction the reversals are no different from the rest of the circle: what is left at
  // them is the loop's ordinary tracking error (nanometres), below a tenth of the glitches and
  // below the friction run's error away from the reversals.
  constexpr double kVanished = 0.1;
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(without.near[k], kVanished * with.near[k]) << 90 * k << " degrees";
    EXPECT_LT(without.near[k], with.elsewhere) << 90 * k << " degrees";
  }
  std::printf("frictionless: at reversals %.3g %.3g %.3g %.3g um, elsewhere %.3g um\n", 1e6 * without.near[0],
              1e6 * without.near[1], 1e6 * without.near[2], 1e6 * without.near[3], 1e6 * without.elsewhere);
}
