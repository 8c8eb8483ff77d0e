// simulate_batch: results in order, identical to a single-threaded run and to simulate() itself,
// failures captured per run.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <vector>

#include "frictionlab/cancellation.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/simulate/batch.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace fl = frictionlab;

namespace {

// A short Canudas stick-slip run (3 s, the first slip) with the spring stiffness and drive
// velocity of grid point i: cheap, and each run differs.
std::vector<fl::Scenario> grid(int n) {
  fl::Scenario base = fl::load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/canudas_stick_slip.yaml");
  base.options.duration = 3.0;
  base.options.output_rate = 100.0;
  std::vector<fl::Scenario> out;
  for (int i = 0; i < n; ++i) {
    fl::Scenario s = base;
    fl::SpringBaseParams p;
    p.m = 1.0;
    p.k = 1.0 + 0.5 * i;
    p.V0 = 0.05 + 0.02 * i;
    s.plant = std::make_shared<fl::SpringBase>(p);
    out.push_back(s);
  }
  return out;
}

// Same code, same inputs, one CVODE context per run: bit-identical results are expected.
void expect_same(const fl::Trajectory& a, const fl::Trajectory& b) {
  ASSERT_EQ(a.rows(), b.rows());
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.friction, b.friction);
  EXPECT_EQ(a.stats.steps, b.stats.steps);
}

}  // namespace

TEST(Batch, MultiThreadedEqualsSingleThreadedAndSimulate) {
  const auto scenarios = grid(6);
  fl::BatchOptions one;
  one.threads = 1;
  fl::BatchOptions many;
  many.threads = 3;  // more threads than cores is allowed and still deterministic
  const auto r1 = fl::simulate_batch(scenarios, one);
  const auto r3 = fl::simulate_batch(scenarios, many);
  ASSERT_EQ(r1.size(), scenarios.size());
  ASSERT_EQ(r3.size(), scenarios.size());
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    ASSERT_TRUE(r1[i].ok()) << r1[i].message;
    ASSERT_TRUE(r3[i].ok()) << r3[i].message;
    expect_same(r1[i].trajectory, r3[i].trajectory);
    expect_same(r1[i].trajectory, fl::simulate(scenarios[i]));
  }
  // In order: the runs differ (stiffer springs slip earlier), so a permutation would show.
  EXPECT_NE(r3[0].trajectory.velocity, r3[1].trajectory.velocity);
}

TEST(Batch, FailureIsCapturedPerRun) {
  auto scenarios = grid(4);
  scenarios[1].plant = nullptr;            // simulate() throws invalid_argument
  scenarios[2].options.duration = -1.0;    // bad option
  fl::BatchOptions o;
  o.threads = 2;
  std::atomic<int> calls{0};
  o.progress = [&](std::size_t, std::size_t) { ++calls; };
  const auto r = fl::simulate_batch(scenarios, o);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_TRUE(r[0].ok());
  EXPECT_TRUE(r[3].ok());
  EXPECT_FALSE(r[1].ok());
  EXPECT_FALSE(r[2].ok());
  EXPECT_FALSE(r[1].message.empty());
  EXPECT_NE(r[2].message.find("duration"), std::string::npos) << r[2].message;
  EXPECT_THROW(std::rethrow_exception(r[1].error), std::invalid_argument);
  EXPECT_EQ(r[1].trajectory.rows(), 0u);
  EXPECT_EQ(calls.load(), 4);
}

TEST(Batch, ThreadCount) {
  EXPECT_EQ(fl::batch_threads(4, 2), 2);   // never more threads than runs
  EXPECT_EQ(fl::batch_threads(1, 100), 1);
  EXPECT_GE(fl::batch_threads(0, 100), 1);  // hardware concurrency
  EXPECT_EQ(fl::batch_threads(3, 0), 1);
  EXPECT_THROW(fl::batch_threads(-1, 10), std::invalid_argument);
  EXPECT_TRUE(fl::simulate_batch({}).empty());
}

// Cancellation (frictionlab/cancellation.hpp): a set token stops simulate before its first solver
// step, and a batch before its remaining runs, on every worker; a cancelled batch throws rather
// than returning runs marked failed.
TEST(Batch, ACancelledTokenStopsSimulate) {
  const auto scenarios = grid(1);
  fl::CancelToken token;
  token.cancel();
  const fl::CancelScope scope(&token);
  EXPECT_THROW(fl::simulate(scenarios[0]), fl::Cancelled);
}

TEST(Batch, CancellingStopsTheRemainingRunsOnEveryWorker) {
  constexpr int kRuns = 40;
  const auto scenarios = grid(kRuns);
  fl::CancelToken token;
  std::atomic<int> finished{0};
  fl::BatchOptions o;
  o.threads = 2;
  o.progress = [&](std::size_t, std::size_t) {
    if (++finished == 2) token.cancel();  // from a worker thread, as a host's Stop button would
  };
  const fl::CancelScope scope(&token);
  EXPECT_THROW(fl::simulate_batch(scenarios, o), fl::Cancelled);
  // Each worker finishes the run it is in (at most one per thread after the cancel), no more.
  EXPECT_LE(finished.load(), 2 + o.threads);
  // The same batch without a cancel runs all of them (the bound above is not the batch's size).
  fl::CancelToken unused;
  const fl::CancelScope fresh(&unused);
  finished = 0;
  o.progress = [&](std::size_t, std::size_t) { ++finished; };
  EXPECT_NO_THROW(fl::simulate_batch(scenarios, o));
  EXPECT_EQ(finished.load(), kRuns);
}
