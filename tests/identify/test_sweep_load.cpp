// identify_sweep with a load column: steady speeds run at three loads, friction
// law(v) + mu_load |load| sign(v). The record is made here (first-order speed steps with a rest
// between levels, white force and load-cell noise), independently of the library's laws. Checks:
// mu_load and the zero-load levels found; the std of mu_load covers the truth over seeded cases
// (the coverage suite's binomial rule); the law carries mu_load; loads that do not differ give an
// error status naming why; a load of the wrong length is refused naming the load.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using ::testing::HasSubstr;

// The rig (SI, linear): Coulomb 1 N, static 1.5 N (Stribeck 0.02 m/s, Gaussian), viscous 0.5 N s/m,
// mu_load 0.02 (0.2 to 1.6 N of friction at 10 to 80 N of load).
constexpr double kFc = 1.0, kFs = 1.5, kVs = 0.02, kFv = 0.5, kMu = 0.02;

double law(double v, bool stribeck) {
  const double s = v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0;
  const double level = stribeck ? kFc + (kFs - kFc) * std::exp(-(v / kVs) * (v / kVs)) : kFc;
  return s * level + kFv * v;
}

// Every speed at every load, each level 1.5 s after 0.3 s at rest; 1 kHz. Force noise 0.05 N
// and load-cell noise 0.5 N, white.
SweepData load_sweep(const std::vector<double>& loads, unsigned seed, bool stribeck) {
  constexpr double kDt = 1e-3, kRest = 0.3, kHold = 1.5, kTau = 0.05, kMass = 0.5;  // s, s, s, s, kg
  const std::vector<double> speeds = stribeck ? std::vector<double>{0.005, 0.01, 0.02, 0.04, 0.1, 0.3}
                                              : std::vector<double>{0.05, 0.1, 0.2, 0.4};
  std::mt19937 gen(seed);
  std::normal_distribution<double> n01;
  std::vector<double> t, f, v, l;
  double vel = 0, time = 0;
  for (double load : loads)
    for (double sgn : {1.0, -1.0})
      for (double speed : speeds)
        for (const auto& [ref, dur] : {std::pair{0.0, kRest}, std::pair{sgn * speed, kHold}})
          for (int k = 0; k < static_cast<int>(dur / kDt); ++k) {
            const double a = (ref - vel) / kTau;
            vel += kDt * a;
            if (ref == 0.0 && std::abs(vel) < 1e-9) vel = 0.0;
            t.push_back(time);
            time += kDt;
            v.push_back(vel);
            const double friction = law(vel, stribeck) + (vel == 0.0 ? 0.0 : (vel > 0 ? 1 : -1) * kMu * load);
            f.push_back(friction + kMass * a + 0.05 * n01(gen));
            l.push_back(load + 0.5 * n01(gen));
          }
  const auto vec = [](const std::vector<double>& x) { return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()))); };
  return SweepData{vec(t), vec(f), vec(v), vec(l)};
}

SweepOptions options(bool stribeck) {
  SweepOptions o;
  o.axis = Axis::linear;
  o.fit.model = stribeck ? StaticFitModel::stribeck : StaticFitModel::coulomb_viscous;
  if (stribeck) o.fit.fixed_delta = 2.0;
  return o;
}

TEST(SweepLoad, CoulombViscousFindsMuLoadAndTheZeroLoadLevels) {
  const Result r = identify_sweep(load_sweep({10, 40, 80}, 1, false), options(false));
  ASSERT_TRUE(r.ok()) << r.message;
  // 24 points, each a mean over 1.2 s of 0.05 N noise: mu_load and Fc have a std under 0.1 %, so
  // 1 % is over 10 std; Fv rests on four speeds from 0.05 to 0.4 m/s and has a std near 0.5 %
  // (0.0024 N s/m), so 3 % is over 5 std.
  constexpr double kLevelRelTol = 0.01, kViscousRelTol = 0.03;
  EXPECT_NEAR(r.value("mu_load"), kMu, kLevelRelTol * kMu);
  EXPECT_NEAR(r.value("Fc"), kFc, kLevelRelTol * kFc);
  EXPECT_NEAR(r.value("Fv"), kFv, kViscousRelTol * kFv);
  ASSERT_TRUE(r.law.has_value());
  EXPECT_DOUBLE_EQ(r.law->scalars.at("mu_load"), r.value("mu_load"));
  EXPECT_EQ(r.find("mu_load")->unit, "");
  EXPECT_EQ(r.diagnostics.lists.at("points").size(), 24u);
  EXPECT_NEAR(r.diagnostics.lists.at("points").front().at("load"), 10.0, 0.1);  // 1200 samples of 0.5 N noise
  EXPECT_NEAR(r.diagnostics.numbers.at("load_max"), 80.0, 0.1);
}

TEST(SweepLoad, StribeckLevelsAtZeroLoad) {
  const Result r = identify_sweep(load_sweep({10, 40, 80}, 2, true), options(true));
  ASSERT_TRUE(r.ok()) << r.message;
  // The nonlinear fit rests on the slow points (settling, 0.05 N noise): a few percent.
  constexpr double kRelTol = 0.05;
  EXPECT_NEAR(r.value("mu_load"), kMu, kRelTol * kMu);
  EXPECT_NEAR(r.value("Fc"), kFc, kRelTol * kFc);
  EXPECT_NEAR(r.value("Fs"), kFs, kRelTol * kFs);
  EXPECT_TRUE(std::isfinite(r.find("mu_load")->std));
}

// The suite's rule (tests/rigs/idim_coverage.py): of 100 seeded cases, at least 89 intervals
// value +- 1.96 std hold the truth (an honest 95 % interval fails this with probability < 0.01).
TEST(SweepLoad, StdOfMuLoadCoversTheTruth) {
  constexpr int kCases = 100, kLeastHits = 89;
  constexpr double kZ95 = 1.959963984540054;
  int hits = 0, hits_fc = 0;
  for (int i = 0; i < kCases; ++i) {
    const Result r = identify_sweep(load_sweep({10, 40, 80}, 100 + static_cast<unsigned>(i), false), options(false));
    ASSERT_TRUE(r.ok()) << r.message;
    const auto* mu = r.find("mu_load");
    const auto* fc = r.find("Fc");
    hits += std::abs(mu->value - kMu) <= kZ95 * mu->std;
    hits_fc += std::abs(fc->value - kFc) <= kZ95 * fc->std;
  }
  EXPECT_GE(hits, kLeastHits) << "mu_load covered in " << hits << " of " << kCases << " cases";
  EXPECT_GE(hits_fc, kLeastHits) << "Fc covered in " << hits_fc << " of " << kCases << " cases";
}

TEST(SweepLoad, OneLoadCannotSeparateMuLoad) {
  const Result r = identify_sweep(load_sweep({40}, 3, false), options(false));
  EXPECT_FALSE(r.ok());
  EXPECT_THAT(r.message, HasSubstr("mu_load cannot be told from the levels"));
}

TEST(SweepLoad, LoadOfTheWrongLengthIsRefused) {
  SweepData d = load_sweep({10, 40}, 4, false);
  d.load.conservativeResize(d.load.size() - 1);
  EXPECT_THAT(error_of([&] { identify_sweep(d, options(false)); }), HasSubstr("the load has"));
  d = load_sweep({10, 40}, 4, false);
  d.load[7] = std::nan("");
  EXPECT_THAT(error_of([&] { sweep_points(d, options(false)); }), HasSubstr("load sample 8 (counted from 1) is not finite"));
}

}  // namespace
}  // namespace frictionlab
