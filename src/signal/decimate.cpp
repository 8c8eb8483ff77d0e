#include "frictionlab/signal/decimate.hpp"

#include <stdexcept>
#include <string>

#include "frictionlab/signal/chebyshev.hpp"
#include "frictionlab/signal/filtfilt.hpp"

namespace frictionlab {

Eigen::VectorXd decimate(const Eigen::VectorXd& x, int q) {
  if (q < 1) throw std::invalid_argument("decimate: factor q = " + std::to_string(q) + " must be a positive integer");
  constexpr int kOrder = 8;            // scipy's default IIR order
  constexpr double kRippleDb = 0.05;   // scipy's default pass-band ripple
  constexpr double kCutoffFraction = 0.8;  // of the new Nyquist frequency
  const SecondOrderSections sos = cheby1_sos(kOrder, kRippleDb, kCutoffFraction / q);
  const Eigen::VectorXd y = sosfiltfilt(sos, x);
  const Eigen::Index n = (y.size() + q - 1) / q;
  Eigen::VectorXd out(n);
  for (Eigen::Index i = 0; i < n; ++i) out(i) = y(i * q);
  return out;
}

}  // namespace frictionlab
