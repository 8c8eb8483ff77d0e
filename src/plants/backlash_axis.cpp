#include "frictionlab/plants/backlash_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

// Throws "axis: backlash.NAME = VALUE must be RULE".
void require(bool ok, const char* name, double value, const char* rule) {
  if (!ok)
    throw std::invalid_argument(std::string("axis: backlash.") + name + " = " + detail::format_value(value) + " must be " + rule);
}

// State indices: the contact (the friction side's body), the other body, the contact state.
constexpr std::size_t kPos = 0, kVel = 1, kOtherPos = 2, kOtherVel = 3, kEngaged = 4;

// A rebound slower than this fraction of the bodies' speed (or than kRestSpeed) ends the bounces
// in a plastic impact: with a restitution e the bounces of a motor pushed onto its flank shrink
// by e each and would otherwise come ever closer in time without end.
constexpr double kReboundFraction = 1e-6;
constexpr double kRestSpeed = 1e-10;  // m/s or rad/s

// The contact state x[4] as -1, 0 or +1: it is integrated with a zero derivative, so the
// integrator may leave roundoff (1e-49) on it.
double engaged(std::span<const double> x) { return x[kEngaged] > 0.5 ? 1.0 : x[kEngaged] < -0.5 ? -1.0 : 0.0; }

}  // namespace

BacklashAxis::BacklashAxis(BacklashParams p) : p_(p) {
  require(std::isfinite(p.M_load) && p.M_load > 0, "M_load", p.M_load, "> 0 (kg or kg m^2)");
  require(std::isfinite(p.M_motor) && p.M_motor > 0, "M_motor", p.M_motor, "> 0 (kg or kg m^2)");
  require(std::isfinite(p.width) && p.width > 0, "width", p.width, "> 0 (m or rad: the total play)");
  require(std::isfinite(p.restitution) && p.restitution >= 0 && p.restitution < 1, "restitution", p.restitution,
          "in [0, 1) (0: plastic impact)");
  require(std::isfinite(p.offset), "offset", p.offset, "finite (N or N m)");
  require(std::isfinite(p.initial_gap) && std::abs(p.initial_gap) <= p.width / 2, "initial_gap", p.initial_gap,
          "within +-width/2 (m or rad)");
}

double BacklashAxis::inertia(int) const { return p_.friction_side == FrictionSide::load ? p_.M_load : p_.M_motor; }

double BacklashAxis::gap(std::span<const double> x) const {
  // motor position less load position
  return p_.friction_side == FrictionSide::load ? x[kOtherPos] - x[kPos] : x[kPos] - x[kOtherPos];
}

void BacklashAxis::initial_extras(std::span<double> x) const {
  const double side = p_.friction_side == FrictionSide::load ? 1.0 : -1.0;
  x[kOtherPos] = x[kPos] + side * p_.initial_gap;
  x[kOtherVel] = x[kVel];
  // Starting on a flank, the bodies start engaged (the engine then checks that they push).
  const double half = p_.width / 2;
  x[kEngaged] = p_.initial_gap >= half ? 1.0 : p_.initial_gap <= -half ? -1.0 : 0.0;
}

double BacklashAxis::applied(double, std::span<const double> x, const InputValue& u) const {
  if (engaged(x) != 0.0) return u.value + p_.offset;
  return p_.friction_side == FrictionSide::load ? p_.offset : u.value;
}

void BacklashAxis::derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                               std::span<double> dx) const {
  dx[kPos] = x[kVel];
  dx[kEngaged] = 0.0;
  if (engaged(x) != 0.0) {
    // One body: the other follows the contact (its states are reset exactly at separation).
    dx[kVel] = (applied(t, x, u) - friction) / (p_.M_load + p_.M_motor);
    dx[kOtherPos] = x[kVel];
    dx[kOtherVel] = dx[kVel];
    return;
  }
  dx[kVel] = (applied(t, x, u) - friction) / inertia();
  dx[kOtherPos] = x[kOtherVel];
  dx[kOtherVel] = p_.friction_side == FrictionSide::load ? u.value / p_.M_motor : p_.offset / p_.M_load;
}

double BacklashAxis::transmitted(std::span<const double> x, double u, double friction) const {
  if (engaged(x) == 0.0) return 0.0;
  // The load's equation M_load a = N + offset (- friction on the load side).
  const double a = (u + p_.offset - friction) / (p_.M_load + p_.M_motor);
  const double load_friction = p_.friction_side == FrictionSide::load ? friction : 0.0;
  return p_.M_load * a - p_.offset + load_friction;
}

PlantSignals BacklashAxis::signals(double, std::span<const double>, const InputValue& u) const {
  // drive: the input force on the motor (what a recorded motor force is compared with).
  return {0.0, 0.0, u.value, u.value};
}

void BacklashAxis::events(double, std::span<const double> x, Inputs u, std::span<const double> friction,
                          std::span<double> g) const {
  const double s = engaged(x);
  if (s == 0.0) {
    const double d = gap(x);
    // A flank just left reads within rounding of the positions (not of the gap): that much slack
    // keeps it from reading as a new impact (the guard contract).
    const double slack = 4 * std::numeric_limits<double>::epsilon() * (std::abs(x[kPos]) + std::abs(x[kOtherPos]) + p_.width);
    g[0] = p_.width / 2 - d + slack;  // the motor reaches the forward flank
    g[1] = d + p_.width / 2 + slack;  // ... the backward flank
    g[2] = 1.0;
  } else {
    g[0] = g[1] = 1.0;
    g[2] = s * transmitted(x, u[0].value, friction[0]);  // the motor pushes while > 0
  }
}

void BacklashAxis::on_event(double, std::span<double> x, Inputs, int k) const {
  const bool load_side = p_.friction_side == FrictionSide::load;
  const double side = load_side ? 1.0 : -1.0;  // other position = contact position + side * gap
  if (k == 2) {
    // Separation: the gap opens at the flank, both bodies at their common velocity.
    x[kOtherPos] = x[kPos] + side * engaged(x) * p_.width / 2;
    x[kOtherVel] = x[kVel];
    x[kEngaged] = 0.0;
    return;
  }
  const double s = k == 0 ? 1.0 : -1.0;
  double& vm = load_side ? x[kOtherVel] : x[kVel];
  double& vl = load_side ? x[kVel] : x[kOtherVel];
  const double M = p_.M_load + p_.M_motor;
  const double v = (p_.M_motor * vm + p_.M_load * vl) / M;  // momentum is kept
  const double closing = vm - vl;                          // > 0 toward the forward flank
  const double rebound = p_.restitution * std::abs(closing);
  x[kOtherPos] = x[kPos] + side * s * p_.width / 2;  // exactly on the flank
  if (rebound <= std::max(kReboundFraction * std::max(std::abs(vm), std::abs(vl)), kRestSpeed)) {
    vm = vl = v;  // plastic: the flank engages
    x[kEngaged] = s;
    return;
  }
  vm = v - p_.restitution * p_.M_load / M * closing;
  vl = v + p_.restitution * p_.M_motor / M * closing;
}

}  // namespace frictionlab
