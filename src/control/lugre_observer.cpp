#include "frictionlab/control/lugre_observer.hpp"

#include <ceres/jet.h>

#include <cmath>
#include <stdexcept>
#include <variant>

#include "frictionlab/models/relaxation.hpp"

namespace frictionlab {
namespace {

const LuGre& require_lugre(const FrictionLaw& law) {
  const auto* lugre = std::get_if<LuGre>(&law.variant());
  if (lugre == nullptr)
    throw std::invalid_argument("lugre-observer: law = " + law.name() +
                                " must be lugre (the observer runs a copy of the LuGre bristle state)");
  // The observer's copy of the bristles runs on the law's own levels; moving them with a load or
  // temperature would change its bristle state's meaning between samples, which it does not model.
  if (law.effects().moves_levels())
    throw std::invalid_argument("lugre-observer: law = " + law.name() + " carries " +
                                (law.effects().load ? "a load term (mu_load)" : "a temperature term (Fv_per_K, Fc_per_K)") +
                                ", which the observer does not follow (its bristle copy runs on fixed levels); use "
                                "feedforward or feedback compensation, which take the load and temperature");
  return *lugre;
}

// dz^/dt and F^ at position x, velocity v and state z, reference r: one formula for the values
// (double) and the Jacobian (Jets). The bristle terms are the law's own (LuGreT).
template <class T>
void evaluate(const LuGre& law, double k, const T& x, const T& v, const T& z, double r, T& dz, T& F) {
  dz = law.state_derivative(z, v) - T(k) * (x - T(r));
  F = T(law.sigma0) * z + law.damping(v) * dz + T(law.sigma2) * v;
}

}  // namespace

LuGreObserver::LuGreObserver(const FrictionLaw& law, LuGreObserverParams p)
    : law_(require_lugre(law)), ripple_(law.effects().ripple), p_(p) {
  detail::require(std::isfinite(p.gain) && p.gain >= 0, "lugre-observer", "gain", p.gain,
                  ">= 0 (1/s: bristle rate per position error)");
}

void LuGreObserver::initial_states(const CompensatorInput& in, std::span<double> z) const {
  law_.steady_state(in.velocity, z);
}

double LuGreObserver::output(const CompensatorInput& in, std::span<const double> z) const {
  double dz, F;
  evaluate(law_, p_.gain, in.position, in.velocity, z[0], in.reference, dz, F);
  return ripple_ ? F + ripple_->force(in.position) : F;
}

void LuGreObserver::derivatives(const CompensatorInput& in, std::span<const double> z, std::span<double> dz) const {
  double F;
  evaluate(law_, p_.gain, in.position, in.velocity, z[0], in.reference, dz[0], F);
}

bool LuGreObserver::jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                             std::span<double> dderiv) const {
  using J = ceres::Jet<double, 3>;  // d/d(position, velocity, z^); the drive does not enter
  const J x(in.position, 0), v(in.velocity, 1), zz(z[0], 2);
  J dz, F;
  evaluate(law_, p_.gain, x, v, zz, in.reference, dz, F);
  doutput[0] = F.v[0] + (ripple_ ? ripple_->slope(in.position) : 0.0);
  doutput[1] = F.v[1];
  doutput[2] = 0.0;
  doutput[3] = F.v[2];
  dderiv[0] = dz.v[0];
  dderiv[1] = dz.v[1];
  dderiv[2] = 0.0;
  dderiv[3] = dz.v[2];
  return true;
}

double LuGreObserver::update(const CompensatorInput& in, std::span<double> z, double dt) const {
  // dz^/dt = c - rate z^ with c = v - k e and rate = sigma0 |v| / g(v), both held over the step.
  const double v = in.velocity;
  const double rate = bristle_relaxation(law_, v).rate;         // 1/s
  const double c = v - p_.gain * (in.position - in.reference);  // m/s or rad/s
  if (rate > 0) {
    z[0] = relax(z[0], c / rate, std::exp(-rate * dt));
  } else {
    z[0] += c * dt;
  }
  const double dz = c - rate * z[0];
  const double F = law_.sigma0 * z[0] + law_.damping(v) * dz + law_.sigma2 * v;
  return ripple_ ? F + ripple_->force(in.position) : F;
}

}  // namespace frictionlab
