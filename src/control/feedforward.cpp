#include "frictionlab/control/feedforward.hpp"

#include <algorithm>
#include <cmath>

#include "velocity_band.hpp"

namespace frictionlab {

FeedforwardCompensation::FeedforwardCompensation(FrictionLaw law, FeedforwardParams p)
    : law_(std::move(law)), p_(p) {
  detail::require(std::isfinite(p.band) && p.band > 0, "feedforward", "band", p.band, "> 0 (m/s or rad/s)");
  at_plus_ = law_.sliding(p.band);
  at_minus_ = law_.sliding(-p.band);
}

double FeedforwardCompensation::force_in(double region, double vr) const {
  if (region != 0.0) return law_.sliding(vr);
  return at_minus_ + (at_plus_ - at_minus_) * (vr + p_.band) / (2.0 * p_.band);
}

double FeedforwardCompensation::force(double vr) const { return force_in(detail::band_region(vr, p_.band), vr); }

void FeedforwardCompensation::initial_states(const CompensatorInput& in, std::span<double> z) const {
  z[0] = detail::band_region(in.reference_rate, p_.band);
}

double FeedforwardCompensation::output(const CompensatorInput& in, std::span<const double> z) const {
  return force_in(detail::band_region_held(z[0], in.reference_rate, p_.band), in.reference_rate);
}

void FeedforwardCompensation::events(const CompensatorInput& in, std::span<const double>, std::span<double> g) const {
  g[0] = in.reference_rate - p_.band;
  g[1] = in.reference_rate + p_.band;
}

void FeedforwardCompensation::on_event(const CompensatorInput& in, std::span<double> z, int k) const {
  z[0] = detail::band_region_after(z[0], in.reference_rate, p_.band, k, in.reference_accel);
}

bool FeedforwardCompensation::jacobian(const CompensatorInput&, std::span<const double>, std::span<double> doutput,
                                       std::span<double> dderiv) const {
  std::fill(doutput.begin(), doutput.end(), 0.0);
  std::fill(dderiv.begin(), dderiv.end(), 0.0);
  return true;
}

double FeedforwardCompensation::update(const CompensatorInput& in, std::span<double> z, double) const {
  z[0] = detail::band_region(in.reference_rate, p_.band);
  return force_in(z[0], in.reference_rate);
}

}  // namespace frictionlab
