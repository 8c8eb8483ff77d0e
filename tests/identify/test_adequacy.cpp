// Residual checks (identify/adequacy.hpp): silent on noise, specific on structure.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "frictionlab/identify/adequacy.hpp"
#include "property_cases.hpp"

namespace fl = frictionlab;

namespace {

// A record that moves both ways at many speeds: v = 0.1 sin(2 pi t / 5) m/s, q its integral,
// 4000 samples at 100 Hz.
struct Record {
  std::vector<double> t, v, q;
};

Record motion() {
  Record r;
  constexpr int kSamples = 4000;
  constexpr double kDt = 0.01, kPeriod = 5.0, kSpeed = 0.1;
  for (int i = 0; i < kSamples; ++i) {
    const double t = i * kDt;
    r.t.push_back(t);
    r.v.push_back(kSpeed * std::sin(2 * M_PI * t / kPeriod));
    r.q.push_back(-kSpeed * kPeriod / (2 * M_PI) * std::cos(2 * M_PI * t / kPeriod));
  }
  return r;
}

std::vector<double> white(std::size_t n, double sigma, unsigned seed) {
  std::mt19937 gen(seed);
  std::normal_distribution<double> d(0.0, sigma);
  std::vector<double> e(n);
  for (auto& x : e) x = d(gen);
  return e;
}

bool has(const fl::Adequacy& a, const std::string& words) {
  for (const auto& f : a.findings)
    if (f.find(words) != std::string::npos) return true;
  return false;
}

std::string all(const fl::Adequacy& a) {
  std::string s;
  for (const auto& f : a.findings) s += f + "\n";
  return s;
}

}  // namespace

TEST(Adequacy, WhiteResidualRaisesNoFindingOverSeededCases) {
  // The false-alarm rate of the structure checks on white residuals: each check's threshold is 4
  // standard errors over about 30 bins, so a false alarm has a probability near 2e-3 per record.
  // Allow 2 % of the cases, which a correct implementation passes with a wide margin and a
  // threshold of 2 standard errors (about 50 % false alarms) fails.
  const Record r = motion();
  const int cases = std::max(50, fl::testing::property_cases() / 10);
  int alarms = 0;
  for (int seed = 1; seed <= cases; ++seed) {
    const auto e = white(r.v.size(), 0.1, static_cast<unsigned>(seed));
    const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
    alarms += a.findings.empty() ? 0 : 1;
  }
  constexpr double kFalseAlarmShare = 0.02;
  EXPECT_LE(alarms, kFalseAlarmShare * cases) << alarms << " of " << cases;
}

TEST(Adequacy, AMissingStribeckDipIsNamedWithTheRemedy) {
  // Friction 0.5 N above the model below about 10 mm/s, with the velocity's sign, plus noise.
  const Record r = motion();
  auto e = white(r.v.size(), 0.1, 7);
  for (std::size_t i = 0; i < e.size(); ++i) e[i] += std::copysign(0.5 * std::exp(-std::pow(r.v[i] / 0.01, 2)), r.v[i]);
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  EXPECT_TRUE(has(a, "friction at low speed is higher than the model")) << all(a);
  EXPECT_TRUE(has(a, "stribeck")) << all(a);
  EXPECT_TRUE(has(a, "sweep")) << all(a);
  EXPECT_FALSE(has(a, "differs by direction")) << all(a);
}

TEST(Adequacy, ADirectionDependentLevelIsNamed) {
  const Record r = motion();
  auto e = white(r.v.size(), 0.1, 11);
  for (std::size_t i = 0; i < e.size(); ++i)
    if (r.v[i] > 0) e[i] += 0.3;  // 0.3 N more friction when moving positive
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  EXPECT_TRUE(has(a, "differs by direction")) << all(a);
  EXPECT_TRUE(has(a, "moving positive")) << all(a);
}

TEST(Adequacy, APositionRippleIsNamed) {
  // A ripple of 2 mm period against position on a record that travels 160 mm.
  const Record r = motion();
  auto e = white(r.v.size(), 0.05, 13);
  for (std::size_t i = 0; i < e.size(); ++i) e[i] += 0.4 * (r.q[i] > 0 ? 1.0 : -1.0);
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  EXPECT_TRUE(has(a, "depends on position")) << all(a);
}

TEST(Adequacy, CorrelatedResidualGivesTheEffectiveSampleSize) {
  // AR(1) with rho = 0.9: the effective sample size is about n (1 - rho) / (1 + rho) = n / 19.
  const Record r = motion();
  const auto w = white(r.v.size(), 0.1, 17);
  std::vector<double> e(w.size());
  constexpr double kRho = 0.9;
  e[0] = w[0];
  for (std::size_t i = 1; i < e.size(); ++i) e[i] = kRho * e[i - 1] + std::sqrt(1 - kRho * kRho) * w[i];
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  const double expected = static_cast<double>(e.size()) * (1 - kRho) / (1 + kRho);
  // 35 %: the estimate sums sample autocorrelations of one 4000-sample record, whose spread at
  // rho = 0.9 is about 20 % of the sum (Bartlett); the check is of the order, not the digits.
  constexpr double kRelTol = 0.35;
  EXPECT_NEAR(a.effective_samples, expected, kRelTol * expected);
  EXPECT_TRUE(has(a, "correlated from sample to sample")) << all(a);
  EXPECT_TRUE(has(a, "idim's std accounts for the correlation")) << all(a);
  // The binned means are judged with the wider standard errors: no structure is claimed.
  EXPECT_FALSE(has(a, "friction at low speed")) << all(a);
  EXPECT_FALSE(has(a, "depends on position")) << all(a);
}

TEST(Adequacy, StandstillShareIsReportedWithItsThreshold) {
  Record r = motion();
  for (std::size_t i = 0; i < r.v.size() / 2; ++i) r.v[i] = 0.0;  // half the record at rest
  const auto e = white(r.v.size(), 0.1, 19);
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  EXPECT_NEAR(a.standstill_share, 0.5, 0.02);
  EXPECT_TRUE(has(a, "near standstill (|v| < 0.002 m/s)")) << all(a);
  EXPECT_TRUE(has(a, "idim: --exclude-below 0.002)")) << "the suggestion names the option and the value; " << all(a);
}

TEST(Adequacy, ResultCarriesBinsAndFindingsAsWarnings) {
  const Record r = motion();
  auto e = white(r.v.size(), 0.1, 23);
  for (std::size_t i = 0; i < e.size(); ++i) e[i] += std::copysign(0.5 * std::exp(-std::pow(r.v[i] / 0.01, 2)), r.v[i]);
  fl::Result result;
  const fl::Adequacy a = fl::assess_residuals(r.v, r.q, r.t, e, "N", "m/s");
  fl::add_adequacy(result, a);
  EXPECT_EQ(result.diagnostics.lists.at("residual_by_velocity").size(), a.by_velocity.size());
  EXPECT_EQ(result.diagnostics.lists.at("residual_autocorrelation").size(), 10u);
  EXPECT_EQ(result.diagnostics.groups.at("adequacy").at("findings"), static_cast<double>(a.findings.size()));
  EXPECT_EQ(result.diagnostics.warnings.size(), a.findings.size());
}

TEST(Adequacy, BadInputNamesTheLengths) {
  const std::vector<double> v(30, 1.0), e(29, 0.0);
  try {
    fl::assess_residuals(v, {}, {}, e, "N", "m/s");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& ex) {
    EXPECT_NE(std::string(ex.what()).find("velocity 30"), std::string::npos) << ex.what();
  }
  EXPECT_THROW(fl::assess_residuals(std::vector<double>(5, 1.0), {}, {}, std::vector<double>(5, 0.0), "N", "m/s"),
               std::invalid_argument);
}
