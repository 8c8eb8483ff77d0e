// The engine's calls into a plant's own states: initial_extras sees the initial position, velocity
// and inputs at t = 0, and in fixed-step mode a plant's own discrete update (a closed loop's
// compensator) replaces explicit Euler for the states it advances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/models/lugre.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"

using namespace frictionlab;

namespace {

// A mass pushed by a force held from the start: the force (state 2) is set once from the input
// at t = 0 plus a spring-like term on the initial position, and then stays (d/dt = 0).
class HeldForce : public SingleContactPlant {
 public:
  std::string type() const override { return "held-force"; }
  int num_states() const override { return 3; }
  double inertia(int = 0) const override { return 1.0; }
  void initial_extras(std::span<double> x, Inputs u) const override { x[2] = u[0].value - kSpring * x[0]; }
  double applied(double, std::span<const double> x, const InputValue&) const override { return x[2]; }
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override {
    dx[0] = x[1];
    dx[1] = applied(t, x, u) - friction;
    dx[2] = 0.0;
  }
  static constexpr double kSpring = 2.0;  // N/m
};

InputSignal sine(double offset, double amplitude, double omega) {
  InputSignal s;
  s.shape = InputShape::sine;
  s.offset = offset;
  s.amplitude = amplitude;
  s.omega = omega;
  return s;
}

}  // namespace

// The held force is the input at t = 0 (a sine's offset: 0.7 N) minus the spring term at the
// initial position, in every solver mode: initial_extras saw both.
TEST(PlantHooks, InitialExtrasSeeTheInputsAndTheInitialPosition) {
  const HeldForce plant;
  const double x0 = 0.1;  // m
  const double held = 0.7 - HeldForce::kSpring * x0;  // N
  for (const SolverMode mode : {SolverMode::stiff, SolverMode::fixed_step}) {
    SimulationOptions o;
    o.duration = 0.5;
    o.output_rate = 100;
    o.mode = mode;
    o.dt = 1e-3;
    o.initial_position = x0;
    const Trajectory tr = simulate(plant, Viscous{0.5}, sine(0.7, 0.3, 4.0), o);
    ASSERT_EQ(tr.rows(), 51u);
    // The force is a state copied, not computed: exactly equal on every row.
    EXPECT_EQ(tr.applied.front(), held) << solver_mode_name(mode);
    EXPECT_EQ(tr.applied.back(), held) << solver_mode_name(mode);
  }
}

// A disturbance observer in a loop that starts in motion starts at its steady state for the
// measured velocity: no compensation at t = 0 (the observed disturbance is 0 before anything
// happened), where an observer started from rest would command -w M v0 at once.
TEST(PlantHooks, ObserverStartsConsistentWithTheInitialVelocity) {
  ControllerParams c;
  c.Kp = 40.0;  // N/m
  c.Kd = 8.0;   // N s/m
  const DisturbanceObserverParams dob{.bandwidth = 50.0, .inertia = 1.0};
  const ClosedLoop loop(std::make_shared<const RigidAxis>(AxisParams{.M = 1.0}), c,
                        std::make_shared<const DisturbanceObserver>(dob));
  SimulationOptions o;
  o.duration = 0.1;
  o.output_rate = 100;
  o.initial_position = 0.02;  // m
  o.initial_velocity = 0.3;   // m/s
  InputSignal r;  // reference 0
  const Trajectory tr = simulate(loop, Viscous{0.5}, r, o);
  const double pd = c.Kp * (0.0 - o.initial_position) - c.Kd * o.initial_velocity;  // N
  constexpr double kForceTol = 1e-12;  // N; the same few products in another order (|pd| = 3.2 N)
  EXPECT_NEAR(tr.drive.front(), pd, kForceTol) << "observer started at rest would add "
                                               << -dob.bandwidth * dob.inertia * o.initial_velocity << " N";
}

// A feedforward whose reference already moves faster than its band at t = 0 starts in the band's
// upper region (its one state), read from the reference's rate at t = 0.
TEST(PlantHooks, FeedforwardRegionStartsFromTheReferenceRate) {
  const LuGre law;  // Table I
  const auto ff = std::make_shared<const FeedforwardCompensation>(FrictionLaw(law), FeedforwardParams{.band = 1e-3});
  ControllerParams c;
  c.Kp = 10.0;
  const ClosedLoop loop(std::make_shared<const RigidAxis>(AxisParams{}), c, ff);
  ASSERT_EQ(loop.num_states(), 4);
  std::vector<double> x(4, 0.0);
  const InputValue moving{0.0, 0.05, 0.0};  // m, m/s (50 times the band), m/s^2
  loop.initial_extras(x, Inputs(&moving, 1));
  EXPECT_EQ(x[3], 1.0);
  const InputValue backwards{0.0, -0.05, 0.0};
  loop.initial_extras(x, Inputs(&backwards, 1));
  EXPECT_EQ(x[3], -1.0);
}

namespace {

// The 1995 paper's unit mass with Table I LuGre friction under a PD loop with velocity
// feedforward, tracking a sine of 0.2 m at 1 rad/s, compensated by the LuGre observer.
struct ObserverLoop {
  LuGre law;  // Table I
  ClosedLoop loop;
  InputSignal reference = sine(0.0, 0.2, 1.0);
  ObserverLoop()
      : loop(std::make_shared<const RigidAxis>(AxisParams{.M = 1.0}), gains(),
             std::make_shared<const LuGreObserver>(law, LuGreObserverParams{.gain = 0.01})) {}
  static ControllerParams gains() {
    ControllerParams c;
    c.Kp = 100.0;   // N/m
    c.Kd = 20.0;    // N s/m
    c.Kvff = 20.0;  // N s/m: feedback on the velocity error
    return c;
  }
  Trajectory run(SolverMode mode, double dt = 0.0) const {
    SimulationOptions o;
    o.duration = 10.0;
    o.output_rate = 100;
    o.mode = mode;
    o.dt = dt;
    o.rtol = 1e-8;
    o.atol = 1e-10;
    return simulate(loop, law, reference, o);
  }
};

double largest_gap(const std::vector<double>& a, const std::vector<double>& b) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) e = std::max(e, std::abs(a[i] - b[i]));
  return e;
}

}  // namespace

// At dt = 1 ms the observer's bristle state relaxes at sigma0 |v| / g(v), up to 2e4 1/s at the
// sine's 0.2 m/s: explicit Euler needs dt < 1e-4 s there and diverges at 1 ms (to 1e39 m within
// the 10 s). The compensator's own update (exact over the step) stays bounded, and the fixed-step
// run follows the CVODE run to first order in dt.
TEST(PlantHooks, LuGreObserverFixedStepAtACoarseStepFollowsCvode) {
  const ObserverLoop setup;
  const Trajectory ref = setup.run(SolverMode::stiff);
  const Trajectory coarse = setup.run(SolverMode::fixed_step, 1e-3);
  const Trajectory finer = setup.run(SolverMode::fixed_step, 5e-4);
  ASSERT_EQ(ref.rows(), coarse.rows());
  for (std::size_t i = 0; i < coarse.rows(); ++i)
    ASSERT_TRUE(std::isfinite(coarse.position[i]) && std::isfinite(coarse.drive[i])) << "row " << i;
  // Measured at dt = 1 ms: 1.4e-4 m of position and 0.058 N of commanded force apart from CVODE
  // (rtol 1e-8), against a 0.2 m sine and a 4.45 N peak force. The tolerances leave a factor of
  // about 3 for other compilers and libm versions, and are still far below what Euler gives.
  constexpr double kPositionTol = 5e-4;  // m: 0.25 % of the amplitude
  constexpr double kDriveTol = 0.2;      // N: 4.5 % of the peak force
  const double gap_coarse = largest_gap(ref.position, coarse.position);
  EXPECT_LT(gap_coarse, kPositionTol);
  EXPECT_LT(largest_gap(ref.drive, coarse.drive), kDriveTol);
  // First order: halving the step halves the gap (measured ratio 0.50); 0.6 allows for rounding of
  // the breakaway instants to the step.
  constexpr double kFirstOrderRatio = 0.6;
  EXPECT_LT(largest_gap(ref.position, finer.position), kFirstOrderRatio * gap_coarse);
}
