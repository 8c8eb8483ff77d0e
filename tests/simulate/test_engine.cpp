// Engine tests against closed forms and the reference results of docs/reference-results.md.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/pendulum.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/plants/velocity_drive.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

// First switch of a kind at or after t0, or NaN.
double switch_time(const Trajectory& tr, SwitchKind kind, double t0 = 0.0) {
  for (const auto& s : tr.switches)
    if (s.kind == kind && s.time >= t0) return s.time;
  return std::nan("");
}

InputSignal craig_trapezoid() {
  InputSignal in;
  in.shape = InputShape::trapezoid;
  in.level = 0.15;
  in.rate = 0.003;
  in.hold = 30.0;
  return in;
}

DcMotorParams craig_motor() {
  DcMotorParams p;
  p.J = 1.06e-6;
  p.R = 7;
  p.L = 0.12;
  p.Kt = 0.0141;
  p.Kb = 0.0141;
  p.Ka = 1.0;
  p.drive = MotorDrive::current;
  return p;
}

}  // namespace

TEST(Hybrid, CraigMotorTrapezoid) {
  const DcMotor motor(craig_motor());
  const FrictionLaw law = StaticCoulombViscous{0.0015, 0.0012, 2.85e-6};
  SimulationOptions o;
  o.duration = 140;
  o.output_rate = 100;
  const Trajectory tr = simulate(motor, law, craig_trapezoid(), o);
  // Closed forms: breakaway when Kt i = Fs (i = Fs/Kt, t = i/0.003); hold speed (Kt 0.15 - Fc)/Fv.
  constexpr double kEventTol = 1e-6;  // root finding locates events to ~1e-12 s; 1e-6 s covers rounding of the closed form
  const double t_break = 0.0015 / 0.0141 / 0.003;
  EXPECT_NEAR(switch_time(tr, SwitchKind::breakaway), t_break, kEventTol);
  EXPECT_NEAR(switch_time(tr, SwitchKind::breakaway), 35.47, 0.02);  // docs/reference-results.md
  const double w_hold = (0.0141 * 0.15 - 0.0012) / 2.85e-6;
  const std::size_t i70 = 7000;
  constexpr double kHoldTol = 1e-6;  // 20 s into the hold = 54 time constants J/B: fully settled
  EXPECT_NEAR(tr.velocity[i70] / w_hold - 1.0, 0.0, kHoldTol);
  EXPECT_NEAR(tr.velocity[i70], 321.05, 321.05 * 1e-3);
  const double t_stop = switch_time(tr, SwitchKind::stick);
  EXPECT_NEAR(t_stop, 102.0, 0.1);
  const double i_stop = 0.15 - 0.003 * (t_stop - 80.0);
  EXPECT_NEAR(i_stop, 0.0840, 0.00005);
  EXPECT_EQ(tr.switches.size(), 2u);
  // After the stop the motor never moves again.
  for (std::size_t r = static_cast<std::size_t>(std::ceil(t_stop * 100)); r < tr.rows(); ++r) {
    EXPECT_EQ(tr.velocity[r], 0.0);
    EXPECT_EQ(tr.position[r], tr.position.back());
  }
  std::printf("craig: breakaway %.4f s, hold %.3f rad/s, stop %.4f s at %.5f A, %ld steps\n",
              switch_time(tr, SwitchKind::breakaway), tr.velocity[i70], t_stop, i_stop, tr.stats.steps);
}

// ---- closed forms ----------------------------------------------------------------------------

namespace {
constexpr double kPi = std::numbers::pi;

InputSignal constant_input(double value) {
  InputSignal in;
  in.value = value;
  return in;
}

SpringBase oscillator(double m, double k, double V0 = 0.0) {
  SpringBaseParams p;
  p.m = m;
  p.k = k;
  p.V0 = V0;
  return SpringBase(p);
}
}  // namespace

TEST(Hybrid, CoulombOscillatorLosesFourFcOverKPerCycleAndStopsInsideFsOverK) {
  const double m = 1.0, k = 100.0, Fc = 1.0, Fs = 1.5, x0 = 0.505;
  const SpringBase plant = oscillator(m, k);
  const FrictionLaw law = StaticCoulombViscous{Fs, Fc, 0.0};
  SimulationOptions o;
  o.duration = 10;
  o.initial_position = x0;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  const Trajectory tr = simulate(plant, law, InputSignal{}, o);
  // Half cycle n ends at |x_n| = x0 - 2 n Fc / k, exactly n pi sqrt(m/k) after the release.
  // |x_n| > Fs/k = 0.015 reverses, so n = 1..24 are reversals and n = 25 (|x| = 0.005) sticks.
  ASSERT_EQ(tr.switches.size(), 25u);
  constexpr double kAbsTol = 1e-8;  // m; BDF damps an undamped swing by ~1e-10 m per half cycle at rtol 1e-11
  const double half = kPi * std::sqrt(m / k);
  for (std::size_t n = 1; n <= tr.switches.size(); ++n) {
    const auto& s = tr.switches[n - 1];
    EXPECT_NEAR(std::abs(s.position), x0 - 2.0 * static_cast<double>(n) * Fc / k, kAbsTol) << "half cycle " << n;
    EXPECT_NEAR(s.time, static_cast<double>(n) * half, 1e-9) << "half cycle " << n;
    EXPECT_EQ(s.kind, n < 25 ? SwitchKind::reversal : SwitchKind::stick);
  }
  // per full cycle: 4 Fc / k
  EXPECT_NEAR(std::abs(tr.switches[0].position) - std::abs(tr.switches[2].position), 4.0 * Fc / k, 2 * kAbsTol);
  // It stops inside |x| <= Fs / k, then never moves.
  EXPECT_LE(std::abs(tr.position.back()), Fs / k);
  EXPECT_EQ(tr.velocity.back(), 0.0);
  EXPECT_EQ(tr.position.back(), tr.switches.back().position);
}

TEST(Stiff, ViscousDecayMatchesTheDampedResponse) {
  const double m = 2.0, k = 50.0, c = 1.5, x0 = 0.3;
  const SpringBase plant = oscillator(m, k);
  const FrictionLaw law = Viscous{c};
  SimulationOptions o;
  o.duration = 8;
  o.initial_position = x0;
  const Trajectory tr = simulate(plant, law, InputSignal{}, o);
  const double wn = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m)), wd = wn * std::sqrt(1 - zeta * zeta);
  constexpr double kAbsTol = 1e-7;  // global error of rtol 1e-8 over ~10 periods, in m (x0 = 0.3 m)
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    const double t = tr.time[i];
    const double x = x0 * std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta * wn / wd * std::sin(wd * t));
    ASSERT_NEAR(tr.position[i], x, kAbsTol) << "t = " << t;
  }
  EXPECT_STREQ(tr.stats.solver, "stiff");
}

TEST(Hybrid, SlowDriveStickSlipSlipsForPiSqrtMOverKWithForceDrop2FsMinusFc) {
  const double m = 1.0, k = 100.0, Fs = 2.0, Fc = 1.5, V0 = 1e-4;
  const SpringBase plant = oscillator(m, k, V0);
  const FrictionLaw law = StaticCoulombViscous{Fs, Fc, 0.0};
  SimulationOptions o;
  o.duration = 201;  // stuck for 200 s while the spring loads at k V0 = 0.01 N/s
  o.output_rate = 10;
  const Trajectory tr = simulate(plant, law, InputSignal{}, o);
  // First breakaway at k V0 t = Fs.
  ASSERT_GE(tr.switches.size(), 2u);
  EXPECT_EQ(tr.switches[0].kind, SwitchKind::breakaway);
  EXPECT_NEAR(tr.switches[0].time, Fs / (k * V0), 1e-9 * Fs / (k * V0));
  // Exact slip: with w = sqrt(k/m), a = (Fs - Fc)/k, the velocity is
  // w a sin(w s) + V0 (1 - cos(w s)); the slip ends at its zero in (pi/w, 2 pi/w).
  const double w = std::sqrt(k / m), a = (Fs - Fc) / k;
  auto vel = [&](double s) { return w * a * std::sin(w * s) + V0 * (1 - std::cos(w * s)); };
  double lo = kPi / w, hi = 2 * kPi / w;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (vel(mid) > 0 ? lo : hi) = mid;
  }
  const double slip = tr.switches[1].time - tr.switches[0].time;
  constexpr double kRel = 1e-7;  // event times from CVODE's root finder at rtol 1e-8
  EXPECT_NEAR(slip, lo, kRel * lo);
  // Slow-drive limit: pi sqrt(m/k) and a force drop of 2 (Fs - Fc), to O(V0 / (w a)) = 2e-3.
  constexpr double kLimitRel = 5e-3;
  EXPECT_NEAR(slip, kPi * std::sqrt(m / k), kLimitRel * slip);
  const double drop = tr.switches[0].applied - tr.switches[1].applied;
  EXPECT_NEAR(drop, 2 * (Fs - Fc), kLimitRel * drop);
  EXPECT_EQ(tr.switches[1].kind, SwitchKind::stick);
}

TEST(Hybrid, HeldForceBelowBreakawayNeverMovesTheMass) {
  const RigidAxis axis(AxisParams{2.0, 0.0});
  const FrictionLaw law = Stribeck{1.0, 1.5, 0.01, 2.0, 0.1};
  SimulationOptions o;
  o.duration = 20;
  o.initial_position = 0.25;
  InputSignal in;  // a sine of amplitude 1.49 N: pushes both ways, never beyond Fs = 1.5 N
  in.shape = InputShape::sine;
  in.amplitude = 1.49;
  in.omega = 3.0;
  const Trajectory tr = simulate(axis, law, in, o);
  for (std::size_t i = 0; i < tr.rows(); ++i) {
    ASSERT_EQ(tr.position[i], 0.25) << "t = " << tr.time[i];
    ASSERT_EQ(tr.velocity[i], 0.0);
    ASSERT_EQ(tr.friction[i], tr.applied[i]);
  }
  EXPECT_TRUE(tr.switches.empty());
  // Also in fixed-step mode (exact zero velocity holds the force there too).
  o.mode = SolverMode::fixed_step;
  const Trajectory fx = simulate(axis, law, in, o);
  for (std::size_t i = 0; i < fx.rows(); ++i) ASSERT_EQ(fx.position[i], 0.25);
}

TEST(Hybrid, StepAboveBreakawayStartsSlidingAtTheStep) {
  const RigidAxis axis(AxisParams{1.0, 0.0});
  const FrictionLaw law = StaticCoulombViscous{1.5, 1.0, 0.0};
  InputSignal in;
  in.shape = InputShape::step;
  in.value = 2.0;
  in.time = 1.0;
  SimulationOptions o;
  o.duration = 3;
  const Trajectory tr = simulate(axis, law, in, o);
  ASSERT_EQ(tr.switches.size(), 1u);
  EXPECT_DOUBLE_EQ(tr.switches[0].time, 1.0);
  // After the step: a = (2 - 1) / 1 = 1 m/s^2, x = (t - 1)^2 / 2.
  constexpr double kRel = 1e-8;
  EXPECT_NEAR(tr.position.back(), 2.0, 2.0 * kRel);
  EXPECT_NEAR(tr.velocity.back(), 2.0, 2.0 * kRel);
}

TEST(Stiff, PassiveLuGreNeverGainsEnergyUnforced) {
  // sigma2 = 6 > sigma1 (Fs - Fc) / Fc = 10 * 0.5 / 1 = 5: passive.
  LuGre lg;
  lg.sigma0 = 1e4;
  lg.sigma1 = 10.0;
  lg.sigma2 = 6.0;
  ASSERT_TRUE(lg.passivity().passive);
  const double m = 1.0, k = 20.0;
  const SpringBase plant = oscillator(m, k);
  SimulationOptions o;
  o.duration = 10;
  o.output_rate = 1000;
  o.initial_position = 0.4;
  o.rtol = 1e-10;
  o.atol = 1e-12;
  const Trajectory tr = simulate(plant, FrictionLaw(lg), InputSignal{}, o);
  ASSERT_EQ(tr.law_state.size(), 1u);
  auto energy = [&](std::size_t i) {
    const double z = tr.law_state[0][i];
    return 0.5 * m * tr.velocity[i] * tr.velocity[i] + 0.5 * k * tr.position[i] * tr.position[i] + 0.5 * lg.sigma0 * z * z;
  };
  const double e0 = energy(0);
  constexpr double kRelTol = 1e-8;  // integration error allowance at rtol 1e-10, relative to E0
  for (std::size_t i = 1; i < tr.rows(); ++i) ASSERT_LE(energy(i), energy(i - 1) + kRelTol * e0) << "t = " << tr.time[i];
  EXPECT_LT(energy(tr.rows() - 1), 0.1 * e0);
}

TEST(FixedStep, ConvergesToTheExactSolutionAsDtShrinks) {
  const double m = 1.0, k = 40.0;
  const SpringBase plant = oscillator(m, k);
  const FrictionLaw law = Viscous{0.8};
  SimulationOptions o;
  o.duration = 2;
  o.output_rate = 100;
  o.initial_position = 0.1;
  const Trajectory exact = simulate(plant, law, InputSignal{}, o);
  o.mode = SolverMode::fixed_step;
  double prev = 1e300;
  for (double dt : {1e-3, 1e-4, 1e-5}) {
    o.dt = dt;
    const Trajectory fx = simulate(plant, law, InputSignal{}, o);
    double err = 0;
    for (std::size_t i = 0; i < fx.rows(); ++i) err = std::max(err, std::abs(fx.position[i] - exact.position[i]));
    // First order: ten times smaller steps, about ten times smaller error (at least five).
    EXPECT_LT(err, prev / 5) << "dt = " << dt;
    prev = err;
  }
  EXPECT_LT(prev, 1e-5);
}

TEST(FixedStep, CraigMotorBreakawayAndHoldConverge) {
  const DcMotor motor(craig_motor());
  const FrictionLaw law = StaticCoulombViscous{0.0015, 0.0012, 2.85e-6};
  SimulationOptions o;
  o.duration = 75;
  o.output_rate = 10;
  o.mode = SolverMode::fixed_step;
  const double w_hold = (0.0141 * 0.15 - 0.0012) / 2.85e-6;
  for (double dt : {1e-3, 1e-4}) {
    o.dt = dt;
    const Trajectory fx = simulate(motor, law, craig_trapezoid(), o);
    // first moving sample vs the exact breakaway 35.461 s: within a sample of the output
    std::size_t i = 0;
    while (fx.velocity[i] == 0.0) ++i;
    EXPECT_NEAR(fx.time[i], 0.0015 / 0.0141 / 0.003, 0.1 + 1e-9);
    EXPECT_NEAR(fx.velocity.back(), w_hold, w_hold * 1e-4);
  }
}

TEST(Options, BadValuesAreRefusedWithTheirName) {
  const RigidAxis axis(AxisParams{});
  const FrictionLaw law = Coulomb{};
  SimulationOptions o;
  o.duration = -1;
  try {
    simulate(axis, law, InputSignal{}, o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("duration = -1"), std::string::npos) << e.what();
  }
  o = {};
  o.mode = SolverMode::stiff;
  EXPECT_THROW(simulate(axis, law, InputSignal{}, o), std::invalid_argument);  // stiction needs hybrid
  o = {};
  o.mode = SolverMode::hybrid;
  EXPECT_THROW(simulate(axis, FrictionLaw(LuGre{}), InputSignal{}, o), std::invalid_argument);
  o = {};
  o.mode = SolverMode::fixed_step;
  o.dt = 3e-3;  // does not divide 0.01 s
  EXPECT_THROW(simulate(axis, law, InputSignal{}, o), std::invalid_argument);
}

TEST(Stiff, IntegratorFailureIsARuntimeErrorNamingTheTime) {
  const RigidAxis axis(AxisParams{});
  SimulationOptions o;
  o.duration = 10;
  o.max_steps = 20;  // far too few for a stiff LuGre start
  try {
    simulate(axis, FrictionLaw(LuGre{}), constant_input(2.0), o);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("simulation failed at t = "), std::string::npos) << e.what();
  }
}
