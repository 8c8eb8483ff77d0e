#include "frictionlab/control/feedback.hpp"

#include <ceres/jet.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "velocity_band.hpp"

namespace frictionlab {
namespace {

// dF/dv of a static law's sliding force at v (N s/m or N m s/rad), by forward-mode automatic
// differentiation of its own formula; nothing for a dynamic law (no differentiable steady state).
std::optional<double> sliding_slope(const FrictionLaw& law, double v) {
  using Dual = ceres::Jet<double, 1>;
  return std::visit(
      [v](const auto& l) -> std::optional<double> {
        if constexpr (requires(const Dual& w) { l.template sliding<Dual>(w); }) {
          Dual w(v);
          w.v[0] = 1.0;  // seed set by hand: Jet's two-argument constructor takes an index
          return l.template sliding<Dual>(w).v[0];
        } else {
          return std::nullopt;
        }
      },
      law.variant());
}

}  // namespace

FeedbackCompensation::FeedbackCompensation(FrictionLaw law, FeedbackParams p)
    : BandCompensation(std::move(law), p.dead_band), p_(p) {
  detail::require(std::isfinite(p.dead_band) && p.dead_band > 0, "feedback", "dead_band", p.dead_band,
                  "> 0 (m/s or rad/s)");
}

bool FeedbackCompensation::jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                                    std::span<double> dderiv) const {
  // A law whose levels move with the load or temperature: no analytic form (the load may follow the
  // plant's state through the loop), difference quotients instead.
  if (law_.is_dynamic() || law_.effects().moves_levels()) return false;
  const double region = detail::band_region_held(z[0], in.velocity, band_);
  const std::optional<double> slope = region == 0.0 ? std::optional<double>(0.0) : sliding_slope(law_, in.velocity);
  if (!slope) return false;
  std::fill(doutput.begin(), doutput.end(), 0.0);
  std::fill(dderiv.begin(), dderiv.end(), 0.0);
  doutput[0] = law_.effects().ripple ? law_.effects().ripple->slope(in.position) : 0.0;
  doutput[1] = *slope;  // w = (position, velocity, drive, region)
  return true;
}

}  // namespace frictionlab
