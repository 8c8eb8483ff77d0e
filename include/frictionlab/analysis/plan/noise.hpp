#pragma once
// The sensor noise an experiment plan is predicted with: white Gaussian noise on each measured
// signal, and the encoder's quantisation of the position.

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Standard deviations of white Gaussian measurement noise (SI units), and the encoder step.
/// All >= 0; 0 (the default) is a clean signal.
struct SensorNoise {
  double position = 0.0;  ///< m or rad
  double velocity = 0.0;  ///< m/s or rad/s
  double current = 0.0;   ///< A (motor current; the force is Kt times the measured current)
  double force = 0.0;     ///< N or N m (a measured drive force; axis plants)
  double encoder = 0.0;   ///< position quantisation step, m or rad (0: none)

  /// \throws std::invalid_argument naming the key and value when one is negative or not finite.
  void validate(const std::string& option = "noise") const;
};

/// Reads noise from KEY=VALUE items (comma-separated, repeatable), keys position (m or rad),
/// velocity (m/s or rad/s), current (A), force (N or N m), encoder (m or rad).
/// \throws std::invalid_argument naming the option and item: unknown key (listing the known
///         ones), a value that is not a number >= 0, a key given twice.
SensorNoise parse_sensor_noise(const std::vector<std::string>& specs, const std::string& option = "--noise");

/// `clean` + N(0, std^2) per sample from `rng` (std >= 0; std 0 returns `clean` and draws nothing),
/// then rounded to multiples of `step` when step > 0. Same length as `clean`.
Eigen::VectorXd add_noise(const Eigen::VectorXd& clean, double std, std::mt19937_64& rng, double step = 0.0);

}  // namespace frictionlab
