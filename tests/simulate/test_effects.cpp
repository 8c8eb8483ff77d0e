// The exact engine with load-, temperature- and position-dependent friction (models/law_effects.hpp,
// simulate/environment.hpp): breakaway at the loaded level, where a ripple stops an axis, a
// thermal run, energy balances and located events.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "frictionlab/error.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/velocity_drive.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

FrictionLaw stribeck_with(LawEffects e) { return FrictionLaw(Stribeck{1.0, 1.5, 0.01, 2.0, 0.1}).with_effects(std::move(e)); }

InputSignal constant(double value) {
  InputSignal in;
  in.value = value;
  return in;
}

InputSignal step_at(double time, double value) {
  InputSignal in;
  in.shape = InputShape::step;
  in.time = time;
  in.value = value;
  return in;
}

ContactEnvironment load_of(InputSignal load) {
  ContactEnvironment e;
  e.load.signal = std::move(load);
  return e;
}

}  // namespace

TEST(LoadHybrid, HoldsJustBelowTheLoadedBreakawayAndBreaksAwayJustAbove) {
  // Fs' = 1.5 + 0.1 * |-10| = 2.5 N at a load of -10 N (its magnitude counts).
  LawEffects e;
  e.load = LoadDependence{0.1, 0.1};
  const FrictionLaw law = stribeck_with(e);
  const RigidAxis axis(AxisParams{1.0, 0.0});
  SimulationOptions o;
  o.duration = 3;
  o.environments = {load_of(constant(-10.0))};
  constexpr double kMargin = 1e-9;  // relative: far below the level, far above the roundoff of 1.5 + 0.1 * 10
  const Trajectory held = simulate(axis, law, step_at(1.0, 2.5 * (1 - kMargin)), o);
  EXPECT_TRUE(held.switches.empty());
  for (std::size_t i = 0; i < held.rows(); ++i) {
    ASSERT_EQ(held.position[i], 0.0) << "t = " << held.time[i];
    ASSERT_EQ(held.friction[i], held.applied[i]);
    ASSERT_EQ(held.load[i], -10.0);
  }
  const Trajectory broke = simulate(axis, law, step_at(1.0, 2.5 * (1 + kMargin)), o);
  ASSERT_FALSE(broke.switches.empty());
  EXPECT_EQ(broke.switches[0].kind, SwitchKind::breakaway);
  EXPECT_DOUBLE_EQ(broke.switches[0].time, 1.0);
  EXPECT_GT(broke.position.back(), 0.0);
  // The plain law (no load) breaks away at 1.5 N: the load is what held it.
  const Trajectory plain = simulate(axis, FrictionLaw(Stribeck{1.0, 1.5, 0.01, 2.0, 0.1}), step_at(1.0, 2.0), o);
  EXPECT_FALSE(plain.switches.empty());
}

TEST(LoadHybrid, FallingLoadReleasesAHeldAxisAtTheLocatedInstant) {
  // Load 10 - t N: level 2.5 - 0.1 t; a held push of 2.2 N breaks loose at t = 3 s exactly.
  LawEffects e;
  e.load = LoadDependence{0.1, 0.1};
  const FrictionLaw law = stribeck_with(e);
  const RigidAxis axis(AxisParams{1.0, 0.0});
  InputSignal load;
  load.shape = InputShape::ramp;
  load.initial = 10.0;
  load.rate = -1.0;
  SimulationOptions o;
  o.duration = 4;
  o.environments = {load_of(load)};
  const Trajectory tr = simulate(axis, law, constant(2.2), o);
  ASSERT_FALSE(tr.switches.empty());
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::breakaway);
  constexpr double kRel = 1e-7;  // event times from CVODE's root finder at rtol 1e-8
  EXPECT_NEAR(tr.switches[0].time, 3.0, kRel * 3.0);
  EXPECT_EQ(tr.switches[0].direction, 1);
  // Also a load given as a function of the state (here of time only, through t).
  o.environments[0] = ContactEnvironment{};
  o.environments[0].load.of_state = [](double t, std::span<const double>) { return 10.0 - t; };
  const Trajectory fn = simulate(axis, law, constant(2.2), o);
  ASSERT_FALSE(fn.switches.empty());
  EXPECT_NEAR(fn.switches[0].time, 3.0, kRel * 3.0);
}

TEST(RippleHybrid, TheRippleDecidesWhereAPushedAxisStops) {
  // Coulomb 1 N with a ripple 0.5 sin(2 pi q / P), pushed by 1.3 N from rest at q = 0: it breaks
  // away (1.3 - 0 > 1), and stops where the work (1.3 - 1) q equals the ripple's potential
  // U(q) = 0.5 P / (2 pi) (1 - cos(2 pi q / P)); it sticks there, as 1.3 - r(q) < 1.
  constexpr double P = 0.01, A = 0.5, push = 1.3, Fc = 1.0;
  LawEffects e;
  e.ripple = PositionRipple{P, {A}, {}, {}, {}};
  const FrictionLaw law = FrictionLaw(Coulomb{Fc}).with_effects(e);
  const RigidAxis axis(AxisParams{0.5, 0.0});
  SimulationOptions o;
  o.duration = 2;
  const Trajectory tr = simulate(axis, law, step_at(0.1, push), o);
  // The stop position by bisection on f(q) = (push - Fc) q - U(q), positive just after 0.
  auto f = [&](double q) { return (push - Fc) * q - A * P / (2 * std::numbers::pi) * (1 - std::cos(2 * std::numbers::pi * q / P)); };
  double lo = 0.01 * P, hi = 0.5 * P;
  ASSERT_GT(f(lo), 0.0);
  ASSERT_LT(f(hi), 0.0);
  for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
  const double q_stop = 0.5 * (lo + hi);
  ASSERT_GE(tr.switches.size(), 2u);
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::breakaway);
  EXPECT_EQ(tr.switches[1].kind, SwitchKind::stick);
  constexpr double kRel = 1e-6;  // the integrated position at rtol 1e-8, atol 1e-10 over one stop
  EXPECT_NEAR(tr.switches[1].position, q_stop, kRel * q_stop);
  EXPECT_EQ(tr.switches.size(), 2u) << "it stays where it stopped";
  EXPECT_EQ(tr.position.back(), tr.switches[1].position);
  EXPECT_EQ(tr.stuck.back(), 1.0);
  // Stuck, the friction balances the push; its velocity-law part, push - r(q), is below Fc.
  EXPECT_EQ(tr.friction.back(), push);
  EXPECT_LT(push - law.ripple(q_stop), Fc);
}

TEST(RippleHybrid, WorkOfTheInputIsKineticPlusDissipatedPlusRipplePotential) {
  // Stribeck with a load and a ripple, pushed above the loaded breakaway level: it slides forward
  // all the way. Input work u x = M v^2 / 2 + integral (F - r(x)) v dt + U(x).
  LawEffects e;
  e.load = LoadDependence{0.05, 0.03};
  e.ripple = PositionRipple{0.02, {0.3, 0.1}, {0.2, 0.0}, {}, {}};
  const FrictionLaw law = stribeck_with(e);
  constexpr double M = 0.8, u = 3.5;
  const RigidAxis axis(AxisParams{M, 0.0});
  SimulationOptions o;
  o.duration = 1.0;
  o.output_rate = 20000;  // fine rows: the trapezoid rule's error ~ h^2 below
  o.environments = {load_of(constant(20.0))};  // Fs' = 2.5 N < 3.5 - |r| everywhere
  const Trajectory tr = simulate(axis, law, constant(u), o);
  EXPECT_TRUE(tr.switches.empty());  // slides from t = 0 (a start in motion records no switch), never stops
  double dissipated = 0.0;
  auto law_power = [&](std::size_t i) { return (tr.friction[i] - law.ripple(tr.position[i])) * tr.velocity[i]; };
  for (std::size_t i = 1; i < tr.rows(); ++i) dissipated += 0.5 * (law_power(i) + law_power(i - 1)) * (tr.time[i] - tr.time[i - 1]);
  const std::size_t n = tr.rows() - 1;
  const double x = tr.position[n], v = tr.velocity[n];
  const double work = u * x, balance = 0.5 * M * v * v + dissipated + e.ripple->potential(x);
  constexpr double kRel = 1e-6;  // trapezoid error (h = 5e-5 s, smooth sliding) and rtol 1e-8
  EXPECT_NEAR(balance, work, kRel * work);
  // The plain velocity law's force: the recorded friction less the ripple is Fc' + ... > 0 always.
  for (std::size_t i = 1; i < tr.rows(); ++i) ASSERT_GT(law_power(i), 0.0);
}

TEST(ThermalStiff, ViscousForceFollowsFvOfTheTemperatureAsTheGreaseWarms) {
  // A velocity drive at 2 rad/s through viscous friction Fv(T) = 0.5 - 0.004 (T - 20): the power
  // Fv(T) v^2 heats the contact, C dT/dt = Fv(T) v^2 - (T - T_amb) / R, a linear ODE with the
  // closed form T(t) = T_inf + (T0 - T_inf) exp(alpha t).
  constexpr double v = 2.0, Fv0 = 0.5, k = -0.004, Tref = 20.0, Tamb = 20.0, R = 20.0, tau = 50.0;
  LawEffects e;
  e.temperature = TemperatureDependence{Tref, 0.0, k, std::nullopt, std::nullopt};
  const FrictionLaw law = FrictionLaw(Viscous{Fv0}).with_effects(e);
  const VelocityDrive drive(VelocityDriveParams{0.0});
  SimulationOptions o;
  o.duration = 200;
  o.output_rate = 10;
  ContactEnvironment env;
  env.thermal = ThermalModel{Tamb, std::nullopt, tau, R};
  o.environments = {env};
  const Trajectory tr = simulate(drive, law, constant(v), o);
  const double alpha = (R * v * v * k - 1) / tau, beta = (R * v * v * (Fv0 - k * Tref) + Tamb) / tau;
  const double T_inf = -beta / alpha;
  ASSERT_EQ(tr.temperature.size(), tr.rows());
  constexpr double kRelT = 1e-6;  // CVODE at rtol 1e-8 over 200 s (four time constants)
  constexpr double kRelF = 1e-12; // the friction column is Fv(T) v of the recorded T: roundoff only
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    const double T = T_inf + (Tamb - T_inf) * std::exp(alpha * tr.time[i]);
    EXPECT_NEAR(tr.temperature[i], T, kRelT * T) << "t = " << tr.time[i];
    const double F = (Fv0 + k * (tr.temperature[i] - Tref)) * v;
    EXPECT_NEAR(tr.friction[i], F, kRelF * F) << "t = " << tr.time[i];
  }
  EXPECT_GT(tr.temperature.back(), 40.0);                 // it warmed by tens of K
  EXPECT_LT(tr.friction.back(), 0.9 * tr.friction.front());  // and the viscous force fell
  // The thermal state's energy balance: heat in = stored C (T - T0) + heat out to ambient.
  const double C = tau / R;
  double in = 0, out = 0;
  for (std::size_t i = 1; i < tr.rows(); ++i) {
    const double h = tr.time[i] - tr.time[i - 1];
    in += 0.5 * h * (tr.friction[i] * v + tr.friction[i - 1] * v);
    out += 0.5 * h * ((tr.temperature[i] - Tamb) + (tr.temperature[i - 1] - Tamb)) / R;
  }
  constexpr double kRelE = 1e-4;  // trapezoid rule at 0.1 s on a curve with a 60 s time constant
  EXPECT_NEAR(in, C * (tr.temperature.back() - Tamb) + out, kRelE * in);
}

TEST(ThermalHybrid, AWarmingContactSticksAtItsTemperaturesLevel) {
  // Coulomb level 1 N falling 0.01 N/K: a held 0.8 N push breaks loose when the contact, fixed at
  // 20 degC, is replaced by one at 45 degC (level 0.75 N). Also the fixed temperature form.
  LawEffects e;
  e.temperature = TemperatureDependence{20.0, -0.01, 0.0, std::nullopt, std::nullopt};
  const FrictionLaw law = FrictionLaw(Coulomb{1.0}).with_effects(e);
  const RigidAxis axis(AxisParams{1.0, 0.0});
  SimulationOptions o;
  o.duration = 1;
  ContactEnvironment env;
  env.temperature = 20.0;
  o.environments = {env};
  EXPECT_TRUE(simulate(axis, law, step_at(0.5, 0.8), o).switches.empty());
  o.environments[0].temperature = 45.0;
  const Trajectory tr = simulate(axis, law, step_at(0.5, 0.8), o);
  ASSERT_FALSE(tr.switches.empty());
  EXPECT_DOUBLE_EQ(tr.switches[0].time, 0.5);
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::breakaway);
  EXPECT_EQ(tr.temperature.back(), 45.0);
}

TEST(EffectsFixedStep, AgreesWithTheExactRunAsDtShrinks) {
  // The ripple stop of RippleHybrid in fixed-step mode: the stop position converges to the exact one.
  LawEffects e;
  e.ripple = PositionRipple{0.01, {0.5}, {}, {}, {}};
  const FrictionLaw law = FrictionLaw(Coulomb{1.0}).with_effects(e);
  const RigidAxis axis(AxisParams{0.5, 0.0});
  SimulationOptions o;
  o.duration = 1;
  const double exact = simulate(axis, law, constant(1.3), o).position.back();
  o.mode = SolverMode::fixed_step;
  o.dt = 1e-5;
  const double fixed = simulate(axis, law, constant(1.3), o).position.back();
  constexpr double kRel = 1e-2;  // symplectic Euler's O(dt) error at dt = 1e-5 s over a 0.1 s slide
  EXPECT_NEAR(fixed, exact, kRel * exact);
}

TEST(EffectsOptions, EnvironmentsMustMatchTheContacts) {
  const RigidAxis axis(AxisParams{1.0, 0.0});
  SimulationOptions o;
  o.environments.resize(2);
  EXPECT_THROW(simulate(axis, FrictionLaw(Coulomb{1.0}), constant(0.0), o), std::invalid_argument);
  o.environments.resize(1);
  o.environments[0].temperature = 20.0;
  o.environments[0].thermal = ThermalModel{};
  EXPECT_THROW(simulate(axis, FrictionLaw(Coulomb{1.0}), constant(0.0), o), std::invalid_argument);
  o.environments[0].temperature.reset();
  o.environments[0].thermal->tau = 0.0;
  try {
    simulate(axis, FrictionLaw(Coulomb{1.0}), constant(0.0), o);
    FAIL();
  } catch (const std::invalid_argument& ex) {
    EXPECT_NE(std::string(ex.what()).find("tau"), std::string::npos) << ex.what();
  }
}

TEST(LoadStiff, LuGreUnderLoadSlidesAtItsLoadedSteadyForce) {
  // A velocity drive at 0.05 m/s through LuGre with mu_load 0.1 under 10 N: the force settles on
  // the loaded law's steady-state (Stribeck) force, 1 + 1 (Fc') plus the decayed rise plus sigma2 v.
  LawEffects e;
  e.load = LoadDependence{0.1, 0.1};
  const FrictionLaw law = FrictionLaw(LuGre{}).with_effects(e);
  const VelocityDrive drive(VelocityDriveParams{0.0});
  SimulationOptions o;
  o.duration = 0.5;
  o.environments = {load_of(constant(10.0))};
  const Trajectory tr = simulate(drive, law, constant(0.05), o);
  Conditions c;
  c.load = 10.0;
  const double steady = law.sliding(0.05, c);
  constexpr double kSteadyAbs = 1e-12;  // N: exp(-50^2) of the Stribeck rise is 0 in doubles; roundoff only
  EXPECT_NEAR(steady, 2.0 + 0.4 * 0.05, kSteadyAbs);  // far past vs = 1 mm/s: Fc' + sigma2 v
  constexpr double kRel = 1e-6;  // the bristle state after 25 mm of sliding (relaxation length Fc'/sigma0 = 20 um)
  EXPECT_NEAR(tr.friction.back(), steady, kRel * steady);
}

TEST(ThermalHybrid, ARunThatHeatsPastTheLawsRangeStopsWithTheTypedError) {
  // Viscous 1 N s/m at 2 m/s heats towards 20 + 4 * 10 = 60 degC; the law serves up to 40 degC.
  LawEffects e;
  e.temperature = TemperatureDependence{20.0, 0.0, -0.001, std::nullopt, 40.0};
  const FrictionLaw law = FrictionLaw(Viscous{1.0}).with_effects(e);
  const VelocityDrive drive(VelocityDriveParams{0.0});
  SimulationOptions o;
  o.duration = 100;
  ContactEnvironment env;
  env.thermal = ThermalModel{20.0, std::nullopt, 10.0, 10.0};
  o.environments = {env};
  try {
    (void)simulate(drive, law, constant(2.0), o);
    FAIL() << "the run went past T_max";
  } catch (const InputError& ex) {
    EXPECT_EQ(ex.code(), "law.parameter");
    EXPECT_EQ(ex.fields().key, "T_max");
  }
}

TEST(RippleHybrid, ATableRippleHoldsAStuckAxisWhileTheRestIsWithinTheStaticLevel) {
  // Static level 1.2 N, Coulomb 1 N, and a ripple by table whose value at the rest position q = 0
  // is 0.5 N: stepped at 0.1 s to an applied force u, the axis holds while |u - 0.5| <= 1.2
  // (exactly: velocity 0, friction = u) and breaks away, at the step, in the direction of u - 0.5
  // just beyond it.
  LawEffects e;
  e.ripple = PositionRipple{0.01, {}, {}, {-0.005, -0.002, 0.0, 0.003, 0.005}, {-0.4, 0.1, 0.5, -0.2, -0.4}};
  const FrictionLaw law = FrictionLaw(StaticCoulombViscous{1.2, 1.0, 0.2}).with_effects(e);
  ASSERT_EQ(law.ripple(0.0), 0.5);
  const RigidAxis axis(AxisParams{0.5, 0.0});
  SimulationOptions o;
  o.duration = 0.5;
  o.output_rate = 200;
  constexpr double kMargin = 1e-3;  // N: just inside and just beyond the level
  for (const double u : {0.5 + 1.2 - kMargin, 0.5 - 1.2 + kMargin}) {
    const Trajectory tr = simulate(axis, law, step_at(0.1, u), o);
    EXPECT_TRUE(tr.switches.empty()) << "u = " << u;
    EXPECT_EQ(tr.position.back(), 0.0) << "u = " << u;
    EXPECT_EQ(tr.velocity.back(), 0.0) << "u = " << u;
    EXPECT_EQ(tr.stuck.back(), 1.0) << "u = " << u;
    EXPECT_EQ(tr.friction.back(), u) << "u = " << u;  // stuck, the friction balances the push
  }
  for (const double u : {0.5 + 1.2 + kMargin, 0.5 - 1.2 - kMargin}) {
    const Trajectory tr = simulate(axis, law, step_at(0.1, u), o);
    ASSERT_FALSE(tr.switches.empty()) << "u = " << u;
    EXPECT_EQ(tr.switches[0].kind, SwitchKind::breakaway) << "u = " << u;
    constexpr double kEventAbs = 1e-9;  // s: the step is a corner of the run, where the breakaway is
    EXPECT_NEAR(tr.switches[0].time, 0.1, kEventAbs) << "u = " << u;
    EXPECT_GT(tr.position[30] * (u - 0.5), 0.0) << "u = " << u;  // row 30 = 0.15 s: moved the way u - r pushes
  }
}
