#pragma once
// Digital filter representations shared by the filter designs (Butterworth, Chebyshev) and the
// filters that run them (filtfilt, sosfiltfilt): transfer function (b, a), zeros-poles-gain,
// and second-order sections, with the conversions scipy.signal uses (zpk2tf, zpk2sos).

#include <Eigen/Core>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Transfer function H(z) = (b0 + b1 z^-1 + ...) / (a0 + a1 z^-1 + ...), coefficients in
/// descending powers of z as scipy.signal returns them (a0 = 1 for the designs here).
struct TransferFunction {
  Eigen::VectorXd b;  ///< numerator, length nb >= 1
  Eigen::VectorXd a;  ///< denominator, length na >= 1, a(0) != 0
};

/// Zeros, poles and gain of a digital filter: H(z) = gain * prod(z - zeros) / prod(z - poles).
/// Complex roots come in conjugate pairs.
struct ZerosPolesGain {
  Eigen::VectorXcd zeros;
  Eigen::VectorXcd poles;
  double gain = 1.0;
};

/// Second-order sections, one row per section: [b0 b1 b2 a0 a1 a2] (scipy's `sos` layout).
using SecondOrderSections = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

/// Polynomial coefficients from zeros and poles (scipy.signal.zpk2tf): b = gain * poly(zeros),
/// a = poly(poles), real parts kept. Shapes: b has zeros.size()+1 entries, a poles.size()+1.
TransferFunction zpk_to_tf(const ZerosPolesGain& zpk);

/// Second-order sections of a low-pass whose zeros all lie at z = -1 (the Butterworth and
/// Chebyshev I designs here), paired as scipy.signal.zpk2sos(pairing='nearest'): poles closest
/// to the unit circle in the last section, the gain in the first. Shape: ceil(n/2) x 6.
/// \throws std::invalid_argument if the number of zeros differs from the number of poles.
SecondOrderSections zpk_to_sos(const ZerosPolesGain& zpk);

/// Digital low-pass from an analog low-pass prototype with cut-off 1 rad/s (poles only, gain
/// k): frequency pre-warping, scaling to the cut-off and the bilinear transform, exactly as
/// scipy.signal's iirfilter (lp2lp_zpk then bilinear_zpk with fs = 2). `wn` is the cut-off
/// normalised by the Nyquist frequency, 0 < wn < 1.
/// \throws std::invalid_argument naming `wn` when it is outside (0, 1).
ZerosPolesGain analog_prototype_to_digital_lowpass(const Eigen::VectorXcd& analog_poles, double analog_gain,
                                                   double wn);

}  // namespace frictionlab
