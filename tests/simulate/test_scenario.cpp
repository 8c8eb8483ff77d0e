// Scenario YAML: what is read, and what is refused with which message.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/plants/dc_motor.hpp"

using namespace frictionlab;

namespace {

Scenario parse(const std::string& text) { return scenario_from_yaml(YAML::Load(text), "s.yaml"); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

const char* kBase = R"(
plant: {type: axis, M: 2}
friction: {law: coulomb, Fc: 1}
duration: 5
)";

}  // namespace

TEST(Scenario, ReadsEverySection) {
  const Scenario sc = parse(R"(
plant: {type: dc-motor, drive: voltage, J: 1e-6, R: 2, L: 1e-3, Kt: 0.02, Kb: 0.02}
friction: {law: stribeck, Fc: 0.001, Fs: 0.002, vs: 1, Fv: 1e-6}
controller: {loop: velocity, Kp: 0.1, Ki: 2}
input: {type: table, times: [0, 1], values: [10, 20], interpolation: hold}
duration: 2
output_rate: 50
solver: {mode: hybrid, rtol: 1e-7, atol: 1e-9}
initial: {position: 0.5}
)");
  ASSERT_TRUE(sc.plant);
  EXPECT_EQ(sc.plant->type(), "dc-motor");
  EXPECT_EQ(sc.plant->num_states(), 4);  // angle, speed, current, integrator
  const auto* loop = dynamic_cast<const ClosedLoop*>(sc.plant.get());
  ASSERT_NE(loop, nullptr);
  EXPECT_EQ(loop->controller().loop, ControlLoop::velocity);
  EXPECT_EQ(sc.law.name(), "stribeck");
  EXPECT_EQ(sc.input.shape, InputShape::table);
  EXPECT_TRUE(sc.input.hold_steps);
  EXPECT_EQ(sc.input.at(1.5).value, 20.0);
  EXPECT_EQ(sc.options.duration, 2.0);
  EXPECT_EQ(sc.options.output_rate, 50.0);
  EXPECT_EQ(sc.options.mode, SolverMode::hybrid);
  EXPECT_EQ(sc.options.rtol, 1e-7);
  EXPECT_EQ(sc.options.initial_position, 0.5);
}

TEST(Scenario, MessagesNameFileKeyValueAndWhatIsValid) {
  const std::string base = kBase;
  EXPECT_NE(error_of(base + "input: {type: chirp}\n").find("s.yaml: input.type: unknown input type 'chirp'; valid input types: constant, step, ramp, trapezoid, sine, table"), std::string::npos);
  EXPECT_NE(error_of(base + "output_rate: 0\n").find("s.yaml: output_rate: 0 must be > 0 (Hz)"), std::string::npos);
  EXPECT_NE(error_of(base + "solver: {rtol: -1}\n").find("s.yaml: solver.rtol: -1 must be > 0"), std::string::npos);
  EXPECT_NE(error_of(base + "solver: {mode: magic}\n").find("valid modes: auto, hybrid, stiff, fixed-step"), std::string::npos);
  EXPECT_NE(error_of(base + "solver: {mode: stiff}\n").find("stiction needs the hybrid engine"), std::string::npos);
  EXPECT_NE(error_of(base + "speed: 3\n").find("s.yaml.speed: unknown field 'speed'"), std::string::npos);
  EXPECT_NE(error_of(base + "input: {type: trapezoid, level: 1}\n").find("s.yaml: input: missing 'rate'"), std::string::npos);
  EXPECT_NE(error_of(base + "input: {type: constant, value: abc}\n").find("s.yaml: input.value: expected a number, got 'abc'"), std::string::npos);
  EXPECT_NE(error_of(R"(
plant: {type: axis, M: -2}
friction: {law: coulomb, Fc: 1}
duration: 5
)").find("s.yaml: plant: axis: M = -2 must be > 0"), std::string::npos);
  EXPECT_NE(error_of(R"(
plant: {type: axis, M: 2}
friction: {law: coulomb, Fc: 1}
controller: {loop: velocity, Kd: 1}
duration: 5
)").find("s.yaml: controller: controller: Kd = 1 must be 0 in a velocity loop"), std::string::npos);
  EXPECT_NE(error_of("plant: {type: axis, M: 1}\nduration: 1\n").find("s.yaml: friction"), std::string::npos);
}
