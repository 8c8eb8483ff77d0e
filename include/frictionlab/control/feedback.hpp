#pragma once
// Feedback friction compensation: the friction law evaluated at the measured velocity, switched off
// inside a dead band around rest.

#include <string>

#include "frictionlab/control/band_compensation.hpp"

namespace frictionlab {

/// Options of the feedback compensation.
struct FeedbackParams {
  /// Half-width of the dead band (m/s or rad/s), finite and > 0. Default 1e-3. Inside |v| <= dead_band
  /// the output is 0: a measured velocity near rest is mostly noise and quantisation, and the law's
  /// sign there would push the body back and forth. Choose it above the velocity's noise level.
  double dead_band = 1e-3;
};

/// Output = F(v), the law at the measured velocity, for |v| > dead_band; 0 inside the dead band (a
/// jump at its edges, as drive firmware does). The band's region is the one own state
/// (BandCompensation); an edge event crosses the edge.
class FeedbackCompensation : public BandCompensation {
 public:
  /// \throws std::invalid_argument "feedback: dead_band = VALUE must be > 0 (m/s or rad/s)" when the
  ///         dead band is not finite and > 0.
  explicit FeedbackCompensation(FrictionLaw law, FeedbackParams p = {});

  std::string type() const override { return "feedback"; }
  const FeedbackParams& params() const { return p_; }

 protected:
  double speed(const CompensatorInput& in) const override { return in.velocity; }
  double inside(double) const override { return 0.0; }

 private:
  FeedbackParams p_;
};

}  // namespace frictionlab
