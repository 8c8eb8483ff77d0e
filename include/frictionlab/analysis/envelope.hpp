#pragma once
// Decay envelope of a free oscillation (Craig's pendulum cases): the amplitude of each half
// cycle, and which law it decays by. Coulomb friction takes a constant amount off every half
// cycle (linear envelope), viscous friction a constant fraction (exponential envelope), both
// together give a mixed envelope.

#include <span>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How the envelope decays.
enum class DecayKind {
  none,         ///< the amplitude stays (frictionless)
  linear,       ///< A(t) = A0 - r t          (Coulomb)
  exponential,  ///< A(t) = A0 exp(-lambda t) (viscous)
  mixed,        ///< A(t) = (A0 + c) exp(-lambda t) - c (viscous + Coulomb)
};

/// Name as printed and in JSON ("none", "linear", "exponential", "mixed").
const char* decay_kind_name(DecayKind kind);

/// Options of decay_envelope.
struct EnvelopeOptions {
  /// Relative amplitude loss over the record below which the kind is `none`. Default 0.02:
  /// a frictionless simulation loses nothing; measured data may need more.
  double none_tolerance = 0.02;
  /// The mixed model is chosen only if its relative rms error is below this fraction of the best
  /// two-parameter model's (linear or exponential). Default 0.5: a third parameter always fits a
  /// little better, so it must fit much better to count.
  double mixed_gain = 0.5;
  /// A two-parameter model (linear or exponential) whose relative rms error is below this is
  /// kept even if the mixed model fits better. Default 0.01: a large pendulum swing (sin th, not
  /// th) bends a Coulomb envelope by about 0.2 %, which must not read as viscous friction.
  double fit_tolerance = 0.01;
  /// Half swings smaller than this fraction of the largest are ignored (noise, the last creep).
  /// Default 1e-3.
  double min_relative_amplitude = 1e-3;
};

/// One fitted envelope model: A(t) = p exp(-lambda t) + q (linear: q + slope t).
struct EnvelopeFit {
  double lambda = 0.0;  ///< decay rate (1/s); 0 for the linear model
  double p = 0.0;       ///< amplitude unit
  double q = 0.0;       ///< amplitude unit (linear: intercept)
  double slope = 0.0;   ///< linear model only: amplitude unit per s (negative when decaying)
  double relative_rms = 0.0;  ///< rms residual / mean amplitude
};

/// Result of decay_envelope.
struct EnvelopeResult {
  std::vector<double> peak_times;  ///< time of each extreme after the first (s)
  std::vector<double> amplitudes;  ///< half swing between consecutive extremes, |x_k - x_{k-1}| / 2 (position unit)
  double half_period = 0.0;        ///< mean time between extremes (s)
  DecayKind kind = DecayKind::none;
  EnvelopeFit linear, exponential, mixed;
  /// Linear: amplitude lost per half cycle (position unit) = -slope * half_period.
  double decrement_per_half_cycle = 0.0;
  /// Exponential: logarithmic decrement per full cycle = lambda * 2 half_period.
  double log_decrement = 0.0;
  double decay_fraction = 0.0;     ///< 1 - last amplitude / first amplitude
};

/// Envelope of the free oscillation x(t).
/// \param t  sample times (s), strictly increasing; \param x  position (m or rad), same length.
/// Extremes are where the slope of x changes sign (refined by a parabola through 3 samples), plus
/// the start of a final rest (the body stuck), plus the first sample when the record starts at
/// rest (released from a deflection). Half swings between consecutive extremes are the
/// amplitudes (independent of where the oscillation is centred).
/// \throws std::invalid_argument when lengths differ, fewer than 3 samples, or fewer than 4
///         extremes are found (names how many and what is needed).
EnvelopeResult decay_envelope(std::span<const double> t, std::span<const double> x, const EnvelopeOptions& options = {});

}  // namespace frictionlab
