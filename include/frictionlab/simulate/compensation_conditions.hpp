#pragma once
// What a closed loop tells its friction compensator about the compensated contact's conditions
// (CompensatorInput::load, ::temperature), for a law with load or temperature terms. Both loops
// (simulate/closed_loop.hpp's PID, simulate/emps_pd_loop.hpp's EMPS controller) hand them on
// the same way.

#include <optional>
#include <span>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/simulate/environment.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct CompensationConditions {
  /// The load (N or N m): measured (`signal`, e.g. a load cell's column) or estimated from the
  /// plant's known load function (`of_state`, called with the inner plant's states). None = 0.
  LoadSource load;
  /// A measured temperature (degC or K); none = the law's T_ref (the compensation does not see a
  /// thermal state of the run, only a temperature it is given).
  std::optional<double> temperature;
  /// or a measured temperature over time (degC or K; a log's column), in place of `temperature`.
  std::optional<InputSignal> temperature_log;

  /// The compensation's conditions of a run's contact environment: its load and its fixed or
  /// logged temperature (a thermal state is the run's, which a drive does not measure).
  static CompensationConditions of(const ContactEnvironment& e) {
    return {.load = e.load, .temperature = e.temperature, .temperature_log = e.temperature_log};
  }
  /// Writes the load (N or N m) and temperature (degC or K) at time t (s) and the inner plant's
  /// states x into `in`.
  void fill(CompensatorInput& in, double t, std::span<const double> x) const {
    in.load = load.at(t, x);
    in.temperature = temperature_log ? std::optional<double>(temperature_log->at(t).value) : temperature;
  }
};

}  // namespace frictionlab
