#include "frictionlab/analysis/plan/rig.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "frictionlab/format.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/plants/dc_motor.hpp"

namespace frictionlab {

const char* plan_drive_name(PlanDrive drive) {
  switch (drive) {
    case PlanDrive::force: return "force";
    case PlanDrive::current: return "current";
    case PlanDrive::velocity_loop: return "velocity-loop";
    case PlanDrive::position_loop: return "position-loop";
  }
  return "force";
}

double PlanRig::prior(const std::string& name) const {
  if (name == "M") return inertia;
  if (name == "offset") return offset;
  // The effects' parameters as idim's load, temperature and ripple terms name them.
  const LawEffects& e = law.effects();
  if (name == "mu_load") return e.load ? e.load->mu_coulomb : std::numeric_limits<double>::quiet_NaN();
  if (name == "load_gain") return e.load ? 0.0 : std::numeric_limits<double>::quiet_NaN();  // the simulated load presses the contact only
  if (name == "Fv_per_K") return e.temperature ? e.temperature->Fv_per_K : std::numeric_limits<double>::quiet_NaN();
  for (const char* kind : {"ripple_sin_", "ripple_cos_"})
    if (name.rfind(kind, 0) == 0 && e.ripple) {
      const std::size_t k = std::stoul(name.substr(std::string(kind).size()));
      const std::vector<double>& c = kind[7] == 's' ? e.ripple->a : e.ripple->b;
      return k >= 1 && k <= c.size() ? c[k - 1] : 0.0;
    }
  for (const auto& p : law.parameters())
    if (p.name == name) return p.value;
  if (name == "Fv")
    for (const auto& p : law.parameters())
      if (p.name == "sigma2") return p.value;
  if (name == "Fs" && !law.is_dynamic()) return law.breakaway_positive();
  if (name == "Fc" && !law.is_dynamic()) return law.breakaway_positive();  // a law without Fs/Fc: its level
  return std::numeric_limits<double>::quiet_NaN();
}

double PlanRig::time_constant() const {
  return damping > 0 ? inertia / damping : std::numeric_limits<double>::infinity();
}

PlanRig make_plan_rig(const Scenario& scenario, const FrictionLaw& prior_law, std::optional<double> prior_inertia,
                      std::optional<Axis> prior_axis, const std::string& scenario_file, const std::string& prior_file) {
  if (!scenario.plant) throw std::invalid_argument(scenario_file + ": no plant");
  const Plant& plant = *scenario.plant;
  if (plant.num_inputs() != 1 || plant.num_contacts() != 1)
    throw std::invalid_argument(scenario_file + ": plant '" + plant.type() +
                                "' has several inputs or contacts; a plan is made for one axis (axis or dc-motor, with "
                                "or without a controller)");
  const auto* loop = dynamic_cast<const ClosedLoop*>(&plant);
  if (!loop && plant.sample_period() > 0)
    throw std::invalid_argument(scenario_file + ": controller: a sampled loop (emps-pd) is not supported by plan; use a "
                                "continuous controller {loop: position|velocity, Kp, Ki, Kd, limit}");
  const Plant& inner = loop ? loop->inner() : plant;
  const auto* motor = dynamic_cast<const DcMotor*>(&inner);
  const auto* axis = dynamic_cast<const RigidAxis*>(&inner);
  if (!motor && !axis && inner.num_events() > 0)
    throw std::invalid_argument(scenario_file + ": plant.backlash: an axis with backlash is not supported by plan (its "
                                "impacts are not in the predicted information); plan on the axis without it");
  if (!motor && !axis)
    throw std::invalid_argument(scenario_file + ": plant.type '" + inner.type() +
                                "' is not supported by plan; expected axis or dc-motor (with or without a controller)");
  if (prior_inertia && !(*prior_inertia > 0 && std::isfinite(*prior_inertia)))
    throw std::invalid_argument(prior_file + ": parameters.M = " + format_number(*prior_inertia) +
                                " must be > 0 (kg or kg m^2)");

  PlanRig rig;
  rig.scenario = scenario;
  rig.scenario.law = prior_law;
  rig.scenario.inputs.clear();
  rig.law = prior_law;
  rig.prior_file = prior_file;
  rig.scenario_file = scenario_file;
  rig.axis = prior_axis ? *prior_axis : (motor ? Axis::rotary : Axis::linear);

  if (axis) {
    AxisParams p = axis->params();
    if (prior_inertia) p.M = *prior_inertia;
    rig.offset = -p.offset;  // the plant adds its offset to the drive; IDIM's force = ... + offset
    auto new_axis = std::make_shared<const RigidAxis>(p);
    rig.scenario.plant = loop ? std::shared_ptr<const Plant>(std::make_shared<const ClosedLoop>(
                                    new_axis, loop->controller(),
                                    loop->compensator() ? std::shared_ptr<const Compensator>(scenario.plant, loop->compensator()) : nullptr))
                              : std::shared_ptr<const Plant>(new_axis);
  }
  rig.inertia = rig.scenario.plant->inertia();
  const double fv = rig.prior("Fv");
  rig.damping = std::isfinite(fv) ? fv : 0.0;
  if (motor) {
    const auto& m = motor->params();
    rig.torque_constant = m.Kt;
    if (m.drive == MotorDrive::voltage) rig.damping += m.Kt * m.Kb / m.R;
  }
  const bool rotary = rig.axis == Axis::rotary;
  if (loop) {
    const bool velocity = loop->controller().loop == ControlLoop::velocity;
    rig.drive = velocity ? PlanDrive::velocity_loop : PlanDrive::position_loop;
    rig.command = velocity ? "velocity" : "position";
    rig.command_unit = velocity ? (rotary ? "rad/s" : "m/s") : (rotary ? "rad" : "m");
  } else if (motor) {
    if (motor->params().drive != MotorDrive::current)
      throw std::invalid_argument(scenario_file + ": plant.drive: voltage; plan drives an open-loop motor through its "
                                  "current amplifier (drive: current) or a closed loop (controller: {loop: ...})");
    rig.drive = PlanDrive::current;
    rig.command = "current";
    rig.command_unit = "A";
    rig.input_per_command = 1.0 / motor->params().Ka;
    rig.force_per_command = motor->params().Kt;
  } else {
    rig.drive = PlanDrive::force;
    rig.command = rotary ? "torque" : "force";
    rig.command_unit = rotary ? "N m" : "N";
    rig.force_per_command = 1.0;
  }
  return rig;
}

}  // namespace frictionlab
