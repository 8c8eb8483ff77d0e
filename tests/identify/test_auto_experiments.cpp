// identify_auto (identify/auto.hpp) on the experiments that are not trajectories, each recorded by
// the project's simulator from a bundled scenario: a slow ramp of current with stick (breakaway),
// a pendulum's free decay (decay) and LuGre presliding. auto must say what it sees, run the
// method that fits it and say why; it must not fit the inverse dynamic model to them.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <iostream>
#include <random>
#include <string>

#include "frictionlab/identify/auto.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace fl = frictionlab;

namespace {

std::string example(const std::string& name) { return std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name; }

Eigen::VectorXd vec(const std::vector<double>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size()));
}

bool contains(const std::string& text, const std::string& words) { return text.find(words) != std::string::npos; }

// A record of a simulated run: its time and position, the drive force `force` (N or N m).
fl::IdimData record(const fl::Trajectory& tr, Eigen::VectorXd force, const std::string& file) {
  fl::IdimData d;
  d.time = vec(tr.time);
  d.position = vec(tr.position);
  d.force = std::move(force);
  d.file = file;
  return d;
}

// `r` is auto's answer whose texts `key` hold `words`.
void expect_text(const fl::Result& r, const std::string& key, const std::string& words) {
  EXPECT_TRUE(contains(r.diagnostics.texts.at(key), words)) << r.diagnostics.texts.at(key);
}

// The first candidate of the selection chosen, named `name`, and `others` after it, none chosen,
// each a runner-up or refused with a reason.
void expect_single_choice(const fl::Result& r, const std::string& name, std::size_t others = 0) {
  const auto sel = nlohmann::json::parse(r.json_sections.at("diagnostics.selection"));
  ASSERT_EQ(sel.size(), 1u + others) << sel.dump();
  EXPECT_EQ(sel[0]["name"], name) << sel.dump();
  EXPECT_EQ(sel[0]["status"], "chosen") << sel.dump();
  for (std::size_t i = 1; i < sel.size(); ++i) {
    EXPECT_TRUE(sel[i]["status"] == "runner-up" || sel[i]["status"] == "refused") << sel[i].dump();
    if (sel[i]["status"] == "refused") {
      EXPECT_FALSE(sel[i]["reason"].get<std::string>().empty()) << sel[i].dump();
    }
  }
  EXPECT_EQ(r.method, "auto");
}

// Craig's torque-mode trapezoid (examples/craig_motor_trapezoid.yaml): the motor stuck while the
// current ramps, then turning, then stopping. Truth Tfs 0.0015, Tfd 0.0012 N m, B 2.85e-6 N m s/rad.
// 1 %: breakaway's own test holds 0.5 % on this record with the velocity simulated; here the
// velocity is the encoder position's central difference.
TEST(AutoExperiments, SlowRampWithStickRunsBreakaway) {
  constexpr double kRel = 0.01, Kt = 0.0141;
  const fl::Trajectory tr = fl::simulate(fl::load_scenario(example("craig_motor_trapezoid.yaml")));
  fl::IdimData d = record(tr, Kt * vec(tr.current), "trapezoid");
  fl::AutoOptions o;
  o.axis = fl::Axis::rotary;
  const fl::Result r = fl::identify_auto(d, o);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_text(r, "experiment", "a slow ramp of force with stick");
  expect_text(r, "choice", "only its onset of motion shows the static level Fs");
  // The trajectory candidates follow as runners-up (3 idim; the sweep's only with plateaus).
  const auto sel = nlohmann::json::parse(r.json_sections.at("diagnostics.selection"));
  ASSERT_GE(sel.size(), 4u) << sel.dump();
  expect_single_choice(r, "breakaway static-coulomb-viscous", sel.size() - 1);
  EXPECT_EQ(sel[1]["name"], "idim coulomb-viscous") << sel.dump();
  EXPECT_TRUE(contains(r.diagnostics.texts.at("candidate 2"), "idim coulomb-viscous")) << r.diagnostics.texts.at("candidate 2");
  EXPECT_NEAR(r.value("Fs"), 0.0015, kRel * 0.0015);
  EXPECT_NEAR(r.value("Fc"), 0.0012, kRel * 0.0012);
  EXPECT_NEAR(r.value("Fv"), 2.85e-6, kRel * 2.85e-6);
  EXPECT_EQ(r.find("Fc")->unit, "N m");
}

// Craig's pendulum with static, Coulomb and viscous pivot friction
// (examples/craig_pendulum_combined.yaml: m = l = 1, g = 9.81, Fc 0.16 N m, Fv 0.5 N m s/rad),
// released from 0.5 rad with no drive: a free decay. Without the stiffness auto reports Fc/k and
// zeta: truth 0.16 / 9.81 rad and 0.5 / (2 sqrt(9.81)).
// 2 %: auto takes the restoring force whose balance fits better (here the pendulum's k sin x) and
// the centre that fits it best, so Fc/k is as decay's own; zeta carries the natural frequency auto
// reads off the half periods, which a pendulum's amplitude lengthens (by x^2/16, 1.5 % at 0.5 rad).
TEST(AutoExperiments, FreeDecayRunsDecay) {
  constexpr double kRel = 0.02;
  const fl::Trajectory tr = fl::simulate(fl::load_scenario(example("craig_pendulum_combined.yaml")));
  const fl::IdimData d = record(tr, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(tr.rows())), "pendulum");  // no drive
  const fl::Result r = fl::identify_auto(d);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_text(r, "experiment", "a free decay: the drive force is constant");
  expect_text(r, "choice", "decay: the record is a free decay");
  // The trajectory candidates follow, each with the reason it was not run.
  expect_single_choice(r, "decay coulomb-viscous", 4);
  expect_text(r, "candidate 2", "refused: not run: the record is a free decay");
  expect_text(r, "restoring_force", "pendulum, k sin(x)");
  const double wn = std::sqrt(9.81);
  EXPECT_NEAR(r.value("Fc_over_k"), 0.16 / 9.81, kRel * 0.16 / 9.81);
  EXPECT_NEAR(r.value("zeta"), 0.5 / (2 * wn), kRel * 0.5 / (2 * wn));
  // With the stiffness (m g l = 9.81 N m/rad, decay's --stiffness) the same record gives Fc and Fv
  // in force units: 0.16 N m and 0.5 N m s/rad, within the same 2 % (Fv, like zeta, carries the
  // restoring force's fit; the natural frequency is no longer used).
  fl::AutoOptions o;
  o.stiffness = 9.81;
  o.axis = fl::Axis::rotary;
  const fl::Result k = fl::identify_auto(d, o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.find("Fc_over_k"), nullptr);
  EXPECT_NEAR(k.value("Fc"), 0.16, kRel * 0.16);
  EXPECT_NEAR(k.value("Fv"), 0.5, kRel * 0.5);
  EXPECT_EQ(k.find("Fc")->unit, "N m");
  expect_text(k, "choice", "with the stiffness given (--stiffness 9.81 N m/rad)");
}

// --stiffness on a record without a decay is not used, and a warning says so.
TEST(AutoExperiments, StiffnessWithoutADecayIsSaidUnused) {
  const fl::Trajectory tr = fl::simulate(fl::load_scenario(example("craig_motor_trapezoid.yaml")));
  fl::IdimData d = record(tr, 0.0141 * vec(tr.current), "trapezoid");
  fl::AutoOptions o;
  o.axis = fl::Axis::rotary;
  o.stiffness = 2.0;
  const fl::Result r = fl::identify_auto(d, o);
  ASSERT_TRUE(r.ok()) << r.message;
  bool said = false;
  for (const auto& w : r.diagnostics.warnings) said |= contains(w, "--stiffness = 2 N m/rad is not used: the record holds no free decay");
  EXPECT_TRUE(said);
  o.stiffness = -1.0;
  EXPECT_THROW(fl::identify_auto(d, o), std::invalid_argument);
}

// A coast-down (no spring, no drive): no method identifies it; auto says so and fits nothing.
TEST(AutoExperiments, CoastDownIsSeenAndRefused) {
  constexpr double dt = 1e-3, M = 1.0, Fc = 0.5, Fv = 2.0;
  fl::IdimData d;
  const Eigen::Index n = 2000;
  d.time = Eigen::VectorXd::LinSpaced(n, 0.0, dt * static_cast<double>(n - 1));
  d.position.resize(n);
  d.force = Eigen::VectorXd::Zero(n);
  double x = 0, v = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    d.position(i) = x;
    if (v > 0) v = std::max(0.0, v - (Fc + Fv * v) / M * dt);
    x += v * dt;
  }
  d.file = "coast";
  const fl::Result r = fl::identify_auto(d);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(contains(r.message, "a free coast-down")) << r.message;
  EXPECT_TRUE(r.parameters.empty());
}

// Canudas de Wit's presliding (examples/canudas_presliding.yaml): a force ramped to 0.95 Fs and
// held on a unit mass with LuGre friction (sigma0 1e5 N/m): 14 um of bristle deflection, no
// sliding. auto sees it, reports the stiffness (the initial slope of the steady presliding curve)
// and names lugre for the rest.
// 10 %: the steady curve leaves out the bristle damping and the mass, small at this 0.14 N/s ramp.
TEST(AutoExperiments, PreslidingIsSeenAndOnlyTheStiffnessReported) {
  constexpr double kRel = 0.10;
  const fl::Trajectory tr = fl::simulate(fl::load_scenario(example("canudas_presliding.yaml")));
  const fl::IdimData d = record(tr, vec(tr.applied), "presliding");
  const fl::Result r = fl::identify_auto(d);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_text(r, "experiment", "presliding: the displacement");
  expect_text(r, "choice", "lugre is the method for the whole LuGre model");
  expect_single_choice(r, "presliding stiffness");
  ASSERT_EQ(r.parameters.size(), 1u);
  EXPECT_NEAR(r.value("sigma0"), 1e5, kRel * 1e5);
  EXPECT_EQ(r.find("Fc"), nullptr) << "no friction level may be fitted to presliding";
}


// sigma0's std on seeded records that follow the steady curve f = A (1 - exp(-sigma0 x / A))
// exactly, with white force noise (0.01 N) and a 0.1 N offset in the force: the 95 % interval must
// cover the truth in at least 90 % of 100 records (it covered 3 of 100 while the offset read at the
// start was held exact), and the model-error warning (residual structure or halves that differ)
// must be rare: at most 5 of 100 (its tests are at 4 standard errors and two-sided 1 %). Its firing
// on a record with the model error (the rig log's bristle damping) is tested in
// tests/cli/identify_rig_experiments.sh.
TEST(AutoExperiments, PreslidingStdCoversOnTheExactCurveAndTheModelErrorWarningIsRare) {
  constexpr double kSigma0 = 1e5, kA = 4.5, kNoise = 0.01, kOffset = 0.1;  // N/m, N, N, N
  constexpr int kRecords = 100, kFewestCovered = 90, kMostWarned = 5;
  int warned = 0, covered = 0;
  for (int seed = 0; seed < kRecords; ++seed) {
    std::mt19937 gen(900u + static_cast<unsigned>(seed));
    std::normal_distribution<double> noise(0.0, kNoise);
    constexpr Eigen::Index n = 8000;  // 8 s at 1 kHz: a ramp to 0.9 A over 6 s, then held
    fl::IdimData d;
    d.time.resize(n);
    d.force.resize(n);
    d.position.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = 1e-3 * static_cast<double>(i), f = 0.9 * kA * std::min(t / 6.0, 1.0);
      d.time(i) = t;
      d.position(i) = -kA / kSigma0 * std::log1p(-f / kA);  // the curve's inverse
      d.force(i) = kOffset + f + noise(gen);
    }
    d.file = "exact-curve";
    const fl::Result r = fl::identify_auto(d);
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_EQ(r.parameters.size(), 1u);
    ASSERT_TRUE(r.diagnostics.numbers.count("presliding_sigma0_lower_half")) << "seed " << seed;
    const fl::Parameter* p = r.find("sigma0");
    covered += std::abs(p->value - kSigma0) <= 1.96 * p->std;
    bool w = false;
    for (const auto& x : r.diagnostics.warnings) w |= contains(x, "excludes this model error");
    warned += w;
  }
  std::cout << "presliding, exact curve: sigma0 covered " << covered << "/" << kRecords << ", model-error warnings "
            << warned << "/" << kRecords << "\n";
  EXPECT_GE(covered, kFewestCovered);
  EXPECT_LE(warned, kMostWarned);
}
}  // namespace
