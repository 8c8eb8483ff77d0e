// Identification on data simulated from the seed documents' experiments (examples/*.yaml):
// each method must recover the parameters the simulation used.
#include <gtest/gtest.h>

#include <random>

#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace fl = frictionlab;

namespace {

std::string example(const std::string& name) { return std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name; }

Eigen::VectorXd vec(const std::vector<double>& x) { return Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(x.size())); }

double param(const fl::Result& r, const std::string& name) { return r.value(name); }

// The Virgala motor's sweep as measured: Km times the simulated current, with white noise on the
// current (2 mA) and the speed (0.05 rad/s) from `seed`.
struct NoisySweep {
  Eigen::VectorXd time, force, speed;
};
NoisySweep noisy_sweep(const fl::Trajectory& tr, unsigned seed) {
  constexpr double Km = 0.039;  // N m/A
  std::mt19937 rng(seed);
  std::normal_distribution<double> current_noise(0.0, 2e-3), speed_noise(0.0, 0.05);  // A, rad/s
  NoisySweep s{vec(tr.time), Km * vec(tr.current), vec(tr.velocity)};
  for (Eigen::Index i = 0; i < s.force.size(); ++i) {
    s.force[i] += Km * current_noise(rng);
    s.speed[i] += speed_noise(rng);
  }
  return s;
}

// Segmentation that holds with that noise.
fl::SweepOptions noisy_sweep_options() {
  fl::SweepOptions o;
  o.relative_tolerance = 0.02;
  o.velocity_tolerance = 0.3;  // rad/s: covers the speed noise at the slowest step
  return o;
}

bool has_warning(const fl::Result& r, const std::string& text) {
  for (const auto& w : r.diagnostics.warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

// The lecture's trapezoid (J = 1.06e-6, B = 2.85e-6, Tfs = 0.0015, Tfd = 0.0012, Kt = 0.0141).
// The issue asks the dynamic estimate for 0.5 %; the exact simulation sampled at 100 Hz gives
// central-difference accelerations good to about 1e-4, so the estimates land well inside.
TEST(IdentifySimulated, BreakawayRecoversCraigMotorWithinHalfAPercent) {
  constexpr double kRelTol = 5e-3;
  const fl::Scenario sc = fl::load_scenario(example("craig_motor_trapezoid.yaml"));
  const fl::Trajectory tr = fl::simulate(sc);
  constexpr double Kt = 0.0141;
  fl::BreakawayData d{vec(tr.time), Kt * vec(tr.current), vec(tr.velocity), {}};
  fl::BreakawayOptions rotary;
  rotary.axis = fl::Axis::rotary;  // a motor; every method's default axis is linear
  const fl::Result r = fl::identify_breakaway(d, rotary);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(param(r, "Fs"), 0.0015, kRelTol * 0.0015);
  EXPECT_NEAR(param(r, "Fc"), 0.0012, kRelTol * 0.0012);
  EXPECT_NEAR(param(r, "Fv"), 2.85e-6, kRelTol * 2.85e-6);
  EXPECT_NEAR(param(r, "M"), 1.06e-6, kRelTol * 1.06e-6);
  EXPECT_EQ(r.find("Fs")->unit, "N m");
  // The lecture's read-offs are reported for comparison and are biased by the ignored inertia:
  // the stop read-off lies below Tfd because the rotor still decelerates there.
  const auto& readoff = r.diagnostics.groups.at("readoff");
  EXPECT_NEAR(readoff.at("Fs"), 0.0015, 0.02 * 0.0015);
  EXPECT_GT(std::abs(readoff.at("Fc") - 0.0012), std::abs(param(r, "Fc") - 0.0012));
  EXPECT_TRUE(r.law.has_value());
  // With the inertia given the same figures come out.
  fl::BreakawayOptions o;
  o.inertia = 1.06e-6;
  const fl::Result rj = fl::identify_breakaway(d, o);
  ASSERT_TRUE(rj.ok()) << rj.message;
  EXPECT_NEAR(param(rj, "Fc"), 0.0012, kRelTol * 0.0012);
  EXPECT_EQ(rj.find("M"), nullptr);
}

// Adequacy of the breakaway fit over its sliding samples, with current noise (seeded): the
// lecture's law leaves nothing; a Stribeck law whose dip spans a third of the sliding speeds is
// absorbed into Fc and Fv (17 % and 23 % off), which leaves the residual correlated, and the
// warning says that breakaway's std are then too small, naming the factor.
TEST(IdentifySimulated, BreakawaySaysWhenItsStdCannotBeTrusted) {
  constexpr double Kt = 0.0141;
  const auto run = [&](const fl::Scenario& sc, unsigned seed) {
    const fl::Trajectory tr = fl::simulate(sc);
    std::mt19937 rng(seed);
    std::normal_distribution<double> current_noise(0.0, 2e-3);  // A
    Eigen::VectorXd force = Kt * vec(tr.current);
    for (Eigen::Index i = 0; i < force.size(); ++i) force[i] += Kt * current_noise(rng);
    fl::BreakawayOptions o;
    o.axis = fl::Axis::rotary;
    return fl::identify_breakaway({vec(tr.time), force, vec(tr.velocity), {}}, o);
  };
  const fl::Scenario lecture = fl::load_scenario(example("craig_motor_trapezoid.yaml"));
  fl::ScenarioOptions with_dip;
  with_dip.law = fl::FrictionLaw(fl::Stribeck{0.0012, 0.0015, 100.0, 2.0, 2.85e-6});  // vs 100 rad/s
  const fl::Scenario dipped = fl::load_scenario(example("craig_motor_trapezoid.yaml"), with_dip);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const fl::Result right = run(lecture, seed);
    ASSERT_TRUE(right.ok()) << right.message;
    EXPECT_EQ(right.diagnostics.groups.at("adequacy").at("findings"), 0.0) << "seed " << seed;
    const fl::Result wrong = run(dipped, seed);
    ASSERT_TRUE(wrong.ok()) << wrong.message;
    EXPECT_TRUE(has_warning(wrong, "breakaway's std_ols of Fc, Fv and M (they assume independent samples) are too small by about"))
        << "seed " << seed;
  }
}

TEST(IdentifySimulated, BreakawayWithoutMotionIsAnErrorStatus) {
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(100, 0.0, 0.99);
  fl::BreakawayData d{t, 1e-3 * t, Eigen::VectorXd::Zero(100), {}};
  const fl::Result r = fl::identify_breakaway(d);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("no motion detected"), std::string::npos) << r.message;
}

// The paper's constant-speed experiment with noise on the measured current and velocity: the
// true Stribeck parameters lie inside the reported 2-sigma intervals.
TEST(IdentifySimulated, SweepRecoversVirgalaStribeckWithinTwoSigma) {
  const fl::Scenario sc = fl::load_scenario(example("virgala_motor_sweep.yaml"));
  const NoisySweep m = noisy_sweep(fl::simulate(sc), 7);
  const fl::Result r = fl::identify_sweep({m.time, m.force, m.speed}, noisy_sweep_options());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.diagnostics.lists.at("points").size(), 15u);
  const std::map<std::string, double> truth{{"Fc", 0.002}, {"Fs", 0.003}, {"vs", 5.0}, {"delta", 2.0}, {"Fv", 1e-5}};
  for (const auto& [name, value] : truth) {
    const auto* p = r.find(name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_LE(std::abs(p->value - value), 2 * p->std) << name << " = " << p->value << " +- " << p->std;
  }
}

// Adequacy of a sweep: the same noisy Stribeck sweep fitted with the Stribeck law leaves no
// structure in its segments' samples; fitted with the Coulomb-viscous law it leaves the slow
// segments above the law, and the warning names the dip and sweep's own remedy.
TEST(IdentifySimulated, SweepNamesAMissingStribeckDipAndNothingWhenTheLawFits) {
  const fl::Scenario sc = fl::load_scenario(example("virgala_motor_sweep.yaml"));
  const fl::Trajectory tr = fl::simulate(sc);
  // Seeded noise draws: a white residual must pass every one (the checks' significance of 4
  // standard errors makes a false finding rarer than 1 in 1000 per draw).
  constexpr unsigned kSeeds = 10;
  for (unsigned seed = 1; seed <= kSeeds; ++seed) {
    const NoisySweep m = noisy_sweep(tr, seed);
    fl::SweepOptions o = noisy_sweep_options();
    o.axis = fl::Axis::rotary;
    const fl::Result right = fl::identify_sweep({m.time, m.force, m.speed}, o);
    ASSERT_TRUE(right.ok()) << right.message;
    EXPECT_EQ(right.diagnostics.groups.at("adequacy").at("findings"), 0.0) << "seed " << seed;
    EXPECT_FALSE(right.diagnostics.lists.at("residual_by_velocity").empty());
    o.fit.model = fl::StaticFitModel::coulomb_viscous;
    const fl::Result wrong = fl::identify_sweep({m.time, m.force, m.speed}, o);
    ASSERT_TRUE(wrong.ok()) << wrong.message;
    EXPECT_TRUE(has_warning(wrong, "friction at low speed is higher than the model")) << "seed " << seed;
    EXPECT_TRUE(has_warning(wrong, "N m more at |v| about")) << "units of the rotary axis";
    EXPECT_TRUE(has_warning(wrong, "(sweep --model stribeck)"));
    EXPECT_FALSE(has_warning(wrong, "idim")) << "a sweep's finding names sweep's remedy";
  }
}

// The lecture's pendulum cases at several initial angles: T_slip and B within 2 %, and the
// friction a case does not have reported as zero within its uncertainty.
TEST(IdentifySimulated, DecayRecoversPendulumFrictionAtAnyAngleUpToOneRadian) {
  constexpr double kRelTol = 0.02;
  struct Case {
    const char* file;
    double Fc, Fv;
  };
  for (const Case c : {Case{"craig_pendulum_coulomb.yaml", 0.16, 0.0}, Case{"craig_pendulum_viscous.yaml", 0.0, 0.5},
                       Case{"craig_pendulum_combined.yaml", 0.16, 0.5}}) {
    for (double angle : {0.3, 0.6, 1.0}) {
      SCOPED_TRACE(std::string(c.file) + " at " + std::to_string(angle) + " rad");
      fl::Scenario sc = fl::load_scenario(example(c.file));
      sc.options.initial_position = angle;
      const fl::Trajectory tr = fl::simulate(sc);
      fl::DecayOptions o;
      o.stiffness = 9.81;  // m g l
      o.pendulum = true;
      o.axis = fl::Axis::rotary;
      const fl::Result r = fl::identify_decay({vec(tr.time), vec(tr.position)}, o);
      ASSERT_TRUE(r.ok()) << r.message;
      for (const auto& [name, value] : {std::pair{"Fc", c.Fc}, std::pair{"Fv", c.Fv}}) {
        const auto* p = r.find(name);
        if (value > 0) {
          EXPECT_NEAR(p->value, value, kRelTol * value) << name;
        } else {
          EXPECT_LE(std::abs(p->value), 2 * p->std + 1e-9) << name << " = " << p->value << " +- " << p->std;
        }
      }
    }
  }
}

// Adequacy of decay's energy balance, checked sample by sample (identify/decay.hpp): on the
// lecture's combined pendulum (Coulomb and viscous, the model's own law) nothing is found; with a
// Stribeck law in the pivot (Fs 0.3 N m over Fc 0.16, vs 0.1 rad/s, a tenth of the swing's top
// speed) the balance's Coulomb-viscous fit leaves friction above it at low speed, and the warning
// names the remedy. Both with the stiffness known (Fc, Fv in N m) and as auto runs it (Fc/k, zeta).
TEST(IdentifySimulated, DecaySaysWhenTheFrictionIsNotCoulombViscous) {
  const auto run = [&](const fl::Scenario& sc, bool with_stiffness) {
    const fl::Trajectory tr = fl::simulate(sc);
    fl::DecayOptions o;
    if (with_stiffness) o.stiffness = 9.81;  // m g l
    else o.natural_frequency = std::sqrt(9.81);
    o.pendulum = true;
    o.axis = fl::Axis::rotary;
    return fl::identify_decay({vec(tr.time), vec(tr.position)}, o);
  };
  const fl::Scenario lecture = fl::load_scenario(example("craig_pendulum_combined.yaml"));
  fl::ScenarioOptions with_dip;
  with_dip.law = fl::FrictionLaw(fl::Stribeck{0.16, 0.3, 0.1, 2.0, 0.5});
  const fl::Scenario dipped = fl::load_scenario(example("craig_pendulum_combined.yaml"), with_dip);
  for (const bool with_stiffness : {true, false}) {
    SCOPED_TRACE(with_stiffness ? "stiffness given" : "natural frequency only");
    const fl::Result right = run(lecture, with_stiffness);
    ASSERT_TRUE(right.ok()) << right.message;
    ASSERT_TRUE(right.diagnostics.groups.count("adequacy")) << "the residual check must run";
    EXPECT_EQ(right.diagnostics.groups.at("adequacy").at("findings"), 0.0);
    EXPECT_FALSE(has_warning(right, "Stribeck")) << right.diagnostics.warnings.front();
    EXPECT_FALSE(right.diagnostics.lists.at("residual_by_velocity").empty());
    const fl::Result wrong = run(dipped, with_stiffness);
    ASSERT_TRUE(wrong.ok()) << wrong.message;
    EXPECT_TRUE(has_warning(wrong, "a rise at low speed (a Stribeck dip) biases both levels"))
        << (wrong.diagnostics.warnings.empty() ? std::string("no warning") : wrong.diagnostics.warnings.front());
  }
}
