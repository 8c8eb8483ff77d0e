// Experiment planning (analysis/plan): the designs against the seeds and the limits, the
// prediction's parameters and undetermined ones, and the self-check that the predicted std
// agrees with the spread of identifications on a simulated rig with independent noise.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "error_message.hpp"
#include "frictionlab/analysis/plan/fisher.hpp"
#include "frictionlab/analysis/plan/plan.hpp"
#include "frictionlab/scenario/plan_files.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;
using ::testing::HasSubstr;

namespace {

const std::string kExamples = std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/";

PlanRig craig() { return load_plan_rig(kExamples + "plan/craig_motor_prior.json", kExamples + "craig_motor_trapezoid.yaml"); }
PlanRig virgala() { return load_plan_rig(kExamples + "plan/virgala_motor_prior.json", kExamples + "virgala_motor_sweep.yaml"); }
PlanRig canudas() { return load_plan_rig(kExamples + "plan/canudas_prior.json", kExamples + "canudas_presliding.yaml"); }

// The LuGre plan of the README: 5 cm of travel, 0.1 um of position noise, a 1 kHz record.
PlanOptions lugre_options(int runs) {
  PlanOptions o;
  o.limits = parse_plan_limits({"travel=0.05"});
  o.noise = parse_sensor_noise({"position=1e-7"});
  o.design.sample_rate = 1000;
  o.runs = runs;
  return o;
}
PlanRig emps_axis() { return load_plan_rig(kExamples + "plan/emps_prior.json", kExamples + "plan/axis_position_loop.yaml"); }

// Design formulas are closed-form: equal to rounding.
constexpr double kExact = 1e-12;
// The predicted std (Monte Carlo) and the spread of the check identifications are sample stds of
// R runs each: the agreement criterion.
constexpr double kAgreement = 1.5;

// The rig's "truth" for the self-check: the prior's law with Fc and Fs off by +kRigOffset and Fv
// by -kRigOffset, so the plan is checked on a rig that is not its prior: a prior good to 5 %, as
// a first identification gives. (At 10 % the breakaway spread itself moves by about 30 %: the
// plan is then a plan for another motor.)
constexpr double kRigOffset = 0.05;

FrictionLaw perturbed(const FrictionLaw& law) {
  LawSpec s = law.to_spec();
  for (auto& [name, v] : s.scalars) {
    if (name == "Fc" || name == "Fs") v *= 1 + kRigOffset;
    if (name == "Fv") v *= 1 - kRigOffset;
  }
  return FrictionLaw::from_spec(s);
}

// Spread of `runs` identifications on the perturbed rig with seeds independent of the prediction's.
MonteCarloSpread check_spread(PlanMethod m, const PlanResult& plan, const PlanRig& rig, const SensorNoise& noise,
                              int runs) {
  PlanRig truth = rig;
  truth.law = perturbed(rig.law);
  truth.scenario.law = truth.law;
  const Trajectory clean = simulate_profile(plan.profile, truth, truth.law);
  return monte_carlo_spread(m, plan.profile, truth, clean, noise, runs, /*seed=*/900001);
}

// The Fisher std (the method's own s^2 (J'J)^-1) must agree too where the residual is the noise
// alone (sweep: segment means); idim's residual also carries the position noise through the
// regressors (M qdd of the filtered noise), so there it may only be conservative, never optimistic.
enum class Fisher { agrees, conservative };

// The a-priori std (fisher.hpp, from the noise-free plan alone) against the spread of the
// check identifications: within the factor where the method's model holds.
void expect_a_priori_agreement(const PlanResult& plan, const MonteCarloSpread& check) {
  for (const auto& p : plan.prediction.parameters) {
    if (p.undetermined) continue;
    const double actual = check.parameter(p.name).std_monte_carlo;
    ASSERT_TRUE(std::isfinite(p.std_a_priori)) << p.name;
    EXPECT_GT(p.std_a_priori / actual, 1 / kAgreement) << p.name << ": a priori " << p.std_a_priori << ", actual " << actual;
    EXPECT_LT(p.std_a_priori / actual, kAgreement) << p.name << ": a priori " << p.std_a_priori << ", actual " << actual;
  }
}

void expect_agreement(const PlanResult& plan, const MonteCarloSpread& check, Fisher fisher = Fisher::agrees) {
  for (const auto& p : plan.prediction.parameters) {
    if (p.undetermined) continue;
    if (p.std_monte_carlo == 0 && check.parameter(p.name).std_monte_carlo == 0) continue;  // held (lugre's delta)
    const double actual = check.parameter(p.name).std_monte_carlo;
    ASSERT_TRUE(std::isfinite(actual) && actual > 0) << p.name;
    const double ratio = p.std_monte_carlo / actual;
    std::cout << "  " << p.name << ": predicted std " << p.std_monte_carlo << " (Fisher " << p.std_fisher
              << ", a priori " << p.std_a_priori << "), actual " << actual << ", ratio " << ratio << "\n";
    EXPECT_GT(ratio, 1 / kAgreement) << p.name << ": predicted " << p.std_monte_carlo << ", actual " << actual;
    EXPECT_LT(ratio, kAgreement) << p.name << ": predicted " << p.std_monte_carlo << ", actual " << actual;
    if (std::isfinite(p.std_fisher)) {
      EXPECT_GT(p.std_fisher / actual, 1 / kAgreement) << p.name << " (Fisher)";
      if (fisher == Fisher::agrees) {
        EXPECT_LT(p.std_fisher / actual, kAgreement) << p.name << " (Fisher)";
      }
    }
  }
}

}  // namespace

TEST(PlanLimits, ParsesKeyValueListsAndNamesWhatIsWrong) {
  const PlanLimits l = parse_plan_limits({"current=0.2,speed=400", "travel=0.3"});
  EXPECT_EQ(l.current, 0.2);
  EXPECT_EQ(l.speed, 400);
  EXPECT_EQ(l.travel, 0.3);
  EXPECT_TRUE(std::isinf(l.force));
  EXPECT_THAT(error_of([] { parse_plan_limits({"torque=1"}); }),
              HasSubstr("--limits 'torque=1': unknown key 'torque'; expected one of current (A)"));
  EXPECT_THAT(error_of([] { parse_plan_limits({"speed=fast"}); }), HasSubstr("'fast' is not a number"));
  EXPECT_THAT(error_of([] { parse_plan_limits({"speed=1,speed=2"}); }), HasSubstr("key 'speed' given twice"));
  EXPECT_THAT(error_of([] { parse_plan_limits({"current=-1"}); }), HasSubstr("--limits current = -1 A must be > 0"));
  EXPECT_THAT(error_of([] { parse_plan_limits({"speed"}); }), HasSubstr("expected KEY=VALUE"));
  EXPECT_THAT(error_of([] { parse_plan_limits({"speed=1,min_speed=2"}); }), HasSubstr("min_speed = 2 must be below speed = 1"));
  const SensorNoise n = parse_sensor_noise({"position=1e-6,current=1e-3", "encoder=1e-5"});
  EXPECT_EQ(n.position, 1e-6);
  EXPECT_EQ(n.current, 1e-3);
  EXPECT_EQ(n.encoder, 1e-5);
  EXPECT_THAT(error_of([] { parse_sensor_noise({"velocity=-0.1"}); }), HasSubstr("--noise velocity = -0.1 m/s or rad/s"));
  EXPECT_THAT(error_of([] { parse_sensor_noise({"accel=1"}); }), HasSubstr("unknown key 'accel'"));
}

TEST(PlanNoise, QuantisesAndDrawsReproducibly) {
  std::mt19937_64 a(7), b(7);
  const Eigen::VectorXd clean = Eigen::VectorXd::LinSpaced(1000, 0.0, 1.0);
  const Eigen::VectorXd x = add_noise(clean, 0.01, a, 1e-3), y = add_noise(clean, 0.01, b, 1e-3);
  EXPECT_EQ(x, y);
  for (Eigen::Index i = 0; i < x.size(); ++i) EXPECT_NEAR(std::remainder(x[i], 1e-3), 0.0, 1e-12);
  const double sd = std::sqrt((x - clean).squaredNorm() / 1000.0);
  EXPECT_NEAR(sd, 0.01, 0.002);  // 1000 draws: the sample std within 20 %
}

TEST(PlanBreakaway, DesignsTheLecturesTrapezoidFromItsMotor) {
  const PlanRig rig = craig();
  EXPECT_EQ(rig.drive, PlanDrive::current);
  EXPECT_EQ(rig.axis, Axis::rotary);
  const ExperimentProfile p = design_experiment(PlanMethod::breakaway, rig, {}, {});
  const double Kt = 0.0141, Fs = 0.0015, Fc = 0.0012, B = 2.85e-6, J = 1.06e-6, tau = J / B;
  EXPECT_NEAR(p.figure("peak"), 1.4 * Fs / Kt, kExact);  // 0.149 A: the lecture's 0.15 A
  EXPECT_NEAR(p.figure("ramp_rate"), 0.01 * Fc / tau / Kt, kExact);  // 2.3e-3 A/s: the lecture's 3e-3 A/s
  EXPECT_NEAR(p.figure("time_constant"), tau, kExact);
  EXPECT_GE(p.figure("hold"), 2 * 5 * tau - kExact);  // settling plus averaging
  EXPECT_EQ(p.column_names(), (std::vector<std::string>{"time_s", "current_A"}));
  const std::string csv = p.to_csv();
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "time_s,current_A");
  std::vector<double> t, u;
  p.samples(t, u);
  EXPECT_EQ(t.size(), static_cast<std::size_t>(std::floor(p.duration * 100 + 1e-9)) + 1);
  EXPECT_NEAR(*std::max_element(u.begin(), u.end()), p.figure("peak"), kExact);
  EXPECT_EQ(u.front(), 0.0);
  EXPECT_EQ(u.back(), 0.0);
}

TEST(PlanBreakaway, LimitsLowerThePeakOrRefuseThePlanNamingTheLimit) {
  const PlanRig rig = craig();
  PlanLimits l;
  l.current = 0.13;  // above 1.1 Fs / Kt = 0.117 A, below 1.4 Fs / Kt = 0.149 A
  const ExperimentProfile p = design_experiment(PlanMethod::breakaway, rig, l, {});
  EXPECT_NEAR(p.figure("peak"), 0.13, kExact);
  EXPECT_THAT(p.warnings.at(0), HasSubstr("--limits current = 0.13 A"));
  l.current = 0.1;
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::breakaway, rig, l, {}); }),
              HasSubstr("--limits current = 0.1 A (Kt i = 0.00141 N m) is below 1.1 Fs = 0.117 A"));
  PlanLimits s;
  s.speed = 10;  // rad/s: the peak would be Fc + 0.95 Fv 10, below Fs
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::breakaway, rig, s, {}); }),
              HasSubstr("--limits speed = 10 rad/s is reached below 1.1 Fs"));
  PlanLimits f;
  f.force = 1;  // N m, on a motor: a force limit applies too
  EXPECT_NO_THROW(design_experiment(PlanMethod::breakaway, rig, f, {}));
  PlanLimits tr;
  tr.travel = 100;  // rad: the motor turns thousands of radians in the hold
  EXPECT_THAT(error_of([&] { plan_experiment(PlanMethod::breakaway, rig, PlanOptions{{}, tr, {}, 2, 1, {}}); }),
              HasSubstr("--limits travel = 100 rad: the plan moves the axis"));
}

TEST(PlanBreakaway, WrongDriveOrPriorIsNamed) {
  EXPECT_THAT(error_of([] { design_experiment(PlanMethod::breakaway, virgala(), {}, {}); }),
              HasSubstr("a breakaway plan needs an open-loop drive"));
  EXPECT_THAT(error_of([] { design_experiment(PlanMethod::idim, craig(), {}, {}); }),
              HasSubstr("an idim plan needs a position loop"));
  EXPECT_THAT(error_of([] { design_experiment(PlanMethod::lugre, craig(), {}, {}); }),
              HasSubstr("craig_motor_prior.json: the prior law is 'static-coulomb-viscous'; a lugre plan needs a LuGre prior"));
  SensorNoise n;
  n.current = 1e-3;
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::idim, emps_axis(), {}, n); }),
              HasSubstr("--noise current = 0.001 A: the scenario's plant (axis) has no motor current; use force="));
  EXPECT_THAT(error_of([] { parse_plan_method("ramp"); }), HasSubstr("expected one of breakaway, sweep, idim, lugre"));
}

// The seed's trapezoid on the seed's motor: the prediction, and the self-check on a rig 10 % off
// the prior with independent noise seeds.
TEST(PlanBreakaway, PredictedStdAgreesWithTheSpreadOnASimulatedRig) {
  const PlanRig rig = craig();
  PlanOptions o;
  o.noise = parse_sensor_noise({"current=2e-4,velocity=0.5"});
  o.runs = 60;
  const PlanResult r = plan_experiment(PlanMethod::breakaway, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.prediction.failed, 0);
  for (const char* name : {"Fs", "Fc", "Fv"}) {
    const auto& p = r.prediction.parameter(name);
    EXPECT_FALSE(p.undetermined) << name;
    EXPECT_GT(p.std_monte_carlo, 0) << name;
    EXPECT_LT(p.std_monte_carlo, 0.05 * p.prior) << name;  // a usable plan: each to within 5 %
    EXPECT_TRUE(std::isnan(p.std_fisher)) << name;            // no Fisher std for breakaway
  }
  ASSERT_EQ(r.prediction.readoff.size(), 3u);
  const MonteCarloSpread check = check_spread(PlanMethod::breakaway, r, rig, o.noise, 60);
  expect_agreement(r, check);
}

TEST(PlanSweep, SpeedsSpanVsAndThePredictionAgreesOnASimulatedRig) {
  const PlanRig rig = virgala();
  PlanOptions o;
  o.noise = parse_sensor_noise({"current=2e-3,velocity=0.2"});
  o.limits = parse_plan_limits({"speed=300"});
  o.design.speeds = 8;
  o.runs = 80;
  const PlanResult r = plan_experiment(PlanMethod::sweep, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.profile.column_names()[1], "velocity_rad_s");
  EXPECT_NEAR(r.profile.figure("bottom_speed"), 5.0 / 5, kExact);  // vs / 5
  EXPECT_NEAR(r.profile.figure("top_speed"), 0.95 * 300, kExact);
  EXPECT_EQ(r.profile.windows.size(), 16u);  // 8 speeds, both directions
  EXPECT_TRUE(r.undetermined.empty());
  for (const auto& p : r.prediction.parameters) EXPECT_TRUE(std::isfinite(p.std_fisher)) << p.name;
  const MonteCarloSpread check = check_spread(PlanMethod::sweep, r, rig, o.noise, 80);
  expect_agreement(r, check);
  expect_a_priori_agreement(r, check);  // the segment means' noise is white: the a-priori std holds
}

TEST(PlanSweep, NoSpeedBelowVsLeavesVsAndDeltaUndetermined) {
  PlanOptions o;
  o.noise = parse_sensor_noise({"current=1e-3"});
  o.limits = parse_plan_limits({"speed=300,min_speed=6"});  // above the prior's vs = 5 rad/s
  o.design.speeds = 6;
  o.runs = 3;
  const PlanResult r = plan_experiment(PlanMethod::sweep, virgala(), o);
  // Fs too: with vs free and no speed below it, Fs - Fc trades against vs (singular information).
  EXPECT_THAT(r.undetermined, ::testing::UnorderedElementsAre("vs", "delta", "Fs"));
  EXPECT_THAT(::testing::Matches(HasSubstr("Fs is not determined by this plan: its Fisher information"))(
                  [&] { std::string all; for (const auto& w : r.warnings) all += w + "\n"; return all; }()),
              true);
  EXPECT_TRUE(std::isnan(r.prediction.parameter("vs").std_monte_carlo));
  EXPECT_TRUE(std::isfinite(r.prediction.parameter("Fc").std_monte_carlo));
  EXPECT_TRUE(std::isnan(r.prediction.parameter("vs").std_a_priori));
  EXPECT_TRUE(std::isnan(r.prediction.parameter("Fs").std_a_priori));
  EXPECT_TRUE(std::isfinite(r.prediction.parameter("Fc").std_a_priori));
  const auto j = nlohmann::json::parse(plan_to_json(r, o));
  EXPECT_TRUE(j["prediction"]["parameters"]["vs"]["std"].is_null());
  EXPECT_TRUE(j["prediction"]["parameters"]["vs"]["std_fisher"].is_null());
  EXPECT_TRUE(j["prediction"]["parameters"]["vs"]["std_a_priori"].is_null());
  EXPECT_GT(j["prediction"]["parameters"]["Fc"]["std_a_priori"].get<double>(), 0);
  EXPECT_EQ(j["undetermined"].size(), 3u);
  EXPECT_THAT(j["warnings"][0].get<std::string>(), HasSubstr("below the prior's vs = 5 rad/s"));
  EXPECT_THAT(error_of([&] {
                PlanLimits l = parse_plan_limits({"speed=10,min_speed=6"});
                design_experiment(PlanMethod::sweep, virgala(), l, {});
              }),
              HasSubstr("--limits min_speed = 6 rad/s leaves no range of speeds"));
}

TEST(PlanIdim, MovesStayInTheTravelAndThePredictionAgreesOnASimulatedRig) {
  const PlanRig rig = emps_axis();
  EXPECT_EQ(rig.drive, PlanDrive::position_loop);
  PlanOptions o;
  o.noise = parse_sensor_noise({"position=2e-6,force=2,encoder=1e-6"});
  o.limits = parse_plan_limits({"travel=0.2,force=1500"});
  o.runs = 40;
  const PlanResult r = plan_experiment(PlanMethod::idim, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.profile.column_names()[1], "position_m");
  double excursion = 0;
  for (const auto& f : r.simulated)
    if (f.name == "excursion") excursion = f.value;
  EXPECT_LE(excursion, 0.2);
  EXPECT_GT(excursion, 0.15);  // the moves use the travel: 0.9 of it
  for (const char* name : {"M", "Fv", "Fc", "offset"}) {
    const auto& p = r.prediction.parameter(name);
    EXPECT_FALSE(p.undetermined) << name;
    EXPECT_TRUE(std::isfinite(p.std_fisher)) << name;
  }
  const MonteCarloSpread check = check_spread(PlanMethod::idim, r, rig, o.noise, 40);
  expect_agreement(r, check, Fisher::conservative);
  // The a-priori std misses what the position noise does to the Coulomb column sign(qd) (sign
  // flips at standstill and near reversals: not linear in the noise), so with position noise
  // it is optimistic; the Monte Carlo std is the prediction then (README, Plan the experiment).
  for (const auto& p : r.prediction.parameters)
    EXPECT_LT(p.std_a_priori, check.parameter(p.name).std_monte_carlo) << p.name;
  EXPECT_THAT(error_of([&] {
                design_experiment(PlanMethod::idim, rig, parse_plan_limits({"force=25"}), {});
              }),
              HasSubstr("--limits force = 25 N leaves no force to accelerate"));
}

// Force noise alone: the idim model is linear in its parameters and the noise is in the fitted
// signal only, filtered and decimated (correlated between decimated samples, counted through the
// pipeline's impulse responses): the a-priori std agrees with the spread of identifications.
TEST(PlanIdim, APrioriStdAgreesWithTheSpreadUnderForceNoise) {
  const PlanRig rig = emps_axis();
  PlanOptions o;
  o.noise = parse_sensor_noise({"force=2"});
  o.limits = parse_plan_limits({"travel=0.2,force=1500"});
  o.runs = 40;
  const PlanResult r = plan_experiment(PlanMethod::idim, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  const MonteCarloSpread check = check_spread(PlanMethod::idim, r, rig, o.noise, 40);
  expect_agreement(r, check, Fisher::conservative);
  expect_a_priori_agreement(r, check);
  const AprioriSpread a = a_priori_spread(PlanMethod::idim, r.profile, rig, simulate_profile(r.profile, rig, rig.law), o.noise);
  EXPECT_EQ(a.names, (std::vector<std::string>{"M", "Fv", "Fc", "offset"}));
  EXPECT_TRUE(a.undetermined.empty());
  ASSERT_EQ(a.std_white.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k)
    std::cout << "  " << a.names[k] << ": a priori " << a.std[k] << ", white-noise formula " << a.std_white[k] << "\n";
  // No noise: a std of zero, not NaN.
  const AprioriSpread none = a_priori_spread(PlanMethod::idim, r.profile, rig, simulate_profile(r.profile, rig, rig.law), {});
  for (double x : none.std) EXPECT_EQ(x, 0.0);
  EXPECT_TRUE(a_priori_spread(PlanMethod::breakaway, r.profile, rig, {}, o.noise).names.empty());
}

// The LuGre self-check with few runs: each output-error fit takes about 0.3 s here, so 24 runs
// predict and 24 check (about 12 s). The ratio of two sample stds of 24 runs each lies within
// 1.5 with about 95 % probability (F(23, 23)), so the factor is also the statistical limit.
TEST(PlanLugre, PredictedStdAgreesWithTheSpreadOnASimulatedRig) {
  const PlanRig rig = canudas();
  const PlanOptions o = lugre_options(24);
  const PlanResult r = plan_experiment(PlanMethod::lugre, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.prediction.failed, 0);
  const MonteCarloSpread check = check_spread(PlanMethod::lugre, r, rig, o.noise, 24);
  EXPECT_EQ(check.failed, 0);
  expect_agreement(r, check);
}

TEST(PlanLugre, PreslidingAndSlidingWithinTheTravel) {
  const PlanRig rig = canudas();
  const PlanOptions o = lugre_options(2);
  const PlanResult r = plan_experiment(PlanMethod::lugre, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.profile.column_names()[1], "force_N");
  EXPECT_NEAR(r.profile.figure("sliding_amplitude"), 3.0, kExact);  // 2 Fs
  EXPECT_LE(r.profile.figure("excursion"), 0.9 * 0.05);
  EXPECT_GT(r.profile.figure("peak_speed"), 10 * 0.001);  // well over vs
  EXPECT_GT(r.profile.figure("sliding_frequency"), 0.5);  // raised from 0.5 Hz by the travel
  for (const char* name : {"sigma0", "sigma1", "Fc", "Fs"}) EXPECT_GT(r.prediction.parameter(name).runs, 0) << name;
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::lugre, rig, parse_plan_limits({"force=1.5"}), {}); }),
              HasSubstr("--limits force = 1.5 N is below"));
}

// ---- the effects' designs: load steps, warm-up, ripple scan (issue: load, temperature, position) ----
namespace {

// The EMPS-like axis with `e` on its prior law (and so on the simulated rig).
PlanRig effects_rig(const LawEffects& e) {
  PlanRig rig = emps_axis();
  rig.law = rig.law.with_effects(e);
  rig.scenario.law = rig.law;
  return rig;
}

LawEffects load_effect() {
  LawEffects e;
  e.load = LoadDependence{0.1, 0.1};  // 20 N more Coulomb friction at the largest load, 200 N
  return e;
}

LawEffects temperature_effect() {
  LawEffects e;
  TemperatureDependence t;
  t.T_ref = 20.0;
  t.Fv_per_K = -2.0;  // N s/m/K: 1 % of Fv per kelvin, as grease thinning
  e.temperature = t;
  return e;
}

// A thermal model that heats the EMPS axis by about 10 K in the run (about 6 W dissipated).
PlanRig warm_rig(double tau) {
  PlanRig rig = effects_rig(temperature_effect());
  ContactEnvironment env;
  ThermalModel th;
  th.T_ambient = 20.0;
  th.tau = tau;
  th.R = 2.0;
  env.thermal = th;
  rig.scenario.options.environments = {env};
  return rig;
}

LawEffects ripple_effect() {
  LawEffects e;
  e.ripple = PositionRipple{0.02, {2.0}, {-1.0}, {}, {}};  // N: cogging of a 20 mm pitch
  return e;
}

// Force noise alone (as PlanIdim.APrioriStdAgreesWithTheSpreadUnderForceNoise): the idim model is
// linear in its parameters, so both predictions (Monte Carlo and a priori) must agree with the
// spread of identifications on an independent rig within kAgreement.
PlanOptions effects_options(int runs) {
  PlanOptions o;
  o.noise = parse_sensor_noise({"force=2"});
  o.limits = parse_plan_limits({"travel=0.2,force=1500"});
  o.runs = runs;
  return o;
}

void expect_effect_determined(const PlanResult& r, const MonteCarloSpread& check, const std::string& name) {
  const auto& p = r.prediction.parameter(name);
  EXPECT_FALSE(p.undetermined) << name;
  const double actual = check.parameter(name).std_monte_carlo;
  std::cout << "  " << name << ": prior " << p.prior << ", mean " << p.mean << ", predicted std " << p.std_monte_carlo
            << " (a priori " << p.std_a_priori << "), check spread " << actual << "\n";
  EXPECT_LT(p.std_a_priori / actual, kAgreement) << name;
  EXPECT_GT(p.std_a_priori / actual, 1 / kAgreement) << name;
  // The effect is seen, not lost in the noise: its std is well below its prior value.
  EXPECT_LT(p.std_monte_carlo, 0.2 * std::abs(p.prior)) << name;
}

}  // namespace

TEST(PlanEffects, LoadStepsSeparateMuLoadAndThePredictionAgreesOnASimulatedRig) {
  const PlanRig rig = effects_rig(load_effect());
  PlanOptions o = effects_options(40);
  o.design.load = 200;  // N
  const PlanResult r = plan_experiment(PlanMethod::load_steps, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.profile.column_names(), (std::vector<std::string>{"time_s", "position_m", "load_N"}));
  EXPECT_THAT(r.profile.to_csv(), HasSubstr(",200\n"));
  for (const auto& w : r.warnings) EXPECT_THAT(w, ::testing::Not(HasSubstr("confounded"))) << w;
  const MonteCarloSpread check = check_spread(PlanMethod::load_steps, r, rig, o.noise, 40);
  expect_agreement(r, check, Fisher::conservative);
  expect_a_priori_agreement(r, check);
  expect_effect_determined(r, check, "mu_load");
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::load_steps, rig, o.limits, o.noise, {}); }),
              HasSubstr("--load: a load-steps plan needs the largest load"));
}

TEST(PlanEffects, WarmUpSeparatesFvPerKAndThePredictionAgreesOnASimulatedRig) {
  const PlanRig rig = warm_rig(20.0);  // s: the run lasts 2 tau = 40 s
  const PlanOptions o = effects_options(40);
  const PlanResult r = plan_experiment(PlanMethod::warm_up, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  double rise = 0;
  for (const auto& f : r.simulated)
    if (f.name == "temperature_rise") rise = f.value;
  EXPECT_GT(rise, 5.0);  // K: the contact does warm up
  for (const auto& f : r.simulated) std::cout << "  " << f.name << " " << f.value << " " << f.unit << "\n";
  for (const auto& w : r.warnings) EXPECT_THAT(w, ::testing::Not(HasSubstr("confounded"))) << w;
  const MonteCarloSpread check = check_spread(PlanMethod::warm_up, r, rig, o.noise, 40);
  expect_agreement(r, check, Fisher::conservative);
  expect_a_priori_agreement(r, check);
  expect_effect_determined(r, check, "Fv_per_K");
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::warm_up, emps_axis(), o.limits, o.noise, {}); }),
              HasSubstr("a warm-up plan needs the contact's thermal model"));
}

// A contact whose temperature follows the dissipated power at once (tau = 50 ms) is hot at the
// fast moves and cool at the slow ones: qd (T - T_ref) is then a function of the speed, which
// sign(qd) and qd span at two speeds. The plan says it cannot separate Fv_per_K.
TEST(PlanEffects, TemperatureThatFollowsTheSpeedIsWarnedAsConfounded) {
  const PlanRig rig = warm_rig(0.05);
  PlanOptions o = effects_options(4);
  o.design.warm_up = 6;  // s
  const PlanResult r = plan_experiment(PlanMethod::warm_up, rig, o);
  bool warned = false;
  for (const auto& w : r.warnings)
    if (w.find("Fv_per_K is confounded with the speed") != std::string::npos &&
        w.find("temperature follows the speed schedule") != std::string::npos)
      warned = true;
  for (const auto& f : r.simulated) std::cout << "  " << f.name << " " << f.value << " " << f.unit << "\n";
  EXPECT_TRUE(warned) << ::testing::PrintToString(r.warnings);
}

TEST(PlanEffects, RippleScanResolvesTheHarmonicsAndThePredictionAgreesOnASimulatedRig) {
  const PlanRig rig = effects_rig(ripple_effect());
  const PlanOptions o = effects_options(40);
  const PlanResult r = plan_experiment(PlanMethod::ripple_scan, rig, o);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.profile.figure("distance"), 4 * 0.02, 4 * 0.02 * kExact);
  for (const auto& f : r.simulated) std::cout << "  " << f.name << " " << f.value << " " << f.unit << "\n";
  for (const auto& f : r.profile.figures) std::cout << "  " << f.name << " " << f.value << " " << f.unit << "\n";
  for (const auto& w : r.warnings) std::cout << "  warning: " << w << "\n";
  for (const auto& w : r.warnings) EXPECT_THAT(w, ::testing::Not(HasSubstr("confounded"))) << w;
  const MonteCarloSpread check = check_spread(PlanMethod::ripple_scan, r, rig, o.noise, 40);
  expect_agreement(r, check, Fisher::conservative);
  expect_a_priori_agreement(r, check);
  expect_effect_determined(r, check, "ripple_sin_1");
  expect_effect_determined(r, check, "ripple_cos_1");
  EXPECT_THAT(error_of([&] { design_experiment(PlanMethod::ripple_scan, emps_axis(), o.limits, o.noise, {}); }),
              HasSubstr("has no ripple"));
  EXPECT_THAT(error_of([&] {
                design_experiment(PlanMethod::ripple_scan, rig, parse_plan_limits({"travel=0.05"}), o.noise, {});
              }),
              HasSubstr("--limits travel = 0.05 m is shorter than 4 ripple periods"));
}
