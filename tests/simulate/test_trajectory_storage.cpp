// A Trajectory is a plain value: its columns are its own, a run leaves nothing behind on its
// thread, and runs on any thread, repeated or not, give the same numbers.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

Scenario example(const std::string& name) {
  return load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name + ".yaml");
}

void expect_same_run(const Trajectory& a, const Trajectory& b, const std::string& what) {
  for (const auto& name : Trajectory::column_names()) EXPECT_EQ(a.column(name), b.column(name)) << what << ": " << name;
  EXPECT_EQ(a.law_state, b.law_state) << what;
  EXPECT_EQ(a.switches.size(), b.switches.size()) << what;
  EXPECT_EQ(a.stats.steps, b.stats.steps) << what;
}

}  // namespace

// The same scenario run again, after the first run's trajectory is gone, on this thread and on a
// new one: the same numbers to the bit (no state of a run survives it).
TEST(TrajectoryStorage, RepeatedRunsOnAnyThreadGiveTheSameNumbers) {
  const Scenario s = example("canudas_stick_slip");  // 30 001 rows, a dynamic law's state column
  const Trajectory first = simulate(s);
  ASSERT_GT(first.rows(), 30000u);
  { const Trajectory dropped = simulate(s); }
  expect_same_run(simulate(s), first, "again on this thread");
  std::thread([&] { expect_same_run(simulate(s), first, "on a new thread"); }).join();
}

// Each column holds exactly its rows' worth of values, reserved once by the engine: no column
// shares storage with another, and none was grown beyond what the run needed.
TEST(TrajectoryStorage, ColumnsAreTheRunsOwnAndSizedToIt) {
  const Trajectory t = simulate(example("canudas_stick_slip"));
  std::vector<const double*> seen;
  for (const auto& name : Trajectory::column_names()) {
    const auto& c = t.column(name);
    EXPECT_EQ(c.size(), t.rows()) << name;
    EXPECT_EQ(c.capacity(), t.rows()) << name << ": reserved for the rows the run records";
    for (const double* p : seen) EXPECT_NE(p, c.data()) << name;
    seen.push_back(c.data());
  }
}

// `t = simulate(s)` in a loop: the assignment takes every part of the result.
TEST(TrajectoryStorage, MoveAssignmentTakesEverything) {
  Scenario s = example("craig_motor_trapezoid");  // hybrid: switches and stats to carry over
  Trajectory t = simulate(s);
  Trajectory fresh = simulate(s);
  const Trajectory expected = fresh;  // a copy to compare with
  t = std::move(fresh);
  expect_same_run(t, expected, "moved");
  EXPECT_GT(t.switches.size(), 0u);
  EXPECT_STREQ(t.stats.solver, "hybrid");
}
