#pragma once
// A P/PD/PI/PID controller closed around a plant (axis or motor): the plant's input becomes the
// controller output, and the scenario's input becomes the reference.

#include <memory>

#include "frictionlab/plants/plant.hpp"

namespace frictionlab {

/// What the loop controls.
enum class ControlLoop {
  position,  ///< e = r - x;  out = Kp e + Ki int(e) - Kd v   (derivative on the measurement: no kick at a step)
  velocity,  ///< e = r - v;  out = Kp e + Ki int(e)          (Kd must be 0)
};

/// Controller gains and limits. Output unit = the plant's input unit (N, N m, V or amplifier V).
struct ControllerParams {
  ControlLoop loop = ControlLoop::position;  ///< position (default) or velocity loop
  double Kp = 0.0;     ///< proportional gain (output unit per m, rad, m/s or rad/s), >= 0. Default 0.
  double Ki = 0.0;     ///< integral gain (output unit per (error unit s)), >= 0. Default 0.
  double Kd = 0.0;     ///< velocity feedback gain of the position loop (output unit per m/s or rad/s), >= 0. Default 0.
  /// Output saturation |out| <= limit (output unit); 0 = none (default). The integrator keeps
  /// integrating while saturated (no anti-windup: what a plain PID does).
  double limit = 0.0;
};

/// Closed loop around `inner` (a 1-DOF plant). States: the inner plant's, then the integral of
/// the error. Signals: the inner plant's at the controller output (drive: the force it commands),
/// with reference = r.
class ClosedLoop : public SingleContactPlant {
 public:
  /// \throws std::invalid_argument when a gain is negative or not finite, Kd != 0 in a velocity
  ///         loop, the limit is negative, or `inner` is null, kinematic or not 1-DOF.
  ClosedLoop(std::shared_ptr<const Plant> inner, ControllerParams c);
  std::string type() const override { return inner_->type(); }
  int num_states() const override { return n_inner_ + 1; }
  double inertia(int = 0) const override { return inner_->inertia(); }
  void initial_extras(std::span<double> x) const override;
  double applied(double t, std::span<const double> x, const InputValue& r) const override;
  void derivatives(double t, std::span<const double> x, const InputValue& r, double friction,
                   std::span<double> dx) const override;
  PlantSignals signals(double t, std::span<const double> x, const InputValue& r) const override;
  /// Controller output (plant input unit) at state x and reference r.
  double control(std::span<const double> x, double r) const;
  const ControllerParams& controller() const { return c_; }
  const Plant& inner() const { return *inner_; }

 private:
  std::shared_ptr<const Plant> inner_;
  ControllerParams c_;
  int n_inner_;
};

}  // namespace frictionlab
