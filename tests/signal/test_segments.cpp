#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "frictionlab/signal/segments.hpp"

namespace fl = frictionlab;

namespace {

// A velocity staircase: 0 for 1 s, 0.1 m/s for 2 s, a 0.5 s ramp, 0.3 m/s for 2 s, 0 for 1 s,
// sampled at 1 kHz with a +-0.002 m/s ripple.
struct Staircase {
  Eigen::VectorXd t, v;
  Staircase() {
    const int n = 6500;
    t.resize(n);
    v.resize(n);
    for (int i = 0; i < n; ++i) {
      const double ti = i * 1e-3;
      t(i) = ti;
      double vi = 0;
      if (ti >= 1.0 && ti < 3.0) vi = 0.1;
      else if (ti >= 3.0 && ti < 3.5) vi = 0.1 + 0.4 * (ti - 3.0);
      else if (ti >= 3.5 && ti < 5.5) vi = 0.3;
      v(i) = vi + 0.002 * std::sin(37.0 * ti);
    }
  }
};

constexpr double kTimeTol = 2e-3;  // s: two samples at 1 kHz
// s: next to the 0.4 m/s^2 ramp, samples stay in the 0.01 m/s band for up to 0.01 / 0.4 s.
constexpr double kRampTol = 0.025;

}  // namespace

TEST(Segments, FindsSteadyVelocityPlateaus) {
  const Staircase s;
  fl::SteadySegmentOptions o;
  o.velocity_tolerance = 0.005;
  o.min_duration = 0.5;
  o.min_speed = 0.01;
  const auto segs = fl::steady_segments(s.t, s.v, o);
  ASSERT_EQ(segs.size(), 2u);
  EXPECT_NEAR(segs[0].t_begin, 1.0, kTimeTol);
  EXPECT_NEAR(segs[0].t_end, 3.0, kRampTol);
  EXPECT_NEAR(segs[1].t_begin, 3.5, kRampTol);
  EXPECT_NEAR(segs[1].t_end, 5.5, kTimeTol);
  EXPECT_EQ(segs[0].size(), segs[0].end - segs[0].begin);
}

TEST(Segments, RelativeTolerance) {
  const Staircase s;
  fl::SteadySegmentOptions o;
  o.relative_tolerance = 0.05;  // 5 mm/s at 0.1 m/s, 15 mm/s at 0.3 m/s
  o.min_speed = 0.01;
  const auto segs = fl::steady_segments(s.t, s.v, o);
  ASSERT_EQ(segs.size(), 2u);
  EXPECT_NEAR(segs[1].t_end, 5.5, kTimeTol);
}

TEST(Segments, KeepsStandstillWhenMinSpeedIsZero) {
  const Staircase s;
  fl::SteadySegmentOptions o;
  o.velocity_tolerance = 0.005;
  const auto segs = fl::steady_segments(s.t, s.v, o);
  EXPECT_EQ(segs.size(), 4u);  // rest, 0.1, 0.3, rest
}

TEST(Segments, MotionOnsetAndStandstill) {
  const Staircase s;
  const auto onset = fl::motion_onset(s.v, 0.01);
  ASSERT_TRUE(onset.has_value());
  EXPECT_NEAR(s.t(static_cast<Eigen::Index>(*onset)), 1.0, kTimeTol);
  EXPECT_FALSE(fl::motion_onset(s.v, 1.0).has_value());
  const auto rest = fl::standstill_intervals(s.t, s.v, 0.01, 0.5);
  ASSERT_EQ(rest.size(), 2u);
  EXPECT_NEAR(rest[0].t_end, 1.0, kTimeTol);
  EXPECT_NEAR(rest[1].t_begin, 5.5, kTimeTol);
  const auto moving = fl::motion_intervals(s.t, s.v, 0.01, 0.5);
  ASSERT_EQ(moving.size(), 1u);
  EXPECT_NEAR(moving[0].duration(), 4.5, kTimeTol);
}

TEST(Segments, RejectsBadArguments) {
  const Staircase s;
  EXPECT_THROW(fl::steady_segments(s.t, s.v, {}), std::invalid_argument);  // tolerance 0
  EXPECT_THROW(fl::motion_onset(s.v, -1.0), std::invalid_argument);
  EXPECT_THROW(fl::standstill_intervals(s.t.head(10), s.v, 0.1), std::invalid_argument);
}

// The noise of a staircase with white noise, from its differences: the steps do not count.
TEST(Segments, DifferenceNoiseStdIgnoresSteps) {
  std::mt19937 gen(2026);
  std::normal_distribution<double> noise(0.0, 0.01);
  Eigen::VectorXd x(20000);
  for (Eigen::Index k = 0; k < x.size(); ++k) x(k) = static_cast<double>(k / 2000) + noise(gen);  // 10 levels, steps of 1
  constexpr double kStdRelTol = 0.05;  // 20000 differences: the median's sampling error is ~1 %
  EXPECT_NEAR(fl::difference_noise_std(x), 0.01, kStdRelTol * 0.01);
  EXPECT_EQ(fl::difference_noise_std(Eigen::VectorXd::Constant(1, 3.0)), 0.0);
}

TEST(Segments, MovingAverageIsCentredAndKeepsLength) {
  Eigen::VectorXd x(7);
  x << 0, 1, 2, 3, 4, 5, 6;
  const Eigen::VectorXd m = fl::moving_average(x, 3);
  ASSERT_EQ(m.size(), 7);
  constexpr double kTol = 1e-12;  // sums of a few small integers
  EXPECT_NEAR(m(3), 3.0, kTol);   // a line is its own centred average
  EXPECT_NEAR(m(0), 0.5, kTol);   // shortened at the ends
  EXPECT_NEAR(m(6), 5.5, kTol);
  EXPECT_THROW(fl::moving_average(x, 0), std::invalid_argument);
}
