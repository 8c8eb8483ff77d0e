#include "frictionlab/control/band_compensation.hpp"

#include "velocity_band.hpp"

namespace frictionlab {

double BandCompensation::force(double s, const Conditions& c) const { return force_in(detail::band_region(s, band_), s, c); }

void BandCompensation::initial_states(const CompensatorInput& in, std::span<double> z) const {
  z[0] = detail::band_region(speed(in), band_);
}

double BandCompensation::output(const CompensatorInput& in, std::span<const double> z) const {
  const double s = speed(in);
  return force_in(detail::band_region_held(z[0], s, band_), s, conditions(in)) + law_.ripple(ripple_position(in));
}

void BandCompensation::events(const CompensatorInput& in, std::span<const double>, std::span<double> g) const {
  const double s = speed(in);
  g[0] = s - band_;
  g[1] = s + band_;
}

void BandCompensation::on_event(const CompensatorInput& in, std::span<double> z, int k) const {
  z[0] = detail::band_region_after(z[0], speed(in), band_, k, speed_direction(in));
}

double BandCompensation::update(const CompensatorInput& in, std::span<double> z, double) const {
  const double s = speed(in);
  z[0] = detail::band_region(s, band_);
  return force_in(z[0], s, conditions(in)) + law_.ripple(ripple_position(in));
}

}  // namespace frictionlab
