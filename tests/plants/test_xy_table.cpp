// The two-axis table (simulate/xy_table.hpp): axis equations, each axis's loop against the 1-DOF
// ClosedLoop, the sampled loop's arithmetic, a compensator wired in, and the checks of its parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "xy_loop.hpp"
#include "frictionlab/control/feedback.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/models/static_coulomb_viscous.hpp"
#include "frictionlab/models/stribeck.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;
using frictionlab::testing::gains_for;
using frictionlab::testing::relative_difference;

namespace {

XyAxis axis_of(double mass, FrictionLaw law, ControllerParams gains) {
  XyAxis a;
  a.mass = mass;
  a.law = std::move(law);
  a.gains = gains;
  return a;
}

}  // namespace

TEST(XyTable, EquivalentMassReflectsTheScrewInertia) {
  XyAxis a;
  a.mass = 12.0;      // kg
  a.inertia = 4e-5;   // kg m^2
  a.lead = 0.005;     // m/rev: 2 pi / 0.005 = 1256.6 rad/m
  const double ratio = 2.0 * std::numbers::pi / 0.005;
  constexpr double kRelTol = 1e-15;  // two products and a sum: a few roundoffs
  EXPECT_NEAR(a.equivalent_mass(), 12.0 + 4e-5 * ratio * ratio, kRelTol * 75.0);
  XyAxis screw_only = a;
  screw_only.mass = 0.0;
  EXPECT_NEAR(screw_only.equivalent_mass(), 63.165468167, 1e-8);  // 4e-5 (2 pi / 0.005)^2 kg, by hand
  const XyTable plant(a, axis_of(3.0, Viscous{0.0}, {}));
  EXPECT_DOUBLE_EQ(plant.inertia(0), a.equivalent_mass());
  EXPECT_DOUBLE_EQ(plant.inertia(1), 3.0);
  EXPECT_EQ(plant.contact(0).name, "x");
  EXPECT_EQ(plant.contact(1).name, "y");
  EXPECT_EQ(plant.contact(1).position, 2);
  EXPECT_EQ(plant.contact(1).velocity, 3);
  EXPECT_EQ(plant.num_states(), 6);  // 2 contacts x (position, velocity) + 2 integrals
}

TEST(XyTable, AxisEquationIsNewtonWithTheControllerForce) {
  // dv/dt = (u - F) / M with u = Kp e + Ki I - Kd v + Kvff dr/dt + Kaff d2r/dt2 on each axis.
  ControllerParams cx{.Kp = 1000, .Ki = 50, .Kd = 30, .Kvff = 20, .Kaff = 2};
  ControllerParams cy{.Kp = 400, .Ki = 0, .Kd = 10, .Kvff = 0, .Kaff = 0};
  XyAxis x = axis_of(2.0, Viscous{0.0}, cx);
  x.inertia = 1e-5;
  x.lead = 0.01;
  const XyTable plant(x, axis_of(5.0, Viscous{0.0}, cy));
  const std::vector<double> state = {0.01, 0.2, -0.02, 0.1, 0.003, -0.004};
  const InputValue r[2] = {{0.015, 0.3, -1.0}, {-0.01, 0.05, 2.0}};
  const double friction[2] = {3.0, -1.5};
  std::vector<double> dx(6);
  plant.derivatives(0.0, state, r, friction, dx);
  const double ux = 1000 * (0.015 - 0.01) + 50 * 0.003 - 30 * 0.2 + 20 * 0.3 + 2 * -1.0;
  const double uy = 400 * (-0.01 + 0.02) - 10 * 0.1;
  constexpr double kRelTol = 1e-14;  // a handful of products and sums
  EXPECT_NEAR(dx[0], 0.2, kRelTol);
  EXPECT_NEAR(dx[1], (ux - 3.0) / x.equivalent_mass(), kRelTol * std::abs(ux));
  EXPECT_NEAR(dx[2], 0.1, kRelTol);
  EXPECT_NEAR(dx[3], (uy + 1.5) / 5.0, kRelTol * std::abs(uy));
  EXPECT_NEAR(dx[4], 0.015 - 0.01, kRelTol);   // integral of x's position error
  EXPECT_NEAR(dx[5], -0.01 + 0.02, kRelTol);   // of y's
  double applied[2];
  plant.applied(0.0, state, r, applied);
  EXPECT_NEAR(applied[0], ux, kRelTol * std::abs(ux));
  EXPECT_NEAR(applied[1], uy, kRelTol * std::abs(uy));
  PlantSignals s[2];
  plant.signals(0.0, state, r, s);
  EXPECT_EQ(s[0].reference, 0.015);
  EXPECT_NEAR(s[1].drive, uy, kRelTol * std::abs(uy));
}

// Each axis, with the other one idle (reference 0: it never leaves rest), is the 1-DOF ClosedLoop
// around a RigidAxis of its equivalent mass, with the same law and gains.
TEST(XyTable, EachAxisIsTheOneDofClosedLoopWhenTheOtherIsIdle) {
  // The runs take different steps (CVODE's error norm averages over 6 states instead of 3, and
  // the idle axis adds its own root functions), so they agree to the integration error: at
  // rtol = 1e-12 about 1e-11 of the motion's scale; 1e-9 leaves a margin for other platforms.
  constexpr double kRelTol = 1e-9;
  // The drive is Kp times the small position error (and Kd times the velocity's) of a stiff loop:
  // it magnifies the runs' difference (measured 2.1e-9 of its scale against 2.3e-11 of the
  // positions'); 1e-8 leaves a margin of 5.
  constexpr double kDriveRelTol = 1e-8;
  const double M = 3.0;
  const StaticCoulombViscous law{12.0, 8.0, 20.0};  // Fs, Fc (N), Fv (N s/m): sticks at each reversal
  const ControllerParams c = gains_for(M);
  InputSignal r;  // 10 mm sine at 4 rad/s
  r.shape = InputShape::sine;
  r.amplitude = 0.01;
  r.omega = 4.0;
  InputSignal idle;                                 // constant 0 m
  SimulationOptions o;
  o.duration = 2.0;
  o.output_rate = 500.0;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  const Trajectory one = simulate(ClosedLoop(std::make_shared<const RigidAxis>(AxisParams{M, 0.0}), c), law, r, o);
  ASSERT_GT(one.switches.size(), 2u) << "the case must stick at the reversals";
  for (int active : {0, 1}) {
    SCOPED_TRACE(active == 0 ? "x moves" : "y moves");
    const XyTable plant(axis_of(M, law, c), axis_of(M, law, c));
    const InputSignal inputs[2] = {active == 0 ? r : idle, active == 0 ? idle : r};
    const Trajectory two = simulate(plant, Viscous{0.0}, inputs, o);
    ASSERT_EQ(two.num_contacts(), 2);
    const ContactColumns& moving = two.contact(active);
    EXPECT_LT(relative_difference(moving.position, one.position), kRelTol);
    EXPECT_LT(relative_difference(moving.velocity, one.velocity), kDriveRelTol);
    EXPECT_LT(relative_difference(moving.drive, one.drive), kDriveRelTol);
    std::printf("relative differences: position %.2g, velocity %.2g, drive %.2g\n",
                relative_difference(moving.position, one.position), relative_difference(moving.velocity, one.velocity),
                relative_difference(moving.drive, one.drive));
    const ContactColumns& still = two.contact(1 - active);
    EXPECT_EQ(*std::max_element(still.position.begin(), still.position.end()), 0.0);
    EXPECT_EQ(*std::min_element(still.position.begin(), still.position.end()), 0.0);
    std::size_t switches = 0;
    for (const ModeSwitch& s : two.switches) switches += s.contact == active ? 1 : 0;
    EXPECT_EQ(switches, one.switches.size());
  }
}

// A compensator on an axis runs as in ClosedLoop: its states are plant states, its switches plant
// events located by the engine, and the axis's run is the 1-DOF compensated loop's.
TEST(XyTable, CompensatorIsWiredAsInTheClosedLoop) {
  constexpr double kRelTol = 1e-9;        // as in the uncompensated comparison: integration error at rtol 1e-12
  constexpr double kDriveRelTol = 1e-8;   // Kp times the position difference, as there
  const double M = 3.0;
  const StaticCoulombViscous law{12.0, 8.0, 20.0};
  const ControllerParams c = gains_for(M);
  const auto comp = std::make_shared<const FeedbackCompensation>(law, FeedbackParams{.dead_band = 0.005});
  ASSERT_GT(comp->num_events(), 0);
  ASSERT_GT(comp->num_states(), 0);
  InputSignal r;  // 10 mm sine at 4 rad/s
  r.shape = InputShape::sine;
  r.amplitude = 0.01;
  r.omega = 4.0;
  SimulationOptions o;
  o.duration = 2.0;
  o.output_rate = 500.0;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  const ClosedLoop loop(std::make_shared<const RigidAxis>(AxisParams{M, 0.0}), c, comp);
  const Trajectory one = simulate(loop, law, r, o);
  ASSERT_FALSE(one.plant_events.empty()) << "the case must cross the dead band";

  XyAxis x = axis_of(M, law, c);
  x.compensator = comp;
  const XyTable plant(x, axis_of(M, law, c));
  EXPECT_EQ(plant.num_events(), comp->num_events());
  EXPECT_EQ(plant.num_states(), 4 + 2 + comp->num_states());
  const InputSignal inputs[2] = {r, InputSignal{}};
  const Trajectory two = simulate(plant, Viscous{0.0}, inputs, o);
  EXPECT_LT(relative_difference(two.contact(0).position, one.position), kRelTol);
  EXPECT_LT(relative_difference(two.contact(0).drive, one.drive), kDriveRelTol);
  ASSERT_EQ(two.plant_events.size(), one.plant_events.size());
  for (std::size_t i = 0; i < one.plant_events.size(); ++i) {
    EXPECT_EQ(two.plant_events[i].index, one.plant_events[i].index);
    EXPECT_NEAR(two.plant_events[i].time, one.plant_events[i].time, kRelTol);
  }
  // On y instead, its events come after x's (none here): the same indices.
  XyAxis y = axis_of(M, law, c);
  y.compensator = comp;
  const XyTable swapped(axis_of(M, law, c), y);
  const InputSignal swapped_inputs[2] = {InputSignal{}, r};
  const Trajectory three = simulate(swapped, Viscous{0.0}, swapped_inputs, o);
  EXPECT_LT(relative_difference(three.contact(1).position, one.position), kRelTol);
  EXPECT_EQ(three.plant_events.size(), one.plant_events.size());
}

// The sampled loop: the command computed at a sample is applied at once (delay 0) or at the next
// sample (delay 1), the integral accumulates Ts e, and nothing moves between samples.
TEST(XyTable, SampledLoopHoldsAndDelaysTheCommand) {
  const ControllerParams c{.Kp = 1000, .Ki = 200, .Kd = 10, .limit = 30, .Kvff = 5, .Kaff = 1};
  const double Ts = 1e-3;
  for (int delay : {0, 1}) {
    SCOPED_TRACE("delay " + std::to_string(delay));
    const XyTable plant(axis_of(2.0, Viscous{0.0}, c), axis_of(1.0, Viscous{0.0}, c), XyTiming{Ts, delay});
    EXPECT_EQ(plant.sample_period(), Ts);
    EXPECT_EQ(plant.num_states(), 4 + 3 + 3);
    std::vector<double> x(10, 0.0);
    plant.initial_extras(x);
    x[0] = 0.001;
    x[1] = 0.05;
    const InputValue r[2] = {{0.004, 0.1, 0.5}, {0.1, 0.0, 0.0}};  // y: a 0.1 m error saturates
    plant.sample(0.0, x, r);
    const double integral = Ts * 0.003;  // m s: the first sample's error, rectangle rule
    const double u0 = 1000 * 0.003 + 200 * integral - 10 * 0.05 + 5 * 0.1 + 1 * 0.5;
    constexpr double kRelTol = 1e-14;  // a handful of products and sums
    EXPECT_NEAR(x[4], integral, kRelTol);
    double applied[2];
    plant.applied(0.0, x, r, applied);
    EXPECT_NEAR(applied[0], delay == 0 ? u0 : 0.0, kRelTol * u0);
    EXPECT_EQ(applied[1], delay == 0 ? 30.0 : 0.0);  // saturated at the limit
    std::vector<double> dx(10);
    const double friction[2] = {0.0, 0.0};
    plant.derivatives(0.0, x, r, friction, dx);
    for (std::size_t k = 4; k < 10; ++k) EXPECT_EQ(dx[k], 0.0) << "state " << k << " is discrete";
    plant.sample(Ts, x, r);
    plant.applied(Ts, x, r, applied);
    if (delay == 1) {
      EXPECT_NEAR(applied[0], u0, kRelTol * u0);  // the first sample's command, one sample late
    }
  }
}

// Sampled: the compensator runs in its fixed-step form at the samples, its output in the command
// computed there (before the saturation); it has no event functions (a drive switches at samples).
TEST(XyTable, SampledCompensatorAddsItsOutputAtTheSample) {
  const ControllerParams c{.Kp = 1000, .limit = 100};
  const StaticCoulombViscous law{12.0, 8.0, 20.0};
  const auto ff = std::make_shared<const FeedforwardCompensation>(law, FeedforwardParams{.band = 1e-3});
  XyAxis x = axis_of(2.0, law, c);
  x.compensator = ff;
  const XyTable plant(x, axis_of(1.0, law, c), XyTiming{1e-3, 0});
  EXPECT_EQ(plant.num_events(), 0);
  EXPECT_EQ(plant.num_states(), 4 + 3 + ff->num_states() + 3);
  std::vector<double> state(static_cast<std::size_t>(plant.num_states()), 0.0);
  plant.initial_extras(state);
  const InputValue r[2] = {{0.002, 0.05, 0.0}, {0.0, 0.0, 0.0}};  // x's reference moves at 0.05 m/s
  plant.sample(0.0, state, r);
  double applied[2];
  plant.applied(0.0, state, r, applied);
  // Out of the band the feedforward is the law at the reference velocity: Fc + Fv dr/dt.
  constexpr double kRelTol = 1e-14;  // a handful of products and sums
  const double expected = 1000 * 0.002 + (8.0 + 20.0 * 0.05);
  EXPECT_NEAR(applied[0], expected, kRelTol * expected);
  EXPECT_EQ(applied[1], 0.0);
}

TEST(XyTable, RejectsBadParametersNamingAxisAndUnit) {
  const XyAxis good = axis_of(1.0, Viscous{0.0}, {});
  XyAxis neg = good;
  neg.mass = -1.0;
  EXPECT_EQ(error_of([&] { XyTable(good, neg); }), "xy-table: axis y: mass = -1 must be >= 0 (kg)");
  XyAxis no_lead = good;
  no_lead.inertia = 1e-4;
  EXPECT_EQ(error_of([&] { XyTable(no_lead, good); }), "xy-table: axis x: lead = 0 must be > 0 (m/rev) when an inertia is given");
  XyAxis massless = good;
  massless.mass = 0.0;
  EXPECT_NE(error_of([&] { XyTable(massless, good); }).find("axis x: equivalent mass = 0 must be > 0 (kg)"), std::string::npos);
  XyAxis bad_gain = good;
  bad_gain.gains.Kd = -2.0;
  EXPECT_EQ(error_of([&] { XyTable(good, bad_gain); }), "xy-table: axis y: Kd = -2 must be >= 0 (N/(m/s))");
  XyAxis bad_limit = good;
  bad_limit.gains.limit = std::nan("");
  EXPECT_NE(error_of([&] { XyTable(bad_limit, good); }).find("axis x: limit = nan must be >= 0 (N"), std::string::npos);
  XyAxis velocity_loop = good;
  velocity_loop.gains.loop = ControlLoop::velocity;
  EXPECT_NE(error_of([&] { XyTable(velocity_loop, good); }).find("axis x: the axis runs a position loop"), std::string::npos);
  EXPECT_EQ(error_of([&] { XyTable(good, good, XyTiming{-1e-3, 0}); }), "xy-table: Ts = -0.001 must be >= 0 (s; 0 = continuous controller)");
  EXPECT_EQ(error_of([&] { XyTable(good, good, XyTiming{1e-3, 2}); }), "xy-table: delay = 2 must be 0 or 1 (samples)");
  EXPECT_EQ(error_of([&] { XyTable(good, good, XyTiming{0.0, 1}); }), "xy-table: delay = 1 needs a sampled controller (Ts > 0 s)");
}
