// Implementations of the plants in include/frictionlab/plants/.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/plants/dc_motor.hpp"
#include "frictionlab/plants/pendulum.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/plants/spring_base.hpp"
#include "frictionlab/plants/velocity_drive.hpp"

namespace frictionlab {
namespace {


// Throws "PLANT: NAME = VALUE must be RULE".
void require(bool ok, const char* plant, const char* name, double value, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string(plant) + ": " + name + " = " + detail::format_value(value) + " must be " + rule);
}

}  // namespace

Contact Plant::contact(int) const { return {}; }

void Plant::initial_extras(std::span<double> x, Inputs) const { initial_extras(x); }

void Plant::fixed_step_update(double, double, std::span<const double>, Inputs, std::span<double>, Inputs) const {}

void Plant::initial_extras(std::span<double> x) const {
  // Zero every state but the contacts' positions and velocities (the caller sets those).
  const int nc = num_contacts();
  for (std::size_t i = 0; i < x.size(); ++i) {
    bool motion = false;
    for (int k = 0; k < nc && !motion; ++k) {
      const Contact c = contact(k);
      motion = static_cast<std::size_t>(c.position) == i || static_cast<std::size_t>(c.velocity) == i;
    }
    if (!motion) x[i] = 0.0;
  }
}

bool Plant::jacobian(double, std::span<const double>, Inputs, std::span<const double>, std::span<double>,
                     std::span<double>) const {
  return false;
}

void Plant::signals(double, std::span<const double>, Inputs u, std::span<PlantSignals> out) const {
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = PlantSignals{0.0, 0.0, i < u.size() ? u[i].value : 0.0, 0.0};
}

void Plant::sample(double, std::span<double>, Inputs) const {}

void Plant::events(double, std::span<const double>, Inputs, std::span<double>) const {}

void Plant::on_event(double, std::span<double>, Inputs, int) const {}

void Plant::events(double t, std::span<const double> x, Inputs u, std::span<const double>, std::span<double> g) const {
  events(t, x, u, g);
}

bool Plant::guard_event(int) const { return false; }

// ---- 1-DOF plants ------------------------------------------------------------------------------

PlantSignals SingleContactPlant::signals(double, std::span<const double>, const InputValue& u) const {
  return {0.0, 0.0, u.value, 0.0};
}

void SingleContactPlant::sample(double, std::span<double>, const InputValue&) const {}

bool SingleContactPlant::jacobian(double, std::span<const double>, const InputValue&, double, std::span<double>,
                                  std::span<double>) const {
  return false;
}

double SingleContactPlant::applied_of(const Plant& p, double t, std::span<const double> x, const InputValue& u) {
  double f = 0.0;
  p.applied(t, x, Inputs(&u, 1), std::span<double>(&f, 1));
  return f;
}

void SingleContactPlant::derivatives_of(const Plant& p, double t, std::span<const double> x, const InputValue& u,
                                        double friction, std::span<double> dx) {
  p.derivatives(t, x, Inputs(&u, 1), std::span<const double>(&friction, 1), dx);
}

PlantSignals SingleContactPlant::signals_of(const Plant& p, double t, std::span<const double> x, const InputValue& u) {
  PlantSignals s;
  p.signals(t, x, Inputs(&u, 1), std::span<PlantSignals>(&s, 1));
  return s;
}

void SingleContactPlant::require_loop_plant(const Plant* inner_ptr, const char* who) {
  if (!inner_ptr) throw std::invalid_argument(std::string(who) + ": no plant to control");
  const Plant& inner = *inner_ptr;
  if (inner.kinematic())
    throw std::invalid_argument(std::string(who) + ": cannot close a loop around a " + inner.type() +
                                " (its velocity is imposed); use axis or dc-motor");
  if (inner.num_contacts() != 1 || inner.num_inputs() != 1)
    throw std::invalid_argument(std::string(who) + ": cannot close this loop around a " + inner.type() + " with " +
                                std::to_string(inner.num_contacts()) + " contacts and " +
                                std::to_string(inner.num_inputs()) + " inputs; it needs a 1-DOF plant (1 contact, 1 input)");
}

// ---- rigid axis -------------------------------------------------------------------------------

RigidAxis::RigidAxis(AxisParams p) : p_(p) {
  require(std::isfinite(p.M) && p.M > 0, "axis", "M", p.M, "> 0 (kg or kg m^2)");
  require(std::isfinite(p.offset), "axis", "offset", p.offset, "finite (N or N m)");
}

double RigidAxis::applied(double, std::span<const double>, const InputValue& u) const { return u.value + p_.offset; }

void RigidAxis::derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                            std::span<double> dx) const {
  dx[0] = x[1];
  dx[1] = (applied(t, x, u) - friction) / p_.M;
}

bool RigidAxis::jacobian(double, std::span<const double>, const InputValue&, double, std::span<double> dfdx,
                         std::span<double> dfdF) const {
  dfdx[0] = 0.0;  // dx0 = v
  dfdx[1] = 1.0;
  dfdx[2] = 0.0;  // dv = (u + offset - F) / M
  dfdx[3] = 0.0;
  dfdF[0] = 0.0;
  dfdF[1] = -1.0 / p_.M;
  return true;
}

PlantSignals RigidAxis::signals(double, std::span<const double>, const InputValue& u) const {
  return {0.0, 0.0, u.value, u.value};
}

// ---- pendulum ---------------------------------------------------------------------------------

Pendulum::Pendulum(PendulumParams p) : p_(p) {
  require(std::isfinite(p.m) && p.m > 0, "pendulum", "m", p.m, "> 0 (kg)");
  require(std::isfinite(p.l) && p.l > 0, "pendulum", "l", p.l, "> 0 (m)");
  require(std::isfinite(p.g) && p.g >= 0, "pendulum", "g", p.g, ">= 0 (m/s^2)");
  require(std::isfinite(p.B) && p.B >= 0, "pendulum", "B", p.B, ">= 0 (N m s/rad)");
}

double Pendulum::applied(double, std::span<const double> x, const InputValue& u) const {
  return u.value - p_.m * p_.g * p_.l * std::sin(x[0]) - p_.B * x[1];
}

void Pendulum::derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                           std::span<double> dx) const {
  dx[0] = x[1];
  dx[1] = (applied(t, x, u) - friction) / inertia();
}

PlantSignals Pendulum::signals(double, std::span<const double>, const InputValue& u) const {
  return {0.0, 0.0, u.value, u.value};
}

double Pendulum::energy(std::span<const double> x) const {
  return 0.5 * inertia() * x[1] * x[1] + p_.m * p_.g * p_.l * (1.0 - std::cos(x[0]));
}

// ---- spring with moving base ------------------------------------------------------------------

SpringBase::SpringBase(SpringBaseParams p) : p_(p) {
  require(std::isfinite(p.m) && p.m > 0, "spring-base", "m", p.m, "> 0 (kg)");
  require(std::isfinite(p.k) && p.k > 0, "spring-base", "k", p.k, "> 0 (N/m)");
  require(std::isfinite(p.c) && p.c >= 0, "spring-base", "c", p.c, ">= 0 (N s/m)");
  require(std::isfinite(p.V0), "spring-base", "V0", p.V0, "finite (m/s)");
  require(std::isfinite(p.x0), "spring-base", "x0", p.x0, "finite (m)");
}

double SpringBase::applied(double t, std::span<const double> x, const InputValue& u) const {
  const double base = p_.x0 + p_.V0 * t;
  return u.value - p_.k * (x[0] - base) - p_.c * (x[1] - p_.V0);
}

void SpringBase::derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                             std::span<double> dx) const {
  dx[0] = x[1];
  dx[1] = (applied(t, x, u) - friction) / p_.m;
}

bool SpringBase::jacobian(double, std::span<const double>, const InputValue&, double, std::span<double> dfdx,
                          std::span<double> dfdF) const {
  dfdx[0] = 0.0;  // dx0 = v
  dfdx[1] = 1.0;
  dfdx[2] = -p_.k / p_.m;  // dv = (u - k (x - xb) - c (v - V0) - F) / m
  dfdx[3] = -p_.c / p_.m;
  dfdF[0] = 0.0;
  dfdF[1] = -1.0 / p_.m;
  return true;
}

PlantSignals SpringBase::signals(double t, std::span<const double> x, const InputValue& u) const {
  const double base = p_.x0 + p_.V0 * t;
  return {0.0, 0.0, base, u.value - p_.k * (x[0] - base) - p_.c * (x[1] - p_.V0)};
}

// ---- DC motor ---------------------------------------------------------------------------------

DcMotor::DcMotor(DcMotorParams p) : p_(p) {
  require(std::isfinite(p.J) && p.J > 0, "dc-motor", "J", p.J, "> 0 (kg m^2)");
  require(std::isfinite(p.R) && p.R > 0, "dc-motor", "R", p.R, "> 0 (ohm)");
  if (p.drive == MotorDrive::voltage) require(std::isfinite(p.L) && p.L > 0, "dc-motor", "L", p.L, "> 0 (H)");
  require(std::isfinite(p.Kt) && p.Kt > 0, "dc-motor", "Kt", p.Kt, "> 0 (N m/A)");
  require(std::isfinite(p.Kb) && p.Kb >= 0, "dc-motor", "Kb", p.Kb, ">= 0 (V s/rad)");
  require(std::isfinite(p.Ka) && p.Ka > 0, "dc-motor", "Ka", p.Ka, "> 0 (A/V)");
  require(std::isfinite(p.load), "dc-motor", "load", p.load, "finite (N m)");
}

double DcMotor::current(std::span<const double> x, const InputValue& u) const {
  return p_.drive == MotorDrive::voltage ? x[2] : p_.Ka * u.value;
}

double DcMotor::applied(double, std::span<const double> x, const InputValue& u) const {
  return p_.Kt * current(x, u) - p_.load;
}

void DcMotor::derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                          std::span<double> dx) const {
  dx[0] = x[1];
  dx[1] = (applied(t, x, u) - friction) / p_.J;
  if (p_.drive == MotorDrive::voltage) dx[2] = (u.value - p_.R * x[2] - p_.Kb * x[1]) / p_.L;
}

PlantSignals DcMotor::signals(double, std::span<const double> x, const InputValue& u) const {
  const double i = current(x, u);
  const double v = p_.drive == MotorDrive::voltage ? u.value : p_.R * i + p_.Kb * x[1];
  return {i, v, u.value, p_.Kt * i};
}

// ---- velocity drive ---------------------------------------------------------------------------

VelocityDrive::VelocityDrive(VelocityDriveParams p) : p_(p) {
  require(std::isfinite(p.M) && p.M >= 0, "velocity-drive", "M", p.M, ">= 0 (kg or kg m^2)");
}

double VelocityDrive::applied(double, std::span<const double>, const InputValue& u) const { return p_.M * u.rate; }

void VelocityDrive::derivatives(double, std::span<const double>, const InputValue& u, double,
                                std::span<double> dx) const {
  dx[0] = u.value;
  dx[1] = u.rate;
}

PlantSignals VelocityDrive::signals(double, std::span<const double>, const InputValue& u) const {
  return {0.0, 0.0, u.value, p_.M * u.rate};
}

}  // namespace frictionlab
