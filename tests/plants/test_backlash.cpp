// Axis with backlash (plants/backlash_axis.hpp): the crossing of the play, impacts and separation
// at the exact instants of their closed forms, the exact stick of the engaged drivetrain, the
// friction on the motor side, a PID around the play, and the scenario keys.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/plants/backlash_axis.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

// Event times come from CVODE's root finder at the default rtol 1e-8 (and closed forms of a few
// operations): 1e-7 relative covers both. Velocities and positions of a row are integrated at
// rtol 1e-8 over a second of piecewise-constant accelerations: 1e-6 relative.
constexpr double kEventRel = 1e-7;
constexpr double kStateRel = 1e-6;

InputSignal constant(double u) {
  InputSignal in;
  in.value = u;
  return in;
}

// A motor of 0.5 kg across a play of 20 mm onto a load of 1.5 kg.
BacklashParams rig() {
  BacklashParams p;
  p.M_motor = 0.5;
  p.M_load = 1.5;
  p.width = 0.02;
  return p;
}

std::size_t row_at(const Trajectory& tr, double t) {
  for (std::size_t i = 0; i < tr.rows(); ++i)
    if (tr.time[i] >= t - 1e-12) return i;
  return tr.rows() - 1;
}

// The motor of rig() pushed by 2 N onto the load held by Fs 1.2, Fc 1 N, one second.
Trajectory strike(SimulationOptions o) {
  o.duration = 1.0;
  o.output_rate = 1000;
  return simulate(BacklashAxis(rig()), StaticCoulombViscous{1.2, 1.0, 0.0}, constant(2.0), o);
}

}  // namespace

TEST(Backlash, TheMotorCrossesThePlayAndStrikesTheStuckLoad) {
  // u = 2 N accelerates the motor alone at 4 m/s^2 over half the play (10 mm): it strikes at
  // t1 = sqrt(2 * 0.01 / 4) with 4 t1; a plastic impact gives both 0.5 * 4 t1 / 2; engaged they
  // slide at (2 - Fc) / 2 = 0.5 m/s^2 against Fc = 1 N.
  const Trajectory tr = strike({});
  const double t1 = std::sqrt(2 * 0.01 / 4.0), v1 = 0.5 * 4 * t1 / 2.0;
  ASSERT_EQ(tr.plant_events.size(), 1u);
  EXPECT_EQ(tr.plant_events[0].index, 0);  // the forward flank
  EXPECT_NEAR(tr.plant_events[0].time, t1, kEventRel * t1);
  ASSERT_EQ(tr.switches.size(), 1u);
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::impact);
  EXPECT_EQ(tr.switches[0].direction, 1);
  EXPECT_NEAR(tr.switches[0].time, t1, kEventRel * t1);
  // The load did not move before the impact (stuck, exactly), then follows the closed form.
  EXPECT_EQ(tr.position[row_at(tr, t1 - 0.002)], 0.0);
  EXPECT_EQ(tr.stuck[row_at(tr, t1 - 0.002)], 1.0);
  const double dt = 1.0 - t1;
  EXPECT_NEAR(tr.velocity.back(), v1 + 0.5 * dt, kStateRel * (v1 + 0.5 * dt));
  EXPECT_NEAR(tr.position.back(), v1 * dt + 0.25 * dt * dt, kStateRel * (v1 * dt + 0.25 * dt * dt));
  EXPECT_DOUBLE_EQ(tr.friction.back(), 1.0);
}

TEST(Backlash, TheEngagedDrivetrainHoldsBelowTheBreakawayLevelAndMovesAbove) {
  // Starting on the forward flank, the motor pushes the load with u: the whole drivetrain is
  // stuck while u <= Fs (exactly: position 0 to the last bit) and breaks away at once above.
  BacklashParams p = rig();
  p.initial_gap = p.width / 2;
  const BacklashAxis plant(p);
  const FrictionLaw law = StaticCoulombViscous{1.2, 1.0, 0.0};
  SimulationOptions o;
  o.duration = 1.0;
  o.output_rate = 100;
  constexpr double kMargin = 1e-9;  // N: far above the roundoff of the level, far below its size
  const Trajectory held = simulate(plant, law, constant(1.2 - kMargin), o);
  EXPECT_TRUE(held.switches.empty());
  EXPECT_TRUE(held.plant_events.empty());
  for (double q : held.position) ASSERT_EQ(q, 0.0);
  const Trajectory moved = simulate(plant, law, constant(1.2 + kMargin), o);
  EXPECT_TRUE(moved.plant_events.empty());  // it slides from t = 0, engaged throughout
  EXPECT_GT(moved.position.back(), 0.0);
  // Pulling back with 0.5 N, the motor leaves the flank at once (a separation at t = 0), crosses
  // the play at 1 m/s^2 while the load stays, strikes its backward flank at t = sqrt(0.04) with
  // -0.2 m/s (plastic: both -0.05 m/s), and the two stop after 0.2 s more at (1 - 0.5) / 2 m/s^2.
  const Trajectory pulled = simulate(plant, law, constant(-0.5), o);
  ASSERT_EQ(pulled.plant_events.size(), 2u);
  EXPECT_EQ(pulled.plant_events[0].index, 2);
  EXPECT_EQ(pulled.plant_events[0].time, 0.0);
  EXPECT_EQ(pulled.plant_events[1].index, 1);
  EXPECT_NEAR(pulled.plant_events[1].time, 0.2, kEventRel * 0.2);
  EXPECT_EQ(pulled.position[row_at(pulled, 0.19)], 0.0);
  ASSERT_EQ(pulled.switches.size(), 2u);
  EXPECT_EQ(pulled.switches[1].kind, SwitchKind::stick);
  EXPECT_NEAR(pulled.switches[1].time, 0.4, kEventRel * 0.4);
  EXPECT_NEAR(pulled.position.back(), -0.005, kStateRel * 0.005);
}

TEST(Backlash, ARestitutionReversesTheClosingSpeedAndKeepsMomentum) {
  // e = 0.5: after the first impact the load has v + e Mm/M vr, the motor v - e Ml/M vr; the
  // load then slides freely against Fc = 0.3 N (decelerating at 0.2 m/s^2) until the motor,
  // pushed again at 4 m/s^2, strikes it a second time.
  BacklashParams p = rig();
  p.restitution = 0.5;
  const BacklashAxis plant(p);
  const FrictionLaw law = StaticCoulombViscous{0.3, 0.3, 0.0};
  SimulationOptions o;
  o.duration = 0.5;
  o.output_rate = 10000;
  const Trajectory tr = simulate(plant, law, constant(2.0), o);
  const double t1 = std::sqrt(2 * 0.01 / 4.0), vr = 4 * t1, v = 0.5 * vr / 2.0;
  const double vl = v + 0.5 * 0.5 / 2.0 * vr;
  ASSERT_GE(tr.plant_events.size(), 2u);
  EXPECT_NEAR(tr.plant_events[0].time, t1, kEventRel * t1);
  // Between the impacts the load decelerates from vl at Fc / Ml.
  const double t2 = tr.plant_events[1].time;
  ASSERT_GT(t2, t1 + 0.002);
  const std::size_t i = row_at(tr, t1 + 0.001);
  const double expected = vl - 0.3 / 1.5 * (tr.time[i] - t1);
  EXPECT_NEAR(tr.velocity[i], expected, kStateRel * expected);
  // The second impact closes the gap again: the motor (v - e Ml/M vr, then 4 m/s^2) catches the
  // load where their positions differ by the play's half again.
  const double vm = v - 0.5 * 1.5 / 2.0 * vr, dt = t2 - t1;
  const double motor = vm * dt + 2.0 * dt * dt, load = vl * dt - 0.1 * dt * dt;
  EXPECT_NEAR(motor - load, 0.0, kStateRel * 0.01);
  EXPECT_EQ(tr.plant_events[1].index, 0);
}

TEST(Backlash, FrictionOnTheMotorSideHoldsTheMotorWhileTheLoadFallsAcrossThePlay) {
  // The load (1 kg) has its weight of 1 N as offset; the motor (friction side, Fs 1.5 N) is held.
  // The load falls 10 mm across the play (t1 = sqrt(0.02)), strikes the motor into motion
  // (plastic, v = 1 * 0.1414 / 1.5) and the two slow down at (1 - Fc) / 1.5 until they stop and stick.
  BacklashParams p;
  p.M_motor = 0.5;
  p.M_load = 1.0;
  p.width = 0.02;
  p.offset = 1.0;
  p.friction_side = FrictionSide::motor;
  const BacklashAxis plant(p);
  const FrictionLaw law = StaticCoulombViscous{1.5, 1.3, 0.0};
  SimulationOptions o;
  o.duration = 1.0;
  o.output_rate = 1000;
  const Trajectory tr = simulate(plant, law, constant(0.0), o);
  const double t1 = std::sqrt(0.02), v = 1.0 * t1 / 1.5;
  ASSERT_EQ(tr.plant_events.size(), 1u);
  EXPECT_EQ(tr.plant_events[0].index, 1);  // the load reached the motor's backward flank
  EXPECT_NEAR(tr.plant_events[0].time, t1, kEventRel * t1);
  ASSERT_EQ(tr.switches.size(), 2u);
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::impact);
  EXPECT_EQ(tr.switches[1].kind, SwitchKind::stick);
  const double t_stop = t1 + v / (0.3 / 1.5);
  EXPECT_NEAR(tr.switches[1].time, t_stop, kEventRel * t_stop);
  EXPECT_NEAR(tr.position.back(), v * v / (2 * 0.3 / 1.5), kStateRel * 0.01);
}

TEST(Backlash, APidAcrossThePlayReachesTheTargetAndReportsItsImpacts) {
  // A PD loop on the load position (the friction side), 5 mm and back at 1.5 s: the motor crosses
  // the play, strikes the load, and the load sticks within reach of the target (stiction holds
  // it where Kp |error| < Fs). Reversed, the motor leaves the flank at once while the stuck load
  // stays put: no breakaway at 1.5 s (the engaged force that would have broken it loose is gone
  // with the separation), only the next impact moves it.
  BacklashParams p = rig();
  p.width = 0.002;
  auto axis = std::make_shared<const BacklashAxis>(p);
  PidParams c;
  c.Kp = 400;
  c.Kd = 60;
  const auto loop = close_loop(axis, c);
  const FrictionLaw law = StaticCoulombViscous{0.5, 0.4, 0.5};
  InputSignal steps;
  steps.shape = InputShape::table;
  steps.times = {0.0, 1.5};
  steps.values = {0.005, 0.0};
  steps.hold_steps = true;
  SimulationOptions o;
  o.duration = 3.0;
  o.output_rate = 500;
  const Trajectory tr = simulate(*loop, law, steps, o);
  ASSERT_EQ(tr.plant_events.size(), 3u);
  EXPECT_EQ(tr.plant_events[0].index, 0);  // the forward flank
  EXPECT_EQ(tr.plant_events[1].index, 2);  // separation at the reversal
  EXPECT_EQ(tr.plant_events[1].time, 1.5);
  EXPECT_EQ(tr.plant_events[2].index, 1);  // the backward flank
  // Impacts at the two flank events; at the reversal the load only sticks (the separation took
  // its drive away while it crept to its equilibrium), never breaks away.
  std::vector<double> impacts;
  for (const ModeSwitch& sw : tr.switches) {
    EXPECT_NE(sw.kind, SwitchKind::breakaway) << "at t = " << sw.time << " s";
    if (sw.kind == SwitchKind::impact) impacts.push_back(sw.time);
  }
  ASSERT_EQ(impacts.size(), 2u);
  EXPECT_EQ(impacts[0], tr.plant_events[0].time);
  EXPECT_EQ(impacts[1], tr.plant_events[2].time);
  const double held = 0.5 / 400;  // m: the error that stiction (Fs 0.5 N) holds against Kp
  EXPECT_NEAR(tr.position[row_at(tr, 1.49)], 0.005, held);
  EXPECT_NEAR(tr.position.back(), 0.0, held);
  constexpr double kCreep = 1e-6;  // m/s: the overdamped approach to the Coulomb equilibrium
  EXPECT_LT(std::abs(tr.velocity.back()), kCreep);
}

TEST(Backlash, FixedStepAgreesWithTheExactEngineToAStep) {
  const Trajectory exact = strike({});
  SimulationOptions o;
  o.dt = 1e-5;
  o.mode = SolverMode::fixed_step;
  const Trajectory fixed = strike(o);
  ASSERT_EQ(fixed.plant_events.size(), 1u);
  EXPECT_NEAR(fixed.plant_events[0].time, exact.plant_events[0].time, 2 * o.dt);
  constexpr double kEulerRel = 1e-3;  // first-order steps of 1e-5 s over 1 s
  EXPECT_NEAR(fixed.position.back(), exact.position.back(), kEulerRel * exact.position.back());
}

TEST(Backlash, ScenarioReadsThePlayAndRefusesBadValuesNamingTheKey) {
  const std::string head = "input: {type: constant, value: 2}\nduration: 1\nfriction: {law: static-coulomb-viscous, Fs: 1.2, Fc: 1, Fv: 0}\n";
  const Scenario sc = scenario_from_yaml(
      YAML::Load(head + "plant: {type: axis, M: 1.5, backlash: {width: 0.02, motor_inertia: 0.5}}\n"), "s.yaml");
  const auto* b = dynamic_cast<const BacklashAxis*>(sc.plant.get());
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->params().M_load, 1.5);
  EXPECT_EQ(b->params().M_motor, 0.5);
  EXPECT_EQ(b->params().friction_side, FrictionSide::load);
  EXPECT_EQ(simulate(sc).plant_events.size(), 1u);
  auto refused = [&](const std::string& backlash, const std::string& named) {
    try {
      (void)scenario_from_yaml(YAML::Load(head + "plant: {type: axis, M: 1.5, backlash: " + backlash + "}\n"), "s.yaml");
      ADD_FAILURE() << "accepted backlash " << backlash;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.yaml"), std::string::npos) << e.what();
    }
  };
  refused("{width: 0, motor_inertia: 0.5}", "backlash.width = 0 must be > 0 (m or rad");
  refused("{width: 0.02}", "missing 'motor_inertia'");
  refused("{width: 0.02, motor_inertia: 0.5, restitution: 1}", "backlash.restitution = 1 must be in [0, 1)");
  refused("{width: 0.02, motor_inertia: 0.5, friction_side: base}", "unknown friction side 'base'; valid sides: load, motor");
  refused("{width: 0.02, motor_inertia: 0.5, initial_gap: 0.02}", "backlash.initial_gap = 0.02 must be within +-width/2");
  refused("{width: 0.02, motor_inertia: 0.5, gap: 1}", "unknown field 'gap'");
  // The EMPS controller does not forward the plant's impacts: refused, naming the remedy.
  try {
    (void)close_loop(std::make_shared<const BacklashAxis>(rig()), EmpsPdParams{});
    ADD_FAILURE() << "an EMPS loop around a backlash was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("use a pid controller"), std::string::npos) << e.what();
  }
}
