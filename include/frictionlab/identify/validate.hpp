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
#include <string>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/scenario.hpp"

namespace frictionlab {

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
/// law, see io/scenario.hpp ScenarioOptions; its options are overridden: duration (N - 1) dt,
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

}  // namespace frictionlab
