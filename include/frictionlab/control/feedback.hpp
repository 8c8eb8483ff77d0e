#pragma once
// Feedback friction compensation: the friction law evaluated at the measured velocity, switched off
// inside a dead band around rest.

#include <string>

#include "frictionlab/control/band_compensation.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of the feedback compensation.
struct FeedbackParams {
  /// Half-width of the dead band (m/s or rad/s), finite and > 0. Default 1e-3. Inside |v| <= dead_band
  /// the output is 0: a measured velocity near rest is mostly noise and quantisation, and the law's
  /// sign there would push the body back and forth. Choose it above the velocity's noise level.
  double dead_band = 1e-3;
};

/// Output = F(v), the law at the measured velocity, for |v| > dead_band; 0 inside the dead band (a
/// jump at its edges, as drive firmware does). The band's region is the one own state
/// (BandCompensation); an edge event crosses the edge. A law with a position ripple adds r(x), its
/// ripple at the measured position (CompensatorInput::position), in and outside the dead band: the
/// ripple acts on a stuck axis as on a sliding one, and depends on the position, not on noise in v.
class FeedbackCompensation : public BandCompensation {
 public:
  /// \throws std::invalid_argument "feedback: dead_band = VALUE must be > 0 (m/s or rad/s)" when the
  ///         dead band is not finite and > 0.
  explicit FeedbackCompensation(FrictionLaw law, FeedbackParams p = {});

  std::string type() const override { return "feedback"; }
  /// d output / d velocity = the law's slope dF/dv at the measured velocity (N s/m or N m s/rad)
  /// outside the dead band (in the region the state holds), 0 inside it; d output / d position =
  /// the ripple's slope dr/dx (N/m or N m/rad; 0 without a ripple); every other entry 0 (the
  /// region is discrete). The slope comes from forward-mode automatic differentiation of the law's
  /// sliding formula, so it is exact. Static laws only: for a dynamic law (whose output is the
  /// steady-state force) it returns false, writing nothing.
  bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                std::span<double> dderiv) const override;
  const FeedbackParams& params() const { return p_; }

 protected:
  double speed(const CompensatorInput& in) const override { return in.velocity; }
  double ripple_position(const CompensatorInput& in) const override { return in.position; }
  double inside(double, const Conditions&) const override { return 0.0; }

 private:
  FeedbackParams p_;
};

}  // namespace frictionlab
