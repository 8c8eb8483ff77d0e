// The controllers as control/ blocks: the PID's law (position and velocity loops, feedforward,
// compensation, saturation), its sampled update, its one check with the units its messages
// quote, the EMPS controller's sample, and their composition with a plant by close_loop: a sampled
// PID closed around a rigid axis runs as one axis of the xy-table, which uses the same block.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "../plants/xy_loop.hpp"
#include "error_message.hpp"
#include "frictionlab/control/emps_pd.hpp"
#include "frictionlab/control/pid.hpp"
#include "frictionlab/models/static_coulomb_viscous.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "frictionlab/simulate/xy_table.hpp"

namespace frictionlab {
namespace {

using testing::error_of;
using testing::relative_difference;

// The laws below are sums of a few products of short decimals: a few roundings of 1 ulp each.
constexpr double kRelTol = 1e-14;

PidParams gains() {
  PidParams p;
  p.Kp = 3.0;
  p.Ki = 4.0;
  p.Kd = 6.0;
  p.Kvff = 2.0;
  p.Kaff = 0.5;
  p.compensation_gain = 2.0;
  return p;
}

TEST(Pid, PositionLawKnownValue) {
  const Pid pid(gains());
  const PidInput in{.position = 0.2, .velocity = 0.1, .reference = 1.0, .reference_rate = 0.3, .reference_accel = 0.4};
  // 3 (1 - 0.2) + 4 0.5 - 6 0.1 + 2 0.3 + 0.5 0.4 + 2 0.7 = 2.4 + 2 - 0.6 + 0.6 + 0.2 + 1.4
  EXPECT_NEAR(pid.output(in, 0.5, 0.7), 6.0, 6.0 * kRelTol);
  EXPECT_NEAR(pid.error(in), 0.8, 0.8 * kRelTol);
  EXPECT_EQ(pid.num_states(), 1);
  EXPECT_FALSE(pid.sampled());
}

TEST(Pid, VelocityLawKnownValue) {
  PidParams p = gains();
  p.loop = ControlLoop::velocity;
  p.Kd = 0.0;
  const Pid pid(p);
  // r is the reference velocity (1 m/s), its rate 0.3 m/s^2; the position plays no part.
  const PidInput in{.position = 5.0, .velocity = 0.1, .reference = 1.0, .reference_rate = 0.3, .reference_accel = 9.0};
  // 3 (1 - 0.1) + 4 0.5 + 2 1 + 0.5 0.3 + 2 0.7 = 2.7 + 2 + 2 + 0.15 + 1.4
  EXPECT_NEAR(pid.output(in, 0.5, 0.7), 8.25, 8.25 * kRelTol);
  EXPECT_NEAR(pid.error(in), 0.9, 0.9 * kRelTol);
}

TEST(Pid, SaturationHoldsWithTheCompensation) {
  PidParams p = gains();
  p.limit = 2.0;
  const Pid pid(p);
  const PidInput in{.position = 0.2, .velocity = 0.1, .reference = 1.0, .reference_rate = 0.3, .reference_accel = 0.4};
  EXPECT_EQ(pid.output(in, 0.5, 0.7), 2.0);
  EXPECT_EQ(pid.output(in, 0.5, -10.0), -2.0);
  EXPECT_EQ(pid.saturation_slope(6.0), 0.0);
  EXPECT_EQ(pid.saturation_slope(2.0), 1.0);  // clamp is the identity at the limit
  EXPECT_EQ(pid.saturation_slope(-1.0), 1.0);
}

TEST(Pid, SampledUpdateWithOneSampleDelay) {
  PidParams p;
  p.Kp = 10.0;
  p.Ki = 100.0;
  p.Ts = 1e-3;
  p.delay = 1;
  const Pid pid(p);
  EXPECT_TRUE(pid.sampled());
  ASSERT_EQ(pid.num_states(), 3);
  std::array<double, 3> s{};  // integral, applied, computed
  const PidInput first{.position = 0.0, .reference = 0.5};
  const double v1 = pid.sample(first, s, 0.0);
  // The integral takes Ts e at once (rectangle rule, e(j) included): 1e-3 0.5 m s.
  EXPECT_NEAR(s[0], 5e-4, 5e-4 * kRelTol);
  EXPECT_NEAR(v1, 10.0 * 0.5 + 100.0 * 5e-4, 5.05 * kRelTol);
  EXPECT_EQ(Pid::held(s), 0.0);  // delay 1: nothing computed before
  EXPECT_EQ(s[2], v1);
  const double v2 = pid.sample(PidInput{.position = 0.1, .reference = 0.5}, s, 0.0);
  EXPECT_EQ(Pid::held(s), v1);  // the previous sample's output goes to the drive now
  EXPECT_EQ(s[2], v2);
  p.delay = 0;
  std::array<double, 3> s0{};
  EXPECT_EQ(Pid::held(s0), 0.0);
  (void)Pid(p).sample(first, s0, 0.0);
  EXPECT_EQ(Pid::held(s0), v1);  // delay 0: applied at once
}

TEST(Pid, OneCheckNamesTheGainAndItsUnit) {
  PidParams p = gains();
  p.Kp = -1.0;
  EXPECT_EQ(error_of([&] { Pid(p, "controller"); }),
            "controller: Kp = -1 must be >= 0 (output unit per m, rad, m/s or rad/s)");
  EXPECT_EQ(error_of([&] { Pid(p, "xy-table: axis x", PidUnits::force_on_linear_axis()); }),
            "xy-table: axis x: Kp = -1 must be >= 0 (N/m)");
  p = gains();
  p.Ki = std::nan("");
  EXPECT_EQ(error_of([&] { Pid(p, "xy-table: axis y", PidUnits::force_on_linear_axis()); }),
            "xy-table: axis y: Ki = nan must be >= 0 (N/(m s))");
  p = gains();
  p.limit = -3.0;
  EXPECT_EQ(error_of([&] { Pid{p}; }), "controller: limit = -3 must be >= 0 (output unit; 0 = no saturation)");
  p = gains();
  p.loop = ControlLoop::velocity;
  EXPECT_EQ(error_of([&] { Pid{p}; }),
            "controller: Kd = 6 must be 0 in a velocity loop (it would need the acceleration)");
  p = gains();
  p.Ts = -1e-3;
  EXPECT_EQ(error_of([&] { Pid{p}; }), "controller: Ts = -0.001 must be >= 0 (s; 0 = continuous controller)");
  p = gains();
  p.Ts = 1e-3;
  p.delay = 2;
  EXPECT_EQ(error_of([&] { Pid{p}; }), "controller: delay = 2 must be 0 or 1 (samples)");
  p = gains();
  p.delay = 1;
  EXPECT_EQ(error_of([&] { Pid{p}; }), "controller: delay = 1 needs a sampled controller (Ts > 0 s)");
  // The closed loop and the xy-table check through the same block.
  p = gains();
  p.Kvff = -2.0;
  EXPECT_EQ(error_of([&] { ClosedLoop(std::make_shared<const RigidAxis>(AxisParams{.M = 1.0}), p); }),
            "controller: Kvff = -2 must be >= 0 (output unit per m/s or rad/s)");
  XyAxis a;
  a.mass = 1.0;
  a.gains = gains();
  a.gains.compensation_gain = 1.0;
  a.gains.Kaff = -1.0;
  EXPECT_EQ(error_of([&] { XyTable(a, a); }), "xy-table: axis x: Kaff = -1 must be >= 0 (N/(m/s^2))");
  a.gains.Kaff = 0.0;
  a.gains.Ts = 1e-3;
  EXPECT_NE(error_of([&] { XyTable(a, a); }).find("xy-table: axis x: Ts = 0.001 must be 0 (the table's timing"),
            std::string::npos);
}

TEST(EmpsPd, SampleKnownValues) {
  EmpsPdParams p;
  p.kp = 2.0;   // 1/s
  p.kv = 3.0;   // V/(m/s)
  p.dt = 0.1;   // s
  p.delay = 0;
  const EmpsPd pd(p);
  std::array<double, EmpsPd::kStates> s{};
  // First sample: the memory starts at rest here, so qd_m = 0 and v = kp kv (r - q) = 6 0.4.
  EmpsPdMeasurement m = pd.measure(s, 0.1, 0.5);
  EXPECT_TRUE(m.first);
  EXPECT_EQ(m.velocity, 0.0);
  EXPECT_NEAR(pd.sample(s, 0.0, 0.1, 0.5, m, 0.0), 2.4, 2.4 * kRelTol);
  EXPECT_EQ(EmpsPd::held(s), EmpsPd::computed(s));  // delay 0
  // Second: qf = (0.2 + 0.1) / 2, qd_m = (0.15 - 0.1) / 0.1 = 0.5 m/s; v = 6 0.3 - 3 0.5 + 0.2 (compensation, V).
  m = pd.measure(s, 0.2, 0.5);
  EXPECT_FALSE(m.first);
  EXPECT_NEAR(m.velocity, 0.5, 0.5 * 1e-13);  // (0.15 - 0.1) / 0.1 loses digits to the difference
  EXPECT_NEAR(pd.sample(s, 0.1, 0.2, 0.5, m, 0.2), 0.5, 0.5 * 1e-13);
  p.kv = -1.0;
  EXPECT_EQ(error_of([&] { EmpsPd{p}; }), "controller (emps-pd): kv = -1 must be >= 0 (V/(m/s))");
}

TEST(CloseLoop, BuildsTheLoopOfTheController) {
  const auto axis = std::make_shared<const RigidAxis>(AxisParams{.M = 2.0});
  const auto pid = close_loop(axis, gains());
  ASSERT_NE(dynamic_cast<const ClosedLoop*>(pid.get()), nullptr);
  EXPECT_EQ(pid->num_states(), 3);
  EmpsPdParams e;
  e.kp = 1.0;
  e.kv = 1.0;
  const auto emps = close_loop(axis, e);
  ASSERT_NE(dynamic_cast<const EmpsPdLoop*>(emps.get()), nullptr);
  EXPECT_EQ(emps->sample_period(), e.dt);
  EXPECT_EQ(error_of([&] { close_loop(nullptr, gains()); }), "controller: no plant to control");
}

// A sampled PID closed around a rigid axis runs as an axis of the xy-table with the same timing
// (whose axes run the same block), the other axis idle.
TEST(CloseLoop, SampledPidIsAnXyTableAxis) {
  // The runs take different steps (CVODE's error norm averages over more states on the table),
  // so they agree to the integration error: at rtol = 1e-12 about 1e-11 of the motion's scale.
  constexpr double kRunRelTol = 1e-9;
  // The drive is Kp times the small position error of a stiff loop: it magnifies the difference.
  constexpr double kDriveRelTol = 1e-8;
  const double M = 3.0;
  const StaticCoulombViscous law{12.0, 8.0, 20.0};  // Fs, Fc (N), Fv (N s/m): sticks at each reversal
  PidParams c = testing::gains_for(M);
  InputSignal r;  // 10 mm sine at 4 rad/s
  r.shape = InputShape::sine;
  r.amplitude = 0.01;
  r.omega = 4.0;
  SimulationOptions o;
  o.duration = 1.0;
  o.output_rate = 500.0;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  XyAxis a;
  a.mass = M;
  a.law = law;
  a.gains = c;
  const XyTable table(a, a, XyTiming{1e-3, 1});
  c.Ts = 1e-3;
  c.delay = 1;
  const auto loop = close_loop(std::make_shared<const RigidAxis>(AxisParams{.M = M}), c);
  EXPECT_EQ(loop->sample_period(), 1e-3);
  EXPECT_EQ(loop->num_states(), 2 + 3);
  EXPECT_EQ(loop->num_events(), 0);
  const Trajectory one = simulate(*loop, law, r, o);
  ASSERT_GT(one.switches.size(), 2u) << "the case must stick at the reversals";
  const InputSignal inputs[2] = {r, InputSignal{}};
  const Trajectory two = simulate(table, Viscous{0.0}, inputs, o);
  EXPECT_LT(relative_difference(two.contact(0).position, one.position), kRunRelTol);
  EXPECT_LT(relative_difference(two.contact(0).drive, one.drive), kDriveRelTol);
}

}  // namespace
}  // namespace frictionlab
