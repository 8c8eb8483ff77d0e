#pragma once
// Anti-aliased down-sampling, scipy.signal.decimate(x, q) with its default IIR filter.

#include <Eigen/Core>

#include "frictionlab/signal/filtfilt.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Low-pass with an order-8 Chebyshev type I filter (0.05 dB ripple, cut-off 0.8 / q of the
/// Nyquist frequency, second-order sections) run forward and backward (sosfiltfilt, odd
/// padding of 27 samples), then keep samples 0, q, 2q, ... as scipy 1.10's decimate(x, q).
/// Shapes: x of length N > 27; returns ceil(N / q) samples.
/// \throws std::invalid_argument when q < 1 or x is too short (naming q or the length).
Eigen::VectorXd decimate(const Eigen::VectorXd& x, int q);

/// decimate of every column of x (the same numbers as column by column, filtered several
/// columns at a time). Shapes: x is N x C with N > 27; returns ceil(N / q) x C.
/// \throws std::invalid_argument when q < 1 or x is too short.
Eigen::MatrixXd decimate_columns(const Eigen::MatrixXd& x, int q);

/// The same for columns held elsewhere, all of the same length (no copy into a matrix first).
Eigen::MatrixXd decimate_columns(const ColumnViews& x, int q);

/// The same with the caller's work space (signal/filter_workspace.hpp), for calls in a loop: the
/// numbers equal those of the call without it.
/// \throws std::invalid_argument as above; std::bad_alloc when the workspace cannot grow.
Eigen::MatrixXd decimate_columns(const ColumnViews& x, int q, FilterWorkspace& workspace);

}  // namespace frictionlab
