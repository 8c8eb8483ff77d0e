#pragma once
// Stick-slip rig: a mass tied by a spring to a base moving at constant speed,
//   m x'' + k (x - xb(t)) + c (x' - V0) + F = u,   xb(t) = x0 + V0 t.

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Parameters of the mass-spring with moving base.
struct SpringBaseParams {
  double m = 1.0;   ///< mass (kg), > 0. Default 1.
  double k = 1.0;   ///< spring stiffness (N/m), > 0. Default 1.
  double c = 0.0;   ///< spring damping (N s/m), >= 0. Default 0.
  double V0 = 0.0;  ///< base velocity (m/s), any sign. Default 0 (a free mass-spring oscillator).
  double x0 = 0.0;  ///< base position at t = 0 (m). Default 0: the spring is relaxed at x = 0.
};

/// Mass-spring with moving base; the input u is an extra force on the mass (usually 0).
/// The base position is exact (x0 + V0 t), so it needs no state. Signals: `reference` = base
/// position (m), `drive` = the force of the spring, its damper and u on the mass (N).
class SpringBase : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument naming the first parameter out of range.
  explicit SpringBase(SpringBaseParams p);
  std::string type() const override { return "spring-base"; }
  int num_states() const override { return 2; }
  double inertia(int = 0) const override { return p_.m; }
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  bool jacobian(double t, std::span<const double> x, const InputValue& u, double friction, std::span<double> dfdx,
                std::span<double> dfdF) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;
  const SpringBaseParams& params() const { return p_; }

 private:
  SpringBaseParams p_;
};

}  // namespace frictionlab
