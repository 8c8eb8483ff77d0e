#pragma once
// The rig an experiment is planned for: the scenario's plant (and controller) with the prior
// model's friction law, and what the plan needs to know about it: how the command becomes a
// force, what is measured, the mechanical time constant.

#include <optional>
#include <string>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/simulate/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What the plan commands.
enum class PlanDrive {
  force,          ///< an axis driven by a force or torque (N or N m)
  current,        ///< a dc-motor behind a current amplifier (drive: current): the motor current (A)
  velocity_loop,  ///< a closed velocity loop: the reference velocity (m/s or rad/s)
  position_loop,  ///< a closed position loop: the reference position (m or rad)
};

/// The planned-for rig. Made by make_plan_rig; the scenario's friction is the prior's law.
struct PlanRig {
  Scenario scenario;        ///< plant, controller and solver options; law = prior law; input set by the plan
  FrictionLaw law;          ///< the prior's friction law
  double inertia = 0.0;     ///< kg or kg m^2 (the plant's, after the prior's M replaced an axis's)
  /// Constant force offset as identification reports it (force = M a + F(v) + offset), N or N m:
  /// minus an axis plant's offset (which the plant adds to the drive force).
  double offset = 0.0;
  PlanDrive drive = PlanDrive::force;
  Axis axis = Axis::linear;  ///< rotary for a dc-motor
  /// Motor torque constant Kt (N m/A): measured force = Kt * measured current. 0 for an axis
  /// (the drive force itself is measured).
  double torque_constant = 0.0;
  /// Plant input per command unit: 1 / Ka (V/A) for a current-driven motor (the CSV holds the
  /// current, the simulation takes the amplifier's command), else 1.
  double input_per_command = 1.0;
  /// Force per command unit in open loop: Kt for a current-driven motor, 1 for a force-driven
  /// axis, 0 for closed loops.
  double force_per_command = 0.0;
  /// Viscous damping the body sees in open loop, N s/m or N m s/rad: the prior's Fv (sigma2 of a
  /// LuGre law) plus, for a voltage-driven motor, Kt Kb / R.
  double damping = 0.0;
  std::string command;       ///< "current", "force", "torque", "velocity", "position"
  std::string command_unit;  ///< "A", "N", "N m", "m/s", "rad/s", "m", "rad"
  std::string prior_file, scenario_file;  ///< for results and messages

  /// The prior law's parameter `name` (Fc, Fs, Fv, vs, delta, sigma0, ...), "M" (inertia),
  /// "offset"; "Fv" falls back to a LuGre law's sigma2 and "Fs" to the breakaway level. The
  /// effects' parameters as idim names them: "mu_load" (the Coulomb level's), "load_gain" (0: a
  /// simulated load presses the contact only), "Fv_per_K", "ripple_sin_k", "ripple_cos_k".
  /// NaN when the prior has no such parameter.
  double prior(const std::string& name) const;
  /// Mechanical time constant inertia / damping, s; infinity without damping.
  double time_constant() const;
};

/// Builds the rig from a scenario whose plant is an axis or a dc-motor (a 1-DOF plant), with or
/// without a P/PI/PID controller, and the prior law (replacing the scenario's friction).
/// `prior_inertia` (kg or kg m^2), when given, replaces an axis plant's M (a motor keeps its J);
/// `prior_axis` (the MODEL.json's "axis") sets the units, else rotary for a motor, linear for an axis.
/// \throws std::invalid_argument naming scenario_file and the plant type or key that is not
///         supported (several axes, a velocity-drive, a pendulum, a spring-base, an emps-pd loop
///         with data inputs), or a prior inertia that is not > 0.
PlanRig make_plan_rig(const Scenario& scenario, const FrictionLaw& prior_law, std::optional<double> prior_inertia,
                      std::optional<Axis> prior_axis,
                      const std::string& scenario_file = "scenario", const std::string& prior_file = "prior");

/// "force", "current", "velocity-loop", "position-loop".
const char* plan_drive_name(PlanDrive drive);

}  // namespace frictionlab
