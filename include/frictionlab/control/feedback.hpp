#pragma once
// Feedback friction compensation: the friction law evaluated at the measured velocity, switched off
// inside a dead band around rest.

#include <span>
#include <string>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {

/// Options of the feedback compensation.
struct FeedbackParams {
  /// Half-width of the dead band (m/s or rad/s), finite and > 0. Default 1e-3. Inside |v| < dead_band
  /// the output is 0: a measured velocity near rest is mostly noise and quantisation, and the law's
  /// sign there would push the body back and forth. Choose it above the velocity's noise level.
  double dead_band = 1e-3;
};

/// Output = F(v), the law's sliding force (steady-state force for dynamic laws) at the measured
/// velocity, for |v| >= dead_band; 0 inside the dead band (a jump at its edges, as drive firmware does).
/// One own state, discrete: the region of v (-1 below -dead_band, 0 inside, +1 above), switched by
/// two events, g0 = v - dead_band and g1 = v + dead_band, so the jumps are located exactly (at an
/// event the region crosses the edge). A stored region more than 1 % of the dead band off v (a run
/// started at another velocity than its initial states saw) gives way to the region of v itself.
class FeedbackCompensation : public Compensator {
 public:
  /// \throws std::invalid_argument "feedback: dead_band = VALUE must be > 0 (m/s or rad/s)" when the
  ///         dead band is not finite and > 0.
  explicit FeedbackCompensation(FrictionLaw law, FeedbackParams p = {});

  std::string type() const override { return "feedback"; }
  int num_states() const override { return 1; }
  void initial_states(const CompensatorInput& in, std::span<double> z) const override;
  double output(const CompensatorInput& in, std::span<const double> z) const override;
  int num_events() const override { return 2; }
  void events(const CompensatorInput& in, std::span<const double> z, std::span<double> g) const override;
  void on_event(const CompensatorInput& in, std::span<double> z, int k) const override;
  double update(const CompensatorInput& in, std::span<double> z, double dt) const override;

  /// The compensation force (N or N m) at measured velocity v (m/s or rad/s), the region taken from v.
  double force(double v) const;
  const FrictionLaw& law() const { return law_; }
  const FeedbackParams& params() const { return p_; }

 private:
  FrictionLaw law_;
  FeedbackParams p_;
};

}  // namespace frictionlab
