// The `compensation:` block of scenario files (scenario/scenario.hpp): what it builds on a pid loop and
// on the xy-table's axes, the messages of bad blocks, and the two compensated examples: the
// lecture's hunting case settles, and feedforward flattens the circular test's quadrant glitches.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/control/disturbance_observer.hpp"
#include "frictionlab/control/feedforward.hpp"
#include "frictionlab/control/lugre_observer.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/models/viscous.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "radial_error.hpp"
#include "temp_dir.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;
using frictionlab::testing::radial_error;
using frictionlab::testing::RadialError;
using frictionlab::testing::TempDir;

namespace {

std::string example(const std::string& name) { return std::string(FRICTIONLAB_SOURCE_DIR) + "/examples/" + name; }

Scenario read(const std::string& text, const ScenarioOptions& o = {}) { return scenario_from_yaml(YAML::Load(text), "s.yaml", o); }
std::string error(const std::string& text) {
  return error_of([&] { read(text); });
}

// A pid loop on a unit mass with Stribeck friction; `comp` is the controller's compensation block.
std::string pid_loop(const std::string& comp) {
  return "plant: {type: axis, M: 2.0}\n"
         "friction: {law: stribeck, Fc: 1.0, Fs: 1.5, vs: 0.001, delta: 2, Fv: 0.4}\n"
         "input: {type: step, value: 1.0}\nduration: 1\n"
         "controller: {Kp: 3, Ki: 4, Kd: 6, compensation: " + comp + "}\n";
}

const Compensator* compensator_of(const Scenario& sc) {
  const auto* loop = dynamic_cast<const ClosedLoop*>(sc.plant.get());
  return loop ? loop->compensator() : nullptr;
}

double largest(const RadialError& e) { return *std::max_element(std::begin(e.near), std::end(e.near)); }

}  // namespace

TEST(CompensationScenario, PidLoopTakesTheScenarioLawScaled) {
  const Scenario exact = read(pid_loop("{type: feedforward, band: 0.002}"));
  const auto* ff = dynamic_cast<const FeedforwardCompensation*>(compensator_of(exact));
  ASSERT_NE(ff, nullptr);
  EXPECT_EQ(ff->params().band, 0.002);
  const Scenario over = read(pid_loop("{type: feedforward, scale: 1.2}"));
  const auto* ff_over = dynamic_cast<const FeedforwardCompensation*>(compensator_of(over));
  ASSERT_NE(ff_over, nullptr);
  // Every newton-carrying parameter (Fc, Fs, Fv) times 1.2: the force is 1.2 times the law's at
  // every velocity; vs and delta are untouched. Equal to a few roundoffs of the products.
  constexpr double kRelTol = 1e-14;
  for (double v : {-0.05, -0.002, 0.0015, 0.01, 0.3}) {
    EXPECT_NEAR(ff_over->force(v), 1.2 * exact.law.sliding(v), kRelTol * std::abs(exact.law.sliding(v))) << "v = " << v;
  }
}

TEST(CompensationScenario, ObserversAndModelFiles) {
  const Scenario dob = read(pid_loop("{type: disturbance-observer, bandwidth: 50}"));
  const auto* d = dynamic_cast<const DisturbanceObserver*>(compensator_of(dob));
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->params().bandwidth, 50.0);
  EXPECT_EQ(d->params().inertia, 2.0);  // the plant's M when the block gives none

  // A model file, relative to the scenario file's directory; its identified M is the observer's.
  TempDir dir;
  std::ofstream(dir.path() / "model.json")
      << R"({"model": "lugre", "status": "ok", "parameters": {"sigma0": {"value": 1e5}, "sigma1": {"value": 300},)"
         R"( "sigma2": {"value": 0.4}, "Fc": {"value": 1.0}, "Fs": {"value": 1.5}, "vs": {"value": 0.001},)"
         R"( "M": {"value": 2.5}}})";
  std::ofstream(dir.path() / "s.yaml") << pid_loop("{type: lugre-observer, model: model.json, gain: 0.02}");
  const Scenario obs = load_scenario((dir.path() / "s.yaml").string());
  const auto* o = dynamic_cast<const LuGreObserver*>(compensator_of(obs));
  ASSERT_NE(o, nullptr);
  EXPECT_EQ(o->params().gain, 0.02);
  EXPECT_EQ(o->law().sigma1, 300.0);
  std::ofstream(dir.path() / "d.yaml") << pid_loop("{type: disturbance-observer, model: model.json}");
  const auto* dm = dynamic_cast<const DisturbanceObserver*>(compensator_of(load_scenario((dir.path() / "d.yaml").string())));
  ASSERT_NE(dm, nullptr);
  EXPECT_EQ(dm->params().inertia, 2.5);
}

TEST(CompensationScenario, XyTableSharedPerAxisAndNone) {
  const std::string table = R"(plant:
  type: xy-table
  compensation: {type: feedforward}
  axes:
    x: {mass: 10, friction: {law: coulomb, Fc: 5}, drive: {limit: 300}}
    y: {mass: 4, friction: {law: coulomb, Fc: 3}, AXIS_Y}
  controller: {Kp: 2.0e5, Ki: 1.0e6, Kd: 1500}
input: {type: circle, radius: 0.01, feed: 0.02}
)";
  auto with = [&](const std::string& y) {
    std::string t = table;
    t.replace(t.find("AXIS_Y"), 6, y);
    return read(t);
  };
  const Scenario shared = with("drive: {limit: 100}");
  const auto& p = dynamic_cast<const XyTable&>(*shared.plant);
  const auto* fx = dynamic_cast<const FeedforwardCompensation*>(p.axis(0).compensator.get());
  const auto* fy = dynamic_cast<const FeedforwardCompensation*>(p.axis(1).compensator.get());
  ASSERT_NE(fx, nullptr);
  ASSERT_NE(fy, nullptr);
  EXPECT_EQ(fx->force(0.1), 5.0);  // each axis its own law
  EXPECT_EQ(fy->force(0.1), 3.0);
  const Scenario own = with("compensation: {type: disturbance-observer, bandwidth: 80}");
  const auto* dy = dynamic_cast<const DisturbanceObserver*>(dynamic_cast<const XyTable&>(*own.plant).axis(1).compensator.get());
  ASSERT_NE(dy, nullptr);
  EXPECT_EQ(dy->params().inertia, 4.0);  // the axis's equivalent mass
  const Scenario off = with("compensation: none");
  EXPECT_EQ(dynamic_cast<const XyTable&>(*off.plant).axis(1).compensator, nullptr);
  EXPECT_NE(dynamic_cast<const XyTable&>(*off.plant).axis(0).compensator, nullptr);
}

TEST(CompensationScenario, BadBlocksNameTheirKey) {
  EXPECT_EQ(error(pid_loop("{type: lugre-observer}")), 
            "s.yaml: controller.compensation.type: lugre-observer: law = stribeck must be lugre (the observer runs a copy of the LuGre bristle state); without 'model' or 'friction' the compensation uses the compensated contact's own law: give a LuGre law in 'friction' or 'model'");
  EXPECT_EQ(error(pid_loop("{type: lugre-observer, friction: {law: coulomb, Fc: 1}}")), 
            "s.yaml: controller.compensation.friction: lugre-observer: law = coulomb must be lugre (the observer runs a copy of the LuGre bristle state)");
  EXPECT_EQ(error(pid_loop("{type: observer}")), 
            "s.yaml: controller.compensation.type: unknown compensation type 'observer'; valid types: feedforward, feedback, lugre-observer, disturbance-observer");
  EXPECT_EQ(error(pid_loop("{band: 0.1}")), 
            "s.yaml: controller.compensation: missing 'type'; valid compensation types: feedforward, feedback, lugre-observer, disturbance-observer");
  EXPECT_EQ(error(pid_loop("{type: feedforward, gain: 0.1}")), 
            "s.yaml: controller.compensation: compensation feedforward has no parameter 'gain'; it has band (and type, model, friction, scale)");
  EXPECT_EQ(error(pid_loop("{type: feedforward, frction: {law: coulomb, Fc: 1}}")),
            "s.yaml: controller.compensation: compensation feedforward has no parameter 'frction'; it has band (and type, model, friction, scale)");
  EXPECT_EQ(error(pid_loop("{type: feedforward, scale: 0}")), 
            "s.yaml: controller.compensation.scale: 0 must be > 0 (factor on the law's forces)");
  EXPECT_EQ(error(pid_loop("{type: feedforward, band: -1}")), 
            "s.yaml: controller.compensation: feedforward: band = -1 must be > 0 (m/s or rad/s)");
  EXPECT_EQ(error(pid_loop("{type: disturbance-observer, friction: {law: coulomb, Fc: 1}}")), 
            "s.yaml: controller.compensation.friction: a disturbance-observer uses no friction law (its parameters: bandwidth, inertia; 'model' may give the inertia M)");
  EXPECT_EQ(error(pid_loop("{type: feedforward, model: nowhere.json}")), 
            "s.yaml: controller.compensation.model: nowhere.json: cannot open the model file");
  EXPECT_EQ(error(pid_loop("{type: feedforward, model: m.json, friction: {law: coulomb, Fc: 1}}")), 
            "s.yaml: controller.compensation: give either 'model' (a MODEL.json or law file) or 'friction' (a law), not both");
}

// The lecture's hunting case (examples/canudas_pid_hunting.yaml) with the LuGre observer of the
// exact model: the limit cycle disappears.
TEST(CompensationScenario, HuntingExampleSettlesWithTheLuGreObserver) {
  auto late_error = [](const Trajectory& tr) {
    double e = 0;
    for (std::size_t i = 0; i < tr.rows(); ++i)
      if (tr.time[i] >= 50.0) e = std::max(e, std::abs(tr.position[i] - 1.0));  // m, target 1 m
    return e;
  };
  const double plain = late_error(simulate(load_scenario(example("canudas_pid_hunting.yaml"))));
  const Trajectory tr = simulate(load_scenario(example("canudas_pid_hunting_compensated.yaml")));
  const double comp = late_error(tr);
  std::printf("hunting: largest |x - 1| after 50 s: %.3g m plain, %.3g m compensated; final error %.3g m\n", plain, comp,
              std::abs(tr.position.back() - 1.0));
  EXPECT_GT(plain, 3e-2);  // the limit cycle: slips of centimetres keep coming
  // Compensated, the mass rests on the target: ~1e-14 m measured (steps <= 1 ms); the bound leaves
  // room for other solver versions and is still six decades below the hunting.
  constexpr double kSettled = 1e-8;  // m
  EXPECT_LT(comp, kSettled);
}

// examples/xy_circle_compensated.yaml: feedforward from the exact model lowers the largest quadrant
// glitch of examples/xy_circle.yaml by at least 80 %.
TEST(CompensationScenario, FeedforwardFlattensTheQuadrantGlitches) {
  constexpr double R = 0.01;      // m, the examples' radius
  constexpr double kFrom = 0.2;   // s: past the start transient (as tests/plants/test_xy_circle.cpp)
  constexpr double kNear = 15.0;  // degrees around each reversal
  constexpr double kFar = 30.0;   // degrees
  const RadialError plain = radial_error(simulate(load_scenario(example("xy_circle.yaml"))), 0, 0, R, kFrom, kNear, kFar);
  const RadialError comp =
      radial_error(simulate(load_scenario(example("xy_circle_compensated.yaml"))), 0, 0, R, kFrom, kNear, kFar);
  std::printf("largest quadrant glitch: %.3g um without, %.3g um with feedforward (%.0f %% lower)\n", 1e6 * largest(plain),
              1e6 * largest(comp), 100.0 * (1.0 - largest(comp) / largest(plain)));
  constexpr double kRequiredDrop = 0.8;  // the acceptance criterion of the compensated example
  EXPECT_LT(largest(comp), (1.0 - kRequiredDrop) * largest(plain));
}

// examples/emps_closed_loop_compensated.yaml: the EMPS loop with feedforward from its own
// (identified) friction law. The tracking error qg - q of the EMPS PD loop is mostly its following
// error qd/kp (no velocity feedforward), which friction does not cause; the part friction causes
// is the difference to the same run without friction, and the compensation must remove most of it.
TEST(CompensationScenario, EmpsLoopFeedforwardRemovesTheFrictionPartOfTheTrackingError) {
  auto tracking = [](const Trajectory& tr) {
    std::vector<double> e(tr.rows());
    for (std::size_t i = 0; i < tr.rows(); ++i) e[i] = tr.reference[i] - tr.position[i];  // m
    return e;
  };
  ScenarioOptions frictionless;
  frictionless.law = FrictionLaw(Viscous{0.0});
  const auto free = tracking(simulate(load_scenario(example("emps_closed_loop.yaml"), frictionless)));
  const auto plain = tracking(simulate(load_scenario(example("emps_closed_loop.yaml"))));
  const auto comp = tracking(simulate(load_scenario(example("emps_closed_loop_compensated.yaml"))));
  ASSERT_EQ(plain.size(), free.size());
  ASSERT_EQ(comp.size(), free.size());
  auto rms = [](const std::vector<double>& a, const std::vector<double>& b) {
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s / static_cast<double>(a.size()));
  };
  const std::vector<double> zero(free.size(), 0.0);
  const double part_plain = rms(plain, free), part_comp = rms(comp, free);
  std::printf("EMPS tracking error rms: %.4g mm without, %.4g mm with feedforward (%.4g mm without friction); "
              "friction's part %.3g um -> %.3g um\n",
              1e3 * rms(plain, zero), 1e3 * rms(comp, zero), 1e3 * rms(free, zero), 1e6 * part_plain, 1e6 * part_comp);
  EXPECT_GT(part_plain, 1e-5);  // m: friction's part without compensation (27 um rms measured)
  // Measured: 0.8 um rms, 3 % of it: the feedforward sees the reference's velocity, not the axis's,
  // and the loop's one-sample delay; 10 % leaves room for solver versions and still needs most removed.
  constexpr double kRemainingShare = 0.1;
  EXPECT_LT(part_comp, kRemainingShare * part_plain);
  EXPECT_LT(rms(comp, zero), rms(plain, zero));
}

// A scenario law with a position ripple: the controller's feedforward of the exact model carries
// the ripple at the reference position, the feedback at the measured one, and `scale` scales the
// ripple's amplitudes with the law's other forces.
TEST(CompensationScenario, RippleOfTheScenarioLawIsCompensatedAndScaled) {
  auto loop = [](const std::string& comp) {
    return "plant: {type: axis, M: 1.0}\n"
           "friction: {law: coulomb-viscous, Fc: 1.0, Fv: 0.4, ripple_period: 0.01, ripple_a: [0.8]}\n"
           "input: {type: ramp, rate: 0.005}\nduration: 1\n"
           "controller: {Kp: 400, Kd: 40, compensation: " + comp + "}\n";
  };
  const Scenario sc = read(loop("{type: feedforward}"));
  const Compensator* ff = compensator_of(sc);
  ASSERT_NE(ff, nullptr);
  CompensatorInput in;
  in.reference = 0.0025;  // m: a quarter period, r = 0.8 N
  in.reference_rate = 0.005;
  in.position = 0.0;  // r(0) = 0: the feedforward reads the reference, not this
  std::vector<double> z(1);
  ff->initial_states(in, z);
  constexpr double kRelTol = 1e-14;  // a sum and a product of a few rounded terms
  const double expected = sc.law.sliding(0.005) + 0.8;
  EXPECT_NEAR(ff->output(in, z), expected, kRelTol * expected);
  const Scenario over = read(loop("{type: feedforward, scale: 1.2}"));
  ff = compensator_of(over);
  ASSERT_NE(ff, nullptr);
  EXPECT_NEAR(ff->output(in, z), 1.2 * expected, kRelTol * expected);
  const Scenario fb = read(loop("{type: feedback}"));
  ASSERT_NE(compensator_of(fb), nullptr);
  in.position = 0.0025;
  in.reference = 0.0;
  in.velocity = 0.0;  // at rest, inside the dead band: the ripple alone
  compensator_of(fb)->initial_states(in, z);
  EXPECT_NEAR(compensator_of(fb)->output(in, z), 0.8, kRelTol);
}
