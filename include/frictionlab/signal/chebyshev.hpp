#pragma once
// Digital low-pass Chebyshev type I design, matching scipy.signal.cheby1(order, rp, wn).
// Hand-written for the same reason as butterworth.hpp (no filter design in our libraries).

#include "frictionlab/signal/transfer_function.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Zeros, poles and gain of an order-`order` Chebyshev type I low-pass with pass-band ripple
/// `ripple_db` (dB, > 0) and cut-off `wn` (normalised by Nyquist; the gain leaves the ripple
/// band at wn). scipy.signal.cheby1(order, ripple_db, wn, output='zpk').
/// \throws std::invalid_argument when order < 1, ripple_db <= 0 or wn outside (0, 1).
ZerosPolesGain cheby1_zpk(int order, double ripple_db, double wn);

/// Transfer function (b, a), scipy.signal.cheby1(order, ripple_db, wn). Shapes: order + 1.
/// High orders at low cut-offs are badly conditioned in this form: prefer cheby1_sos there.
/// \throws std::invalid_argument as cheby1_zpk.
TransferFunction cheby1(int order, double ripple_db, double wn);

/// Second-order sections, scipy.signal.cheby1(order, ripple_db, wn, output='sos').
/// Shape: ceil(order/2) x 6. \throws std::invalid_argument as cheby1_zpk.
SecondOrderSections cheby1_sos(int order, double ripple_db, double wn);

}  // namespace frictionlab
