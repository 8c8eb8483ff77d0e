#include "frictionlab/signal/chebyshev.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace frictionlab {

ZerosPolesGain cheby1_zpk(int order, double ripple_db, double wn) {
  if (order < 1) {
    throw std::invalid_argument("cheby1: filter order = " + std::to_string(order) + " must be a positive integer");
  }
  if (!(ripple_db > 0.0) || !std::isfinite(ripple_db)) {
    std::ostringstream msg;
    msg << "cheby1: pass-band ripple = " << ripple_db << " dB must be a positive number";
    throw std::invalid_argument(msg.str());
  }
  // scipy.signal.cheb1ap: poles on an ellipse, p = -sinh(mu + j theta), gain prod(-p) (divided
  // by sqrt(1 + eps^2) for even orders, whose DC gain is -ripple dB).
  using cd = std::complex<double>;
  const double eps = std::sqrt(std::pow(10.0, 0.1 * ripple_db) - 1.0);
  const double mu = 1.0 / order * std::asinh(1.0 / eps);
  Eigen::VectorXcd poles(order);
  cd k(1.0, 0.0);
  for (int i = 0; i < order; ++i) {
    const double m = -order + 1 + 2 * i;
    const double theta = std::numbers::pi * m / (2.0 * order);
    poles(i) = -std::sinh(cd(mu, theta));
    k *= -poles(i);
  }
  double gain = k.real();
  if (order % 2 == 0) gain /= std::sqrt(1.0 + eps * eps);
  return analog_prototype_to_digital_lowpass(poles, gain, wn);
}

TransferFunction cheby1(int order, double ripple_db, double wn) { return zpk_to_tf(cheby1_zpk(order, ripple_db, wn)); }

SecondOrderSections cheby1_sos(int order, double ripple_db, double wn) {
  return zpk_to_sos(cheby1_zpk(order, ripple_db, wn));
}

}  // namespace frictionlab
