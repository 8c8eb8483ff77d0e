// The one linear least-squares helper (identify/least_squares.hpp): estimates, covariance and
// information against the normal equations, independence of the columns' units, and refusals
// that name the parameters.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "frictionlab/identify/least_squares.hpp"

namespace fl = frictionlab;

namespace {

// A friction regression as an axis log gives it: sign(v), v (rad/s, up to 300), acceleration
// (rad/s^2, up to 3e4) and a constant, with force noise. Seeded.
struct Regression {
  Eigen::MatrixXd X;
  Eigen::VectorXd y, truth;
};

Regression friction_regression(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.02);
  Regression r;
  r.X.resize(n, 4);
  r.truth = Eigen::Vector4d(0.12, 2.5e-4, 3.1e-5, 0.01);  // Fc N m, Fv N m s/rad, M kg m^2, offset N m
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = 0.001 * static_cast<double>(i);
    const double v = 300.0 * std::sin(2.0 * t) + 0.5, a = 600.0 * std::cos(2.0 * t) + 3e4 * std::sin(97.0 * t);
    r.X.row(i) << (v > 0 ? 1.0 : -1.0), v, a, 1.0;
  }
  r.y = r.X * r.truth;
  for (Eigen::Index i = 0; i < n; ++i) r.y(i) += noise(rng);
  return r;
}

const std::vector<std::string> kNames = {"Fc", "Fv", "M", "offset"};

}  // namespace

TEST(LeastSquares, AgreesWithTheNormalEquations) {
  const Regression g = friction_regression(5000, 7);
  const fl::LeastSquaresFit f = fl::linear_least_squares(g.X, g.y, kNames);
  ASSERT_TRUE(f.ok) << f.message;
  // The normal equations lose about cond(X)^2 eps of accuracy; cond(X) here is ~1e5 unscaled,
  // so they carry about 6 good digits: the comparison allows 1e-6 relative.
  constexpr double kRelTol = 1e-6;
  const Eigen::MatrixXd XtX = g.X.transpose() * g.X;
  const Eigen::VectorXd theta = XtX.ldlt().solve(g.X.transpose() * g.y);
  for (Eigen::Index j = 0; j < 4; ++j) EXPECT_NEAR(f.theta(j), theta(j), kRelTol * std::abs(theta(j))) << kNames[j];
  const double s2 = (g.y - g.X * theta).squaredNorm() / (5000.0 - 4.0);
  EXPECT_NEAR(f.residual_variance, s2, kRelTol * s2);
  const Eigen::MatrixXd cov = s2 * XtX.inverse();
  for (Eigen::Index j = 0; j < 4; ++j) {
    EXPECT_NEAR(f.stdev(j), std::sqrt(cov(j, j)), kRelTol * std::sqrt(cov(j, j))) << kNames[j];
    for (Eigen::Index k = 0; k < 4; ++k) {
      EXPECT_NEAR(f.information(j, k), XtX(j, k), kRelTol * std::sqrt(XtX(j, j) * XtX(k, k)));
      EXPECT_NEAR(f.covariance(j, k), cov(j, k), kRelTol * std::sqrt(cov(j, j) * cov(k, k)));
    }
  }
  // The estimates hold the truth within their own uncertainty (5 std: a seeded draw).
  for (Eigen::Index j = 0; j < 4; ++j) EXPECT_LT(std::abs(f.theta(j) - g.truth(j)), 5 * f.stdev(j)) << kNames[j];
  EXPECT_NEAR(f.rmse, std::sqrt((g.y - g.X * theta).squaredNorm() / 5000.0), kRelTol * f.rmse);
  EXPECT_GT(f.condition_number, 10 * f.condition_number_scaled);  // units make the plain one large
}

TEST(LeastSquares, ScaledConditionDoesNotDependOnUnits) {
  const Regression g = friction_regression(2000, 11);
  Eigen::MatrixXd X = g.X;
  X.col(2) *= 1e-6;  // the acceleration in another unit
  const fl::LeastSquaresFit a = fl::linear_least_squares(g.X, g.y, kNames), b = fl::linear_least_squares(X, g.y, kNames);
  ASSERT_TRUE(a.ok && b.ok);
  // Column scaling is exact in binary only for powers of two; 1e-6 leaves rounding of a few eps
  // times the scaled condition number (~10): 1e-12 relative.
  constexpr double kRelTol = 1e-12;
  EXPECT_NEAR(a.condition_number_scaled, b.condition_number_scaled, kRelTol * a.condition_number_scaled);
  EXPECT_NEAR(b.theta(2) * 1e-6, a.theta(2), kRelTol * 1e3 * std::abs(a.theta(2)));  // M carries the inverse unit
}

TEST(LeastSquares, RefusalsNameTheParameters) {
  Regression g = friction_regression(500, 3);
  Eigen::MatrixXd X = g.X;
  X.col(1).setZero();
  fl::LeastSquaresFit f = fl::linear_least_squares(X, g.y, kNames);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.refusal, fl::LeastSquaresRefusal::no_excitation);
  EXPECT_EQ(f.message, "no excitation of parameter Fv: its regressor column is zero");

  X = g.X;
  X.col(3) = 2.0 * X.col(0);  // the offset as a copy of the sign column: Fc and offset collinear
  f = fl::linear_least_squares(X, g.y, kNames);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.refusal, fl::LeastSquaresRefusal::rank_deficient);
  EXPECT_NE(f.message.find("rank-deficient regressors: condition number"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("Fc and offset cannot be told apart"), std::string::npos) << f.message;
  EXPECT_GT(f.condition_number_scaled, 1e8);

  f = fl::linear_least_squares(g.X.topRows(4), g.y.head(4), kNames);
  EXPECT_EQ(f.refusal, fl::LeastSquaresRefusal::too_few_samples);
  EXPECT_EQ(f.message, "4 samples for 4 parameters; expected more samples than parameters");
  // Allowed, N = p is an exact fit (two map points of a side: Fc and Fv through them).
  fl::LeastSquaresOptions exact;
  exact.min_redundancy = 0;
  const Eigen::Matrix2d X2 = (Eigen::Matrix2d() << 1.0, 0.1, 1.0, 0.3).finished();
  f = fl::linear_least_squares(X2, Eigen::Vector2d(0.2, 0.3), {"Fc", "Fv"}, exact);
  ASSERT_TRUE(f.ok) << f.message;
  constexpr double kExactTol = 1e-13;  // a 2 x 2 solve of condition ~10: rounding only
  EXPECT_NEAR(f.theta(0), 0.15, kExactTol);
  EXPECT_NEAR(f.theta(1), 0.5, kExactTol);
  EXPECT_NEAR(f.residual.norm(), 0.0, kExactTol);

  EXPECT_THROW(fl::linear_least_squares(g.X, g.y.head(10), kNames), std::invalid_argument);
  EXPECT_THROW(fl::linear_least_squares(g.X, g.y, {"Fc"}), std::invalid_argument);
}
