#pragma once
// Scenario files: a YAML description of a simulation (plant, friction law, input, controller,
// duration, output rate, solver, initial state) turned into a Scenario.
//
//   plant:      {type: axis|pendulum|spring-base|dc-motor|velocity-drive, ...parameters}
//   friction:   {law: NAME, ...parameters}          # the law YAML form of io/law_file.hpp
//   input:      {type: constant|step|ramp|trapezoid|sine|table, ...}
//   controller: {loop: position|velocity, Kp, Ki, Kd, limit}   # optional
//   duration: 30            # s, > 0 (required)
//   output_rate: 100        # Hz, > 0 (default 100)
//   solver: {mode: auto|hybrid|stiff|fixed-step, rtol, atol, dt, max_step}   # optional
//   initial: {position: 0, velocity: 0}                                     # optional
//   description: free text  # optional
//
// Plant parameters (SI): axis: M (required), offset; pendulum: m, l (required), g (9.81), B (0);
// spring-base: m, k, V0 (required), c (0), x0 (0); dc-motor: J, R, Kt, Kb (required), L (required
// in voltage drive), Ka (1), load (0), drive: voltage|current (voltage); velocity-drive: M (0).
// Inputs: constant: value; step: value, initial (0), time (0); ramp: rate, initial (0), time (0),
// limit (none); trapezoid: level, rate, hold (0), rate_down (= rate), initial (0), time (0);
// sine: amplitude, omega (rad/s) or frequency (Hz), phase (0, rad), offset (0);
// table: times, values, interpolation: linear|hold (linear).

#include <string>

#include "frictionlab/simulate/scenario.hpp"

namespace YAML {
class Node;
}

namespace frictionlab {

/// Reads a scenario from a parsed YAML mapping. `where` prefixes every message (the file name).
/// \throws std::invalid_argument "WHERE: KEY.PATH: ..." for an unknown plant/law/input type or
///         field (listing the valid ones), a missing required field (naming it), a value that is
///         not a number, or a non-positive duration, output rate, tolerance or step (with its value).
Scenario scenario_from_yaml(const YAML::Node& root, const std::string& where);

/// Reads a scenario file. \throws std::invalid_argument naming the file when it cannot be read
/// or is not valid YAML (with line and column), and what scenario_from_yaml throws.
Scenario load_scenario(const std::string& path);

}  // namespace frictionlab
