// Model selection on held-out data (identify/selection.hpp): contiguous blocks, held-out errors
// of a linear model, physical refusals, and the rule that held-out error decides, not training error.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/QR>
#include <cmath>
#include <random>
#include <stdexcept>

#include "frictionlab/identify/selection.hpp"

namespace frictionlab {
namespace {

TEST(Selection, BlocksAreContiguousAndCoverTheRecord) {
  const auto b = contiguous_blocks(10, 4);
  ASSERT_EQ(b.size(), 4u);
  EXPECT_EQ(b.front().first, 0);
  EXPECT_EQ(b.back().second, 10);
  for (std::size_t k = 1; k < b.size(); ++k) EXPECT_EQ(b[k].first, b[k - 1].second);
  EXPECT_THROW(contiguous_blocks(10, 1), std::invalid_argument);
  EXPECT_THROW(contiguous_blocks(7, 4), std::invalid_argument);
}

// An exact linear signal is predicted exactly on every held-out block.
TEST(Selection, ExactModelHasNoHeldOutError) {
  constexpr double kExact = 1e-9;  // percent: rounding of a 200-row least-squares solve only
  Eigen::MatrixXd X(200, 2);
  Eigen::VectorXd y(200);
  for (int i = 0; i < 200; ++i) {
    X(i, 0) = std::sin(0.1 * i);
    X(i, 1) = 1.0;
    y(i) = 3.0 * X(i, 0) + 0.5;
  }
  const HeldOutErrors h = linear_heldout_errors(X, y, contiguous_blocks(200, 4));
  EXPECT_EQ(h.samples, 200u);
  EXPECT_LT(h.relative_error_percent(), kExact);
}

// The heart of the selection: a structure with spurious freedom (a polynomial in time on top of
// the true regressor) always fits its training data at least as well, but predicts held-out
// time blocks worse; the held-out error picks the true structure. Seeded noise, several seeds.
TEST(Selection, HeldOutErrorDecidesNotTrainingError) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    std::mt19937 gen(seed);
    std::normal_distribution<double> noise(0.0, 0.3);
    constexpr int kN = 400, kDegree = 8;
    Eigen::MatrixXd simple(kN, 1), flexible(kN, 1 + kDegree);
    Eigen::VectorXd y(kN);
    for (int i = 0; i < kN; ++i) {
      const double t = static_cast<double>(i) / kN;
      const double x = std::sin(40.0 * t);
      simple(i, 0) = x;
      flexible(i, 0) = x;
      for (int d = 1; d <= kDegree; ++d) flexible(i, d) = std::pow(2.0 * t - 1.0, d);
      y(i) = 2.0 * x + noise(gen);
    }
    // The flexible structure listed first, so that the choice cannot come from the order.
    std::vector<SelectionCandidate> c(2);
    c[0].name = "flexible";
    c[1].name = "simple";
    const auto train = [&](const Eigen::MatrixXd& X) {
      const Eigen::VectorXd th = X.colPivHouseholderQr().solve(y);
      return 100.0 * (y - X * th).norm() / y.norm();
    };
    c[0].training_error_percent = train(flexible);
    c[1].training_error_percent = train(simple);
    const auto blocks = contiguous_blocks(kN, 4);
    const HeldOutErrors hf = linear_heldout_errors(flexible, y, blocks), hs = linear_heldout_errors(simple, y, blocks);
    c[0].heldout_error_percent = hf.relative_error_percent();
    c[0].block_errors_percent = hf.block_errors_percent();
    c[1].heldout_error_percent = hs.relative_error_percent();
    c[1].block_errors_percent = hs.block_errors_percent();
    EXPECT_LT(c[0].training_error_percent, c[1].training_error_percent) << "seed " << seed;
    EXPECT_GT(c[0].heldout_error_percent, c[1].heldout_error_percent) << "seed " << seed;
    const auto chosen = select_candidate(c);
    ASSERT_TRUE(chosen.has_value());
    EXPECT_EQ(*chosen, 1u) << "seed " << seed;
  }
}

// Within one standard error of the best, the candidate listed first (the simpler) is chosen; a
// clearly better one (beyond its standard error) wins.
TEST(Selection, OneStandardErrorRulePrefersTheSimplerStructure) {
  std::vector<SelectionCandidate> c(2);
  c[0].heldout_error_percent = 1.41;
  c[0].block_errors_percent = {1.3, 1.5, 1.4, 1.44};
  c[1].heldout_error_percent = 1.405;  // better by a tenth of its standard error
  c[1].block_errors_percent = {1.2, 1.6, 1.4, 1.42};
  EXPECT_EQ(select_candidate(c), std::optional<std::size_t>(0));
  c[1].heldout_error_percent = 1.0;  // better by several standard errors
  c[1].block_errors_percent = {0.98, 1.02, 1.0, 1.0};
  EXPECT_EQ(select_candidate(c), std::optional<std::size_t>(1));
  EXPECT_GT(heldout_standard_error(c[0]), 0.0);
}

Result with(std::initializer_list<std::pair<const char*, double>> params) {
  Result r;
  for (const auto& [n, v] : params) r.parameters.emplace_back(n, v, 0.1, Quantity::force, Axis::linear);
  return r;
}

TEST(Selection, PhysicallyImpossibleResultsAreRefusedWithTheReason) {
  EXPECT_EQ(physical_refusal(with({{"M", 2}, {"Fv", 20}, {"Fc", 3}, {"Fs_minus_Fc", 1.5}})), "");
  EXPECT_NE(physical_refusal(with({{"Fc", 3}, {"Fs_minus_Fc", -0.4}})).find("Fs_minus_Fc"), std::string::npos);
  EXPECT_NE(physical_refusal(with({{"Fc", 3}, {"Fs", 2.5}})).find("below the Coulomb level"), std::string::npos);
  EXPECT_NE(physical_refusal(with({{"Fc", 3}, {"vs", 0}})).find("vs"), std::string::npos);
  EXPECT_NE(physical_refusal(with({{"Fv_neg", -1}})).find("Fv_neg"), std::string::npos);
  EXPECT_NE(physical_refusal(with({{"M", -0.1}})).find("M = -0.1"), std::string::npos);
  Result failed;
  failed.status = ResultStatus::error;
  failed.message = "no motion";
  EXPECT_NE(physical_refusal(failed).find("no motion"), std::string::npos);
}

// A refused candidate is never chosen, even with the lowest held-out error; none left: nullopt.
TEST(Selection, RefusedCandidateIsNeverChosen) {
  std::vector<SelectionCandidate> c(2);
  c[0].result = with({{"Fc", 3}, {"Fs_minus_Fc", -1}});
  c[0].heldout_error_percent = 1.0;
  c[0].refusal = physical_refusal(c[0].result);
  c[1].result = with({{"Fc", 3}});
  c[1].heldout_error_percent = 5.0;
  ASSERT_TRUE(c[0].refused());
  EXPECT_EQ(select_candidate(c), std::optional<std::size_t>(1));
  c[1].refusal = "test";
  EXPECT_FALSE(select_candidate(c).has_value());
  const std::string json = selection_json(c, std::nullopt);
  EXPECT_NE(json.find("\"refused\""), std::string::npos);
  EXPECT_NE(json.find("static level would be below"), std::string::npos);
}

}  // namespace
}  // namespace frictionlab
