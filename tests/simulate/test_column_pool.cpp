// Recycling of Trajectory column storage between runs on a thread (src/simulate/column_pool.hpp).
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <thread>
#include <vector>

#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "simulate/column_pool.hpp"

using namespace frictionlab;

namespace {

Scenario example(const std::string& name) {
  return load_scenario(std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name + ".yaml");
}

std::set<const double*> column_data(const Trajectory& t) {
  std::set<const double*> out;
  for (const auto& name : Trajectory::column_names()) out.insert(t.column(name).data());
  for (const auto& c : t.law_state) out.insert(c.data());
  return out;
}

}  // namespace

// The point of the pool: a second run reuses the first run's storage (no new pages to map), and
// gives the same numbers.
TEST(ColumnPool, TheNextRunOnTheThreadReusesAFinishedRunsColumns) {
  const Scenario s = example("canudas_stick_slip");  // 30 001 rows: well above the pool's minimum
  std::set<const double*> first_storage;
  std::vector<double> first_velocity;
  {
    const Trajectory first = simulate(s);
    first_storage = column_data(first);
    first_velocity = first.velocity;
  }
  const std::size_t pooled = detail::pooled_doubles();
  EXPECT_GE(pooled, 10u * 30001u) << "nine columns and the bristle state went back to the pool";
  const Trajectory second = simulate(s);
  EXPECT_TRUE(first_storage.count(second.velocity.data())) << "the velocity column was newly allocated";
  EXPECT_TRUE(first_storage.count(second.time.data()));
  EXPECT_LT(detail::pooled_doubles(), pooled);
  EXPECT_EQ(second.velocity, first_velocity);
}

TEST(ColumnPool, TakeGivesAnEmptyColumnWithRoomAndSkipsMuchLargerOnes) {
  detail::recycle_column(std::vector<double>(1 << 20));  // 1 Mi doubles
  const std::vector<double> small = detail::take_column(10000);
  EXPECT_TRUE(small.empty());
  EXPECT_GE(small.capacity(), 10000u);
  EXPECT_LT(small.capacity(), std::size_t(1) << 20) << "a column over 4x the rows asked for stays for a longer run";
  const std::vector<double> big = detail::take_column(600000);
  EXPECT_TRUE(big.empty());
  EXPECT_EQ(big.capacity(), std::size_t(1) << 20);
}

TEST(ColumnPool, SmallColumnsAreNotKept) {
  const std::size_t before = detail::pooled_doubles();
  detail::recycle_column(std::vector<double>(detail::kColumnPoolMinDoubles - 1));
  EXPECT_EQ(detail::pooled_doubles(), before);
}

TEST(ColumnPool, KeepsAtMostItsLimitAndDropsTheSmallestFirst) {
  std::thread([] {  // a fresh thread: a pool of its own
    const std::size_t column = detail::kColumnPoolKeepDoubles / 8;
    for (int i = 0; i < 20; ++i) detail::recycle_column(std::vector<double>(column + static_cast<std::size_t>(i)));
    EXPECT_LE(detail::pooled_doubles(), detail::kColumnPoolKeepDoubles);
    EXPECT_GE(detail::pooled_doubles(), detail::kColumnPoolKeepDoubles - column - 20);
    // The largest (the last recycled) is still there.
    EXPECT_EQ(detail::take_column(column + 19).capacity(), column + 19);
  }).join();
}

// A Trajectory can be destroyed by another thread_local's destructor after the pool's own: that
// must free the column, not touch the destroyed pool (ASan reports it otherwise).
TEST(ColumnPool, RecyclingAfterThePoolIsGoneAtThreadExitJustFrees) {
  struct Holder {
    std::vector<double> column;
    ~Holder() { detail::recycle_column(std::move(column)); }
  };
  std::thread([] {
    thread_local Holder holder;  // constructed before the pool, so destroyed after it
    holder.column.resize(detail::kColumnPoolMinDoubles * 2);
    detail::recycle_column(std::vector<double>(detail::kColumnPoolMinDoubles * 2));  // creates the pool
    EXPECT_GT(detail::pooled_doubles(), 0u);
  }).join();
}

// `t = simulate(s)` in a loop: the assigned-over columns are recycled as well, and the assignment
// takes every part of the result.
TEST(ColumnPool, MoveAssignmentTakesEverythingAndRecyclesTheOldColumns) {
  Scenario s = example("craig_motor_trapezoid");  // hybrid: switches and stats to carry over
  Trajectory t = simulate(s);
  std::size_t old_capacity = 0;
  for (const auto& name : Trajectory::column_names()) old_capacity += t.column(name).capacity();
  Trajectory fresh = simulate(s);
  const Trajectory expected = fresh;  // a copy to compare with
  const std::size_t pooled_before = detail::pooled_doubles();
  t = std::move(fresh);
  EXPECT_EQ(detail::pooled_doubles() - pooled_before, old_capacity) << "all nine assigned-over columns go to the pool";
  EXPECT_EQ(t.time, expected.time);
  EXPECT_EQ(t.velocity, expected.velocity);
  EXPECT_EQ(t.stuck, expected.stuck);
  EXPECT_EQ(t.reference, expected.reference);
  ASSERT_EQ(t.switches.size(), expected.switches.size());
  EXPECT_GT(t.switches.size(), 0u);
  EXPECT_EQ(t.stats.steps, expected.stats.steps);
  EXPECT_STREQ(t.stats.solver, "hybrid");
}
