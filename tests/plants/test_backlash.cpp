// Axis with backlash (plants/backlash_axis.hpp): the crossing of the play, impacts and separation
// at the exact instants of their closed forms, the exact stick of the engaged drivetrain, the
// friction on the motor side, a PID around the play, and the scenario keys.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/plants/axis.hpp"
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

TEST(Backlash, APdLoopMeasuringTheMotorSettlesTheMotorAtTheReferenceAndTheLoadWithinThePlay) {
  // The PD loop of APidAcrossThePlay... with its encoder on the motor (measure: motor), stepped to
  // 5 mm and at 1.5 s back to 3.5 mm. Forward, the motor crosses the play and pushes the load
  // until the push, Kp (r - motor), falls to the load's Coulomb level: the pair stops 1 mm short
  // (motor 4 mm, load 3 mm, engaged). Back, the motor leaves the flank and crosses the play
  // without reaching the other one (3.5 mm lies within the load's 3 mm +- 1 mm): frictionless and
  // free, it settles at the reference (overdamped, slowest time constant 0.14 s), while the load
  // stays stuck where the forward move left it, within half the play of the motor. The run
  // records the motor's position as its own column.
  BacklashParams p = rig();
  p.width = 0.002;
  auto axis = std::make_shared<const BacklashAxis>(p);
  PidParams c;
  c.Kp = 400;
  c.Kd = 60;
  const auto base = std::make_shared<const ClosedLoop>(axis, c);
  const auto loop = base->measuring(MeasuredBody::motor);
  EXPECT_EQ(loop->measured_body(), MeasuredBody::motor);
  const FrictionLaw law = StaticCoulombViscous{0.5, 0.4, 0.5};
  InputSignal steps;
  steps.shape = InputShape::table;
  steps.times = {0.0, 1.5};
  steps.values = {0.005, 0.0035};
  steps.hold_steps = true;
  SimulationOptions o;
  o.duration = 4.0;
  o.output_rate = 500;
  const Trajectory tr = simulate(*loop, law, steps, o);
  ASSERT_EQ(tr.motor_position.size(), tr.rows());
  // Every row: the motor and the load are at most half the play apart.
  constexpr double kGapAbs = 1e-9;  // m: the located flank, to the root finder's tolerance
  for (std::size_t i = 0; i < tr.rows(); ++i)
    ASSERT_LE(std::abs(tr.motor_position[i] - tr.position[i]), p.width / 2 + kGapAbs) << "t = " << tr.time[i];
  // Before the reversal the engaged pair holds 1 mm short: Kp x 1 mm = Fc, the Coulomb level the
  // load slides down to (an overdamped approach: 10 um is what is left of it at 1.5 s, at most).
  constexpr double kApproachAbs = 1e-5;  // m
  const std::size_t before = row_at(tr, 1.49);
  EXPECT_NEAR(tr.motor_position[before], 0.004, kApproachAbs);
  EXPECT_NEAR(tr.position[before], 0.003, kApproachAbs);
  // After it: no impact, the motor at the reference, the load where it was, within the half-play.
  for (const PlantEvent& e : tr.plant_events) {
    if (e.time > 1.5) {
      EXPECT_EQ(e.index, 2) << "an impact after the reversal, at t = " << e.time;
    }
  }
  constexpr double kSettledAbs = 1e-7;  // m: e^(-2.5 s / 0.14 s) of the 0.5 mm step, and the solver's tolerance
  EXPECT_NEAR(tr.motor_position.back(), 0.0035, kSettledAbs);
  EXPECT_LE(std::abs(tr.position.back() - 0.0035), p.width / 2);
  EXPECT_NEAR(tr.position.back(), tr.position[before], kApproachAbs);
  EXPECT_EQ(tr.velocity.back(), 0.0);  // the load is stuck
  // The default loop measures the load (the friction side): the load settles within reach of the
  // reference (stiction holds it where Kp |error| < Fs), and the motor sits at a flank of it.
  const Trajectory on_load = simulate(*base, law, steps, o);
  EXPECT_NEAR(on_load.position.back(), 0.0035, 0.5 / 400);
  EXPECT_NEAR(std::abs(on_load.motor_position.back() - on_load.position.back()), p.width / 2, kGapAbs);
  // The CSV has the motor's column after the contact's.
  const std::string head = tr.to_csv().substr(0, tr.to_csv().find('\n'));
  EXPECT_EQ(head, "time,position,velocity,friction,applied,current,voltage,reference,stuck,motor_position");
  // A plant without a motor and a load is refused, naming the key.
  try {
    (void)ClosedLoop(std::make_shared<const RigidAxis>(AxisParams{}), c).measuring(MeasuredBody::motor);
    ADD_FAILURE() << "measure: motor accepted on a rigid axis";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("controller.measure"), std::string::npos) << e.what();
  }
}

TEST(Backlash, ScenarioControllerMeasuresTheMotorOrTheLoadByName) {
  const std::string head =
      "input: {type: constant, value: 0.005}\nduration: 2\noutput_rate: 100\n"
      "friction: {law: static-coulomb-viscous, Fs: 0.5, Fc: 0.4, Fv: 0.5}\n";
  const std::string plant = "plant: {type: axis, M: 1.5, backlash: {width: 0.002, motor_inertia: 0.5}}\n";
  auto loop_of = [&](const std::string& yaml) {
    const Scenario sc = scenario_from_yaml(YAML::Load(yaml), "s.yaml");
    const auto* loop = dynamic_cast<const ClosedLoop*>(sc.plant.get());
    EXPECT_NE(loop, nullptr);
    return loop ? loop->measured_body() : MeasuredBody::contact;
  };
  EXPECT_EQ(loop_of(head + plant + "controller: {Kp: 400, Kd: 60}\n"), MeasuredBody::contact);
  EXPECT_EQ(loop_of(head + plant + "controller: {Kp: 400, Kd: 60, measure: motor}\n"), MeasuredBody::motor);
  EXPECT_EQ(loop_of(head + plant + "controller: {Kp: 400, Kd: 60, measure: load}\n"), MeasuredBody::load);
  const Trajectory tr = simulate(scenario_from_yaml(YAML::Load(head + plant + "controller: {Kp: 400, Kd: 60, measure: motor}\n"), "s.yaml"));
  EXPECT_FALSE(tr.motor_position.empty());
  auto refused = [&](const std::string& yaml, const std::string& named) {
    try {
      (void)scenario_from_yaml(YAML::Load(yaml), "s.yaml");
      ADD_FAILURE() << "accepted " << yaml;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("s.yaml"), std::string::npos) << e.what();
    }
  };
  refused(head + plant + "controller: {Kp: 400, measure: gearbox}\n", "unknown measured body 'gearbox'; valid bodies: motor, load");
  refused(head + "plant: {type: axis, M: 1.5}\ncontroller: {Kp: 400, measure: motor}\n",
          "controller.measure: the axis has one body");
}
