// LuGre from one record (issue 11): all six parameters from one force/position record in which a
// sum of sinusoids drives a mass through presliding, breakaway in both directions and reversals,
// with encoder noise and quantisation; the fit simulates with the library's LuGreT (vd included);
// a record that never slides gets honest (NaN) uncertainty.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "lugre_record.hpp"

namespace frictionlab {
namespace {

using testing::MultisineRecord;
using testing::multisine_record;

// The acceptance figures of issue 11 for one noisy record with the static part identified too:
// the levels Fc and Fs shape every sliding stretch and the breakaways; sigma0 is seen in the
// presliding micrometres, where the encoder noise is a few percent of the deflection; sigma1 only
// in the damped bristle transients after each breakaway; vs only in the few milliseconds a
// reversal spends below it.
constexpr double kLevelTol = 0.05;
constexpr double kSigma0Tol = 0.10;
constexpr double kSigma1Tol = 0.20;
constexpr double kVsTol = 0.25;

void expect_rel(const Result& r, const std::string& name, double truth, double tol, const std::string& label) {
  EXPECT_NEAR(r.value(name), truth, tol * std::abs(truth)) << label << ": " << name;
}

void print(const Result& r, const std::string& label, double seconds) {
  std::cout << label << ": status " << (r.ok() ? "ok" : r.message);
  for (const auto& p : r.parameters) std::cout << " " << p.name << " " << p.value << " (" << p.std << ")";
  std::cout << " iterations " << r.diagnostics.numbers.at("iterations") << " in " << seconds << " s\n";
  for (const auto& w : r.diagnostics.warnings) std::cout << "  warning: " << w << "\n";
}

Result fit(const MultisineRecord& spec, const std::string& label) {
  const LugreData d = multisine_record(spec);
  LugreOptions o;
  o.inertia = spec.inertia;
  const auto t0 = std::chrono::steady_clock::now();
  Result r = identify_lugre(d, o);
  print(r, label, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return r;
}

void expect_all_six(const Result& r, const LuGre& t, const std::string& label) {
  ASSERT_TRUE(r.ok()) << label << ": " << r.message;
  expect_rel(r, "Fc", t.Fc, kLevelTol, label);
  expect_rel(r, "Fs", t.Fs, kLevelTol, label);
  expect_rel(r, "sigma0", t.sigma0, kSigma0Tol, label);
  expect_rel(r, "sigma1", t.sigma1, kSigma1Tol, label);
  expect_rel(r, "vs", t.vs, kVsTol, label);
  for (const char* name : {"Fc", "Fs", "sigma0", "sigma1", "vs"})
    EXPECT_TRUE(std::isfinite(r.find(name)->std)) << label << ": " << name << " is determined by this record";
  EXPECT_EQ(r.diagnostics.correlation.names.size(), 6u) << label;
}

// Four drives of the Table I contact on 1 kg (peak force up to 1.4 x 1.5..3 Fs, 0.3 to 1 Hz, with
// and without dwells at the reversals) and encoder noise of 0.1 to 0.5 um on a 0.05 um grid.
MultisineRecord table_i(double amplitude, double frequency, unsigned seed, double noise) {
  MultisineRecord s;
  s.amplitude = amplitude;
  s.frequency = frequency;
  s.seed = seed;
  s.noise = noise;
  return s;
}

TEST(LugreOneRecord, TableIDrivenAtTwiceFsHalfHertz) {
  const MultisineRecord s = table_i(2.0, 0.5, 11, 2e-7);
  expect_all_six(fit(s, "A=2 Fs, 0.5 Hz"), s.truth, "A=2 Fs, 0.5 Hz");
}

TEST(LugreOneRecord, TableIDrivenGentlyAtOneHertz) {
  const MultisineRecord s = table_i(1.5, 1.0, 12, 1e-7);
  expect_all_six(fit(s, "A=1.5 Fs, 1 Hz"), s.truth, "A=1.5 Fs, 1 Hz");
}

TEST(LugreOneRecord, TableIDrivenHardAndSlow) {
  const MultisineRecord s = table_i(3.0, 0.3, 13, 3e-7);
  expect_all_six(fit(s, "A=3 Fs, 0.3 Hz"), s.truth, "A=3 Fs, 0.3 Hz");
}

TEST(LugreOneRecord, TableINoisiestEncoder) {
  const MultisineRecord s = table_i(2.5, 0.8, 14, 5e-7);
  expect_all_six(fit(s, "A=2.5 Fs, 0.8 Hz, 0.5 um"), s.truth, "A=2.5 Fs, 0.8 Hz, 0.5 um");
}

// Another rig: a light axis (0.05 kg) with a soft, lightly damped contact and a wide Stribeck dip
// (sigma0 2000 N/m, sigma1 4 N s/m, Fc 0.2 N, Fs 0.32 N, vs 20 mm/s), 1 um noise on a 1 um grid.
TEST(LugreOneRecord, LightAxisSoftContact) {
  MultisineRecord s = table_i(2.0, 0.5, 21, 1e-6);
  s.truth.sigma0 = 2000;
  s.truth.sigma1 = 4;
  s.truth.sigma2 = 0.05;
  s.truth.Fc = 0.2;
  s.truth.Fs = 0.32;
  s.truth.vs = 0.02;
  s.inertia = 0.05;
  s.resolution = 1e-6;
  expect_all_six(fit(s, "light axis"), s.truth, "light axis");
}

// A contact without a Stribeck dip (Fs = Fc): the record cannot give vs, whatever it is. The fit
// must say so (std NaN, a warning naming vs) instead of a confident number, and still give the
// rest.
TEST(LugreOneRecord, NoStribeckDipLeavesVsUndetermined) {
  MultisineRecord s = table_i(2.0, 0.5, 17, 3e-7);
  s.truth.Fs = s.truth.Fc;
  const Result r = fit(s, "Fs = Fc");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(std::isnan(r.find("vs")->std)) << r.find("vs")->std;
  EXPECT_FALSE(r.find("vs")->flag.empty());
  bool named = false;
  for (const auto& w : r.diagnostics.warnings) named = named || w.rfind("vs = ", 0) == 0;
  EXPECT_TRUE(named) << "a warning names vs";
  const auto& d = r.diagnostics;
  const bool listed = std::count(d.undetermined.begin(), d.undetermined.end(), "vs") +
                          std::count(d.at_bound.begin(), d.at_bound.end(), "vs") > 0;
  EXPECT_TRUE(listed);
  expect_rel(r, "Fc", s.truth.Fc, kLevelTol, "Fs = Fc");
  expect_rel(r, "Fs", s.truth.Fs, kLevelTol, "Fs = Fc");
  expect_rel(r, "sigma0", s.truth.sigma0, kSigma0Tol, "Fs = Fc");
  // The correlation matrix covers the six fitted parameters, with NaN where vs is involved.
  ASSERT_EQ(d.correlation.names.size(), 6u);
  const auto iv = static_cast<std::size_t>(
      std::find(d.correlation.names.begin(), d.correlation.names.end(), "vs") - d.correlation.names.begin());
  ASSERT_LT(iv, 6u);
  EXPECT_TRUE(std::isnan(d.correlation.matrix[iv][iv == 0 ? 1 : 0]));
  EXPECT_NE(to_json(r).find("\"correlation\""), std::string::npos);
}

// The revisited damping sigma1 exp(-(v/vd)^2) (Canudas de Wit 1998): the fit must simulate the law
// it is given, vd included (a fit that drops vd gives sigma1 = 106 on this record, a third of the
// truth). The record is the ramp-and-sine experiment of test_lugre.cpp on a law whose damping has
// decayed to 37 % of sigma1 at 5 mm/s (at vd = 1 mm/s the fit needs 16 substeps to follow the
// damping's fall within 5 %); the static part is given as that law's file form (a lugre
// MODEL.json from an earlier fit, say), then as a Stribeck law with vd as an option.
constexpr double kDynamicTol = 0.05;  // test_lugre.cpp's figure for noise-free data: fixed step vs CVODE

TEST(LugreOneRecord, RevisitedDampingVdIsSimulated) {
  LuGre truth{};
  truth.vd = 5e-3;
  SimulationOptions so;
  so.duration = 10;
  so.output_rate = 1000;
  so.mode = SolverMode::stiff;
  const Trajectory tr =
      simulate(RigidAxis(AxisParams{1.0, 0.0}), FrictionLaw(truth), testing::lugre_experiment(truth), so);
  const auto n = static_cast<Eigen::Index>(tr.rows());
  const LugreData d{Eigen::Map<const Eigen::VectorXd>(tr.time.data(), n),
                    Eigen::Map<const Eigen::VectorXd>(tr.applied.data(), n),
                    Eigen::Map<const Eigen::VectorXd>(tr.position.data(), n)};
  LugreOptions o;
  o.inertia = 1.0;
  o.static_law = FrictionLaw(truth);
  const Result r = identify_lugre(d, o);
  print(r, "vd = 5e-3, static part given as the lugre law", 0.0);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_rel(r, "sigma0", truth.sigma0, kDynamicTol, "vd");
  expect_rel(r, "sigma1", truth.sigma1, kDynamicTol, "vd");
  ASSERT_NE(r.find("vd"), nullptr);
  EXPECT_EQ(r.value("vd"), truth.vd);
  ASSERT_TRUE(r.law.has_value());
  EXPECT_EQ(r.law->scalars.at("vd"), truth.vd) << "the identified law keeps the damping shape it was fitted with";

  // The same with the static part as a Stribeck law and vd as an option.
  o.static_law = FrictionLaw(Stribeck{truth.Fc, truth.Fs, truth.vs, truth.delta, truth.sigma2});
  o.vd = truth.vd;
  const Result s = identify_lugre(d, o);
  ASSERT_TRUE(s.ok()) << s.message;
  expect_rel(s, "sigma1", truth.sigma1, kDynamicTol, "vd option");
}

}  // namespace
}  // namespace frictionlab
