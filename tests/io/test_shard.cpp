// io/shard.hpp: shard specs, job selection, part files, merge checks, table writers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "error_message.hpp"
#include "frictionlab/io/shard.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using ::testing::HasSubstr;

Part whole_run(std::size_t total) {
  Part p;
  p.command = "analyze map";
  p.key = std::string(64, 'a');
  p.total = total;
  p.envelope = R"({"schema":1,"status":"ok","result":{"grid":["k=1:2:3"],"rows":[]}})";
  p.rows_at = "/result/rows";
  p.table.columns = {"k", "class", "amplitude"};
  for (std::size_t i = 0; i < total; ++i) {
    p.table.index.push_back(i);
    p.table.rows.push_back({1.0 + 0.1 * static_cast<double>(i), std::string(i % 2 ? "stick-slip" : "steady-sliding"),
                            i == 2 ? std::nan("") : 1.0 / 3.0 * static_cast<double>(i)});
  }
  return p;
}

Part shard_of(const Part& whole, ShardSpec s) {
  Part p = whole;
  p.shard = s;
  p.table.index.clear();
  p.table.rows.clear();
  for (std::size_t i : shard_jobs(whole.total, s)) {
    p.table.index.push_back(i);
    p.table.rows.push_back(whole.table.rows[i]);
  }
  return p;
}

TEST(Shard, ParsesAndRefuses) {
  const ShardSpec s = parse_shard("2/8");
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(s.text(), "2/8");
  EXPECT_EQ(error_of([] { parse_shard("3"); }), "--shard '3': expected K/N (shard K of N, e.g. 2/8)");
  EXPECT_EQ(error_of([] { parse_shard("0/4"); }), "--shard '0/4': K must be a positive integer (shard K of N, 1-based)");
  EXPECT_EQ(error_of([] { parse_shard("5/4"); }), "--shard '5/4': K = 5 must be <= N = 4");
  EXPECT_EQ(error_of([] { parse_shard("1/x"); }), "--shard '1/x': N must be a positive integer");
  EXPECT_EQ(error_of([] { parse_shard("-1/4"); }), "--shard '-1/4': K must be a positive integer (shard K of N, 1-based)");
}

TEST(Shard, RoundRobinCoversEveryJobOnce) {
  constexpr std::size_t kTotal = 23;
  std::vector<int> seen(kTotal, 0);
  for (std::size_t k = 1; k <= 4; ++k)
    for (std::size_t i : shard_jobs(kTotal, {k, 4})) {
      EXPECT_TRUE(in_shard(i, {k, 4}));
      ++seen[i];
    }
  for (int n : seen) EXPECT_EQ(n, 1);
  EXPECT_EQ(shard_jobs(10, {3, 4}), (std::vector<std::size_t>{2, 6}));
  EXPECT_TRUE(shard_jobs(2, {4, 4}).empty());  // more shards than jobs: an empty part, still valid
}

TEST(Shard, PartFileRoundTripsExactly) {
  const Part whole = whole_run(7);
  const Part p = shard_of(whole, {2, 3});
  const auto path = std::filesystem::temp_directory_path() / "frictionlab_test_part.json";
  {
    std::ofstream(path) << part_to_json(p);
  }
  const Part back = read_part(path.string());
  EXPECT_EQ(back.key, p.key);
  EXPECT_EQ(back.shard.text(), "2/3");
  EXPECT_EQ(back.table.index, p.table.index);
  ASSERT_EQ(back.table.rows.size(), p.table.rows.size());
  for (std::size_t r = 0; r < p.table.rows.size(); ++r)
    for (std::size_t c = 0; c < p.table.columns.size(); ++c) {
      const Cell &a = p.table.rows[r][c], &b = back.table.rows[r][c];
      ASSERT_EQ(a.index(), b.index());
      if (const double* x = std::get_if<double>(&a)) {
        const double y = std::get<double>(b);
        if (std::isnan(*x))
          EXPECT_TRUE(std::isnan(y));
        else
          EXPECT_EQ(*x, y);  // exact: the JSON holds the shortest form that reads back exactly
      }
    }
  std::filesystem::remove(path);
}

TEST(Shard, MergeEqualsTheWholeRun) {
  const Part whole = whole_run(11);
  // Parts in any order.
  const Part merged = merge_parts({shard_of(whole, {3, 3}), shard_of(whole, {1, 3}), shard_of(whole, {2, 3})},
                                  {"c.json", "a.json", "b.json"});
  EXPECT_EQ(table_csv(merged.table), table_csv(whole.table));
  EXPECT_EQ(table_json(merged), table_json(whole));
}

TEST(Shard, MergeNamesTheMissingDuplicatedOrForeignPart) {
  const Part whole = whole_run(9);
  const Part a = shard_of(whole, {1, 3}), b = shard_of(whole, {2, 3}), c = shard_of(whole, {3, 3});
  EXPECT_EQ(error_of([&] { merge_parts({a, c}, {"a.json", "c.json"}); }),
            "merge: missing part: shard 2/3 was not given");
  EXPECT_EQ(error_of([&] { merge_parts({a, b, b, c}, {"a.json", "b.json", "b2.json", "c.json"}); }),
            "b2.json: duplicated part: shard 2/3 is also b.json");
  Part other = c;
  other.key = std::string(64, 'b');
  EXPECT_THAT(error_of([&] { merge_parts({a, b, other}, {"a.json", "b.json", "x.json"}); }),
              HasSubstr("x.json: foreign part: its key differs from a.json's"));
  Part cols = c;
  cols.table.columns[2] = "period";
  EXPECT_THAT(error_of([&] { merge_parts({a, b, cols}, {"a.json", "b.json", "y.json"}); }),
              HasSubstr("y.json: foreign part: its columns differ"));
  Part four = shard_of(whole, {3, 4});
  EXPECT_THAT(error_of([&] { merge_parts({a, b, four}, {"a.json", "b.json", "z.json"}); }),
              HasSubstr("z.json: foreign part: its shard count (3/4 against 1/3)"));
  Part cut = c;
  cut.table.rows.pop_back();
  cut.table.index.pop_back();
  EXPECT_THAT(error_of([&] { merge_parts({a, b, cut}, {"a.json", "b.json", "cut.json"}); }),
              HasSubstr("cut.json: shard 3/3 holds 2 rows, not its 3 jobs"));
}

TEST(Shard, ReadPartRefusesOtherFiles) {
  const auto path = std::filesystem::temp_directory_path() / "frictionlab_test_not_part.json";
  {
    std::ofstream(path) << R"({"schema": 1, "status": "ok"})";
  }
  EXPECT_THAT(error_of([&] { read_part(path.string()); }), HasSubstr("not a frictionlab part file (no \"frictionlab_part\""));
  {
    std::ofstream(path) << "time,x\n0,1\n";
  }
  EXPECT_THAT(error_of([&] { read_part(path.string()); }), HasSubstr("not a part file (not JSON"));
  std::filesystem::remove(path);
  EXPECT_THAT(error_of([&] { read_part(path.string()); }), HasSubstr("cannot open the part file"));
}

TEST(Shard, CsvQuotesTextsAndLeavesNonFiniteEmpty) {
  RowTable t;
  t.columns = {"a", "note"};
  t.index = {0, 1};
  t.rows = {{0.1, std::string("plain")}, {std::nan(""), std::string("with, comma \"q\"")}};
  EXPECT_EQ(table_csv(t), "a,note\n0.1,plain\n,\"with, comma \"\"q\"\"\"\n");
}

TEST(Shard, JsonPutsRowsAtThePointerInColumnOrder) {
  Part p = whole_run(1);
  const std::string j = table_json(p, -1);
  EXPECT_THAT(j, HasSubstr(R"("rows":[{"k":1.0,"class":"steady-sliding","amplitude":0.0}])"));
  p.rows_at = "/nowhere/rows";
  EXPECT_THAT(error_of([&] { table_json(p); }), HasSubstr("rows_at '/nowhere/rows' is not a place in the envelope"));
  p.rows_at = "no pointer";
  EXPECT_THAT(error_of([&] { table_json(p); }), HasSubstr("rows_at 'no pointer' is not a place"));
}

}  // namespace
}  // namespace frictionlab
