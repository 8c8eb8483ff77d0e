// identify_auto (identify/auto.hpp) on a record with constant-speed plateaus: the sweep
// candidates join the trajectory ones, every candidate has a held-out error, the answer is a
// physical law near the truth. (The servo logs of tests/rigs are the command line's test,
// tests/cli/identify_auto.sh.)

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <stdexcept>

#include "frictionlab/identify/auto.hpp"

namespace frictionlab {
namespace {

constexpr double kM = 2.0, kFc = 3.0, kFs = 4.5, kVs = 0.01, kFv = 20.0;

double friction(double v) {
  if (v == 0.0) return 0.0;
  return std::copysign(kFc + (kFs - kFc) * std::exp(-(v / kVs) * (v / kVs)), v) + kFv * v;
}

// Plateaus at +-5, 10, 20, 50, 100 mm/s, 2 s each, joined by 0.3 s cosine speed changes; 1 kHz;
// force = M a + friction(v) + seeded noise of 0.02 N.
IdimData plateau_record(unsigned seed) {
  constexpr double kDt = 1e-3, kHold = 2.0, kChange = 0.3;
  const std::vector<double> speeds = {0.005, -0.005, 0.01, -0.01, 0.02, -0.02, 0.05, -0.05, 0.1, -0.1};
  std::vector<double> v, a;
  double prev = 0.0;
  for (double s : speeds) {
    for (int k = 0; k < static_cast<int>(kChange / kDt); ++k) {
      const double f = k * kDt / kChange;
      v.push_back(prev + (s - prev) * (1 - std::cos(std::numbers::pi * f)) / 2);
      a.push_back((s - prev) * std::numbers::pi / (2 * kChange) * std::sin(std::numbers::pi * f));
    }
    for (int k = 0; k < static_cast<int>(kHold / kDt); ++k) v.push_back(s), a.push_back(0.0);
    prev = s;
  }
  std::mt19937 gen(seed);
  std::normal_distribution<double> noise(0.0, 0.02);
  IdimData d;
  const auto n = static_cast<Eigen::Index>(v.size());
  d.time.resize(n), d.position.resize(n), d.force.resize(n);
  double q = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    d.time(i) = static_cast<double>(i) * kDt;
    d.position(i) = q;
    q += v[static_cast<std::size_t>(i)] * kDt;
    d.force(i) = kM * a[static_cast<std::size_t>(i)] + friction(v[static_cast<std::size_t>(i)]) + noise(gen);
  }
  d.file = "plateaus";
  return d;
}

TEST(Auto, PlateausBringTheSweepCandidatesAndTheAnswerIsPhysical) {
  // 5 %: the brief's bound on Fc and Fv for the servo logs; the record here is cleaner.
  constexpr double kRel = 0.05;
  const Result r = identify_auto(plateau_record(7));
  ASSERT_TRUE(r.ok()) << r.message;
  const auto sel = nlohmann::json::parse(r.json_sections.at("diagnostics.selection"));
  ASSERT_EQ(sel.size(), 5u) << sel.dump();  // three idim structures, two sweep laws
  int chosen = 0;
  for (const auto& c : sel) {
    chosen += c["status"] == "chosen";
    if (c["status"] != "refused") EXPECT_TRUE(c["heldout_error_percent"].is_number()) << c.dump();
    else EXPECT_FALSE(c["reason"].get<std::string>().empty()) << c.dump();
  }
  EXPECT_EQ(chosen, 1);
  EXPECT_NE(r.diagnostics.texts.at("experiment").find("constant-speed plateaus"), std::string::npos);
  EXPECT_NEAR(r.value(r.find("Fc") ? "Fc" : "Fc_pos"), kFc, kRel * kFc);
  EXPECT_NEAR(r.value(r.find("Fv") ? "Fv" : "Fv_pos"), kFv, kRel * kFv);
  ASSERT_TRUE(r.law.has_value());
  EXPECT_EQ(r.diagnostics.lists.at("selection").size(), sel.size());
}

// The candidates' results are idim's own (identify_idim on the samples in motion, vs searched as
// by --vs search), so the std auto reports is the Newey-West std that idim reports for the same
// options, not an ordinary least-squares figure of a fit of its own.
TEST(Auto, ChosenStdIsIdimsStdForTheSameOptions) {
  const IdimData d = plateau_record(7);
  const Result r = identify_auto(d);
  ASSERT_TRUE(r.ok()) << r.message;
  const auto sel = nlohmann::json::parse(r.json_sections.at("diagnostics.selection"));
  std::string chosen;
  for (const auto& c : sel)
    if (c["status"] == "chosen") chosen = c["name"].get<std::string>();
  ASSERT_EQ(chosen.rfind("idim ", 0), 0u) << "the record is meant to choose a trajectory candidate: " << chosen;
  IdimOptions o = AutoOptions{}.idim;
  o.terms = chosen == "idim coulomb-viscous" ? std::vector<std::string>{"inertia", "viscous", "coulomb", "offset"}
            : chosen == "idim asymmetric"    ? std::vector<std::string>{"inertia", "asymmetric"}
                                             : std::vector<std::string>{"inertia", "viscous", "coulomb", "offset", "stribeck"};
  o.search_stribeck_vs = chosen == "idim stribeck (vs searched)";
  o.exclude_below = r.diagnostics.numbers.at("exclude_below");  // auto's standstill speed, reported
  const Result idim = identify_idim(d, o);
  ASSERT_TRUE(idim.ok()) << idim.message;
  EXPECT_EQ(r.diagnostics.texts.at("covariance"), idim.diagnostics.texts.at("covariance"));
  EXPECT_EQ(r.fit.samples, idim.fit.samples);
  for (const Parameter& p : idim.parameters) {
    ASSERT_NE(r.find(p.name), nullptr) << p.name;
    // The same computation on the same numbers: equal to the last bit.
    EXPECT_EQ(r.find(p.name)->value, p.value) << p.name;
    EXPECT_EQ(r.find(p.name)->std, p.std) << p.name;
    ASSERT_TRUE(p.std_ols.has_value()) << p.name;
    EXPECT_NE(p.std, *p.std_ols) << p.name << ": the std must be the Newey-West figure, not the ordinary one";
  }
}

// idim's --vs search: the best of the 40-point log grid, refined by a golden-section search
// between its neighbours. The refined vs fits at least as well as every grid value, lies off the
// grid, and is nearer the truth (0.01 m/s) than the grid's quarter-decade step.
TEST(IdimVsSearch, GoldenSectionRefinesTheGridsBest) {
  const IdimData d = plateau_record(3);
  IdimOptions o = AutoOptions{}.idim;
  o.terms = {"inertia", "viscous", "coulomb", "offset", "stribeck"};
  o.search_stribeck_vs = true;
  const Result searched = identify_idim(d, o);
  ASSERT_TRUE(searched.ok()) << searched.message;
  const double vs = searched.diagnostics.numbers.at("stribeck_vs"), top = searched.diagnostics.numbers.at("max_speed");
  o.search_stribeck_vs = false;
  // Relative: the grid's values are products of pow, the refined one an exp of a log.
  constexpr double kOffGrid = 1e-6;
  for (int i = 0; i < 40; ++i) {
    o.stribeck_vs = top * std::pow(10.0, -4.0 + (4.0 - std::log10(2.0)) * i / 39);
    const Result at = identify_idim(d, o);
    if (!at.ok()) continue;
    EXPECT_LE(searched.fit.relative_error_percent, at.fit.relative_error_percent) << "grid vs " << o.stribeck_vs;
    EXPECT_GT(std::abs(vs - o.stribeck_vs), kOffGrid * vs) << "the search stopped on the grid at " << vs;
  }
  // Half the grid's step (a factor 10^(3.7/39/2) = 1.12): the grid alone lands within it only by chance.
  constexpr double kNearTruth = 0.12;
  EXPECT_NEAR(vs, kVs, kNearTruth * kVs);
}

TEST(Auto, TooFewFoldsAreRefused) {
  AutoOptions o;
  o.folds = 1;
  EXPECT_THROW(identify_auto(plateau_record(1), o), std::invalid_argument);
}

}  // namespace
}  // namespace frictionlab
