// Stick-slip detection on records that show none: the result says so (message), the period is
// not a figure to print.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "frictionlab/analysis/stick_slip.hpp"

namespace fl = frictionlab;

TEST(StickSlipDegenerate, NeverSlippingRecordSaysNoSlip) {
  std::vector<double> t, v, f;
  for (int k = 0; k < 300; ++k) {
    t.push_back(0.01 * k);
    v.push_back(0.0);
    f.push_back(0.001 * k);
  }
  const auto r = fl::detect_stick_slip(t, v, f, {});
  EXPECT_FALSE(r.found());
  EXPECT_EQ(r.message.rfind("no slip found: velocity never exceeded", 0), 0u) << r.message;
  EXPECT_TRUE(r.slip.empty());
  EXPECT_TRUE(std::isnan(r.period));
}

TEST(StickSlipDegenerate, ContinuousSlidingIsNotStickSlip) {
  std::vector<double> t, v;
  for (int k = 0; k < 300; ++k) {
    t.push_back(0.01 * k);
    v.push_back(0.5 + 0.01 * std::sin(0.1 * k));
  }
  const auto r = fl::detect_stick_slip(t, v, {}, {});
  EXPECT_FALSE(r.found());
  EXPECT_NE(r.message.find("never sticks"), std::string::npos) << r.message;
}

TEST(StickSlipDegenerate, RegularStickSlipIsFound) {
  std::vector<double> t, v;
  for (int k = 0; k < 1000; ++k) {
    t.push_back(0.01 * k);
    const double phase = std::fmod(0.01 * k, 2.0);  // 2 s period: 0.5 s slip, 1.5 s stick
    v.push_back(phase > 1.0 && phase < 1.5 ? std::sin((phase - 1.0) * 2 * 3.141592653589793) : 0.0);
  }
  const auto r = fl::detect_stick_slip(t, v, {}, {});
  EXPECT_TRUE(r.found()) << r.message;
  constexpr double kPeriodTol = 0.02;  // s: two samples of 10 ms
  EXPECT_NEAR(r.period, 2.0, kPeriodTol);
}
