#include "frictionlab/signal/butterworth.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace frictionlab {

ZerosPolesGain butter_zpk(int order, double wn) {
  if (order < 1) {
    throw std::invalid_argument("butter: filter order = " + std::to_string(order) + " must be a positive integer");
  }
  // scipy.signal.buttap: p = -exp(j pi m / (2N)), m = -N+1, -N+3, ..., N-1; gain 1.
  Eigen::VectorXcd poles(order);
  for (int i = 0; i < order; ++i) {
    const double m = -order + 1 + 2 * i;
    poles(i) = -std::exp(std::complex<double>(0.0, std::numbers::pi * m / (2.0 * order)));
  }
  return analog_prototype_to_digital_lowpass(poles, 1.0, wn);
}

TransferFunction butter(int order, double wn) { return zpk_to_tf(butter_zpk(order, wn)); }

double normalized_cutoff(double cutoff_hz, double dt) {
  const double wn = cutoff_hz / (0.5 / dt);
  if (!(dt > 0.0) || !std::isfinite(dt) || !(wn > 0.0 && wn < 1.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "filter cut-off = " << cutoff_hz << " Hz must be between 0 and the Nyquist frequency "
        << 0.5 / dt << " Hz (sample time " << dt << " s)";
    throw std::invalid_argument(msg.str());
  }
  return wn;
}

}  // namespace frictionlab
