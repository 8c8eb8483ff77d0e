// Disturbance observer: a constant disturbance estimated with the first-order response of the
// observer's bandwidth (time constant 1/w), the same in a sampled loop on a quantised, noisy
// encoder, the Jacobian against central differences, and its errors.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "control/harness.hpp"
#include "error_message.hpp"
#include "frictionlab/control/disturbance_observer.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

TEST(DisturbanceObserver, FirstOrderResponseToAConstantDisturbance) {
  // A 2 kg body driven by u = 3 sin(5 t) N against a constant d = 1.5 N from t = 0, exact model.
  const double M = 2.0, d = 1.5, w = 50.0;  // kg, N, rad/s
  const DisturbanceObserver dob({.bandwidth = w, .inertia = M});
  const testing::InputAt at = [&](double t) {
    CompensatorInput in;
    in.t = t;
    in.drive = 3.0 * std::sin(5.0 * t);
    in.velocity = (3.0 / (5.0 * M)) * (1.0 - std::cos(5.0 * t)) - d * t / M;  // M dv/dt = u - d, v(0) = 0
    return in;
  };
  std::vector<double> z(1);
  dob.initial_states(at(0), z);
  EXPECT_EQ(dob.output(at(0), z), 0.0);
  // RK4 with w h = 5e-4: relative error of the response below 1e-12.
  constexpr double kResponseRelTol = 1e-9;
  double t = 0, prev_t = 0, prev_est = 0, t63 = -1;
  const double level63 = d * (1.0 - std::exp(-1.0));
  for (int i = 1; i <= 200; ++i) {
    const double t_next = i * 0.5e-3;
    testing::run(dob, at, z, t, t_next, 50);
    t = t_next;
    const double est = dob.output(at(t), z);
    EXPECT_NEAR(est, d * (1.0 - std::exp(-w * t)), kResponseRelTol * d) << "t " << t;
    if (t63 < 0 && est >= level63) t63 = prev_t + (t - prev_t) * (level63 - prev_est) / (est - prev_est);
    prev_t = t;
    prev_est = est;
  }
  // The time constant read off the response is 1/w = 20 ms; linear interpolation between samples
  // 0.5 ms apart on a curve of curvature w^2 d e^-1 errs by at most (0.5 ms)^2 w / 8.
  EXPECT_NEAR(t63, 1.0 / w, 0.5e-3 * 0.5e-3 * w);
}

TEST(DisturbanceObserver, SampledLoopOnAQuantisedNoisyEncoder) {
  // 1 kHz loop, encoder of 1 um quantisation with 0.5 um rms noise (seeded), velocity by backward
  // difference, drive held over each sample (zero-order hold) and a constant disturbance d.
  const double M = 2.0, d = 1.5, w = 60.0, Ts = 1e-3;  // kg, N, rad/s, s
  const DisturbanceObserver dob({.bandwidth = w, .inertia = M});
  std::mt19937 rng(15);
  std::normal_distribution<double> noise(0.0, 0.5e-6);
  auto encoder = [&](double x) { return std::round((x + noise(rng)) / 1e-6) * 1e-6; };
  double x = 0, v = 0, u_prev = 0, x_meas_prev = encoder(0.0);
  std::vector<double> z(1);
  dob.initial_states({}, z);
  double sum = 0, sum_sq = 0;
  int count = 0;
  const int n = 4000;  // 4 s: 10 periods of the drive's 2.5 Hz at the end averaged whole
  for (int k = 1; k <= n; ++k) {
    // The plant over the step just ended under the held drive u_prev (exact for constant force).
    const double a = (u_prev - d) / M;
    x += v * Ts + 0.5 * a * Ts * Ts;
    v += a * Ts;
    const double x_meas = encoder(x);
    CompensatorInput in;
    in.t = k * Ts;
    in.position = x_meas;
    in.velocity = (x_meas - x_meas_prev) / Ts;
    in.drive = u_prev;
    const double est = dob.update(in, z, Ts);
    x_meas_prev = x_meas;
    u_prev = d + 3.0 * std::sin(2 * M_PI * 2.5 * in.t);  // the next held command
    if (k > n - 2000) {  // last 2 s: 5 whole periods, 100 time constants after the start
      sum += est;
      sum_sq += est * est;
      ++count;
    }
  }
  const double mean = sum / count, rms = std::sqrt(sum_sq / count - mean * mean);
  std::printf("DOB sampled: mean estimate %.4f N (d = %.1f N), ripple %.3f N rms\n", mean, d, rms);
  // Quantisation and noise are white and the drive's ripple averages over whole periods: the mean
  // estimate holds d to 1 % (what 2000 samples of ~0.1 N rms noise resolve, with margin).
  EXPECT_NEAR(mean, d, 0.01 * d);
  // Noise through the observer: w M sigma_v with sigma_v ~ 1 um / 1 ms; bound it by twice that.
  EXPECT_LT(rms, 2.0 * w * M * 1e-3);
}

TEST(DisturbanceObserver, FixedStepIsStableAtAnyStep) {
  // Held input, a step of 10 time constants: the estimate lands on the disturbance, no overshoot.
  const double M = 1.0, w = 100.0;
  const DisturbanceObserver dob({.bandwidth = w, .inertia = M});
  std::vector<double> z{0.0};
  CompensatorInput in;
  in.drive = 2.0;  // N, with v held at 0: all of the drive is opposed (d = 2 N)
  for (int i = 0; i < 3; ++i) {
    const double est = dob.update(in, z, 10.0 / w);
    EXPECT_LE(est, 2.0);
    EXPECT_GT(est, 2.0 * (1.0 - std::exp(-10.0 * (i + 1))) - 1e-12);
  }
}

TEST(DisturbanceObserver, JacobianMatchesCentralDifferences) {
  const DisturbanceObserver dob({.bandwidth = 80.0, .inertia = 0.7});
  CompensatorInput in;
  in.position = 0.4;
  in.velocity = -0.3;
  in.drive = 2.5;
  constexpr double kFdRelTol = 1e-7;  // linear in every variable: central differences exact to rounding
  testing::expect_jacobian_matches(dob, in, {4.0}, kFdRelTol);
}

TEST(DisturbanceObserver, RejectsBadParameters) {
  EXPECT_EQ(error_of([] { DisturbanceObserver({.bandwidth = 0.0, .inertia = 1.0}); }),
            "disturbance-observer: bandwidth = 0 must be > 0 (rad/s)");
  EXPECT_EQ(error_of([] { DisturbanceObserver({.bandwidth = 100.0}); }),
            "disturbance-observer: inertia = 0 must be > 0 (kg or kg m^2: the nominal inertia of the driven body)");
  EXPECT_EQ(error_of([] { DisturbanceObserver({.bandwidth = 100.0, .inertia = -2.0}); }),
            "disturbance-observer: inertia = -2 must be > 0 (kg or kg m^2: the nominal inertia of the driven body)");
}

}  // namespace
}  // namespace frictionlab
