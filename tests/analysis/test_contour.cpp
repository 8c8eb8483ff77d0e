// The circular test's analysis on synthetic records with known answers: a circle with injected
// quadrant glitches (encoder quantisation, seeded noise, an offset centre), an ellipse of known
// roundness, and bad input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/analysis/contour.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.01;                       // m: a 10 mm ballbar circle
constexpr double kCx = 0.120, kCy = -0.045;       // m: the circle away from the machine's origin
constexpr double kNoise = 0.5e-6;                 // m: std of the measurement noise
constexpr double kQuantum = 0.1e-6;               // m: encoder resolution
constexpr std::array<double, 4> kHeight = {20e-6, 15e-6, 25e-6, 12e-6};  // m: glitch at 0, 90, 180, 270 deg
constexpr double kSigmaDeg = 2.0;                 // deg: width of each glitch (Gaussian in angle)

struct Record {
  std::vector<double> t, x, y, xr, yr;
};

// Two turns counter-clockwise from 45 deg at 1 kHz (20 mm/s), the glitches on each pass.
Record circle_with_glitches(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, kNoise);
  const auto quantise = [](double v) { return kQuantum * std::round(v / kQuantum); };
  Record r;
  const double omega = 0.02 / kR;  // rad/s
  for (int i = 0; i <= 6283; ++i) {
    const double t = i * 1e-3, a = kPi / 4 + omega * t;
    double e = 0;
    for (int k = 0; k < 4; ++k) {
      double d = std::remainder(a * 180 / kPi - 90.0 * k, 360.0);  // deg from reversal k
      e += kHeight[k] * std::exp(-0.5 * d * d / (kSigmaDeg * kSigmaDeg));
    }
    const double rad = kR + e;
    r.t.push_back(t);
    r.x.push_back(quantise(kCx + rad * std::cos(a) + noise(rng)));
    r.y.push_back(quantise(kCy + rad * std::sin(a) + noise(rng)));
    r.xr.push_back(kCx + kR * std::cos(a));
    r.yr.push_back(kCy + kR * std::sin(a));
  }
  return r;
}

// An ellipse with semi-axes a (x) and b (y) about the origin, one turn sampled every 0.1 deg.
Record ellipse(double a, double b) {
  Record r;
  for (int i = 0; i < 3600; ++i) {
    const double th = i * 0.1 * kPi / 180;
    r.t.push_back(i * 1e-3);
    r.x.push_back(a * std::cos(th));
    r.y.push_back(b * std::sin(th));
  }
  return r;
}
}  // namespace

TEST(Contour, RecoversInjectedQuadrantGlitches) {
  const Record rec = circle_with_glitches(12);
  const ContourResult r = analyze_contour(rec.t, rec.x, rec.y, rec.xr, rec.yr);
  EXPECT_EQ(r.centre_source, "reference");
  constexpr double kCentreTol = 1e-9;  // m: the reference is an exact circle: its fit is exact to rounding
  EXPECT_NEAR(r.centre_x, kCx, kCentreTol);
  EXPECT_NEAR(r.centre_y, kCy, kCentreTol);
  EXPECT_NEAR(r.radius, kR, kCentreTol);
  EXPECT_NEAR(r.turns, 2.0, 0.01);
  // The peak is the largest of ~15 samples near the top: noise of 0.5 um lifts it by up to about
  // 3 sigma (1.5 um), 12 % of the smallest glitch (12 um); the median level is within 0.1 um of 0.
  constexpr double kPeakTol = 0.15;
  // Half-height width of a Gaussian: 2 sqrt(2 ln 2) sigma; noise moves each edge by ~0.2 deg.
  const double fwhm = 2 * std::sqrt(2 * std::log(2.0)) * kSigmaDeg;
  constexpr double kExtentTol = 0.2;  // relative: 0.9 deg of 4.7 deg, the two edges' noise
  constexpr double kAngleTol = 1.0;   // deg: the flat top spans about +-0.5 deg within the noise
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    const QuadrantGlitch& g = r.glitches[k];
    EXPECT_EQ(g.reversal_deg, 90.0 * k);
    EXPECT_NEAR(g.peak_m, kHeight[k], kPeakTol * kHeight[k]);
    EXPECT_NEAR(g.extent_deg, fwhm, kExtentTol * fwhm);
    EXPECT_NEAR(std::remainder(g.angle_deg - 90.0 * k, 360.0), 0.0, kAngleTol);
  }
  EXPECT_NEAR(r.max_radial_error_m, kHeight[2], kPeakTol * kHeight[2]);
  ASSERT_EQ(r.x_error.size(), rec.t.size());
  ASSERT_EQ(r.radial_error.size(), rec.t.size());
}

TEST(Contour, FitsTheCircleWithoutAReference) {
  const Record rec = circle_with_glitches(7);
  const ContourResult r = analyze_contour(rec.t, rec.x, rec.y);
  EXPECT_EQ(r.centre_source, "fit");
  EXPECT_TRUE(r.x_error.empty());
  // The glitches pull the fitted radius out by their mean over the turn (~0.5 um) and the noise
  // moves the centre by ~0.01 um: the heights are relative to the local level, so they hold.
  constexpr double kPeakTol = 0.15;  // as with the reference: noise on the peak sample
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r.glitches[k].peak_m, kHeight[k], kPeakTol * kHeight[k]) << k;
}

TEST(Contour, RoundnessOfAnEllipse) {
  constexpr double a = 0.0101, b = 0.0099;  // m
  const Record rec = ellipse(a, b);
  constexpr double kRoundTol = 1e-9;  // relative: the samples fall on both axes; rounding only
  const ContourResult fit = analyze_contour(rec.t, rec.x, rec.y);
  EXPECT_NEAR(fit.roundness_m, a - b, kRoundTol * (a - b));
  EXPECT_NEAR(fit.centre_x, 0.0, 1e-12);
  ContourOptions o;
  o.centre = std::array<double, 2>{0.0, 0.0};
  o.radius = 0.01;
  const ContourResult given = analyze_contour(rec.t, rec.x, rec.y, {}, {}, o);
  EXPECT_EQ(given.centre_source, "given");
  EXPECT_NEAR(given.roundness_m, a - b, kRoundTol * (a - b));
  EXPECT_NEAR(given.max_radial_error_m, a - 0.01, kRoundTol * a);
}

TEST(Contour, FitCircleThroughThreePoints) {
  const std::vector<double> x = {1.0, -1.0, 0.0}, y = {0.0, 0.0, 1.0};
  const auto c = fit_circle(x, y);
  EXPECT_NEAR(c[0], 0.0, 1e-12);
  EXPECT_NEAR(c[1], 0.0, 1e-12);
  EXPECT_NEAR(c[2], 1.0, 1e-12);
  const std::vector<double> lx = {0.0, 1.0, 2.0}, ly = {0.0, 1.0, 2.0};
  EXPECT_EQ(error_of([&] { fit_circle(lx, ly); }), "fit_circle: the points are collinear or coincide: no circle");
}

TEST(Contour, RefusesBadInput) {
  Record rec = circle_with_glitches(3);
  const std::vector<double> few(10, 0.0);
  EXPECT_EQ(error_of([&] { analyze_contour(few, few, few); }), "contour: needs at least 20 samples, got 10");
  const std::span<const double> half_t(rec.t.data(), 1500), half_x(rec.x.data(), 1500), half_y(rec.y.data(), 1500);
  EXPECT_NE(error_of([&] { analyze_contour(half_t, half_x, half_y); }).find("less than one turn: not a closed contour"),
            std::string::npos);
  Record nan = rec;
  nan.y[41] = std::nan("");
  EXPECT_EQ(error_of([&] { analyze_contour(nan.t, nan.x, nan.y); }), "contour: y sample 42 is not a finite number");
  Record back = rec;
  back.t[100] = back.t[99];
  EXPECT_NE(error_of([&] { analyze_contour(back.t, back.x, back.y); }).find("time must increase strictly; sample 101"),
            std::string::npos);
  const std::vector<double> short_ref(rec.t.size() - 1, 0.0);
  EXPECT_NE(error_of([&] { analyze_contour(rec.t, rec.x, rec.y, short_ref, short_ref); }).find("reference x and y"),
            std::string::npos);
  const Record ell = ellipse(0.011, 0.009);
  EXPECT_NE(error_of([&] { analyze_contour(ell.t, ell.x, ell.y, ell.x, ell.y); }).find("the reference is not a circle"),
            std::string::npos);
  ContourOptions o;
  o.radius = -1;
  EXPECT_EQ(error_of([&] { analyze_contour(rec.t, rec.x, rec.y, {}, {}, o); }),
            "contour: radius must be a positive number of m, got -1");
  o = ContourOptions{};
  o.extent_fraction = 1.0;
  EXPECT_EQ(error_of([&] { analyze_contour(rec.t, rec.x, rec.y, {}, {}, o); }),
            "contour: extent fraction must be in (0, 1), got 1");
  std::vector<double> line(rec.t.size());
  for (std::size_t i = 0; i < line.size(); ++i) line[i] = 1e-3 * static_cast<double>(i);
  EXPECT_EQ(error_of([&] { analyze_contour(rec.t, line, line); }),
            "contour: the measured path lies on a line or a point: no circle to measure against");
}
