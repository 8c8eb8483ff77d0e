#pragma once
// What the rig allows an experiment plan to ask for: peak motor current or drive force, peak
// speed, the slowest speed the drive holds steadily, and the travel of the axis.

#include <limits>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Limits of the rig (SI units; force means torque on a rotary axis). An infinite value (the
/// default) is no limit.
struct PlanLimits {
  double current = std::numeric_limits<double>::infinity();  ///< peak |motor current|, A (dc-motor plants only)
  double force = std::numeric_limits<double>::infinity();    ///< peak |drive force|, N or N m
  double speed = std::numeric_limits<double>::infinity();    ///< peak |velocity|, m/s or rad/s
  /// Slowest speed the drive holds steadily (a velocity loop's floor), m/s or rad/s. Default 0.
  double min_speed = 0.0;
  /// Largest |position - start| the axis may reach, m or rad.
  double travel = std::numeric_limits<double>::infinity();

  /// \throws std::invalid_argument "--limits KEY = V must be > 0" naming the first bad value
  ///         (`option` is the flag or argument name used in messages).
  void validate(const std::string& option = "limits") const;
};

/// Reads limits from KEY=VALUE items, each spec a comma-separated list of them (repeatable, as
/// `--limits current=0.2,speed=400 --limits travel=0.3`). Keys: current (A), force (N or N m),
/// speed (m/s or rad/s), min_speed (m/s or rad/s), travel (m or rad). `option` names the flag
/// in messages.
/// \throws std::invalid_argument naming the option, the item and what was expected (an unknown
///         key lists the known ones; a value that is not a number > 0; a key given twice).
PlanLimits parse_plan_limits(const std::vector<std::string>& specs, const std::string& option = "--limits");

}  // namespace frictionlab
