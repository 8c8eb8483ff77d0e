#pragma once
// Digital low-pass Butterworth design, matching scipy.signal.butter(order, wn).
//
// Hand-written: none of the project's Debian libraries (Eigen, Ceres, SUNDIALS, ...) designs
// IIR filters, and the recipe must reproduce scipy's coefficients to rounding. The tests compare
// against scipy's values.

#include "frictionlab/signal/transfer_function.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Zeros, poles and gain of an order-`order` digital Butterworth low-pass with cut-off `wn`
/// (normalised: 1 is the Nyquist frequency; -3 dB at wn). scipy.signal.butter(..., output='zpk').
/// \throws std::invalid_argument when order < 1 or wn is outside (0, 1), naming the parameter.
ZerosPolesGain butter_zpk(int order, double wn);

/// Transfer function (b, a) of the same filter, scipy.signal.butter(order, wn).
/// Shapes: b and a have order + 1 coefficients, a(0) = 1.
/// \throws std::invalid_argument as butter_zpk.
TransferFunction butter(int order, double wn);

/// Normalised cut-off of a filter at `cutoff_hz` for data sampled every `dt` seconds:
/// cutoff_hz / (0.5 / dt). \throws std::invalid_argument when the result is outside (0, 1).
double normalized_cutoff(double cutoff_hz, double dt);

}  // namespace frictionlab
