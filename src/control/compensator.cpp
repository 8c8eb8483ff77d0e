#include "frictionlab/control/compensator.hpp"

#include <algorithm>

namespace frictionlab {

void Compensator::initial_states(const CompensatorInput&, std::span<double>) const {}

void Compensator::derivatives(const CompensatorInput&, std::span<const double>, std::span<double> dz) const {
  std::fill(dz.begin(), dz.end(), 0.0);
}

void Compensator::events(const CompensatorInput&, std::span<const double>, std::span<double>) const {}

void Compensator::on_event(const CompensatorInput&, std::span<double>, int) const {}

bool Compensator::jacobian(const CompensatorInput&, std::span<const double>, std::span<double>,
                           std::span<double>) const {
  return false;
}

}  // namespace frictionlab
