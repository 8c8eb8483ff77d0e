// Harmonic balance of the hunting cycle: the closed forms derived in
// analysis/describing_function.hpp.
#include "frictionlab/analysis/describing_function.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

void require(bool ok, const std::string& name, double value, const std::string& rule) {
  if (!ok) throw std::invalid_argument("hunting loop: " + name + " = " + format_number(value) + " must be " + rule);
}

}  // namespace

void HuntingLoop::validate() const {
  require(std::isfinite(M) && M > 0, "M", M, "> 0 (kg)");
  require(std::isfinite(Kp) && Kp > 0, "Kp", Kp, "> 0 (N/m)");
  require(std::isfinite(Ki) && Ki > 0, "Ki", Ki, "> 0 (N/(m s)): without an integrator the loop does not hunt");
  require(std::isfinite(Kd) && Kd >= 0, "Kd", Kd, ">= 0 (N s/m)");
  require(std::isfinite(Fc) && Fc > 0, "Fc", Fc, "> 0 (N)");
  require(std::isfinite(Fs) && Fs >= Fc, "Fs", Fs, ">= Fc = " + format_number(Fc) + " (N)");
}

HuntingPrediction predict_hunting(const HuntingLoop& loop) {
  loop.validate();
  constexpr double kPi = std::numbers::pi;
  HuntingPrediction p;
  p.damping_ratio = loop.Kd / (2.0 * std::sqrt(loop.Kp * loop.M));
  if (!(loop.Kd * loop.Kp > loop.M * loop.Ki)) {
    p.message = "the loop without friction is unstable (Kd Kp = " + format_number(loop.Kd * loop.Kp) +
                " N^2/m^2 <= M Ki = " + format_number(loop.M * loop.Ki) +
                " N^2/m^2): the motion is not a hunting around the setpoint";
    return p;
  }
  if (!(loop.Fs > loop.Fc)) {
    p.message = "no stiction (Fs = Fc = " + format_number(loop.Fc) + " N): the loop converges, no hunting";
    return p;
  }
  const double zeta = p.damping_ratio;
  const double rho = zeta < 1.0 ? std::exp(-kPi * zeta / std::sqrt(1.0 - zeta * zeta)) : 0.0;
  p.amplitude = (loop.Fs - loop.Fc) * (1.0 + rho) / (2.0 * loop.Kp);
  p.switch_force = loop.Fs - loop.Kp * p.amplitude;  // >= Fc > 0 since (1 + rho) / 2 <= 1
  p.first_harmonic = 4.0 * p.amplitude / kPi;
  const double w = 4.0 * p.amplitude * loop.Ki / (kPi * p.switch_force);
  p.period = 2.0 * kPi / w;
  p.found = true;
  return p;
}

}  // namespace frictionlab
