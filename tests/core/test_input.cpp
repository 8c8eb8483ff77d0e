// InputSignal::at's acceleration (d2u/dt2) against central differences of its rate.
#include <gtest/gtest.h>

#include <cmath>

#include "frictionlab/core/input.hpp"

using namespace frictionlab;

namespace {

// Central difference of the rate with step h: truncation error h^2/6 |u''''| and rounding error
// eps |u'| / h; h = 1e-4 s keeps both below 1e-7 of the acceleration scale of these signals.
constexpr double kStep = 1e-4;
constexpr double kRelTol = 1e-6;  // the difference quotient's error above, with margin

double rate_difference(const InputSignal& s, double t) { return (s.at(t + kStep).rate - s.at(t - kStep).rate) / (2 * kStep); }

}  // namespace

TEST(Input, SineAccelerationMatchesDifferencesOfItsRate) {
  InputSignal s;
  s.shape = InputShape::sine;
  s.amplitude = 2.5;
  s.omega = 7.0;
  s.phase = 0.3;
  s.offset = -1.0;
  const double scale = s.amplitude * s.omega * s.omega;  // peak acceleration, unit/s^2
  for (double t = 0.05; t < 2.0; t += 0.0917) {
    const InputValue v = s.at(t);
    EXPECT_NEAR(v.accel, rate_difference(s, t), kRelTol * scale) << "t = " << t;
    EXPECT_DOUBLE_EQ(v.accel, -s.amplitude * s.omega * s.omega * std::sin(s.omega * t + s.phase));
  }
}

TEST(Input, TableAccelerationMatchesDifferencesOfItsRateInsideSegments) {
  InputSignal s;
  s.shape = InputShape::table;
  s.times = {0.0, 0.4, 1.0, 1.3, 2.0};
  s.values = {0.0, 1.0, -0.5, -0.5, 2.0};
  for (double t : {0.1, 0.35, 0.7, 1.15, 1.6, 1.99}) {  // at least kStep from every corner
    const InputValue v = s.at(t);
    EXPECT_EQ(v.accel, 0.0) << "piecewise linear: no curvature inside a segment, t = " << t;
    EXPECT_EQ(rate_difference(s, t), 0.0) << "t = " << t;
  }
  s.hold_steps = true;
  EXPECT_EQ(s.at(0.7).accel, 0.0);
}

TEST(Input, ShapesWithoutCurvatureHaveZeroAcceleration) {
  InputSignal ramp;
  ramp.shape = InputShape::ramp;
  ramp.rate = 3.0;
  ramp.time = 0.5;
  InputSignal trap;
  trap.shape = InputShape::trapezoid;
  trap.rate = 2.0;
  trap.level = 1.0;
  trap.hold = 0.5;
  InputSignal step;
  step.shape = InputShape::step;
  step.value = 4.0;
  step.time = 0.2;
  for (const InputSignal* s : {&ramp, &trap, &step})
    for (double t = 0.0; t < 2.0; t += 0.13) EXPECT_EQ(s->at(t).accel, 0.0) << InputSignal::shape_name(s->shape) << " t = " << t;
  EXPECT_EQ(ramp.at(1.0).rate, 3.0) << "the rate is still there";
}
