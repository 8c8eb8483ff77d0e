// Coverage of breakaway's 95 % intervals (identify/breakaway.hpp) on seeded synthetic trapezoid
// records: a linear axis of random mass and static-Coulomb-viscous friction, driven by a force
// ramped up from rest, held and ramped down to rest, measured with coloured (AR(1)) noise on the
// force as a drive's current has. The std breakaway reports (Newey-West, as idim's) must cover the
// truth as 95 % intervals do; the ordinary least-squares figure (std_ols) is kept for comparison.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "frictionlab/identify/breakaway.hpp"

namespace fl = frictionlab;

namespace {

struct Truth {
  double M, Fs, Fc, Fv;
};

// One record at 1 kHz: the force ramps from 0 to `level` in 2 s, holds 1 s, ramps back to 0 in
// 2 s and rests 0.5 s; the axis sticks while |F| <= Fs at rest and stops when its velocity
// reaches zero with |F| <= Fs (semi-implicit Euler, 20 substeps a sample). The measured force
// has AR(1) noise (coefficient 0.9, std 2 % of Fc). The velocity is exact, or (encoder > 0) the
// central difference of the position read by an encoder of that resolution (m per count) with
// white noise of a fifth of a count: at 1 um and 1 kHz about 0.3 mm/s of noise per sample,
// which the acceleration regressor differentiates once more.
fl::BreakawayData record(const Truth& p, unsigned seed, double encoder = 0.0) {
  constexpr double dt = 1e-3, ramp = 2.0, hold = 1.0, rest = 0.5;
  constexpr int substeps = 20;
  constexpr double rho = 0.9, relative_noise = 0.02;
  const double level = 1.6 * p.Fs;
  const auto force_at = [&](double t) {
    if (t < ramp) return level * t / ramp;
    if (t < ramp + hold) return level;
    if (t < 2 * ramp + hold) return level * (1 - (t - ramp - hold) / ramp);
    return 0.0;
  };
  const auto n = static_cast<Eigen::Index>((2 * ramp + hold + rest) / dt);
  fl::BreakawayData d;
  d.time.resize(n), d.force.resize(n), d.velocity.resize(n);
  std::mt19937 gen(seed);
  std::normal_distribution<double> white(0.0, relative_noise * p.Fc * std::sqrt(1 - rho * rho));
  double v = 0, q = 0, noise = std::normal_distribution<double>(0.0, relative_noise * p.Fc)(gen);
  std::normal_distribution<double> reading(0.0, 0.2 * encoder);
  Eigen::VectorXd position(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * dt;
    d.time(i) = t;
    d.velocity(i) = v;
    position(i) = encoder > 0 ? std::round((q + reading(gen)) / encoder) * encoder : q;
    noise = rho * noise + white(gen);
    d.force(i) = force_at(t) + noise;
    for (int s = 0; s < substeps; ++s) {
      const double h = dt / substeps, F = force_at(t + s * h);
      if (v == 0.0 && std::abs(F) <= p.Fs) continue;  // stuck
      const double dir = v != 0.0 ? (v > 0 ? 1.0 : -1.0) : (F > 0 ? 1.0 : -1.0);
      const double vn = (p.M * v + h * (F - p.Fc * dir)) / (p.M + h * p.Fv);
      v = vn * dir < 0 && std::abs(F) <= p.Fs ? 0.0 : vn;
      q += h * v;
    }
  }
  if (encoder > 0) {  // the drive's velocity: the encoder's central difference
    d.velocity(0) = (position(1) - position(0)) / dt;
    d.velocity(n - 1) = (position(n - 1) - position(n - 2)) / dt;
    for (Eigen::Index i = 1; i + 1 < n; ++i) d.velocity(i) = (position(i + 1) - position(i - 1)) / (2 * dt);
  }
  return d;
}

// 200 seeded cases: a binomial test at the 1 % level against 95 % coverage rejects 181 covered
// or fewer (P(X <= 181 | 200, 0.95) = 0.006, P(X <= 182) = 0.012), and 182 is 91 %, above the
// 90 % the coverage suite asks of every parameter. breakaway's warning that the difference's width
// moves the fit by more than a std (a systematic error the std exclude) may come in at most 12
// cases, as a residual check's false warnings (docs/coverage.md: the one-sided 95 % upper bound on
// the rate is then below 10 %); the seeded records have no such error beyond the std.
void expect_coverage(const std::string& cell, double encoder) {
  constexpr int kCases = 200;
  constexpr int kLeastCovered = 182;
  constexpr int kMostWidthWarnings = 12;
  int width_warnings = 0;
  const std::vector<std::string> names{"Fs", "Fc", "Fv", "M"};
  std::map<std::string, int> covered, covered_ols;
  std::map<std::string, double> bias;  // mean of (estimate - truth) / std: a bias shows here
  // Root mean square of (estimate - truth) / std: 1 when the std is the spread of the estimates;
  // above 1 when it is small, or varies from record to record more than the spread does.
  std::map<std::string, double> square;
  std::mt19937 draw(20261128);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < kCases; ++k) {
    Truth p;
    p.M = 0.5 + 1.5 * u(draw);
    p.Fc = 2.0 + 2.0 * u(draw);
    p.Fs = p.Fc * (1.2 + 0.3 * u(draw));
    p.Fv = 5.0 + 15.0 * u(draw);
    const fl::Result r = fl::identify_breakaway(record(p, 1000u + static_cast<unsigned>(k), encoder));
    ASSERT_TRUE(r.ok()) << "case " << k << ": " << r.message;
    for (const auto& w : r.diagnostics.warnings) width_warnings += w.find("the fit changes when the acceleration") != std::string::npos;
    const std::map<std::string, double> truth{{"Fs", p.Fs}, {"Fc", p.Fc}, {"Fv", p.Fv}, {"M", p.M}};
    for (const auto& name : names) {
      const fl::Parameter* q = r.find(name);
      ASSERT_NE(q, nullptr) << name;
      ASSERT_TRUE(q->std_ols.has_value()) << name << ": std_ols is kept";
      const double error = std::abs(q->value - truth.at(name));
      covered[name] += error <= 1.959964 * q->std;
      bias[name] += (q->value - truth.at(name)) / q->std / kCases;
      square[name] += std::pow((q->value - truth.at(name)) / q->std, 2) / kCases;
      covered_ols[name] += error <= 1.959964 * *q->std_ols;
    }
  }
  for (const auto& name : names) {
    std::cout << "breakaway (" << cell << ") " << name << ": std covers " << covered[name] << "/" << kCases << ", std_ols "
              << covered_ols[name] << "/" << kCases << ", mean bias / std " << bias[name] << ", rms error / std "
              << std::sqrt(square[name]) << "\n";
    EXPECT_GE(covered[name], kLeastCovered) << name << ": " << covered[name] << " of " << kCases << " covered";
  }
  std::cout << "breakaway (" << cell << "): width warnings " << width_warnings << "/" << kCases << "\n";
  EXPECT_LE(width_warnings, kMostWidthWarnings);
}

}  // namespace

TEST(BreakawayCoverage, NeweyWestIntervalsCoverTheTruthOnSeededTrapezoids) { expect_coverage("exact velocity", 0.0); }

// The velocity a drive logs: a 1 um encoder's central difference (0.3 mm/s of noise per sample,
// 0.1 to 0.4 % of the top speed). Its difference, the acceleration regressor, would carry about
// 0.2 m/s^2 of noise and bias M towards zero (errors in variables); breakaway widens the
// difference until that noise is small (acceleration_half_width), which leaves the mean bias
// within 0.2 std. The acceleration's remaining noise, over-differenced and large beside the force
// noise, made the Newey-West std 10 to 25 % small (Fc, Fv, M covered in 87 to 90 %) until the
// scores were summed over blocks of w/4 rows (covariance_block): this cell fails without them.
TEST(BreakawayCoverage, NoisyEncoderVelocityStillCovers) {
  expect_coverage("encoder velocity, 1 um", 1e-6);
}

// A coarser encoder, 2 um: at rest a reading that flips by one count makes a one- or two-sample
// velocity jump of 2 mm/s, above the default threshold (1 % of the top speed). Read as the
// breakaway, it put Fs some 60 std off in 7 of these 200 records; a motion now lasts at least
// five samples above the threshold, and the cell covers like the others.
TEST(BreakawayCoverage, ACoarseEncodersCountAtRestIsNotTheBreakaway) {
  expect_coverage("encoder velocity, 2 um", 2e-6);
}
