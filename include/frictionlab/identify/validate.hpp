#pragma once
// Validation of an identified model by simulation: the model (friction law, inertia, offset)
// runs in the scenario's plant and controller (open loop from a measured input, or closed loop
// around a measured reference, e.g. the EMPS PD loop), and the simulated position, velocity,
// acceleration and force are compared with the measurement, 100 ||y - y_sim|| / ||y|| each.
// Velocity and acceleration of both come from the IDIM pipeline (identify/idim.hpp steps 1-2:
// zero-phase Butterworth low-pass of the position, central differences), and the comparison is
// made on the IDIM regression grid (first `skip` samples dropped, then scipy-style decimation by
// `decimation`), as the published EMPS figures were; the full-rate figures are reported too.

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The identified model a validation simulates.
struct IdentifiedModel {
  FrictionLaw law;        ///< friction law (MODEL.json "law")
  AxisParams axis;        ///< M (kg or kg m^2) and the plant's offset (N or N m): the negative of MODEL.json's "offset" (see model_from_result)
  std::string method;     ///< identification method, e.g. "idim" (for the report)
  std::string source;     ///< MODEL.json file name, or "" when built in memory
};

/// The model of an identification result: its `law`, parameter M, and offset (0 when absent; the
/// plant adds -offset to the drive, as the identification's u = M a + F + offset means).
/// \throws std::invalid_argument when the result is not ok, has no law, no parameter M, or the
///         values do not make a valid law or axis (message names the parameter).
IdentifiedModel model_from_result(const Result& identified);

/// Measured signals of the validation run (SI units), sampled regularly.
struct ValidationData {
  Eigen::VectorXd time;      ///< s, length N >= 2, strictly increasing and regular
  Eigen::VectorXd position;  ///< m or rad, length N
  Eigen::VectorXd force;     ///< applied force (gain * drive input), N or N m, length N
  std::string file;          ///< source file, for results and messages
  std::string sha256;        ///< its digest
};

/// Options of validate_model. `processing` supplies the low-pass (cutoff_hz, filter_order,
/// padlen), `skip` and `decimation` of the IDIM pipeline; defaults are the EMPS recipe.
struct ValidateOptions {
  IdimOptions processing;
  /// Start the simulation at the measured position and the derived velocity of sample 0 (m,
  /// m/s); false: the scenario's initial state. Default true.
  bool initial_state_from_data = true;
};

/// Simulates `model` in `scenario` (its plant must already carry the model's inertia, offset and
/// law, see scenario/scenario.hpp ScenarioOptions; its options are overridden: duration (N - 1) dt,
/// output rate 1/dt, initial state per options) and compares with `data`.
/// Simulated force: gtau * v(k) for an EMPS loop (the drive input the controller computed at
/// sample k, counterpart of the measured gtau * vir), the scenario input for an open loop.
/// \returns method "validate", parameters M, offset and the law's, `validation` with
///          per-signal errors (position, velocity, acceleration, force; %) on the IDIM grid,
///          diagnostics group "relative_error_percent_full_rate" (same, every sample) and
///          numbers "dt", "samples_full_rate"; series "time", "position", "position_sim",
///          "velocity", "velocity_sim", "acceleration", "acceleration_sim", "force",
///          "force_sim" (N samples each, SI).
/// \throws std::invalid_argument naming the file for unequal lengths, non-finite samples,
///         irregular time, too few samples for the filter, skip and decimation, or a scenario
///         without a plant; std::runtime_error when the simulation fails.
Result validate_model(const IdentifiedModel& model, const Scenario& scenario, const ValidationData& data,
                      const ValidateOptions& options = {});

/// One axis of a multi-axis validation run: the contact it is (Contact::name, e.g. "x") and its
/// measured signals (SI units, each of the time column's length).
struct AxisRecord {
  std::string name;          ///< contact name of the scenario's plant ("x", "y" on an xy-table)
  Eigen::VectorXd position;  ///< m or rad
  Eigen::VectorXd force;     ///< the drive's force (N or N m); empty: not compared
};

/// Measured signals of a run of a plant with several named contacts (an xy-table).
struct MultiAxisValidationData {
  Eigen::VectorXd time;         ///< s, length N >= 2, regular; sample k is compared with the simulation at k dt
  std::vector<AxisRecord> axes;  ///< one per contact compared (at least one)
  std::string file;             ///< source file, for results and messages
  std::string sha256;           ///< its digest
};

/// validate_model for a plant with several named contacts (an xy-table): the scenario (its axes
/// already carrying the identified models, see scenario/scenario.hpp ScenarioOptions::axis_models) is
/// simulated over the record (duration (N - 1) dt, output rate 1/dt, initial state: each axis at
/// its measured position and derived velocity of sample 0 when options.initial_state_from_data,
/// else the scenario's) and each axis's position, velocity, acceleration (derived as in
/// validate_model) and, when measured, drive force are compared with the simulation.
/// `models` names the axes whose law and inertia came from an identified model (for the report).
/// \returns method "validate", model "x: LAW, y: LAW" (every contact's), parameters "AXIS.M" (kg,
///          the equivalent mass), "AXIS.offset" (N; axes in `models`) and "AXIS.PARAM" of each
///          contact's law (units on options.processing.axis); rmse of the measured drive forces
///          (N, every sample; NaN when none was measured);
///          `validation` with errors (%) keyed "AXIS.position", "AXIS.velocity",
///          "AXIS.acceleration", "AXIS.force" on the IDIM grid; diagnostics group
///          "relative_error_percent_full_rate" (same keys, every sample); texts "AXIS.model" (the
///          model file, or "scenario"); series "time" and per axis "AXIS.position",
///          "AXIS.position_sim", "AXIS.velocity", "AXIS.velocity_sim", "AXIS.acceleration",
///          "AXIS.acceleration_sim", "AXIS.reference" (the simulated reference), "AXIS.force_sim",
///          and "AXIS.force" when measured.
/// \throws std::invalid_argument as validate_model, naming the axis and signal; for an axis name
///         the plant has no contact of (listing its contacts), an axis given twice, or no axes;
///         std::runtime_error when the simulation fails.
Result validate_axes(const Scenario& scenario, const MultiAxisValidationData& data,
                     const std::map<std::string, IdentifiedModel>& models, const ValidateOptions& options = {});

}  // namespace frictionlab
