#pragma once
// Rigid axis: an inertia pushed by the input force, M a = u(t) - F.

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Parameters of a rigid axis.
struct AxisParams {
  /// Inertia (kg or kg m^2), > 0. Default 1.
  double M = 1.0;
  /// Constant force added to the input (N or N m), e.g. gravity on a vertical axis. Default 0.
  double offset = 0.0;
};

/// Rigid axis (RigidAxis: `Axis` names the linear/rotary kind): applied = u(t) + offset.
/// States: position, velocity.
class RigidAxis : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when M <= 0 or a value is not finite (message names it).
  explicit RigidAxis(AxisParams p);
  std::string type() const override { return "axis"; }
  int num_states() const override { return 2; }
  double inertia(int = 0) const override { return p_.M; }
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  bool jacobian(double t, std::span<const double> x, const InputValue& u, double friction, std::span<double> dfdx,
                std::span<double> dfdF) const override;
  /// reference = drive = the input force u (N or N m).
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;
  const AxisParams& params() const { return p_; }

 private:
  AxisParams p_;
};

}  // namespace frictionlab
