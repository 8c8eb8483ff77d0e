#pragma once
// A friction ripple that repeats with position (motor cogging, a screw's pitch, a gear's teeth):
//   r(q) = sum_k a_k sin(2 pi k q / P) + b_k cos(2 pi k q / P),   k = 1..K.
// It adds to the friction force whether the contact slides or sticks: a stuck contact holds while
// -breakaway_negative <= applied - r(q) <= breakaway_positive, so the ripple decides where a
// slowly driven axis stops. It has no mean (k >= 1), so it stores energy and gives it back (the
// potential U(q) below) instead of dissipating it.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct PositionRipple {
  double period = 1.0;        ///< P (m or rad), > 0: the position over which the ripple repeats
  std::vector<double> a;      ///< sine amplitudes a_1..a_K (N or N m)
  std::vector<double> b;      ///< cosine amplitudes b_1..b_K (N or N m); as many as a (or empty = 0)

  /// \throws InputError (code law.parameter, key ripple_period, ripple_a or ripple_b) when P <= 0 or
  ///         not finite, an amplitude is not finite, or b has entries but not as many as a.
  void validate() const {
    if (!(std::isfinite(period) && period > 0))
      throw InputError(errc::law_parameter, "ripple_period = " + detail::format_value(period) + " must be > 0 (m or rad)",
                       {.key = "ripple_period", .value = detail::format_value(period)});
    for (const auto* list : {&a, &b})
      for (std::size_t k = 0; k < list->size(); ++k)
        if (!std::isfinite((*list)[k])) {
          const std::string key = std::string(list == &a ? "ripple_a" : "ripple_b") + "[" + std::to_string(k) + "]";
          throw InputError(errc::law_parameter, key + " = " + detail::format_value((*list)[k]) + " must be finite (N or N m)",
                           {.key = key, .value = detail::format_value((*list)[k])});
        }
    if (a.empty() && b.empty())
      throw InputError(errc::law_parameter, "ripple_a: a ripple needs at least one harmonic (ripple_a or ripple_b, N or N m)",
                       {.key = "ripple_a"});
    if (!a.empty() && !b.empty() && a.size() != b.size())
      throw InputError(errc::law_parameter,
                       "ripple_b has " + std::to_string(b.size()) + " amplitudes and ripple_a " + std::to_string(a.size()) +
                           "; give one of each per harmonic (or leave one list out: zeros)",
                       {.key = "ripple_b"});
  }

  /// Number of harmonics K.
  std::size_t harmonics() const { return std::max(a.size(), b.size()); }

  /// The ripple force r(q) (N or N m) at position q (m or rad).
  double force(double q) const {
    const double w = 2.0 * std::numbers::pi * q / period;
    double r = 0.0;
    for (std::size_t k = 0; k < harmonics(); ++k) {
      const double kw = static_cast<double>(k + 1) * w;
      if (k < a.size()) r += a[k] * std::sin(kw);
      if (k < b.size()) r += b[k] * std::cos(kw);
    }
    return r;
  }

  /// dr/dq (N/m or N m/rad) at q.
  double slope(double q) const {
    const double w0 = 2.0 * std::numbers::pi / period, w = w0 * q;
    double d = 0.0;
    for (std::size_t k = 0; k < harmonics(); ++k) {
      const double kk = static_cast<double>(k + 1);
      if (k < a.size()) d += a[k] * kk * w0 * std::cos(kk * w);
      if (k < b.size()) d -= b[k] * kk * w0 * std::sin(kk * w);
    }
    return d;
  }

  /// The potential U(q) = integral of r from 0 to q (J): the work the ripple takes from the body
  /// between 0 and q (energy balances: input work = kinetic energy + dissipated friction + U).
  double potential(double q) const {
    const double w0 = 2.0 * std::numbers::pi / period, w = w0 * q;
    double u = 0.0;
    for (std::size_t k = 0; k < harmonics(); ++k) {
      const double kw0 = static_cast<double>(k + 1) * w0, kw = static_cast<double>(k + 1) * w;
      if (k < a.size()) u += a[k] * (1.0 - std::cos(kw)) / kw0;
      if (k < b.size()) u += b[k] * std::sin(kw) / kw0;
    }
    return u;
  }
};

}  // namespace frictionlab
