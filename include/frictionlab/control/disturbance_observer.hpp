#pragma once
// Disturbance observer: the nominal inverse model M s v of the driven body, low-pass filtered, gives
// the force that the drive did not produce (friction and any other load); the loop adds it back.

#include <span>
#include <string>

#include "frictionlab/control/compensator.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of the disturbance observer.
struct DisturbanceObserverParams {
  /// Bandwidth w of the first-order low-pass Q(s) = w / (s + w) (rad/s), finite and > 0.
  /// Default 100 rad/s. The estimate follows a disturbance with time constant 1/w: higher w
  /// rejects faster and passes more velocity noise (the estimate differentiates v).
  double bandwidth = 100.0;
  /// Nominal inertia M of the driven body (kg or kg m^2), finite and > 0; no default (0 is
  /// rejected): a wrong M makes the estimate include (M - M_true) a.
  double inertia = 0.0;
};

/// Estimate d^ = Q(s) (drive - M s v), with d the force opposing the drive (M a = drive - d):
/// without the derivative of v, through the state p = d^ + w M v:
///   dp/dt = w (drive - p + w M v),   output d^ = p - w M v     (N or N m)
/// so dd^/dt = w (d - d^) when the nominal model is exact: a first-order response of time constant
/// 1/w to a disturbance step. One own state, continuous: p (N or N m), starting at w M v (d^ = 0).
/// No events.
class DisturbanceObserver : public Compensator {
 public:
  /// \throws std::invalid_argument naming bandwidth or inertia, its value, unit and rule.
  explicit DisturbanceObserver(DisturbanceObserverParams p);

  std::string type() const override { return "disturbance-observer"; }
  int num_states() const override { return 1; }
  void initial_states(const CompensatorInput& in, std::span<double> z) const override;
  double output(const CompensatorInput& in, std::span<const double> z) const override;
  void derivatives(const CompensatorInput& in, std::span<const double> z, std::span<double> dz) const override;
  bool jacobian(const CompensatorInput& in, std::span<const double> z, std::span<double> doutput,
                std::span<double> dderiv) const override;
  /// Exact over the step at the held drive and v (p relaxes exponentially with rate w).
  double update(const CompensatorInput& in, std::span<double> z, double dt) const override;

  const DisturbanceObserverParams& params() const { return p_; }

 private:
  DisturbanceObserverParams p_;
};

}  // namespace frictionlab
