// fleet/shard.hpp: shard specs, job selection, part files, merge checks, table writers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "error_message.hpp"
#include "fleet/shard.hpp"

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

// A table whose middle columns come from the rows (parameters that depend on the data): job i
// brings the columns named in `brings[i]`; cells are the job index as an integer, a flag, a text.
// Appends job i's row: the fixed cells, NaN in the grown columns, then the columns it brings.
void push_grown_row(RowTable& t, std::size_t i, const std::vector<std::string>& brings) {
  t.index.push_back(i);
  t.rows.emplace_back(t.columns.size(), Cell{std::nan("")});
  auto& row = t.rows.back();
  row[0] = static_cast<std::int64_t>(i);
  row[1] = std::string(brings.empty() ? "error" : "ok");
  row[row.size() - 2] = static_cast<std::int64_t>(10 * i);
  row[row.size() - 1] = !brings.empty();
  for (const std::string& name : brings) t.rows.back()[grow_column(t, name, i)] = 0.5 + static_cast<double>(i);
}

Part grown_run(const std::vector<std::vector<std::string>>& brings) {
  Part p;
  p.command = "identify";
  p.key = std::string(64, 'c');
  p.total = brings.size();
  p.envelope = R"({"schema":1,"kind":"identify","columns":[],"rows":[]})";
  p.rows_at = "/rows";
  p.columns_at = "/columns";
  p.table.columns = {"index", "status", "samples", "ok"};
  p.table.grown = GrownColumns{2, 2, {}};
  for (std::size_t i = 0; i < brings.size(); ++i) push_grown_row(p.table, i, brings[i]);
  return p;
}

TEST(Shard, GrownColumnsFollowFirstAppearanceAndFillNaN) {
  const Part p = grown_run({{}, {"Fc", "Fv"}, {"Fs", "Fc"}});
  EXPECT_EQ(p.table.columns, (std::vector<std::string>{"index", "status", "Fc", "Fv", "Fs", "samples", "ok"}));
  EXPECT_EQ(p.table.grown->first, (std::vector<std::size_t>{1, 1, 2}));
  EXPECT_EQ(table_csv(p.table), "index,status,Fc,Fv,Fs,samples,ok\n0,error,,,,0,false\n1,ok,1.5,1.5,,10,true\n"
                                "2,ok,2.5,,2.5,20,true\n");
  EXPECT_EQ(table_json(p, -1),
            R"({"schema":1,"kind":"identify","columns":["index","status","Fc","Fv","Fs","samples","ok"],"rows":[)"
            R"({"index":0,"status":"error","Fc":null,"Fv":null,"Fs":null,"samples":0,"ok":false},)"
            R"({"index":1,"status":"ok","Fc":1.5,"Fv":1.5,"Fs":null,"samples":10,"ok":true},)"
            R"({"index":2,"status":"ok","Fc":2.5,"Fv":null,"Fs":2.5,"samples":20,"ok":true}]})"
            "\n");
}

// Shards that see different columns (one with none: every job failed) merge to the whole run's.
TEST(Shard, MergeJoinsGrownColumnsInTheWholeRunsOrder) {
  const std::vector<std::vector<std::string>> brings = {{}, {}, {"b"}, {"a", "b"}, {}, {"c"}, {"a"}, {}};
  const Part whole = grown_run(brings);
  for (std::size_t n : {2u, 3u, 4u, 9u}) {
    std::vector<Part> parts;
    std::vector<std::string> names;
    for (std::size_t k = n; k >= 1; --k) {  // in reverse order
      Part p = grown_run({});
      p.total = brings.size();
      p.shard = {k, n};
      // A shard grows its columns from its own rows only.
      for (std::size_t i : shard_jobs(brings.size(), p.shard)) push_grown_row(p.table, i, brings[i]);
      parts.push_back(p);
      names.push_back("part" + std::to_string(k) + ".json");
    }
    const Part merged = merge_parts(parts, names);
    EXPECT_EQ(merged.table.columns, whole.table.columns) << n << " shards";
    EXPECT_EQ(table_csv(merged.table), table_csv(whole.table)) << n << " shards";
    EXPECT_EQ(table_json(merged), table_json(whole)) << n << " shards";
    // Through the part files too: integers, flags and the grown columns read back.
    const auto path = std::filesystem::temp_directory_path() / "frictionlab_test_grown_part.json";
    std::vector<Part> back;
    for (const Part& p : parts) {
      std::ofstream(path) << part_to_json(p);
      back.push_back(read_part(path.string()));
    }
    std::filesystem::remove(path);
    EXPECT_EQ(table_json(merge_parts(back, names)), table_json(whole)) << n << " shards, read back";
  }
  // The fixed columns must agree.
  Part a = grown_run({{"a"}, {}}), b = a;
  a.shard = {1, 2};
  b.shard = {2, 2};
  a.table.index = {0};
  a.table.rows.pop_back();
  b.table.index = {1};
  b.table.rows.erase(b.table.rows.begin());
  b.table.columns.back() = "flag";
  EXPECT_THAT(error_of([&] { merge_parts({a, b}, {"a.json", "b.json"}); }), HasSubstr("b.json: foreign part: its columns differ"));
}

TEST(Shard, ReadPartRefusesABadGrownField) {
  Part p = grown_run({{"a"}});
  std::string text = part_to_json(p);
  const std::string good = R"("grown":{"begin":2,"end":3,"first":[0]})";
  ASSERT_NE(text.find(good), std::string::npos) << text;
  text.replace(text.find(good), good.size(), R"("grown":{"begin":2,"end":9,"first":[0]})");
  const auto path = std::filesystem::temp_directory_path() / "frictionlab_test_bad_grown.json";
  std::ofstream(path) << text;
  EXPECT_THAT(error_of([&] { read_part(path.string()); }), HasSubstr("(field \"grown\" missing or malformed)"));
  std::filesystem::remove(path);
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
