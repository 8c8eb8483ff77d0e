#pragma once
// Scenario files: a YAML description of a simulation (plant, friction law, input, controller,
// duration, output rate, solver, initial state) turned into a Scenario.
//
//   plant:      {type: axis|pendulum|spring-base|dc-motor|velocity-drive|xy-table, ...parameters}
//   friction:   {law: NAME, ...parameters}          # the law YAML form of scenario/law_file.hpp
//   input:      {type: constant|step|ramp|trapezoid|sine|table, ...}
//   controller: {loop: position|velocity, Kp, Ki, Kd, limit}   # optional, continuous P/PI/PD/PID
//   controller: {type: emps-pd, kp, kv, gtau, limit (10 V), dt, delay (1), pulses}  # EMPS loop
//   data: FILE              # optional: data file of `data` inputs, named constants, pulses
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
// table: times, values, interpolation: linear|hold (linear);
// data: column (required), time (column name, default "time"), file (default: the top-level
// `data`), scale (1), interpolation: linear|hold (linear). The samples are placed on a regular
// grid t_k = k dt from t = 0 s, dt the mean step of the time column (checked regular within 1 %),
// so that a sampled controller with the same dt reads sample k exactly at its instant k.
// Without `duration`, a data input sets it to the data's span (N - 1) dt.
//
// emps-pd (simulate/emps_pd_loop.hpp): kp (1/s), kv (V/(m/s)), gtau (N/V) each a number or the name of
// a scalar of the data file; limit (V, 10); dt (s; default the data input's step); delay (0|1,
// default 1); pulses: COLUMN, or {column, scale (1), optional (false)}: volts added to the
// saturated output, read from the data file on the same grid (optional: none when absent).
// initial.position may name a column of the data file: its first sample (m).
// Relative file names are resolved from the scenario file's directory.
//
// xy-table (simulate/xy_table.hpp), two axes with their own laws and drives:
//   plant:
//     type: xy-table
//     axes:
//       x: {mass: 25, friction: {law: stribeck, ...}, drive: {limit: 2000}}   # kg; law in N vs m/s
//       y: {mass: 8, inertia: 2e-4, lead: 0.01, friction: {...}, drive: {limit: 1000, Kaff: 16}}
//     controller: {Kp, Ki, Kd, Kvff, Kaff, limit, Ts (0 = continuous), delay (0|1)}
//   input: {type: circle, centre: [0, 0], radius: 0.01, feed: 0.02, direction: ccw|cw, turns: 1,
//           start_angle: 0}                                          # m, m/s, rad
//   input: {type: path, file: path.csv, time: time, x: x, y: y, scale: 1}   # columns; scale m per unit
//   initial: {position: [x, y], velocity: [vx, vy]}   # optional; default: at rest on the contour's start
// Per axis: mass (kg) and/or inertia (kg m^2) with lead (m/rev), equivalent mass mass + inertia
// (2 pi / lead)^2; offset (N, default 0: a constant force on the carriage); friction (required unless a top-level `friction` stands in for it); drive: the
// force limit (N) and any gain overriding the plant's controller (gains in N/m, N/(m s), N/(m/s),
// N/(m/s), N/(m/s^2)). The top-level `friction` and `controller` belong to 1-input plants; the
// xy-table refuses a top-level controller. `duration` defaults to the circle's turns 2 pi R / F, or
// the path's last time. Circle and path are refused for a 1-input plant, 1-input types for an xy-table.
//
// Friction compensation (control/*.hpp): a `compensation:` block inside a pid `controller:`, inside
// an xy-table axis (plant.axes.x.compensation), or shared by both axes (plant.compensation, each
// axis then compensating with its own law and mass; an axis's own block replaces it, and
// `compensation: none` on an axis switches it off there):
//   compensation:
//     type: feedforward | feedback | lugre-observer | disturbance-observer
//     model: MODEL.json          # an identified model or a law file (scenario/law_file.hpp); relative
//                                # to the scenario file's directory, as `data:`
//     friction: {law: lugre, ...}   # or the law itself, in the `friction:` syntax
//     scale: 1.2                 # optional, > 0, default 1 (see below)
//     band: 0.001                # feedforward: smoothing half-width (m/s or rad/s; default 1e-3)
//     dead_band: 0.001           # feedback: dead band half-width (m/s or rad/s; default 1e-3)
//     gain: 0.01                 # lugre-observer: observer gain k (1/s; default 0.01)
//     bandwidth: 100             # disturbance-observer: low-pass bandwidth (rad/s; default 100)
//     inertia: 1.0               # disturbance-observer: nominal inertia (kg or kg m^2)
// Without `model` and `friction` the compensation uses the exact model: the law of the contact it
// compensates (the scenario's `friction`, the axis's own law). `scale` multiplies every parameter
// of that law that carries newtons (forces, viscous coefficients, stiffnesses, force rates, a
// table's forces, GMS's element stiffnesses), so the compensation's force is `scale` times the
// law's for every velocity history: 1.2 over-compensates by 20 %, 0.8 under-compensates. The
// disturbance observer uses no law (`friction` and `scale` are refused); its inertia defaults to
// the model file's identified M when `model` gives one, else to the compensated body's inertia
// (the plant's M, the axis's equivalent mass). A pid controller also takes `compensation_gain`
// (plant input per N or N m, default 1: a force-driven plant; a current-driven DC motor wants
// 1 / (Ka Kt)). A type that does not fit the law (lugre-observer without a LuGre law), a parameter
// of another type, or an unknown key is refused naming the key.

#include <map>
#include <memory>
#include <optional>

#include <string>
#include <vector>

#include "frictionlab/io/dataset.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/scenario.hpp"

namespace YAML {
class Node;
}

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// An identified model of one axis: its friction law, inertia M (kg or kg m^2) and offset (N or N m).
struct AxisModel {
  FrictionLaw law;
  AxisParams axis;
};

/// What the caller supplies or replaces when reading a scenario (frictionlab validate: the
/// measured data set, and the identified law, inertia and offset).
struct ScenarioOptions {
  /// Data set for every `data` input, named constant and pulses column; replaces the files the
  /// scenario names (top-level `data`, input `file`). Null: read the named files.
  std::shared_ptr<const Dataset> data;
  /// Replaces the `friction` section (which may then be absent).
  std::optional<FrictionLaw> law;
  /// Replaces M (kg or kg m^2) and offset (N or N m) of the plant, which must then be an axis
  /// (`M` may then be absent in the file).
  std::optional<AxisParams> axis;
  /// Identified models of a two-axis plant's axes (xy-table), by axis name ("x", "y"): each
  /// replaces that axis's friction law, its mass by the model's M (kg: the equivalent mass, so
  /// the axis's inertia and lead are dropped) and its offset (N); an axis not named keeps the
  /// scenario's. The plant must then be an xy-table, and `law` and `axis` must be empty.
  std::map<std::string, AxisModel> axis_models;
  /// Directory relative file names are resolved from; empty = the working directory.
  std::string base_dir;
  /// Where `law` and `axis` (or `axis_models`) came from (MODEL.json): an invalid inertia or offset is blamed on
  /// this file, not on the scenario. Empty: on the scenario's plant section.
  std::string model_source;
  /// When set, the files the scenario names are appended here as they are read (its data
  /// files, its compensations' model files; paths resolved from base_dir), so that a caller can
  /// keep its outputs from replacing them. Not owned.
  std::vector<std::string>* files_read = nullptr;
};

/// Reads a scenario from a parsed YAML mapping. `where` prefixes every message (the file name).
/// \throws std::invalid_argument "WHERE: KEY.PATH: ..." for a key given twice in a mapping
///         (naming it and its line), an output (duration * output_rate rows) larger than half
///         the machine's memory (naming the keys and the memory it needs), an unknown plant/law/input/controller
///         type or field (listing the valid ones), a missing required field (naming it), a value
///         that is not a number, a non-positive duration, output rate, tolerance or step (with its
///         value), a data file that cannot be read, or a column or scalar it lacks (listing the
///         ones it has), and a compensation block that does not fit (see above: naming its key).
Scenario scenario_from_yaml(const YAML::Node& root, const std::string& where, const ScenarioOptions& options = {});

/// Reads a scenario file; relative data files are resolved from its directory unless
/// options.base_dir is set. \throws std::invalid_argument naming the file when it cannot be read
/// or is not valid YAML (with line and column), and what scenario_from_yaml throws.
Scenario load_scenario(const std::string& path, const ScenarioOptions& options = {});

/// A column of a data set as a table input: values * scale at t_k = k dt (s), dt the mean step of
/// `time_column` (checked finite, increasing and regular within 1 %). `hold`: piecewise constant.
/// \throws std::invalid_argument naming the file and the missing column (listing the columns)
///         or the offending time sample.
InputSignal input_from_column(const Dataset& data, const std::string& time_column, const std::string& column,
                              double scale = 1.0, bool hold = false);

}  // namespace frictionlab
