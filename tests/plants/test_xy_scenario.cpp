// Scenario files of the two-axis table (scenario/scenario.hpp): what they build, and the messages of
// bad ones (file, key path, value, unit).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>
#include <string>

#include "error_message.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/xy_table.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "temp_dir.hpp"

using namespace frictionlab;
using frictionlab::testing::error_of;
using frictionlab::testing::TempDir;

namespace {

const char* kTable = R"(plant:
  type: xy-table
  axes:
    x: {mass: 10, friction: {law: coulomb, Fc: 5}, drive: {limit: 300, Kaff: 10}}
    y: {mass: 4, inertia: 1.0e-5, lead: 0.01, friction: {law: coulomb, Fc: 3}}
  controller: {Kp: 2.0e5, Ki: 1.0e6, Kd: 1500, Kvff: 1500, Kaff: 5, limit: 200, Ts: 5.0e-4, delay: 1}
)";

Scenario read(const std::string& text, const ScenarioOptions& o = {}) { return scenario_from_yaml(YAML::Load(text), "s.yaml", o); }
std::string error(const std::string& text) {
  return error_of([&] { read(text); });
}

}  // namespace

TEST(XyScenario, ReadsAxesControllerAndCircle) {
  const Scenario sc = read(std::string(kTable) + "input: {type: circle, centre: [0.1, 0.2], radius: 0.01, feed: 0.02, direction: cw, turns: 3}\n");
  const auto& p = dynamic_cast<const XyTable&>(*sc.plant);
  EXPECT_EQ(p.axis(0).mass, 10.0);
  EXPECT_EQ(p.axis(0).gains.limit, 300.0);  // the axis's drive overrides the controller's
  EXPECT_EQ(p.axis(0).gains.Kaff, 10.0);
  EXPECT_EQ(p.axis(1).gains.Kaff, 5.0);     // ... and keeps the controller's elsewhere
  EXPECT_EQ(p.axis(1).gains.limit, 200.0);
  EXPECT_EQ(p.axis(1).gains.Kp, 2.0e5);
  EXPECT_DOUBLE_EQ(p.inertia(1), 4.0 + 1e-5 * std::pow(2 * std::numbers::pi / 0.01, 2));
  EXPECT_EQ(p.timing().Ts, 5e-4);
  EXPECT_EQ(p.timing().delay, 1);
  ASSERT_EQ(sc.inputs.size(), 2u);
  constexpr double kRelTol = 1e-14;  // duration 3 2 pi R / F and the start point: a few roundoffs
  EXPECT_NEAR(sc.options.duration, 3 * 2 * std::numbers::pi * 0.01 / 0.02, kRelTol * 10);
  // The axes start at rest on the contour's first point (angle 0: (cx + R, cy)).
  ASSERT_EQ(sc.options.initial_positions.size(), 2u);
  EXPECT_NEAR(sc.options.initial_positions[0], 0.11, kRelTol);
  EXPECT_NEAR(sc.options.initial_positions[1], 0.2, kRelTol);
  EXPECT_EQ(sc.options.initial_velocities, (std::vector<double>{0.0, 0.0}));
}

TEST(XyScenario, TopLevelFrictionStandsInForAnAxisWithout) {
  const Scenario sc = read(R"(plant:
  type: xy-table
  axes: {x: {mass: 1, friction: {law: coulomb, Fc: 2}}, y: {mass: 1}}
friction: {law: viscous, Fv: 3}
input: {type: circle, radius: 0.01, feed: 0.01}
initial: {position: [0.02, 0.0]}
duration: 0.5
)");
  EXPECT_NE(sc.plant->contact(0).law, nullptr);
  EXPECT_EQ(sc.plant->contact(1).law, nullptr);  // simulate() gives it sc.law
  EXPECT_EQ(sc.law.name(), "viscous");
  EXPECT_EQ(sc.options.duration, 0.5);
  EXPECT_EQ(sc.options.initial_positions, (std::vector<double>{0.02, 0.0}));
  const Trajectory tr = simulate(sc);
  EXPECT_EQ(tr.names()[1], "x.position");
}

TEST(XyScenario, PathFromCsvRunsBothAxes) {
  TempDir dir;
  dir.file("path.csv", "time,x_mm,y_mm\n0,0,0\n0.5,5,0\n1.0,5,5\n");
  const std::string yaml = std::string(kTable) + "input: {type: path, file: path.csv, x: x_mm, y: y_mm, scale: 0.001}\n";
  ScenarioOptions o;
  o.base_dir = dir.path().string();
  const Scenario sc = read(yaml, o);
  EXPECT_EQ(sc.options.duration, 1.0);  // the path's last time
  constexpr double kRelTol = 1e-15;     // one interpolation and one product
  EXPECT_NEAR(sc.inputs[0].at(0.25).value, 0.0025, kRelTol);
  EXPECT_NEAR(sc.inputs[1].at(0.75).value, 0.0025, kRelTol);
  dir.file("back.csv", "time,x,y\n0,0,0\n0.5,1,0\n0.5,1,1\n");
  o.base_dir = dir.path().string();
  const std::string msg = error_of([&] { read(std::string(kTable) + "input: {type: path, file: back.csv}\n", o); });
  EXPECT_NE(msg.find("s.yaml: input: "), std::string::npos) << msg;
  EXPECT_NE(msg.find("back.csv: line 4, column 'time': time 0.5 s must be after the previous row's 0.5 s"), std::string::npos) << msg;
  const std::string missing = error_of([&] { read(std::string(kTable) + "input: {type: path, file: path.csv}\n", o); });
  EXPECT_NE(missing.find("no column 'x'"), std::string::npos) << missing;
}

TEST(XyScenario, BadFilesNameTheKeyAndWhatIsExpected) {
  const std::string circle = "input: {type: circle, radius: 0.01, feed: 0.02}\n";
  const struct {
    std::string yaml;
    std::string message;
  } cases[] = {
      {std::string(kTable) + "input: {type: circle, radius: 0.01, feed: 0.02, speed: 3}\n",
       "s.yaml: input.speed: unknown field 'speed'; valid fields: type, centre, radius, feed, direction, turns, start_angle"},
      {std::string(kTable) + "input: {type: circle, radius: -0.01, feed: 0.02}\n", "s.yaml: input: radius = -0.01 must be > 0 (m)"},
      {std::string(kTable) + "input: {type: circle, radius: 0.01, feed: 0.02, direction: left}\n",
       "s.yaml: input.direction: unknown direction 'left'; valid directions: ccw, cw"},
      {std::string(kTable) + "input: {type: circle, centre: [1, 2, 3], radius: 0.01, feed: 0.02}\n",
       "s.yaml: input.centre: expected [x, y] (m), got 3 numbers"},
      {std::string(kTable) + "input: {type: sine, amplitude: 1, omega: 1}\n",
       "s.yaml: input.type: unknown two-axis input type 'sine'; valid input types: circle, path"},
      {std::string(kTable) + circle + "controller: {Kp: 1}\n",
       "s.yaml: controller: the xy-table's axes have their controller inside the plant: move it to plant.controller"},
      {"plant: {type: axis, M: 1}\nfriction: {law: coulomb, Fc: 1}\n" + circle + "duration: 1\n",
       "s.yaml: input.type: input type 'circle' gives two references and needs a two-axis plant (xy-table); plant axis takes one input: "
       "constant, step, ramp, trapezoid, sine, table, data"},
      {"plant: {type: xy-table, axes: {x: {mass: 1, friction: {law: coulomb, Fc: 1}}, y: {mass: 1, weight: 2}}}\n" + circle,
       "s.yaml: plant.axes.y.weight: unknown field 'weight'; valid fields: mass, inertia, lead, offset, friction, drive, compensation"},
      {"plant: {type: xy-table, axes: {x: {mass: 1, friction: {law: coulomb, Fc: 1}}, y: {mass: 1}}}\n" + circle,
       "s.yaml: plant.axes.y: missing 'friction' (the axis's law), and there is no top-level 'friction' for it"},
      {"plant: {type: xy-table, axes: {x: {mass: 1, friction: {law: coulomb, Fc: 1}}}}\n" + circle,
       "s.yaml: plant.axes: missing 'y' (the y axis)"},
      {"plant: {type: xy-table, axes: {x: {friction: {law: coulomb, Fc: 1}}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n" + circle,
       "s.yaml: plant.axes.x: missing 'mass' (kg) or 'inertia' (kg m^2) with 'lead' (m/rev)"},
      {"plant: {type: xy-table, axes: {x: {inertia: 1.0e-5, friction: {law: coulomb, Fc: 1}}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n" + circle,
       "s.yaml: plant.axes.x: missing 'lead' (m/rev, the screw's), needed with 'inertia'"},
      {"plant: {type: xy-table, axes: {x: {mass: 1, drive: {Kp: -3}}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n" + circle,
       "s.yaml: plant: xy-table: axis x: Kp = -3 must be >= 0 (N/m)"},
      {"plant: {type: xy-table, axes: {x: {mass: 1, drive: {Kv: 3}}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n" + circle,
       "s.yaml: plant.axes.x.drive.Kv: unknown field 'Kv'; valid fields: limit, Kp, Ki, Kd, Kvff, Kaff"},
      {"plant: {type: xy-table, axes: {x: {mass: 1}, y: {mass: 1}}, controller: {Ts: 1.0e-3, delay: 2}}\nfriction: {law: viscous, Fv: 1}\n" + circle,
       "s.yaml: plant.controller.delay: 2 must be 0 or 1 (samples)"},
      {"plant: {type: xy-table, axes: {x: {mass: 1}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n" + circle + "initial: {position: 0}\n",
       "s.yaml: initial.position: expected a list of numbers, e.g. [0, 1, 2]"},
      {"plant: {type: xy-table, axes: {x: {mass: 1}, y: {mass: 1}}}\nfriction: {law: viscous, Fv: 1}\n",
       "s.yaml: missing 'input' (the contour of the xy-table); valid input types: circle, path"},
  };
  for (const auto& c : cases) EXPECT_EQ(error(c.yaml), c.message) << c.yaml;
}
