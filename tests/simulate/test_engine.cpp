// Engine tests against closed forms and the reference results of DESIGN.md.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/closed_loop.hpp"
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
  EXPECT_NEAR(switch_time(tr, SwitchKind::breakaway), 35.47, 0.02);  // DESIGN.md reference
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
