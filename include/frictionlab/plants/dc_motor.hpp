#pragma once
// DC motor with friction on its shaft:
//   L di/dt = V - R i - Kb w          (voltage mode; i is a state)
//   i = Ka u                          (current mode: ideal current amplifier, no electrical state)
//   J w' = Kt i - T_load - T_friction

#include "frictionlab/plants/plant.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How the input drives the motor.
enum class MotorDrive {
  voltage,  ///< u is the terminal voltage (V); the current is a state
  current,  ///< u is the amplifier command (V); i = Ka u (A), no electrical dynamics
};

/// Parameters of a DC motor (SI units; torque in N m, angle in rad).
struct DcMotorParams {
  double J = 1e-6;      ///< rotor inertia (kg m^2), > 0. Default 1e-6.
  double R = 1.0;       ///< armature resistance (ohm), > 0. Default 1.
  double L = 1e-3;      ///< armature inductance (H), > 0 in voltage mode. Default 1e-3.
  double Kt = 0.01;     ///< torque constant (N m/A), > 0. Default 0.01.
  double Kb = 0.01;     ///< back-emf constant (V s/rad), >= 0. Default 0.01 (= Kt in SI).
  double Ka = 1.0;      ///< current-amplifier gain (A/V), > 0, current mode only. Default 1.
  double load = 0.0;    ///< constant load torque (N m), opposing positive rotation. Default 0.
  MotorDrive drive = MotorDrive::voltage;  ///< voltage (default) or current mode
};

/// DC motor. States: angle, speed, and in voltage mode the current (initially 0).
/// Signals: current (A); voltage (V): the input in voltage mode, R i + Kb w in current mode
/// (the amplifier's output without the L di/dt term); drive = Kt i (N m).
class DcMotor : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument naming the first parameter out of range.
  explicit DcMotor(DcMotorParams p);
  std::string type() const override { return "dc-motor"; }
  Axis motion_axis() const override { return Axis::rotary; }
  int num_states() const override { return p_.drive == MotorDrive::voltage ? 3 : 2; }
  double inertia(int = 0) const override { return p_.J; }
  double applied(double t, std::span<const double> x, const InputValue& u) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& u, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& u) const override;
  const DcMotorParams& params() const { return p_; }
  /// Motor current (A) at state x and input u.
  double current(std::span<const double> x, const InputValue& u) const;

 private:
  DcMotorParams p_;
};

}  // namespace frictionlab
