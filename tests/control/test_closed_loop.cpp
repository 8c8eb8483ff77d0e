// A compensator inside a closed loop, run by the simulation engine: the Canudas de Wit et al. 1995
// PID hunting case hunts without compensation and settles with the LuGre observer; feedforward of
// the exact model shrinks the tracking error of a moving reference; the loop's states, events and
// feedforward gains; and a compensator's switch located exactly by the engine.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedback.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

// The 1995 paper's hunting case: unit mass, Table I LuGre friction, PID Kp = 3 N/m, Ki = 4 N/(m s),
// Kv = 6 N s/m, a step of the reference to 1 m at t = 0.
ControllerParams hunting_pid() {
  ControllerParams c;
  c.Kp = 3.0;
  c.Ki = 4.0;
  c.Kd = 6.0;
  return c;
}

std::shared_ptr<const Plant> unit_mass() { return std::make_shared<const RigidAxis>(AxisParams{.M = 1.0}); }

InputSignal step_to_one() {
  InputSignal s;
  s.shape = InputShape::step;
  s.value = 1.0;
  return s;
}

double late_error(const Trajectory& tr, double from, double target) {
  double e = 0;
  for (std::size_t i = 0; i < tr.rows(); ++i)
    if (tr.time[i] >= from) e = std::max(e, std::abs(tr.position[i] - target));
  return e;
}

TEST(ClosedLoopCompensation, LuGreObserverEndsTheHunting) {
  const LuGre lugre;  // Table I
  SimulationOptions o;
  o.duration = 100;
  o.output_rate = 100;
  const Trajectory plain = simulate(ClosedLoop(unit_mass(), hunting_pid()), lugre, step_to_one(), o);
  const auto observer = std::make_shared<const LuGreObserver>(lugre, LuGreObserverParams{.gain = 0.01});
  const ClosedLoop compensated_loop(unit_mass(), hunting_pid(), observer);
  const Trajectory compensated = simulate(compensated_loop, lugre, step_to_one(), o);
  SimulationOptions fine = o;
  fine.max_step = 1e-3;  // s
  const Trajectory resolved = simulate(compensated_loop, lugre, step_to_one(), fine);
  const double e_plain = late_error(plain, 50.0, 1.0), e_comp = late_error(compensated, 50.0, 1.0),
               e_resolved = late_error(resolved, 50.0, 1.0);
  std::printf("hunting: largest |x - 1| after 50 s: %.3g m plain, %.3g m with the LuGre observer (%.3g m with steps "
              "<= 1 ms)\n", e_plain, e_comp, e_resolved);
  // Without compensation the mass keeps sticking about 6.4 cm short of or past the target.
  EXPECT_GT(e_plain, 3e-2);
  // With the observer it settles where the friction holds about 1.499 N, just below Fs = 1.5 N: an
  // equilibrium at the edge of breakaway, which the solver's long steps at rest nudge into slips
  // of about 1e-4 m (1.3e-4 m here); a bound of 1e-3 m is still 60 times below the hunting.
  EXPECT_LT(e_comp, 1e-3);
  // With steps of at most 1 ms the same loop settles to 2e-14 m (a fixed-step RK4 of the same
  // equations at 10 us agrees: 2e-12 m); the bound leaves room for other solver versions.
  EXPECT_LT(e_resolved, 1e-8);
}

TEST(ClosedLoopCompensation, DisturbanceObserverShrinksTheHunting) {
  // The same loop with a disturbance observer (w = 100 rad/s, the true inertia): its drive input is
  // the force the axis applies, the observer's own output included. The mass still slips now and
  // then, but the largest error after 50 s drops from 6.4 cm to about 2.4 mm.
  const LuGre lugre;
  SimulationOptions o;
  o.duration = 100;
  const auto dob =
      std::make_shared<const DisturbanceObserver>(DisturbanceObserverParams{.bandwidth = 100.0, .inertia = 1.0});
  const double e = late_error(simulate(ClosedLoop(unit_mass(), hunting_pid(), dob), lugre, step_to_one(), o), 50.0, 1.0);
  std::printf("hunting with a disturbance observer: largest |x - 1| after 50 s: %.3g m\n", e);
  EXPECT_LT(e, 6.4e-3);  // a tenth of the uncompensated hunting
}

TEST(ClosedLoopCompensation, FeedforwardOfTheExactModelTracksASine) {
  // r = 0.1 sin(0.5 t) m with the hunting PID, velocity and acceleration feedforward (Kvff = Kv,
  // Kaff = M). Without compensation the body hardly leaves rest (Kp 0.1 m = 0.3 N < Fs = 1.5 N):
  // errors of about the amplitude; with the law's steady-state force at the reference velocity
  // added, the error over the last five periods is about 3e-4 m (the bristles' transient at each
  // reversal).
  const LuGre lugre;
  ControllerParams c = hunting_pid();
  c.Kvff = c.Kd;
  c.Kaff = 1.0;
  InputSignal sine;
  sine.shape = InputShape::sine;
  sine.amplitude = 0.1;
  sine.omega = 0.5;
  SimulationOptions o;
  o.duration = 40 * M_PI;  // 10 periods
  o.output_rate = 200;
  auto tracking = [&](const Trajectory& tr) {
    double e = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i)
      if (tr.time[i] >= 20 * M_PI) e = std::max(e, std::abs(tr.position[i] - 0.1 * std::sin(0.5 * tr.time[i])));
    return e;
  };
  const double e_plain = tracking(simulate(ClosedLoop(unit_mass(), c), lugre, sine, o));
  const auto ff = std::make_shared<const FeedforwardCompensation>(lugre);
  const Trajectory ff_run = simulate(ClosedLoop(unit_mass(), c, ff), lugre, sine, o);
  const double e_ff = tracking(ff_run);
  std::printf("sine tracking: largest error over the last 5 periods %.3g m plain, %.3g m with feedforward\n", e_plain,
              e_ff);
  EXPECT_GT(e_plain, 5e-2);
  EXPECT_LT(e_ff, 1e-3);
  // The feedforward's band edges, dr/dt = 0.05 cos(0.5 t) = +-b, are the loop's events: four a
  // period, each located where the rate crosses the edge (edge 0 at +b, edge 1 at -b).
  const double b = FeedforwardParams{}.band;
  ASSERT_EQ(ff_run.plant_events.size(), 40u);
  for (const PlantEvent& ev : ff_run.plant_events) {
    const double rate = 0.05 * std::cos(0.5 * ev.time);
    constexpr double kRateTol = 1e-10;  // m/s: CVODE's root to ~1e-12 s times |d2r/dt2| <= 0.025 m/s^2, with margin
    EXPECT_NEAR(rate, ev.index == 0 ? b : -b, kRateTol) << "t " << ev.time;
  }
}

TEST(ClosedLoopCompensation, FeedforwardGainsTrackWithoutError) {
  // Frictionless unit mass, r = A (1 - cos w t) (at rest at t = 0 like the body): with Kvff = Kd
  // and Kaff = M the controller supplies exactly M d2r/dt2 and the error stays 0 to the solver's
  // tolerance; without them it lags by decimetres (the loop's bandwidth sqrt(Kp / M) = 1.7 rad/s is
  // below w = 2 rad/s).
  ControllerParams c = hunting_pid();
  InputSignal r;
  r.shape = InputShape::sine;
  r.amplitude = -0.2;
  r.omega = 2.0;
  r.phase = M_PI / 2;
  r.offset = 0.2;  // 0.2 - 0.2 cos(2 t)
  SimulationOptions o;
  o.duration = 10;
  const Viscous none{0.0};
  auto largest_error = [&](const ControllerParams& cp) {
    const Trajectory tr = simulate(ClosedLoop(unit_mass(), cp), none, r, o);
    double e = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i) e = std::max(e, std::abs(tr.position[i] - tr.reference[i]));
    return e;
  };
  const double e_plain = largest_error(c);
  c.Kvff = c.Kd;
  c.Kaff = 1.0;
  const double e_ff = largest_error(c);
  std::printf("feedforward gains: largest error %.3g m without, %.3g m with\n", e_plain, e_ff);
  EXPECT_GT(e_plain, 0.05);
  EXPECT_LT(e_ff, 1e-6);  // 3e-8 m here (rtol 1e-8 on 0.4 m of travel, accumulated); 0.39 m without
}

TEST(ClosedLoopCompensation, StatesAndEventsOfTheLoop) {
  const LuGre lugre;
  const ClosedLoop plain(unit_mass(), hunting_pid());
  EXPECT_EQ(plain.num_states(), 3);
  EXPECT_EQ(plain.num_events(), 0);
  EXPECT_EQ(plain.compensator(), nullptr);
  const ClosedLoop observed(unit_mass(), hunting_pid(), std::make_shared<const LuGreObserver>(lugre));
  EXPECT_EQ(observed.num_states(), 4);  // x, v, integral, z^
  EXPECT_EQ(observed.num_events(), 0);
  const ClosedLoop fed(unit_mass(), hunting_pid(), std::make_shared<const FeedforwardCompensation>(lugre));
  EXPECT_EQ(fed.num_states(), 4);  // x, v, integral, band region
  ASSERT_EQ(fed.num_events(), 2);
  // The events are the compensator's, at the reference velocity: g = dr/dt -+ b.
  const std::vector<double> x{0.0, 0.0, 0.0, 0.0};
  const InputValue r{0.5, 0.004, 0.0};
  std::vector<double> g(2);
  fed.events(0.0, x, Inputs(&r, 1), g);
  EXPECT_DOUBLE_EQ(g[0], 0.004 - 1e-3);
  EXPECT_DOUBLE_EQ(g[1], 0.004 + 1e-3);
  // The compensation is the law at dr/dt and adds to the PID before the limit.
  EXPECT_DOUBLE_EQ(fed.compensation(0.0, x, r), FrictionLaw(lugre).sliding(0.004));
  EXPECT_DOUBLE_EQ(fed.control(0.0, x, r), 3.0 * 0.5 + FrictionLaw(lugre).sliding(0.004));
  ControllerParams limited = hunting_pid();
  limited.limit = 2.0;
  const ClosedLoop capped(unit_mass(), limited, std::make_shared<const FeedforwardCompensation>(lugre));
  EXPECT_EQ(capped.control(0.0, x, r), 2.0);  // 1.5 N of PID + ~1.4 N of compensation, cut to 2 N
}

TEST(ClosedLoopCompensation, RejectsBadGains) {
  ControllerParams c = hunting_pid();
  c.Kvff = -1.0;
  EXPECT_EQ(error_of([&] { ClosedLoop(unit_mass(), c); }),
            "controller: Kvff = -1 must be >= 0 (output unit per m/s or rad/s)");
  c = hunting_pid();
  c.Kaff = std::nan("");
  EXPECT_EQ(error_of([&] { ClosedLoop(unit_mass(), c); }),
            "controller: Kaff = nan must be >= 0 (output unit per m/s^2 or rad/s^2)");
  c = hunting_pid();
  c.compensation_gain = 0.0;
  EXPECT_EQ(error_of([&] { ClosedLoop(unit_mass(), c); }),
            "controller: compensation_gain = 0 must be > 0 (plant input unit per N or N m of compensation)");
}

// A feedback compensation that records where the engine reports its switches.
class RecordingFeedback : public FeedbackCompensation {
 public:
  struct Switch {
    double t, v, region;
  };
  using FeedbackCompensation::FeedbackCompensation;
  void on_event(const CompensatorInput& in, std::span<double> z, int k) const override {
    FeedbackCompensation::on_event(in, z, k);
    switches_->push_back({in.t, in.velocity, z[0]});
  }
  std::shared_ptr<std::vector<Switch>> switches_ = std::make_shared<std::vector<Switch>>();
};

TEST(ClosedLoopCompensation, EngineLocatesTheCompensatorsSwitch) {
  // The hunting loop's first slip with feedback compensation (dead band 0.02 m/s): the velocity
  // rises through +0.02 m/s and falls back through it; each switch of the compensation (a jump of
  // about 1 N) is located where v = 0.02 m/s, not stepped over.
  const LuGre lugre;
  const double db = 0.02;  // m/s
  const auto fb = std::make_shared<const RecordingFeedback>(lugre, FeedbackParams{.dead_band = db});
  SimulationOptions o;
  o.duration = 5;
  const Trajectory tr = simulate(ClosedLoop(unit_mass(), hunting_pid(), fb), lugre, step_to_one(), o);
  ASSERT_GE(fb->switches_->size(), 2u);
  // CVODE places a root to about 1e-12 s of time here; times an acceleration of ~1 m/s^2.
  constexpr double kEdgeTol = 1e-9;  // m/s
  const auto& first = (*fb->switches_)[0];
  EXPECT_NEAR(first.v, db, kEdgeTol);
  EXPECT_EQ(first.region, 1.0);  // entering the compensated region
  const auto& second = (*fb->switches_)[1];
  EXPECT_NEAR(second.v, db, kEdgeTol);
  EXPECT_EQ(second.region, 0.0);  // leaving it
  EXPECT_GT(second.t, first.t);
  std::printf("feedback switches at t = %.9f s and %.9f s, v - db = %.2g and %.2g m/s\n", first.t, second.t,
              first.v - db, second.v - db);
}

}  // namespace
}  // namespace frictionlab

namespace frictionlab {
namespace {

// A loop given the compensation's conditions hands its compensator the load (here a function of
// the plant's state, as a known gravity load is estimated) and the measured temperature; without
// them the compensator sees load 0 and T_ref.
TEST(ClosedLoopCompensation, CompensatorSeesTheLoopsLoadAndTemperature) {
  LawEffects e;
  e.load = LoadDependence{0.1, 0.1};
  TemperatureDependence t;
  t.T_ref = 20.0;
  t.Fv_per_K = -0.01;
  e.temperature = t;
  const FrictionLaw law = FrictionLaw(CoulombViscous{1.0, 0.4}).with_effects(e);
  const auto ff = std::make_shared<const FeedforwardCompensation>(law, FeedforwardParams{.band = 1e-3});
  ControllerParams pd;
  pd.Kp = 100.0;
  pd.Kd = 20.0;
  const ClosedLoop plain(unit_mass(), pd, ff);
  CompensationConditions cc;
  cc.load.of_state = [](double, std::span<const double> x) { return 50.0 * std::cos(x[0]); };  // N, of the plant's position
  cc.temperature = 35.0;
  const auto loop = plain.with_conditions(cc);
  std::vector<double> x(static_cast<std::size_t>(loop->num_states()), 0.0);
  x[0] = 0.3;  // m
  InputValue r;
  r.value = 0.3;
  r.rate = 0.2;  // m/s: outside the band
  Conditions c;
  c.load = 50.0 * std::cos(0.3);
  c.temperature = 35.0;
  EXPECT_NEAR(loop->compensation(0.0, x, r), law.sliding(0.2, c), 1e-12);
  EXPECT_NEAR(plain.compensation(0.0, x, r), law.sliding(0.2), 1e-12);
  EXPECT_GT(loop->compensation(0.0, x, r) - plain.compensation(0.0, x, r), 4.0);  // 0.1 x 47.8 N
}

// Tracking error rms (m) over t in [2, 10] s of `law` on a unit mass following a 5 mm/s ramp under
// a PD loop (Kp 400 N/m, Kd 40 N s/m, velocity feedforward 40 N s/m), compensated by `c` (none: null).
double ramp_error_rms(const FrictionLaw& law, std::shared_ptr<const Compensator> c) {
  ControllerParams pd;
  pd.Kp = 400.0;
  pd.Kd = 40.0;
  pd.Kvff = 40.0;
  InputSignal ramp;
  ramp.shape = InputShape::ramp;
  ramp.rate = 0.005;  // m/s
  SimulationOptions o;
  o.duration = 10;
  o.output_rate = 200;
  const Trajectory tr = simulate(ClosedLoop(unit_mass(), pd, std::move(c)), law, ramp, o);
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < tr.rows(); ++i)
    if (tr.time[i] >= 2.0) {
      sum += std::pow(tr.position[i] - tr.reference[i], 2);
      ++n;
    }
  return std::sqrt(sum / static_cast<double>(n));
}

// A slow position ramp (5 mm/s) on a unit mass with Coulomb-viscous friction and a cogging ripple
// of 0.8 N over a 10 mm period, under a PD loop (Kp = 400 N/m, Kd = Kvff = 40 N s/m): the ripple,
// at pi rad/s far inside the loop's 20 rad/s bandwidth, pushes the error back and forth by about
// r / Kp = 2 mm. A compensation that carries the ripple (at the reference position for the
// feedforward, at the measured one for the feedback) removes it; the same compensation of the
// law without its ripple leaves it. Tracking error rms over t in [2, 10] s (four ripple periods,
// after the start's transient).
TEST(ClosedLoopCompensation, RippleCompensationTracksASlowRampBetter) {
  LawEffects e;
  e.ripple = PositionRipple{0.01, {0.8}, {}, {}, {}};  // m, N
  const FrictionLaw law = FrictionLaw(CoulombViscous{1.0, 0.4}).with_effects(e);
  const FrictionLaw velocity_part(CoulombViscous{1.0, 0.4});  // the same law without its ripple
  const double e_none = ramp_error_rms(law, nullptr);
  const double e_ff_plain = ramp_error_rms(law, std::make_shared<const FeedforwardCompensation>(velocity_part));
  const double e_ff = ramp_error_rms(law, std::make_shared<const FeedforwardCompensation>(law));
  const double e_fb_plain = ramp_error_rms(law, std::make_shared<const FeedbackCompensation>(velocity_part));
  const double e_fb = ramp_error_rms(law, std::make_shared<const FeedbackCompensation>(law));
  std::printf("ramp over a ripple: tracking error rms %.3g m uncompensated; feedforward %.3g m without the ripple, "
              "%.3g m with it; feedback %.3g m without, %.3g m with\n",
              e_none, e_ff_plain, e_ff, e_fb_plain, e_fb);
  // Without the ripple term the error keeps the ripple's r / Kp share: 0.8 / 400 / sqrt(2) = 1.4 mm
  // rms quasi-statically, 1.24 mm here (3.2 mm without any compensation: the Coulomb lag too).
  EXPECT_GT(e_ff_plain, 1e-3);
  EXPECT_GT(e_fb_plain, 1e-3);
  // With it (the exact model) the loop is the frictionless one, which tracks the ramp without error
  // once the start's transient has decayed: 1.6e-11 m (feedforward) and 1.9e-12 m (feedback) here,
  // the solver's tolerance; 1e-6 m leaves room for other solver versions and is still a factor
  // 1000 below the error without the ripple term (1.24 mm) and 3000 below none (3.2 mm).
  EXPECT_LT(e_ff, 1e-6);
  EXPECT_LT(e_fb, 1e-6);
  EXPECT_LT(e_ff, e_ff_plain / 1000);
  EXPECT_LT(e_fb, e_fb_plain / 1000);
  EXPECT_LT(e_ff, e_none / 1000);
}

// The LuGre observer of a law with a ripple adds r(x) at the measured position to its bristle
// copy's force, as the feedback does: on the slow ramp over a LuGre contact (Table I) with a
// 0.8 N ripple of period 10 mm, the observer of the law with its ripple tracks far better than the
// observer of the same law without it, whose position-error integral (sigma0 k = 1000 N/(m s))
// takes up only part of a ripple at pi rad/s.
TEST(ClosedLoopCompensation, LuGreObserverWithTheRippleTracksASlowRampBetter) {
  LawEffects e;
  e.ripple = PositionRipple{0.01, {0.8}, {}, {}, {}};  // m, N
  const FrictionLaw velocity_part(LuGre{});
  const FrictionLaw law = velocity_part.with_effects(e);
  const LuGreObserverParams k{.gain = 0.01};
  const double e_none = ramp_error_rms(law, nullptr);
  const double e_plain = ramp_error_rms(law, std::make_shared<const LuGreObserver>(velocity_part, k));
  const double e_ripple = ramp_error_rms(law, std::make_shared<const LuGreObserver>(law, k));
  std::printf("ramp over a ripple, LuGre contact: tracking error rms %.3g m uncompensated; LuGre observer %.3g m "
              "without the ripple, %.3g m with it\n", e_none, e_plain, e_ripple);
  ASSERT_TRUE(std::make_shared<const LuGreObserver>(law, k)->ripple().has_value());
  // The observer without the ripple leaves most of the ripple's r / Kp share: 1.23 mm rms here
  // (3.2 mm uncompensated). With it, the observer started at the contact's own state (at rest)
  // reproduces the friction, and the loop is the frictionless one, which tracks the ramp to the
  // solver's tolerance: 1.2e-12 m here; 1e-6 m leaves room for other solver versions and is still
  // a factor 1000 below the error without the ripple term.
  EXPECT_GT(e_plain, 1e-3);
  EXPECT_LT(e_ripple, 1e-6);
  EXPECT_LT(e_ripple, e_plain / 1000);
}

// A ripple given by table (a measured cogging profile over one 10 mm period, 0.8 N peak) is
// compensated like the harmonics: the feedforward and feedback of the law with its table remove
// it from the ramp's tracking error, those of the law without it leave r / Kp.
TEST(ClosedLoopCompensation, TableRippleCompensationTracksASlowRampBetter) {
  LawEffects e;
  e.ripple = PositionRipple{0.01, {}, {}, {0.0, 0.002, 0.004, 0.0065, 0.008, 0.01}, {0.0, 0.8, 0.3, -0.8, -0.2, 0.0}};
  const FrictionLaw velocity_part(CoulombViscous{1.0, 0.4});
  const FrictionLaw law = velocity_part.with_effects(e);
  const double e_ff_plain = ramp_error_rms(law, std::make_shared<const FeedforwardCompensation>(velocity_part));
  const double e_ff = ramp_error_rms(law, std::make_shared<const FeedforwardCompensation>(law));
  const double e_fb_plain = ramp_error_rms(law, std::make_shared<const FeedbackCompensation>(velocity_part));
  const double e_fb = ramp_error_rms(law, std::make_shared<const FeedbackCompensation>(law));
  std::printf("ramp over a table ripple: feedforward %.3g m without the ripple, %.3g m with it; feedback %.3g m "
              "without, %.3g m with\n", e_ff_plain, e_ff, e_fb_plain, e_fb);
  EXPECT_GT(e_ff_plain, 5e-4);  // m: about r_rms / Kp
  EXPECT_GT(e_fb_plain, 5e-4);
  // With the table the loop is the frictionless one, which tracks the ramp to the solver's tolerance.
  EXPECT_LT(e_ff, e_ff_plain / 1000);
  EXPECT_LT(e_fb, e_fb_plain / 1000);
}

}  // namespace
}  // namespace frictionlab
