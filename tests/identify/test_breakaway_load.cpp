// identify_breakaway with a load column: trapezoids of drive force from rest, each at its own
// load, on a rig whose static and Coulomb levels grow with |load| (mu_load_static,
// mu_load_coulomb). The record is made here with an explicit stick rule, independently of the
// library's engine. Checks: the zero-load levels and both coefficients found; the law carries
// them; too few starts or one load give an error status naming why; a load of the wrong length is
// refused naming the load.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/identify/breakaway.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using ::testing::HasSubstr;

// The rig (SI, rotary): static 0.3 N m and Coulomb 0.2 N m at zero load, rising by 0.01 and
// 0.005 N m per N m of load; viscous 0.02 N m s/rad; inertia 0.01 kg m^2.
constexpr double kFs = 0.3, kFc = 0.2, kMuS = 0.01, kMuC = 0.005, kFv = 0.02, kJ = 0.01;

// One trapezoid per load (0.5 s at rest, ramp up 1 s to 1.5 times that load's static level plus
// 0.2 N m, hold 1 s, ramp down 1 s, 1 s at rest), sampled at 1 kHz (10 integration steps per
// sample); velocity noise 1e-4 rad/s, force noise 1e-3 N m, load-cell noise 0.05 N m, white.
BreakawayData trapezoids(const std::vector<double>& loads, unsigned seed) {
  constexpr double kDt = 1e-3;
  constexpr int kSub = 10;
  std::mt19937 gen(seed);
  std::normal_distribution<double> n01;
  std::vector<double> t, f, v, l;
  double vel = 0, time = 0;
  for (double load : loads) {
    const double peak = 1.5 * (kFs + kMuS * load) + 0.2;
    const auto drive = [&](double s) {  // s: seconds into this trapezoid
      if (s < 0.5) return 0.0;
      if (s < 1.5) return peak * (s - 0.5);
      if (s < 2.5) return peak;
      if (s < 3.5) return peak * (3.5 - s);
      return 0.0;
    };
    for (int k = 0; k < 4500; ++k) {
      const double s = k * kDt;
      const double u = drive(s);
      for (int j = 0; j < kSub; ++j) {
        const double h = kDt / kSub;
        if (vel == 0.0) {
          if (std::abs(u) > kFs + kMuS * load) vel = h * (u - std::copysign(kFc + kMuC * load, u)) / kJ;
        } else {
          const double a = (u - std::copysign(kFc + kMuC * load, vel) - kFv * vel) / kJ;
          const double next = vel + h * a;
          vel = (next > 0) != (vel > 0) ? 0.0 : next;
        }
      }
      t.push_back(time);
      time += kDt;
      f.push_back(u + 1e-3 * n01(gen));
      v.push_back(vel + 1e-4 * n01(gen));
      l.push_back(load + 0.05 * n01(gen));
    }
  }
  const auto vec = [](const std::vector<double>& x) {
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size())));
  };
  return BreakawayData{vec(t), vec(f), vec(v), vec(l)};
}

TEST(BreakawayLoad, FindsBothLoadCoefficientsAndTheZeroLoadLevels) {
  const Result r = identify_breakaway(trapezoids({5, 20, 40, 60}, 1), {});
  ASSERT_TRUE(r.ok()) << r.message;
  // Sliding fit over thousands of samples: Coulomb level and its load coefficient within 2 %.
  constexpr double kSlidingRelTol = 0.02;
  // The breakaway instants rest on the fitted dynamics integrated back over a sample or two and
  // on 4 starts: within 5 %.
  constexpr double kBreakawayRelTol = 0.05;
  EXPECT_NEAR(r.value("Fc"), kFc, kSlidingRelTol * kFc);
  EXPECT_NEAR(r.value("mu_load_coulomb"), kMuC, kSlidingRelTol * kMuC);
  EXPECT_NEAR(r.value("Fs"), kFs, kBreakawayRelTol * kFs);
  EXPECT_NEAR(r.value("mu_load_static"), kMuS, kBreakawayRelTol * kMuS);
  EXPECT_NEAR(r.value("Fv"), kFv, kBreakawayRelTol * kFv);
  EXPECT_EQ(r.diagnostics.lists.at("breakaways").size(), 4u);
  ASSERT_TRUE(r.law.has_value());
  EXPECT_DOUBLE_EQ(r.law->scalars.at("mu_load_static"), r.value("mu_load_static"));
  EXPECT_DOUBLE_EQ(r.law->scalars.at("mu_load_coulomb"), r.value("mu_load_coulomb"));
}

TEST(BreakawayLoad, WithoutTheLoadTheResultIsAsBefore) {
  BreakawayData d = trapezoids({5, 20, 40, 60}, 1);
  d.load.resize(0);
  const Result r = identify_breakaway(d, {});
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.find("mu_load_static"), nullptr);
  EXPECT_EQ(r.diagnostics.lists.count("breakaways"), 0u);
}

TEST(BreakawayLoad, OneLoadOrTooFewStartsIsAnErrorStatus) {
  const Result one_load = identify_breakaway(trapezoids({30, 30, 30}, 2), {});
  EXPECT_FALSE(one_load.ok());
  EXPECT_THAT(one_load.message, HasSubstr("mu_load_coulomb cannot be told from Fc"));
  const Result two = identify_breakaway(trapezoids({10, 50}, 3), {});
  EXPECT_FALSE(two.ok());
  EXPECT_THAT(two.message, HasSubstr("needs at least 3 starts from rest"));
}

TEST(BreakawayLoad, LoadOfTheWrongLengthIsRefused) {
  BreakawayData d = trapezoids({10, 40, 60}, 4);
  d.load.conservativeResize(d.load.size() - 1);
  EXPECT_THAT(error_of([&] { identify_breakaway(d, {}); }), HasSubstr("the load has"));
}

}  // namespace
}  // namespace frictionlab
