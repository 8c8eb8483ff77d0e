#pragma once
// Anti-aliased down-sampling, scipy.signal.decimate(x, q) with its default IIR filter.

#include <Eigen/Core>

namespace frictionlab {

/// Low-pass with an order-8 Chebyshev type I filter (0.05 dB ripple, cut-off 0.8 / q of the
/// Nyquist frequency, second-order sections) run forward and backward (sosfiltfilt, odd
/// padding of 27 samples), then keep samples 0, q, 2q, ... as scipy 1.10's decimate(x, q).
/// Shapes: x of length N > 27; returns ceil(N / q) samples.
/// \throws std::invalid_argument when q < 1 or x is too short (naming q or the length).
Eigen::VectorXd decimate(const Eigen::VectorXd& x, int q);

}  // namespace frictionlab
