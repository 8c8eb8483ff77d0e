// Fleet drift: log dates from file names and POSIX stamps, and the drift table's rule (a change
// between consecutive logs beyond its combined std is flagged).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../error_message.hpp"
#include "frictionlab/analysis/drift.hpp"

namespace fl = frictionlab;
using fl::testing::error_of;

namespace {
std::string date_of(const std::string& name) {
  const auto d = fl::log_date_from_name(name);
  return d ? d->iso : "<none>";
}
}  // namespace

TEST(LogDate, AcceptedFileNameForms) {
  EXPECT_EQ(date_of("axis3_2026-11-02.csv"), "2026-11-02");
  EXPECT_EQ(date_of("/data/2025-01-01/axis3_2026_11_02.mat"), "2026-11-02");  // folders are not read
  EXPECT_EQ(date_of("axis3-20261102.csv"), "2026-11-02");
  EXPECT_EQ(date_of("log-20261102T0815.mat"), "2026-11-02T08:15:00");
  EXPECT_EQ(date_of("axis3_2026-11-02_08-15-30.csv"), "2026-11-02T08:15:30");
  EXPECT_EQ(date_of("axis3_2026-11-02T08:15.csv"), "2026-11-02T08:15:00");
  EXPECT_EQ(date_of("a_20261102_081530.csv"), "2026-11-02T08:15:30");
  EXPECT_EQ(date_of("2026-11-01_to_2026-11-02.csv"), "2026-11-02");  // the last date
}

TEST(LogDate, NamesWithoutADate) {
  EXPECT_EQ(date_of("axis3.csv"), "<none>");
  EXPECT_EQ(date_of("axis3_2026-13-02.csv"), "<none>");      // month 13
  EXPECT_EQ(date_of("axis3_2026-11-31.csv"), "<none>");      // November has 30 days
  EXPECT_EQ(date_of("run120261102.csv"), "<none>");          // nine digits: not a date
  EXPECT_EQ(date_of("axis3_2026-11-02_25-00.csv"), "2026-11-02");  // hour 25 is no time: the day stays
  EXPECT_EQ(date_of("axis3_2026-1102.csv"), "<none>");       // mixed separators
}

TEST(LogDate, PosixSecondsRoundTrip) {
  const auto named = fl::log_date_from_name("a_2026-11-02_08-15-30.csv");
  ASSERT_TRUE(named);
  const fl::LogDate d = fl::log_date_from_posix(named->posix_seconds);
  EXPECT_EQ(d.iso, "2026-11-02T08:15:30");
  EXPECT_EQ(fl::log_date_from_posix(0.0).iso, "1970-01-01T00:00:00");
  EXPECT_EQ(error_of([] { fl::log_date_from_posix(-1.0); }),
            "log date: POSIX time -1.000000 s: expected seconds since 1970-01-01 UTC, from 1970 to 2999");
}

TEST(Drift, ConsecutiveChangesAgainstCombinedStd) {
  auto at = [](const std::string& name) { return *fl::log_date_from_name(name); };
  // Given out of date order: the table sorts each parameter by date.
  const std::vector<fl::DriftSample> s = {
      {"c_2026-11-03.csv", at("c_2026-11-03.csv"), "Fc", 1.30, 0.03, "N"},
      {"a_2026-11-01.csv", at("a_2026-11-01.csv"), "Fc", 1.00, 0.03, "N"},
      {"b_2026-11-02.csv", at("b_2026-11-02.csv"), "Fc", 1.02, 0.03, "N"},
      {"a_2026-11-01.csv", at("a_2026-11-01.csv"), "Fv", 0.10, std::nan(""), "N s/m"},
      {"b_2026-11-02.csv", at("b_2026-11-02.csv"), "Fv", 0.50, 0.01, "N s/m"},
  };
  const auto rows = fl::drift_table(s);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].sample.file, "a_2026-11-01.csv");
  EXPECT_TRUE(std::isnan(rows[0].change));
  EXPECT_FALSE(rows[0].flagged);
  // 0.02 N against sqrt(2) 0.03 = 0.042 N: within; 0.28 N: beyond.
  constexpr double kRelTol = 1e-12;  // a subtraction and a hypot of exact inputs
  EXPECT_NEAR(rows[1].change, 0.02, kRelTol);
  EXPECT_NEAR(rows[1].combined_std, std::sqrt(2.0) * 0.03, kRelTol);
  EXPECT_FALSE(rows[1].flagged);
  EXPECT_EQ(rows[2].sample.file, "c_2026-11-03.csv");
  EXPECT_TRUE(rows[2].flagged);
  // Unknown std: nothing to judge by, never flagged however large the change.
  EXPECT_EQ(rows[4].sample.parameter, "Fv");
  EXPECT_TRUE(std::isnan(rows[4].combined_std));
  EXPECT_FALSE(rows[4].flagged);
  // A larger threshold clears the 0.28 N change (6.6 combined std) at 7.
  EXPECT_FALSE(fl::drift_table(s, 7.0)[2].flagged);
  EXPECT_TRUE(fl::drift_table(s, 6.0)[2].flagged);
}

TEST(Drift, BadInputNamed) {
  EXPECT_EQ(error_of([] { fl::drift_table({}, 0.0); }),
            "drift: threshold = 0.000000: expected a finite number > 0 (a multiple of the combined std)");
  const std::vector<fl::DriftSample> s = {{"x.csv", {}, "Fc", std::nan(""), 0.1, "N"}};
  EXPECT_EQ(error_of([&] { fl::drift_table(s); }), "drift: x.csv: parameter Fc = nan N: expected a finite value");
}
