#include "frictionlab/control/feedback.hpp"

#include <cmath>

#include "velocity_band.hpp"

namespace frictionlab {

FeedbackCompensation::FeedbackCompensation(FrictionLaw law, FeedbackParams p) : law_(std::move(law)), p_(p) {
  detail::require(std::isfinite(p.dead_band) && p.dead_band > 0, "feedback", "dead_band", p.dead_band,
                  "> 0 (m/s or rad/s)");
}

double FeedbackCompensation::force(double v) const {
  return detail::band_region(v, p_.dead_band) == 0.0 ? 0.0 : law_.sliding(v);
}

void FeedbackCompensation::initial_states(const CompensatorInput& in, std::span<double> z) const {
  z[0] = detail::band_region(in.velocity, p_.dead_band);
}

double FeedbackCompensation::output(const CompensatorInput& in, std::span<const double> z) const {
  return detail::band_region_held(z[0], in.velocity, p_.dead_band) == 0.0 ? 0.0 : law_.sliding(in.velocity);
}

void FeedbackCompensation::events(const CompensatorInput& in, std::span<const double>, std::span<double> g) const {
  g[0] = in.velocity - p_.dead_band;
  g[1] = in.velocity + p_.dead_band;
}

void FeedbackCompensation::on_event(const CompensatorInput& in, std::span<double> z, int k) const {
  z[0] = detail::band_region_after(z[0], in.velocity, p_.dead_band, k);
}

double FeedbackCompensation::update(const CompensatorInput& in, std::span<double> z, double) const {
  z[0] = detail::band_region(in.velocity, p_.dead_band);
  return output(in, z);
}

}  // namespace frictionlab
