#pragma once
// Velocity drive: the input imposes the velocity of the friction body, v = u(t), as in the
// frictional-lag experiment of Canudas de Wit et al. 1995; the result is the friction force the
// drive must overcome.

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Parameters of a velocity drive.
struct VelocityDriveParams {
  /// Inertia of the driven body (kg or kg m^2), >= 0; adds M du/dt to the drive force. Default 0.
  double M = 0.0;
};

/// Kinematic plant: x[1] = u(t), x[0] = integral of u; applied = friction + M du/dt (the drive force).
class VelocityDrive : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when M < 0.
  explicit VelocityDrive(VelocityDriveParams p);
  std::string type() const override { return "velocity-drive"; }
  int num_states() const override { return 2; }
  double inertia(int = 0) const override { return p_.M; }
  bool kinematic() const override { return true; }
  /// The inertial part M du/dt only: the engine adds the friction force.
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  /// dx[0] = u, dx[1] = du/dt (friction has no effect on the motion).
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  /// reference = u; drive = M du/dt (the engine adds the friction force, as to `applied`).
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;

 private:
  VelocityDriveParams p_;
};

}  // namespace frictionlab
