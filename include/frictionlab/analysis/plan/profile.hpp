#pragma once
// An experiment profile: the command signal a plan gives the rig's controller (time and one
// commanded signal with its unit), the figures that describe it, and its time windows.

#include <optional>
#include <string>
#include <vector>

#include "frictionlab/core/input.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// One figure of a plan's design ("ramp_rate" = 0.0023 A/s), with its unit and what it is.
struct PlanFigure {
  std::string name;
  double value = 0.0;
  std::string unit;  ///< "" for a count or a ratio
  std::string what;  ///< one phrase
};

/// A time window of the profile (s) and what happens in it, e.g. the averaging window of one
/// sweep speed ("level" = the speed) or the hold of a trapezoid.
struct PlanWindow {
  std::string kind;  ///< "hold", "speed", "move", "presliding", "sliding"
  double t_begin = 0.0, t_end = 0.0;
  double level = 0.0;  ///< the commanded level in the window (command unit)
};

/// A designed excitation.
struct ExperimentProfile {
  std::string method;        ///< breakaway, sweep, idim, lugre
  std::string command;       ///< what is commanded: "current", "force", "torque", "velocity", "position"
  std::string command_unit;  ///< "A", "N", "N m", "m/s", "rad/s", "m", "rad"
  InputSignal signal;        ///< the command u(t) (command unit), t in s from 0
  /// The load the rig applies with the command (load-steps), N or N m; a third column of the CSV.
  std::optional<InputSignal> load;
  std::string load_unit;     ///< "N" or "N m" with a load
  double duration = 0.0;     ///< s
  double sample_rate = 0.0;  ///< Hz of the written profile and of the simulated measurement
  std::vector<PlanFigure> figures;
  std::vector<PlanWindow> windows;
  std::vector<std::string> warnings;      ///< design compromises (a limit that lowered a level, ...)
  std::vector<std::string> undetermined;  ///< parameters the plan cannot determine (std null)

  /// The figure `name`'s value. \throws std::invalid_argument listing the figures.
  double figure(const std::string& name) const;
  /// CSV header of the two columns: "time_s" and the command with its unit, e.g. "current_A",
  /// "torque_N_m", "velocity_rad_s".
  std::vector<std::string> column_names() const;
  /// The CSV text for the rig's controller: the header row, then one row per sample at
  /// sample_rate from t = 0 to duration (shortest round-trip numbers).
  std::string to_csv() const;
  /// The command at the sample times of to_csv (s and command unit), of one length.
  void samples(std::vector<double>& time, std::vector<double>& command) const;
};

}  // namespace frictionlab
