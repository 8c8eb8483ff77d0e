#pragma once
// Pendulum with pivot friction (Craig's lecture): m l^2 th'' + m g l sin(th) + B th' + Tf = u.

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Parameters of a point-mass pendulum; the angle th (rad) is measured from the hanging position.
struct PendulumParams {
  double m = 1.0;    ///< bob mass (kg), > 0. Default 1.
  double l = 1.0;    ///< length (m), > 0. Default 1.
  double g = 9.81;   ///< gravity (m/s^2), >= 0. Default 9.81.
  double B = 0.0;    ///< viscous pivot damping kept in the plant (N m s/rad), >= 0. Default 0
                     ///< (put viscous friction in the law instead when it is to be identified).
};

/// Pendulum: M = m l^2, applied = u - m g l sin(th) - B th'. States: angle, angular velocity.
class Pendulum : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument naming the first parameter out of range.
  explicit Pendulum(PendulumParams p);
  std::string type() const override { return "pendulum"; }
  Axis motion_axis() const override { return Axis::rotary; }
  int num_states() const override { return 2; }
  double inertia(int = 0) const override { return p_.m * p_.l * p_.l; }
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  /// reference = drive = the input torque u (N m).
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;
  /// Mechanical energy (J) of state x: kinetic + potential (zero at the hanging position).
  double energy(std::span<const double> x) const;
  const PendulumParams& params() const { return p_; }

 private:
  PendulumParams p_;
};

}  // namespace frictionlab
