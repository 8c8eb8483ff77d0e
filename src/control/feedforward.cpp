#include "frictionlab/control/feedforward.hpp"

#include <algorithm>
#include <cmath>

namespace frictionlab {

FeedforwardCompensation::FeedforwardCompensation(FrictionLaw law, FeedforwardParams p)
    : BandCompensation(std::move(law), p.band), p_(p) {
  detail::require(std::isfinite(p.band) && p.band > 0, "feedforward", "band", p.band, "> 0 (m/s or rad/s)");
  at_plus_ = law_.sliding(p.band);
  at_minus_ = law_.sliding(-p.band);
}

double FeedforwardCompensation::inside(double vr) const {
  return at_minus_ + (at_plus_ - at_minus_) * (vr + p_.band) / (2.0 * p_.band);
}

bool FeedforwardCompensation::jacobian(const CompensatorInput&, std::span<const double>, std::span<double> doutput,
                                       std::span<double> dderiv) const {
  std::fill(doutput.begin(), doutput.end(), 0.0);
  std::fill(dderiv.begin(), dderiv.end(), 0.0);
  return true;
}

}  // namespace frictionlab
