// Analysis on synthetic records with known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"

using namespace frictionlab;

namespace {
constexpr double kPi = std::numbers::pi;

// Oscillation released from rest with an envelope A(t), frequency 1 Hz, sampled at 1 kHz.
template <class Env>
void oscillation(Env env, double duration, std::vector<double>& t, std::vector<double>& x) {
  for (int i = 0; i <= static_cast<int>(duration * 1000); ++i) {
    const double ti = i / 1000.0;
    t.push_back(ti);
    x.push_back(std::max(env(ti), 0.0) * std::cos(2 * kPi * ti));
  }
}
}  // namespace

TEST(Envelope, ClassifiesSyntheticEnvelopes) {
  std::vector<double> t, x;
  oscillation([](double) { return 1.0; }, 10, t, x);
  EXPECT_EQ(decay_envelope(t, x).kind, DecayKind::none);

  t.clear();
  x.clear();
  oscillation([](double s) { return std::exp(-0.3 * s); }, 10, t, x);
  EnvelopeResult r = decay_envelope(t, x);
  EXPECT_EQ(r.kind, DecayKind::exponential);
  // half swings of A e^{-lambda t} cos: the fitted rate is lambda (the swing averages neighbours)
  constexpr double kRateTol = 0.01;  // relative: peaks of a modulated cosine sit slightly early
  EXPECT_NEAR(r.exponential.lambda, 0.3, 0.3 * kRateTol);
  EXPECT_NEAR(r.half_period, 0.5, 1e-3);

  t.clear();
  x.clear();
  oscillation([](double s) { return 1.0 - 0.08 * s; }, 10, t, x);
  r = decay_envelope(t, x);
  EXPECT_EQ(r.kind, DecayKind::linear);
  EXPECT_NEAR(r.decrement_per_half_cycle, 0.04, 0.04 * kRateTol);

  t.clear();
  x.clear();
  oscillation([](double s) { return 1.3 * std::exp(-0.4 * s) - 0.3; }, 10, t, x);
  EXPECT_EQ(decay_envelope(t, x).kind, DecayKind::mixed);
}

TEST(Envelope, RefusesRecordsWithoutOscillation) {
  std::vector<double> t = {0, 1, 2, 3}, x = {0, 1, 2, 3};
  EXPECT_THROW(decay_envelope(t, x), std::invalid_argument);
  std::vector<double> shorter = {0, 1};
  EXPECT_THROW(decay_envelope(t, shorter), std::invalid_argument);
}

TEST(StickSlip, FindsIntervalsPeriodAndForces) {
  // 4 cycles of period 2 s: stuck 1.5 s (force ramps 1 -> 2), slip 0.5 s (v = sin bump, force 1.5).
  std::vector<double> t, v, f;
  for (int i = 0; i <= 8000; ++i) {
    const double ti = i / 1000.0;
    const double c = std::fmod(ti, 2.0);
    t.push_back(ti);
    if (c < 1.5) {
      v.push_back(0.0);
      f.push_back(1.0 + c / 1.5);
    } else {
      v.push_back(0.3 * std::sin(kPi * (c - 1.5) / 0.5));
      f.push_back(1.5);
    }
  }
  const StickSlipResult r = detect_stick_slip(t, v, f);
  EXPECT_EQ(r.velocity_threshold, 0.0);  // exact zeros: exact threshold
  EXPECT_EQ(r.slip.size(), 4u);
  constexpr double kSampleTol = 2e-3;  // 1 kHz sampling
  EXPECT_NEAR(r.period, 2.0, kSampleTol);
  EXPECT_NEAR(r.peak_slip_velocity, 0.3, 1e-4);
  EXPECT_NEAR(r.mean_slip_duration, 0.5, kSampleTol);
  EXPECT_NEAR(r.mean_breakaway_force, 2.0, 2e-3);
  EXPECT_NEAR(r.mean_restick_force, 1.0, 2e-3);
  EXPECT_NEAR(r.mean_force_drop, 1.0, 4e-3);
  std::vector<double> bad_t = {0, 1, 1};
  std::vector<double> bad_v = {0, 0, 0};
  EXPECT_THROW(detect_stick_slip(bad_t, bad_v, {}), std::invalid_argument);
}
