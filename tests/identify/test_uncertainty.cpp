// Honest uncertainty: std NaN for parameters at a bound or not determined by the data, a warning
// naming each, and a symmetric unit-diagonal correlation matrix in the result and its JSON.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "frictionlab/identify/uncertainty.hpp"

namespace frictionlab {
namespace {

constexpr double kRelTol = 1e-10;  // the same linear algebra computed two ways; rounding only

Result three_parameter_result() {
  Result r;
  r.method = "test";
  for (const char* n : {"a", "b", "c"}) r.parameters.push_back({n, 1.0, 0.0, "N", ""});
  return r;
}

bool warned_about(const Result& r, const std::string& name) {
  for (const auto& w : r.diagnostics.warnings)
    if (w.rfind(name + " = ", 0) == 0) return true;
  return false;
}

// A well-conditioned regression: std equals s sqrt(diag((X'X)^-1)), no parameter flagged.
TEST(Uncertainty, WellDeterminedMatchesOrdinaryLeastSquares) {
  std::mt19937 gen(11);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd X(200, 3);
  for (Eigen::Index i = 0; i < X.rows(); ++i) X.row(i) << 1.0, n01(gen), n01(gen) + 0.3 * X(i, 1);
  const Eigen::MatrixXd A = X.transpose() * X;
  const double s2 = 0.04;
  Result r = three_parameter_result();
  const Eigen::MatrixXd cov = set_uncertainty_from_information(r, {"a", "b", "c"}, A, s2);
  const Eigen::MatrixXd expected = s2 * A.inverse();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.parameters[i].std, std::sqrt(expected(i, i)), kRelTol * std::sqrt(expected(i, i)));
    EXPECT_TRUE(r.parameters[i].flag.empty());
  }
  EXPECT_NEAR(cov(1, 2), expected(1, 2), kRelTol * std::abs(expected(1, 2)));
  EXPECT_TRUE(r.diagnostics.undetermined.empty());
  EXPECT_TRUE(r.diagnostics.at_bound.empty());
  EXPECT_TRUE(r.diagnostics.warnings.empty());
  const auto& m = r.diagnostics.correlation.matrix;
  ASSERT_EQ(m.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(m[i][i], 1.0);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(m[i][j], m[j][i]);
      EXPECT_LE(std::abs(m[i][j]), 1.0);
    }
  }
  // Columns b and c were built positively correlated, so their estimates are negatively correlated.
  EXPECT_LT(m[1][2], -0.1);
}

// Two identical columns: neither can be told apart, both undetermined, the third keeps its std.
TEST(Uncertainty, CollinearColumnsAreUndetermined) {
  Eigen::MatrixXd X(50, 3);
  for (Eigen::Index i = 0; i < X.rows(); ++i) {
    const double v = std::sin(0.3 * static_cast<double>(i));
    X.row(i) << 1.0, v, 2.0 * v;
  }
  Result r = three_parameter_result();
  set_uncertainty_from_information(r, {"a", "b", "c"}, X.transpose() * X, 1.0);
  EXPECT_TRUE(std::isfinite(r.parameters[0].std));
  EXPECT_TRUE(std::isnan(r.parameters[1].std));
  EXPECT_TRUE(std::isnan(r.parameters[2].std));
  EXPECT_EQ(r.parameters[1].flag, "undetermined");
  EXPECT_EQ(r.diagnostics.undetermined, (std::vector<std::string>{"b", "c"}));
  EXPECT_TRUE(warned_about(r, "b"));
  EXPECT_TRUE(warned_about(r, "c"));
  EXPECT_FALSE(warned_about(r, "a"));
  EXPECT_TRUE(std::isnan(r.diagnostics.correlation.matrix[0][1]));
  EXPECT_EQ(r.diagnostics.correlation.matrix[1][1], 1.0);
}

// A column of zeros (never excited) and a parameter held at its bound.
TEST(Uncertainty, ZeroInformationAndAtBound) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Identity();
  A(2, 2) = 0.0;
  Result r = three_parameter_result();
  std::vector<ParameterState> states(3);
  states[1].at_bound = true;
  set_uncertainty_from_information(r, {"a", "b", "c"}, A, 1.0, states);
  EXPECT_NEAR(r.parameters[0].std, 1.0, kRelTol);
  EXPECT_TRUE(std::isnan(r.parameters[1].std));
  EXPECT_EQ(r.parameters[1].flag, "at bound");
  EXPECT_TRUE(std::isnan(r.parameters[2].std));
  EXPECT_EQ(r.parameters[2].flag, "undetermined");
  EXPECT_EQ(r.diagnostics.at_bound, std::vector<std::string>{"b"});
  EXPECT_EQ(r.diagnostics.undetermined, std::vector<std::string>{"c"});
  EXPECT_TRUE(warned_about(r, "b"));
  EXPECT_TRUE(warned_about(r, "c"));
}

TEST(Uncertainty, AtBoundRule) {
  EXPECT_TRUE(is_at_bound(0.0, 0.0, INFINITY, 1.0));
  EXPECT_TRUE(is_at_bound(5.0 - 1e-9, 0.5, 5.0, 1.0));
  EXPECT_FALSE(is_at_bound(4.9, 0.5, 5.0, 1.0));
  EXPECT_FALSE(is_at_bound(1e-3, 0.0, INFINITY, 1.0));
}

// The JSON carries null std and the correlation matrix.
TEST(Uncertainty, JsonCarriesNullStdAndCorrelation) {
  Eigen::Matrix3d cov;
  cov << 4, 1, 0, 1, 1, 0, 0, 0, 0;  // c has zero variance: not a figure to report
  Result r = three_parameter_result();
  set_uncertainty_from_covariance(r, {"a", "b", "c"}, cov);
  const auto j = nlohmann::json::parse(to_json(r));
  EXPECT_NEAR(j["parameters"]["a"]["std"].get<double>(), 2.0, kRelTol * 2.0);
  EXPECT_TRUE(j["parameters"]["c"]["std"].is_null());
  EXPECT_EQ(j["diagnostics"]["undetermined"], nlohmann::json::array({"c"}));
  EXPECT_EQ(j["diagnostics"]["correlation"]["names"], nlohmann::json::array({"a", "b", "c"}));
  const auto& m = j["diagnostics"]["correlation"]["matrix"];
  EXPECT_NEAR(m[0][1].get<double>(), 0.5, kRelTol);
  EXPECT_NEAR(m[1][0].get<double>(), 0.5, kRelTol);
  EXPECT_TRUE(m[0][2].is_null());
  EXPECT_EQ(m[2][2].get<double>(), 1.0);
}

TEST(Uncertainty, MismatchedSizesThrow) {
  Result r = three_parameter_result();
  EXPECT_THROW(set_uncertainty_from_information(r, {"a", "b"}, Eigen::Matrix3d::Identity(), 1.0), std::invalid_argument);
  EXPECT_THROW(set_uncertainty_from_information(r, {"a", "b", "x"}, Eigen::Matrix3d::Identity(), 1.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab
