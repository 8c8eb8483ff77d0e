#include "frictionlab/control/disturbance_observer.hpp"

#include <cmath>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

DisturbanceObserver::DisturbanceObserver(DisturbanceObserverParams p) : p_(p) {
  detail::require(std::isfinite(p.bandwidth) && p.bandwidth > 0, "disturbance-observer", "bandwidth", p.bandwidth,
                  "> 0 (rad/s)");
  detail::require(std::isfinite(p.inertia) && p.inertia > 0, "disturbance-observer", "inertia", p.inertia,
                  "> 0 (kg or kg m^2: the nominal inertia of the driven body)");
}

void DisturbanceObserver::initial_states(const CompensatorInput& in, std::span<double> z) const {
  z[0] = p_.bandwidth * p_.inertia * in.velocity;
}

double DisturbanceObserver::output(const CompensatorInput& in, std::span<const double> z) const {
  return z[0] - p_.bandwidth * p_.inertia * in.velocity;
}

void DisturbanceObserver::derivatives(const CompensatorInput& in, std::span<const double> z,
                                      std::span<double> dz) const {
  const double w = p_.bandwidth;
  dz[0] = w * (in.drive - z[0] + w * p_.inertia * in.velocity);
}

bool DisturbanceObserver::jacobian(const CompensatorInput&, std::span<const double>, std::span<double> doutput,
                                   std::span<double> dderiv) const {
  const double w = p_.bandwidth, wM = w * p_.inertia;
  // variables (position, velocity, drive, p)
  doutput[0] = 0.0;
  doutput[1] = -wM;
  doutput[2] = 0.0;
  doutput[3] = 1.0;
  dderiv[0] = 0.0;
  dderiv[1] = w * wM;
  dderiv[2] = w;
  dderiv[3] = -w;
  return true;
}

double DisturbanceObserver::update(const CompensatorInput& in, std::span<double> z, double dt) const {
  // dp/dt = w (pss - p) with pss = drive + w M v held over the step: exact exponential relaxation.
  const double w = p_.bandwidth;
  const double pss = in.drive + w * p_.inertia * in.velocity;
  z[0] = pss + (z[0] - pss) * std::exp(-w * dt);
  return output(in, z);
}

}  // namespace frictionlab
