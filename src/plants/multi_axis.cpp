// N independent rigid axes: see include/frictionlab/plants/multi_axis.hpp.
#include "frictionlab/plants/multi_axis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

MultiAxis::MultiAxis(std::vector<NamedAxis> axes) : axes_(std::move(axes)) {
  if (axes_.empty()) throw std::invalid_argument("multi-axis: no axis given");
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    const NamedAxis& a = axes_[k];
    const std::string who = "multi-axis: axis " + std::to_string(k) + (a.name.empty() ? "" : " ('" + a.name + "')");
    if (a.name.empty()) throw std::invalid_argument(who + " has no name (names prefix its columns: x.position)");
    for (std::size_t j = 0; j < k; ++j)
      if (axes_[j].name == a.name) throw std::invalid_argument(who + ": the name is already axis " + std::to_string(j) + "'s");
    if (!(std::isfinite(a.params.M) && a.params.M > 0))
      throw std::invalid_argument(who + ": M = " + detail::format_value(a.params.M) + " must be > 0 (kg or kg m^2)");
    if (!std::isfinite(a.params.offset))
      throw std::invalid_argument(who + ": offset = " + detail::format_value(a.params.offset) + " must be finite (N or N m)");
  }
}

Contact MultiAxis::contact(int i) const {
  const NamedAxis& a = axes_.at(static_cast<std::size_t>(i));
  return {a.name, 2 * i, 2 * i + 1, a.law ? &*a.law : nullptr};
}

double MultiAxis::inertia(int contact) const { return axes_.at(static_cast<std::size_t>(contact)).params.M; }

void MultiAxis::applied(double, std::span<const double>, Inputs u, std::span<double> force) const {
  for (std::size_t k = 0; k < axes_.size(); ++k) force[k] = u[k].value + axes_[k].params.offset;
}

void MultiAxis::derivatives(double, std::span<const double> x, Inputs u, std::span<const double> friction,
                            std::span<double> dx) const {
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    dx[2 * k] = x[2 * k + 1];
    dx[2 * k + 1] = (u[k].value + axes_[k].params.offset - friction[k]) / axes_[k].params.M;
  }
}

bool MultiAxis::jacobian(double, std::span<const double>, Inputs, std::span<const double>, std::span<double> dfdx,
                         std::span<double> dfdF) const {
  const std::size_t n = 2 * axes_.size(), nc = axes_.size();
  std::fill(dfdx.begin(), dfdx.begin() + static_cast<std::ptrdiff_t>(n * n), 0.0);
  std::fill(dfdF.begin(), dfdF.begin() + static_cast<std::ptrdiff_t>(n * nc), 0.0);
  for (std::size_t k = 0; k < nc; ++k) {
    dfdx[(2 * k) * n + 2 * k + 1] = 1.0;                    // d position / dt = velocity
    dfdF[(2 * k + 1) * nc + k] = -1.0 / axes_[k].params.M;  // dv_k = (u_k + offset_k - F_k) / M_k
  }
  return true;
}

void MultiAxis::signals(double, std::span<const double>, Inputs u, std::span<PlantSignals> out) const {
  for (std::size_t k = 0; k < axes_.size(); ++k) out[k] = PlantSignals{0.0, 0.0, u[k].value, u[k].value};
}

}  // namespace frictionlab
