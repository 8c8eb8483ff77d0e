// Load, temperature and ripple effects from scenario and law files: what is read, and what is
// refused naming the key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "frictionlab/error.hpp"
#include "frictionlab/scenario/law_file.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

Scenario parse(const std::string& text) { return scenario_from_yaml(YAML::Load(text), "s.yaml"); }

// `text` must be refused with an InputError whose key is `key` and whose message names `key` and `also`.
void expect_refused(const std::string& text, const std::string& key, const std::string& also = "") {
  try {
    (void)parse(text);
    FAIL() << "accepted a scenario that breaks " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.fields().key, key) << e.what();
    EXPECT_EQ(e.fields().file, "s.yaml") << e.what();
    if (!also.empty()) {
      EXPECT_NE(std::string(e.what()).find(also), std::string::npos) << e.what();
    }
  }
}

}  // namespace

TEST(EffectsScenario, ReadsTheLawsEffectsAndTheEnvironment) {
  const Scenario sc = parse(R"(
plant: {type: axis, M: 1.0}
friction: {law: stribeck, Fc: 1, Fs: 1.5, vs: 0.01, Fv: 0.1, mu_load: 0.1,
           T_ref: 20, Fv_per_K: -0.001, T_min: -20, T_max: 90,
           ripple_period: 0.005, ripple_a: [0.1, 0.02], ripple_b: [0.05, 0]}
environment:
  load: {type: ramp, initial: 10, rate: -1}
  thermal: {T_ambient: 25, tau: 300, R: 2}
input: {type: constant, value: 2.2}
duration: 4
)");
  const LawEffects& e = sc.law.effects();
  ASSERT_TRUE(e.load && e.temperature && e.ripple);
  EXPECT_EQ(e.load->mu_static, 0.1);
  EXPECT_EQ(e.temperature->Fv_per_K, -0.001);
  EXPECT_EQ(*e.temperature->T_max, 90.0);
  EXPECT_EQ(e.ripple->a.size(), 2u);
  ASSERT_EQ(sc.options.environments.size(), 1u);
  EXPECT_TRUE(sc.options.environments[0].load.signal.has_value());
  EXPECT_EQ(sc.options.environments[0].thermal->tau, 300.0);
  // Held by the loaded level 1.5 + 0.1 (10 - t) against 2.2 - r(0) = 2.2 - 0.05: it breaks loose
  // when 2.5 - 0.1 t = 2.15, at t = 3.5 s.
  const Trajectory tr = simulate(sc);
  ASSERT_FALSE(tr.switches.empty());
  constexpr double kRel = 1e-7;  // event times from CVODE's root finder at rtol 1e-8
  EXPECT_NEAR(tr.switches[0].time, 3.5, kRel * 3.5);
  // The CSV has the load and temperature columns.
  EXPECT_NE(tr.to_csv().find(",stuck,load,temperature\n"), std::string::npos);
  EXPECT_EQ(tr.column("temperature").front(), 25.0);
}

TEST(EffectsScenario, GravityLoadOfAJointFollowsItsAngle) {
  // m g l cos(q) = 2 * 10 * 0.5 cos(0.3): a level of Fc + 0.1 of it; a push 1e-6 below holds.
  const double level = 1.0 + 0.1 * 2 * 10 * 0.5 * std::cos(0.3);
  const std::string text = R"(
plant: {type: axis, M: 0.5}
friction: {law: coulomb, Fc: 1, mu_load: 0.1}
environment: {load: {type: gravity, m: 2, l: 0.5, g: 10}}
initial: {position: 0.3}
duration: 1
input: {type: step, time: 0.5, value: )";
  constexpr double kMargin = 1e-6;  // N: far above the roundoff of the level, far below its size
  auto number = [](double x) {
    std::ostringstream o;
    o << std::setprecision(17) << x;
    return o.str();
  };
  const Trajectory held = simulate(parse(text + number(level - kMargin) + "}\n"));
  EXPECT_TRUE(held.switches.empty());
  constexpr double kLoadRel = 1e-15;  // the same product m g l cos(q), in another order at most
  EXPECT_NEAR(held.load.front(), 10 * std::cos(0.3), kLoadRel * 10);
  const Trajectory moved = simulate(parse(text + number(level + kMargin) + "}\n"));
  ASSERT_FALSE(moved.switches.empty());
  EXPECT_DOUBLE_EQ(moved.switches[0].time, 0.5);
}

TEST(EffectsScenario, BadValuesAreRefusedNamingTheKey) {
  const std::string head = "plant: {type: axis, M: 1}\ninput: {type: constant, value: 0}\nduration: 1\n";
  expect_refused(head + "friction: {law: coulomb, Fc: 1, mu_load: -0.2}\n", "friction.mu_load", "mu_load");
  expect_refused(head + "friction: {law: coulomb, Fc: 1, ripple_period: 0, ripple_a: [0.1]}\n", "friction.ripple_period", "> 0");
  expect_refused(head + "friction: {law: viscous, Fv: 1, T_ref: 20, Fv_per_K: -0.01, T_max: 150}\n", "friction.Fv_per_K", "150");
  const std::string law = "friction: {law: viscous, Fv: 1, T_ref: 20, Fv_per_K: -0.01, T_max: 80}\n";
  expect_refused(head + law + "environment: {thermal: {tau: 0, R: 1}}\n", "environment.thermal.tau", "> 0");
  expect_refused(head + law + "environment: {temperature: 20, thermal: {tau: 1, R: 1}}\n", "environment.thermal", "not both");
  expect_refused(head + law + "environment: {temperature: 95}\n", "environment.temperature", "T_max");
  expect_refused(head + law + "environment: {pressure: 1}\n", "environment.pressure", "load, temperature, thermal");
  expect_refused(head + law + "environment: {load: {type: gravity, l: 1}}\n", "environment.load.m");
  expect_refused(head + law + "environment: {load: {type: wave}}\n", "environment.load.type", "gravity");
}

TEST(EffectsScenario, LawFilesCarryTheEffectsBothWays) {
  const FrictionLaw law = law_from_yaml(YAML::Load("{law: lugre, sigma0: 1e5, sigma1: 300, sigma2: 0.4, Fc: 1, Fs: 1.5, vs: 0.001, "
                                                   "mu_load_static: 0.05, mu_load_coulomb: 0.02, ripple_period: 0.01, ripple_a: 0.1}"),
                                        "law.yaml");
  EXPECT_EQ(law.effects().load->mu_coulomb, 0.02);
  EXPECT_EQ(law.effects().ripple->a, std::vector<double>{0.1});
  const FrictionLaw back = law_from_json(law_to_json(law), "law.json");
  EXPECT_EQ(back.to_spec().scalars, law.to_spec().scalars);
  EXPECT_EQ(back.to_spec().arrays, law.to_spec().arrays);
}

// A controller's feedforward compensation of a law with a load term sees the environment's load:
// a gravity load estimated from the plant's state, and the fixed temperature.
TEST(EffectsScenario, CompensationSeesTheEnvironmentsLoadAndTemperature) {
  const Scenario sc = parse(R"(
plant: {type: axis, M: 1.0}
friction: {law: coulomb-viscous, Fc: 1, Fv: 0.4, mu_load: 0.1, T_ref: 20, Fv_per_K: -0.01}
controller: {loop: position, Kp: 100, Kd: 20, compensation: {type: feedforward, band: 0.001}}
environment:
  load: {type: gravity, m: 5, l: 1, g: 9.81, phase: 0}
  temperature: 35
input: {type: ramp, rate: 0.2}
duration: 0.1
)");
  const auto* loop = dynamic_cast<const ClosedLoop*>(sc.plant.get());
  ASSERT_NE(loop, nullptr);
  ASSERT_TRUE(loop->conditions().load.given());
  EXPECT_EQ(loop->conditions().temperature, 35.0);
  std::vector<double> x(static_cast<std::size_t>(loop->num_states()), 0.0);
  x[0] = 0.3;  // m
  InputValue r;
  r.value = 0.3;
  r.rate = 0.2;
  Conditions c;
  c.load = 5 * 9.81 * std::cos(0.3);
  c.temperature = 35.0;
  EXPECT_NEAR(loop->compensation(0.0, x, r), sc.law.sliding(0.2, c), 1e-12);
}

// The EMPS controller's sampled loop hands its compensator the environment's load too: a unit
// mass follows a 50 mm/s ramp under the EMPS PD (kp kv gtau = 100 N/m) with feedforward
// compensation of a law whose Coulomb level rises by mu_load |F_load| = 0.1 x 50 N. Settled, the
// following error differs from the same loop whose compensator sees no load by the uncompensated
// 5 N over the loop's 100 N/m, 50 mm.
TEST(EffectsScenario, EmpsLoopCompensationSeesTheEnvironmentsLoad) {
  const Scenario sc = parse(R"(
plant: {type: axis, M: 1.0}
friction: {law: coulomb-viscous, Fc: 1, Fv: 0.4, mu_load: 0.1, T_ref: 20, Fv_per_K: -0.01}
controller: {type: emps-pd, kp: 20, kv: 5, gtau: 1, limit: 100, delay: 1, dt: 0.001, compensation: {type: feedforward, band: 0.001}}
environment: {load: {type: constant, value: 50}, temperature: 35}
input: {type: ramp, rate: 0.05}
duration: 4
output_rate: 100
)");
  const auto* loop = dynamic_cast<const EmpsPdLoop*>(sc.plant.get());
  ASSERT_NE(loop, nullptr);
  ASSERT_TRUE(loop->conditions().load.given());
  EXPECT_EQ(loop->conditions().temperature, 35.0);
  Scenario blind = sc;  // the same loop, its compensator told nothing (load 0, T_ref)
  blind.plant = loop->with_conditions(CompensationConditions{});
  // Mean following error (m) over the last second, settled (damping ratio 0.25 at 10 rad/s: the
  // start's transient has decayed by exp(-7.5) at t = 3 s).
  auto settled_error = [](const Trajectory& tr) {
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i)
      if (tr.time[i] >= 3.0) sum += tr.reference[i] - tr.position[i], ++n;
    return sum / n;
  };
  const double seen = settled_error(simulate(sc));
  const double unseen = settled_error(simulate(blind));
  // The temperature shift of the viscous term (-0.15 N s/m at 35 degC, 7.5 mN at 50 mm/s) and the
  // transient's remainder are below 1 mm; 2 % of the 50 mm difference covers them.
  constexpr double kRel = 0.02;
  EXPECT_NEAR(unseen - seen, 0.05, kRel * 0.05) << "seen " << seen << " m, unseen " << unseen << " m";
}

// A temperature over time (a log's column, here a table) is replayed: the law's viscous level at
// each row is the one at the logged temperature, a compensator sees the same temperature, and the
// temperature column of the run is the log's.
TEST(EffectsScenario, ALoggedTemperatureIsReplayedAsTheRunGoes) {
  const std::string head = R"(
plant: {type: axis, M: 1.0}
friction: {law: viscous, Fv: 1, T_ref: 20, Fv_per_K: -0.01, T_max: 80}
input: {type: constant, value: 0}
initial: {velocity: 1}
duration: 2
output_rate: 10
)";
  const Trajectory tr = simulate(parse(head + "environment: {temperature: {type: table, times: [0, 2], values: [20, 60]}}\n"));
  constexpr double kRel = 1e-6;  // CVODE at rtol 1e-8 over 2 s of a smooth decay
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    const double T = 20 + 20 * tr.time[i];
    EXPECT_NEAR(tr.temperature[i], T, 1e-12 * T) << "t = " << tr.time[i];
    const double Fv = 1 - 0.01 * (T - 20);
    EXPECT_NEAR(tr.friction[i], Fv * tr.velocity[i], kRel * std::abs(Fv * tr.velocity[i])) << "t = " << tr.time[i];
  }
  // The velocity decays as dv/dt = -Fv(t) v with Fv = 1 - 0.2 t: v = exp(-(t - 0.1 t^2)).
  EXPECT_NEAR(tr.velocity.back(), std::exp(-(2.0 - 0.4)), kRel * std::exp(-1.6));
  // Refused: a log that starts beyond the law's T_max; a log beside a thermal model.
  expect_refused(head + "environment: {temperature: {type: table, times: [0, 1], values: [95, 20]}}\n",
                 "environment.temperature", "T_max");
  expect_refused(head + "environment: {temperature: {type: constant, value: 30}, thermal: {tau: 1, R: 1}}\n",
                 "environment.thermal", "not both");
  const Scenario comp = parse(R"(
plant: {type: axis, M: 1.0}
friction: {law: coulomb-viscous, Fc: 1, Fv: 0.4, T_ref: 20, Fv_per_K: -0.01}
controller: {loop: position, Kp: 100, Kd: 20, compensation: {type: feedforward, band: 0.001}}
environment: {temperature: {type: ramp, initial: 20, rate: 10}}
input: {type: ramp, rate: 0.2}
duration: 0.1
)");
  const auto* loop = dynamic_cast<const ClosedLoop*>(comp.plant.get());
  ASSERT_NE(loop, nullptr);
  ASSERT_TRUE(loop->conditions().temperature_log.has_value());
  std::vector<double> x(static_cast<std::size_t>(loop->num_states()), 0.0);
  InputValue r;
  r.rate = 0.2;
  Conditions c;
  c.temperature = 20 + 10 * 1.5;
  EXPECT_NEAR(loop->compensation(1.5, x, r), comp.law.sliding(0.2, c), 1e-12);
}
