// identify_sweep and sweep_points on data that cannot hold a sweep: no samples (with and without
// explicit windows, where the message used to read past the end of the empty time column) and a
// sample that is not finite, named by its 1-based number.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "error_message.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using ::testing::HasSubstr;

TEST(SweepBadData, NoSamplesIsBadInput) {
  const SweepData empty;
  EXPECT_THAT(error_of([&] { identify_sweep(empty, SweepOptions{}); }), HasSubstr("0 samples are too few; expected at least 2"));
  SweepOptions windowed;
  windowed.windows.push_back({1.0, 2.0});
  EXPECT_THAT(error_of([&] { sweep_points(empty, windowed); }), HasSubstr("0 samples are too few"));
}

TEST(SweepBadData, NonFiniteSampleIsNamedFromOne) {
  SweepData d;
  d.time = Eigen::VectorXd::LinSpaced(5, 0.0, 0.004);
  d.force = Eigen::VectorXd::Constant(5, 1.0);
  d.velocity = Eigen::VectorXd::Constant(5, 0.1);
  d.velocity[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(error_of([&] { sweep_points(d, SweepOptions{}); }), HasSubstr("sample 3 (counted from 1) is not finite"));
}

}  // namespace
}  // namespace frictionlab
