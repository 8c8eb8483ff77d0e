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

double FeedforwardCompensation::inside(double vr, const Conditions& c) const {
  // The band's ends move with the conditions; without load or temperature terms they are fixed.
  const bool moves = law_.effects().moves_levels();
  const double plus = moves ? law_.sliding(p_.band, c) : at_plus_;
  const double minus = moves ? law_.sliding(-p_.band, c) : at_minus_;
  // The share t of the way from -band to +band, then the two ends weighted by it: no product or
  // difference of the ends that could overflow where both ends and the band are finite (a band of
  // 7.7e27 once gave inf at vr = 0 in a float header).
  const double t = 0.5 + 0.5 * (vr / p_.band);
  return minus * (1.0 - t) + plus * t;
}

bool FeedforwardCompensation::jacobian(const CompensatorInput&, std::span<const double>, std::span<double> doutput,
                                       std::span<double> dderiv) const {
  if (law_.effects().moves_levels()) return false;
  std::fill(doutput.begin(), doutput.end(), 0.0);
  std::fill(dderiv.begin(), dderiv.end(), 0.0);
  return true;
}

}  // namespace frictionlab
