// Fits of static laws to friction-velocity points: exact recovery on noiseless data, honest
// uncertainty on noisy data, and the error messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "frictionlab/identify/static_fit.hpp"

namespace fl = frictionlab;

namespace {
// Noiseless data: the fit converges to the true parameters up to the solver's tolerances
// (function tolerance 1e-12); the issue asks for 1e-4.
constexpr double kNoiselessRelTol = 1e-4;

Eigen::VectorXd velocities(int n, double vmax, bool both_directions) {
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) {
    // Log-spaced speeds: dense at low speed, where the Stribeck effect lives.
    const int k = both_directions ? i / 2 : i;
    const int m = both_directions ? n / 2 : n;
    const double s = vmax * std::pow(10.0, -3.0 + 3.0 * k / (m - 1));
    v[i] = (both_directions && i % 2) ? -s : s;
  }
  return v;
}

Eigen::VectorXd forces(const fl::FrictionLaw& law, const Eigen::VectorXd& v) {
  Eigen::VectorXd f(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) f[i] = law.sliding(v[i]);
  return f;
}

double param(const fl::StaticFit& fit, const std::string& name) {
  for (const auto& p : fit.parameters)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}
}  // namespace

TEST(StaticFit, StribeckNoiselessRecoversTruth) {
  const fl::Stribeck truth{0.02, 0.035, 0.8, 1.6, 1.5e-4};  // a small DC motor (N m, rad/s)
  const Eigen::VectorXd v = velocities(60, 300.0, true);
  const auto fit = fl::fit_static_law(v, forces(truth, v));
  EXPECT_NEAR(param(fit, "Fc"), truth.Fc, kNoiselessRelTol * truth.Fc);
  EXPECT_NEAR(param(fit, "Fs"), truth.Fs, kNoiselessRelTol * truth.Fs);
  EXPECT_NEAR(param(fit, "vs"), truth.vs, kNoiselessRelTol * truth.vs);
  EXPECT_NEAR(param(fit, "delta"), truth.delta, kNoiselessRelTol * truth.delta);
  EXPECT_NEAR(param(fit, "Fv"), truth.Fv, kNoiselessRelTol * truth.Fv);
  EXPECT_TRUE(fit.converged);
  EXPECT_LT(fit.relative_error_percent, 1e-4);
  EXPECT_EQ(fit.law.name(), "stribeck");
}

TEST(StaticFit, StribeckWithFixedExponent) {
  const fl::Stribeck truth{1.0, 1.5, 0.001, 2.0, 0.4};  // Canudas de Wit 1995 static part
  const Eigen::VectorXd v = velocities(40, 0.1, false);
  fl::StaticFitOptions o;
  o.fixed_delta = 2.0;
  const auto fit = fl::fit_static_law(v, forces(truth, v), o);
  EXPECT_EQ(param(fit, "delta"), 2.0);
  EXPECT_EQ(fit.parameters[3].std, 0.0);  // held, not estimated
  EXPECT_NEAR(param(fit, "vs"), truth.vs, kNoiselessRelTol * truth.vs);
  EXPECT_NEAR(param(fit, "Fs"), truth.Fs, kNoiselessRelTol * truth.Fs);
}

TEST(StaticFit, AsymmetricStribeckRecoversBothSides) {
  fl::Asymmetric<fl::Stribeck> truth;
  truth.pos = {0.9, 1.4, 0.002, 2.0, 0.3};
  truth.neg = {1.2, 1.5, 0.004, 1.5, 0.5};
  const Eigen::VectorXd v = velocities(80, 0.2, true);
  fl::StaticFitOptions o;
  o.model = fl::StaticFitModel::stribeck_asymmetric;
  const auto fit = fl::fit_static_law(v, forces(truth, v), o);
  EXPECT_EQ(fit.law.name(), "stribeck-asymmetric");
  EXPECT_NEAR(param(fit, "Fc_pos"), 0.9, kNoiselessRelTol * 0.9);
  EXPECT_NEAR(param(fit, "Fs_neg"), 1.5, kNoiselessRelTol * 1.5);
  EXPECT_NEAR(param(fit, "vs_neg"), 0.004, kNoiselessRelTol * 0.004);
  EXPECT_NEAR(param(fit, "delta_neg"), 1.5, kNoiselessRelTol * 1.5);
}

TEST(StaticFit, CoulombViscousIsExactLinearLeastSquares) {
  const fl::CoulombViscous truth{20.39, 203.5};
  const Eigen::VectorXd v = velocities(30, 0.1, true);
  const auto fit = [&] {
    fl::StaticFitOptions o;
    o.model = fl::StaticFitModel::coulomb_viscous;
    return fl::fit_static_law(v, forces(truth, v), o);
  }();
  constexpr double kLinearRelTol = 1e-10;  // a direct QR solve: rounding only
  EXPECT_NEAR(param(fit, "Fc"), truth.Fc, kLinearRelTol * truth.Fc);
  EXPECT_NEAR(param(fit, "Fv"), truth.Fv, kLinearRelTol * truth.Fv);
}

// Seeded batch: with Gaussian noise on the force, the true value lies inside the reported
// 2-sigma interval in most runs. For an unbiased estimator with correct std that is ~95 %;
// we require at least 80 of 100 per parameter (nonlinearity makes the interval approximate).
TEST(StaticFit, StribeckIntervalsCoverTruthOnNoisyData) {
  const fl::Stribeck truth{0.02, 0.035, 0.8, 2.0, 1.5e-4};
  const Eigen::VectorXd v = velocities(200, 300.0, true);
  const Eigen::VectorXd clean = forces(truth, v);
  std::mt19937 rng(20261122);
  std::normal_distribution<double> noise(0.0, 5e-4);  // N m, about 2 % of Fc
  constexpr int kRuns = 100;
  constexpr int kMinInside = 80;
  std::map<std::string, int> inside;
  const std::map<std::string, double> truth_values{{"Fc", 0.02}, {"Fs", 0.035}, {"vs", 0.8}, {"delta", 2.0}, {"Fv", 1.5e-4}};
  for (int run = 0; run < kRuns; ++run) {
    Eigen::VectorXd f = clean;
    for (Eigen::Index i = 0; i < f.size(); ++i) f[i] += noise(rng);
    const auto fit = fl::fit_static_law(v, f);
    for (const auto& p : fit.parameters)
      if (std::abs(p.value - truth_values.at(p.name)) <= 2 * p.std) inside[p.name]++;
  }
  for (const auto& [name, value] : truth_values) EXPECT_GE(inside[name], kMinInside) << name;
}

TEST(StaticFit, ErrorsNameTheProblem) {
  Eigen::VectorXd v(3), f(2);
  v << 1, 2, 3;
  f << 1, 2;
  EXPECT_THROW(
      {
        try {
          fl::fit_static_law(v, f);
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(), "friction fit: velocity has 3 points but force has 2; they must be equal");
          throw;
        }
      },
      std::invalid_argument);
  Eigen::VectorXd v2(7), f2(7);
  v2 << 1, 2, 0, 4, 5, 6, 7;
  f2.setOnes();
  try {
    fl::fit_static_law(v2, f2);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("point 2 has velocity 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fl::parse_static_fit_model("lugre"), std::invalid_argument);
}

// The large-data path reduces chunks of points to their normal equations; on data sorted by
// speed whole chunks lie far past vs, where the decay columns of the Jacobian vanish (a singular
// chunk). The fit must not depend on the order of the points.
TEST(StaticFit, StribeckDoesNotDependOnPointOrder) {
  const fl::Stribeck truth{0.02, 0.035, 0.8, 1.6, 1.5e-4};
  constexpr int kPoints = 40000;  // enough for several chunks
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-3.0, 0.0);
  std::normal_distribution<double> noise(0.0, 2e-4);
  std::vector<std::pair<double, double>> points(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const double v = 300.0 * std::pow(10.0, exponent(rng)) * (i % 2 ? -1.0 : 1.0);
    points[static_cast<std::size_t>(i)] = {v, truth.sliding(v) + noise(rng)};
  }
  const auto fit_of = [](const std::vector<std::pair<double, double>>& pts) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(pts.size())), f(v.size());
    for (std::size_t i = 0; i < pts.size(); ++i) std::tie(v[static_cast<Eigen::Index>(i)], f[static_cast<Eigen::Index>(i)]) = pts[i];
    return fl::fit_static_law(v, f);
  };
  const auto shuffled = fit_of(points);
  std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return std::abs(x.first) < std::abs(y.first); });
  const auto sorted = fit_of(points);
  // Reordering changes only the rounding of sums over 4e4 points; the solver stops within its
  // function tolerance (1e-12) of the same minimum.
  constexpr double kOrderRelTol = 1e-8;
  constexpr double kStdRelTol = 1e-6;  // a standard deviation means two digits at most
  ASSERT_EQ(sorted.parameters.size(), shuffled.parameters.size());
  for (std::size_t k = 0; k < sorted.parameters.size(); ++k) {
    const auto& a = sorted.parameters[k];
    const auto& b = shuffled.parameters[k];
    EXPECT_NEAR(a.value, b.value, kOrderRelTol * std::abs(b.value)) << a.name;
    EXPECT_NEAR(a.std, b.std, kStdRelTol * b.std) << a.name;
    EXPECT_GT(a.std, 0.0) << a.name;
  }
  EXPECT_TRUE(sorted.converged);
  EXPECT_NEAR(sorted.rmse, shuffled.rmse, kOrderRelTol * shuffled.rmse);
}

// The Stribeck fit's residuals come from a vectorised kernel with an analytic Jacobian (speed:
// 1e5 points, a Gram matrix per chunk), not from the law. Its fit figures must be the law's own:
// the sum of squares the kernel reports at the solution equals the one of the fitted law's
// sliding() over the points, on noisy points where the residuals are far from zero.
TEST(StaticFit, StribeckKernelResidualsAreTheLaws) {
  std::mt19937 rng(2024);
  std::normal_distribution<double> noise(0.0, 1e-3);  // N m: force noise of a current sensor
  const fl::Stribeck truth{0.02, 0.035, 0.8, 1.6, 1.5e-4};
  const Eigen::VectorXd v = velocities(400, 300.0, true);
  Eigen::VectorXd f = forces(truth, v);
  for (Eigen::Index i = 0; i < f.size(); ++i) f[i] += noise(rng);
  for (const auto model : {fl::StaticFitModel::stribeck, fl::StaticFitModel::stribeck_asymmetric}) {
    fl::StaticFitOptions o;
    o.model = model;
    const auto fit = fl::fit_static_law(v, f, o);
    double ssr = 0;
    for (Eigen::Index i = 0; i < v.size(); ++i) ssr += std::pow(fit.law.sliding(v[i]) - f[i], 2);
    // The kernel sums the same squares in another order and with exp(delta log x) for the power:
    // rounding of a few eps per point on residuals of ~1e-3 against forces of ~0.05.
    constexpr double kSumRelTol = 1e-9;
    EXPECT_NEAR(fit.rmse, std::sqrt(ssr / static_cast<double>(v.size())), kSumRelTol * fit.rmse);
  }
}
