// The one regular-sampling check and the uniform resampler (signal/sampling.hpp), on time
// columns that look like real loggers' output: jitter, repeated stamps, gaps.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/signal/sampling.hpp"

namespace fl = frictionlab;
using frictionlab::testing::error_of;

namespace {

// A regular clock of n samples from 0 with step dt (s).
Eigen::VectorXd clock(Eigen::Index n, double dt) { return Eigen::VectorXd::LinSpaced(n, 0.0, dt * static_cast<double>(n - 1)); }

// Time stamps whose steps are drawn uniformly from [lo, hi] s (seeded).
Eigen::VectorXd jittered(Eigen::Index n, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> step(lo, hi);
  Eigen::VectorXd t(n);
  t(0) = 0.0;
  for (Eigen::Index k = 1; k < n; ++k) t(k) = t(k - 1) + step(rng);
  return t;
}

std::string what_of(const Eigen::VectorXd& t, const fl::RegularSamplingCheck& c = {}) {
  return error_of([&] { fl::check_regular_sampling(t, c); });
}

fl::SamplingProblem problem_of(const Eigen::VectorXd& t) {
  try {
    fl::check_regular_sampling(t);
  } catch (const fl::SamplingError& e) {
    return e.problem();
  }
  ADD_FAILURE() << "no SamplingError";
  return fl::SamplingProblem::too_few;
}

}  // namespace

TEST(RegularSampling, AcceptsSmallJitterAndReportsSteps) {
  Eigen::VectorXd t = clock(1001, 1e-3);
  t(500) += 2e-6;  // 0.2 % of a step: well inside 1 %
  const double mean = fl::check_regular_sampling(t);
  const fl::TimeSteps s = fl::time_steps(t);
  constexpr double kRel = 1e-9;  // sums of 1e-3 s steps carry rounding at 1e-16 s
  EXPECT_EQ(mean, s.mean);
  EXPECT_NEAR(s.mean, 1e-3, kRel * 1e-3);
  EXPECT_NEAR(s.median, 1e-3, kRel * 1e-3);
  EXPECT_NEAR(s.min, 1e-3 - 2e-6, kRel * 1e-3);
  EXPECT_NEAR(s.max, 1e-3 + 2e-6, kRel * 1e-3);
}

TEST(RegularSampling, IrregularStepNamesTheRowOneBasedAndTheSteps) {
  Eigen::VectorXd t = clock(100, 0.01);
  t.tail(60).array() += 0.005;  // a 15 ms step into sample 41 (0-based 40)
  const std::string msg = what_of(t);
  EXPECT_NE(msg.find("sample 41: time step 0.015 s differs from the median step 0.01 s by more than 1 %"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("steps from 0.01 to 0.015 s"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected regularly sampled data"), std::string::npos) << msg;
  EXPECT_EQ(problem_of(t), fl::SamplingProblem::irregular);

  // The caller's labeller, prefix and requirement.
  fl::RegularSamplingCheck c;
  c.where = "log.csv: ";
  c.row_label = [](Eigen::Index k) { return "line " + std::to_string(k + 3); };
  c.requirement = "IDIM needs regularly sampled data";
  const std::string msg2 = what_of(t, c);
  EXPECT_EQ(msg2.rfind("log.csv: line 43: time step", 0), 0u) << msg2;
  EXPECT_NE(msg2.find("IDIM needs regularly sampled data"), std::string::npos) << msg2;
  c.require_regular = false;
  EXPECT_NO_THROW(fl::check_regular_sampling(t, c));
}

TEST(RegularSampling, JitterOfARobotControllerIsRefused) {
  // 100 Hz nominal, stamps 10 to 12 ms apart: the median-step rule refuses it.
  const Eigen::VectorXd t = jittered(500, 0.010, 0.012, 7);
  EXPECT_EQ(problem_of(t), fl::SamplingProblem::irregular);
}

TEST(RegularSampling, NonIncreasingNonFiniteAndTooFew) {
  Eigen::VectorXd t = clock(10, 0.1);
  t(5) = t(4);
  std::string msg = what_of(t);
  EXPECT_NE(msg.find("sample 6: time 0.4 s is not greater than the previous 0.4 s (a repeated time stamp)"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("strictly increasing"), std::string::npos) << msg;
  EXPECT_EQ(problem_of(t), fl::SamplingProblem::repeated);
  t(5) = 0.3;
  EXPECT_EQ(problem_of(t), fl::SamplingProblem::backwards);
  t(5) = std::nan("");
  msg = what_of(t);
  EXPECT_NE(msg.find("sample 6: time = nan s is not a finite number"), std::string::npos) << msg;
  fl::RegularSamplingCheck c;
  c.min_samples = 3;
  c.where = "decay: ";
  EXPECT_EQ(what_of(clock(2, 0.1), c), "decay: time has 2 samples; expected at least 3");
}

TEST(UniformResampler, IrregularLowSpeedLogOntoTheMedianStep) {
  // A torque-sensor log sampled every 1 to 8 ms (mostly 2 ms), a slow sine on it.
  std::mt19937 rng(11);
  std::discrete_distribution<int> ms({0, 20, 60, 8, 5, 3, 2, 1, 1});  // step in ms, median 2
  const Eigen::Index n = 3000;
  Eigen::VectorXd t(n), x(n);
  t(0) = 0;
  for (Eigen::Index k = 1; k < n; ++k) t(k) = t(k - 1) + 1e-3 * ms(rng);
  constexpr double kOmega = 2.0;  // rad/s: slow against the 8 ms steps
  x = (kOmega * t).array().sin();
  const fl::UniformResampler r(t);
  const fl::ResampleReport& rep = r.report();
  constexpr double kStepRel = 1e-9;  // steps are sums of exact milliseconds
  EXPECT_NEAR(rep.dt_median, 2e-3, kStepRel);
  EXPECT_NEAR(rep.dt_min, 1e-3, kStepRel);
  EXPECT_NEAR(rep.dt_max, 8e-3, kStepRel);
  EXPECT_EQ(rep.dt, rep.dt_median);
  EXPECT_EQ(rep.samples_in, n);
  EXPECT_EQ(rep.merged, 0);
  EXPECT_TRUE(rep.warnings.empty());
  const Eigen::VectorXd& g = r.time();
  EXPECT_EQ(rep.samples_out, g.size());
  EXPECT_EQ(g.size(), static_cast<Eigen::Index>(std::floor(t(n - 1) / 2e-3 + 1e-9)) + 1);
  // Uniform, and passes the check it failed before.
  EXPECT_NO_THROW(fl::check_regular_sampling(g));
  EXPECT_EQ(problem_of(t), fl::SamplingProblem::irregular);
  // Linear interpolation of a sine over steps h <= 8 ms: error <= h^2 w^2 / 8 = 3.2e-5.
  const Eigen::VectorXd y = r.apply(x, "torque");
  constexpr double kInterpTol = 8e-3 * 8e-3 * kOmega * kOmega / 8;
  EXPECT_LE((y.array() - (kOmega * g).array().sin()).abs().maxCoeff(), kInterpTol);
  // The record's own samples on grid points are kept exactly.
  EXPECT_EQ(y(0), x(0));
}

TEST(UniformResampler, RepeatedStampsMergedIntoTheirMeanWithAWarning) {
  Eigen::VectorXd t(6), x(6);
  t << 0.0, 0.1, 0.1, 0.2, 0.3, 0.3;
  x << 0.0, 1.0, 3.0, 2.0, 5.0, 7.0;
  fl::ResampleOptions o;
  o.row_label = [](Eigen::Index k) { return "line " + std::to_string(k + 2); };
  const fl::UniformResampler r(t, o);
  EXPECT_EQ(r.report().merged, 2);
  ASSERT_EQ(r.report().warnings.size(), 1u);
  EXPECT_NE(r.report().warnings[0].find("first at line 4, t = 0.1 s"), std::string::npos) << r.report().warnings[0];
  const Eigen::VectorXd y = r.apply(x, "x");
  ASSERT_EQ(y.size(), 4);
  constexpr double kTol = 1e-12;  // means of a few small integers
  EXPECT_NEAR(y(1), 2.0, kTol);
  EXPECT_NEAR(y(2), 2.0, kTol);
  EXPECT_NEAR(y(3), 6.0, kTol);
}

TEST(UniformResampler, GapLongerThanTenMedianStepsNamesItsRows) {
  Eigen::VectorXd t = clock(200, 0.01);
  t.tail(100).array() += 0.5;  // 0.51 s between 0-based samples 99 and 100
  fl::ResampleOptions o;
  o.where = "log.csv: ";
  o.max_gap_name = "--max-gap";
  const std::string msg = error_of([&] { fl::UniformResampler r(t, o); });
  EXPECT_NE(msg.find("log.csv: sample 100 to sample 101: a gap of 0.51 s"), std::string::npos) << msg;
  EXPECT_NE(msg.find("51 median steps"), std::string::npos) << msg;
  EXPECT_NE(msg.find("longer than 10 median steps"), std::string::npos) << msg;
  EXPECT_NE(msg.find("resampling would invent data"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--max-gap 0.515"), std::string::npos) << msg;
  // Allowed explicitly, it is interpolated over.
  o.max_gap = 0.6;
  const fl::UniformResampler r(t, o);
  EXPECT_EQ(r.report().max_gap, 0.6);
  EXPECT_EQ(r.time().size(), 250);  // 2.49 s in 10 ms steps
  // A limit below the gap names the limit.
  o.max_gap = 0.2;
  EXPECT_NE(error_of([&] { fl::UniformResampler q(t, o); }).find("longer than --max-gap = 0.2 s"), std::string::npos);
}

TEST(UniformResampler, BadOptionsAndColumnsAreNamed) {
  const Eigen::VectorXd t = clock(50, 0.01);
  fl::ResampleOptions o;
  o.dt_name = "--resample";
  o.dt = -1;
  EXPECT_NE(error_of([&] { fl::UniformResampler r(t, o); }).find("--resample = -1"), std::string::npos);
  o.dt = 10;
  EXPECT_NE(error_of([&] { fl::UniformResampler r(t, o); }).find("longer than the record"), std::string::npos);
  o.dt = 1e-12;  // a step given in the wrong unit: refused, not an allocation failure
  EXPECT_NE(error_of([&] { fl::UniformResampler r(t, o); }).find("--resample = 1e-12 s would make 4.9e+11 samples"),
            std::string::npos);
  o.dt = 0;
  const fl::UniformResampler r(t, o);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(50);
  x(7) = std::nan("");
  EXPECT_NE(error_of([&] { r.apply(x, "q1"); }).find("sample 8, column 'q1'"), std::string::npos);
  EXPECT_NE(error_of([&] { r.apply(Eigen::VectorXd::Ones(3), "q1"); }).find("column 'q1' has 3 samples; expected 50"),
            std::string::npos);
  Eigen::VectorXd back = t;
  back(20) = 0.0;
  EXPECT_NE(error_of([&] { fl::UniformResampler q(back); }).find("sample 21: time 0 s is before the previous"),
            std::string::npos);
}

// time_steps selects the median among a bracket of the steps (signal/sampling.cpp); it must give
// exactly the value std::nth_element gives, on clocks that repeat a few step values, on steps
// all distinct, on a record with gaps, and on steps of any sign (the bracket misses and it falls
// back). Lengths straddle the 4096 steps below which it selects over all of them at once.
TEST(TimeSteps, MedianIsExactlyTheUpperMedianOfTheSteps) {
  const auto reference = [](const Eigen::VectorXd& t) {
    std::vector<double> d(static_cast<std::size_t>(t.size() - 1));
    for (std::size_t k = 0; k < d.size(); ++k) d[k] = t(static_cast<Eigen::Index>(k) + 1) - t(static_cast<Eigen::Index>(k));
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());  // the upper median
    return d[d.size() / 2];
  };
  std::mt19937 rng(11);
  for (const Eigen::Index n : {Eigen::Index{4000}, Eigen::Index{4098}, Eigen::Index{24841}, Eigen::Index{100001}}) {
    Eigen::VectorXd stamped(n);  // a 1 kHz clock stored as k * dt: a few distinct rounded steps
    for (Eigen::Index k = 0; k < n; ++k) stamped(k) = static_cast<double>(k) * 1e-3 + 1e4;
    const Eigen::VectorXd uniform = jittered(n, 0.9e-3, 1.1e-3, static_cast<unsigned>(n));
    Eigen::VectorXd gaps = clock(n, 1e-3);
    for (Eigen::Index k = n / 3; k < n; ++k) gaps(k) += 0.5;  // one long gap
    Eigen::VectorXd signs(n);  // not a time column at all: steps of both signs
    std::normal_distribution<double> g(0.0, 1.0);
    for (Eigen::Index k = 0; k < n; ++k) signs(k) = g(rng);
    Eigen::VectorXd halves = clock(n, 1e-3);  // two step values, half of each: the bracket's edge
    for (Eigen::Index k = 1; k < n; ++k) halves(k) = halves(k - 1) + (k % 2 ? 1e-3 : 2e-3);
    for (const auto& [name, t] : {std::pair<const char*, const Eigen::VectorXd*>{"stamped", &stamped}, {"uniform", &uniform},
                                  {"gaps", &gaps}, {"signs", &signs}, {"halves", &halves}}) {
      EXPECT_EQ(fl::time_steps(*t).median, reference(*t)) << name << ", " << n << " samples";
    }
  }
}
