#pragma once
// A friction ripple that repeats with position (motor cogging, a screw's pitch, a gear's teeth):
//   r(q) = sum_k a_k sin(2 pi k q / P) + b_k cos(2 pi k q / P),   k = 1..K,
// or, as measured, a table of force against position over one period, periodic and linearly
// interpolated between its rows.
// It adds to the friction force whether the contact slides or sticks: a stuck contact holds while
// -breakaway_negative <= applied - r(q) <= breakaway_positive, so the ripple decides where a
// slowly driven axis stops. The harmonics have no mean (k >= 1), so the ripple stores energy and
// gives it back (the potential U(q) below) instead of dissipating it; a table's mean, if it has
// one, is a constant force on top (conservative too: U grows by mean * q).

#include <algorithm>
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
  /// The ripple as a table instead of harmonics (a and b then empty): positions q_0 < ... < q_n
  /// (m or rad, n >= 1) spanning one period, q_n - q_0 = P, and the forces r_0..r_n (N or N m) at
  /// them, r_n = r_0 (q_n is q_0 a period on). r(q) is periodic and linear between the rows.
  std::vector<double> table_position;
  std::vector<double> table_force;  ///< r at table_position (N or N m)

  /// True when the ripple is given as a table (table_position, table_force).
  bool is_table() const { return !table_position.empty() || !table_force.empty(); }

  /// \throws InputError (code law.parameter, key ripple_period, ripple_a or ripple_b) when P <= 0 or
  ///         not finite, an amplitude is not finite, or b has entries but not as many as a; for a
  ///         table (keys ripple_position, ripple_force, the entry's index in the key): harmonics
  ///         given too, lists of different lengths or fewer than 2 rows, an entry not finite,
  ///         positions not strictly increasing, a span q_n - q_0 other than P (relative 1e-9), or
  ///         r_n != r_0 (relative 1e-9 of the largest |r|).
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
    if (is_table()) {
      validate_table();
      return;
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

  /// Number of harmonics K (0 for a table).
  std::size_t harmonics() const { return std::max(a.size(), b.size()); }

  /// The ripple force r(q) (N or N m) at position q (m or rad).
  double force(double q) const {
    if (is_table()) {
      const Segment s = segment(q);
      return table_force[s.k - 1] + s.t * (table_force[s.k] - table_force[s.k - 1]);
    }
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
    if (is_table()) {  // the segment's slope (at a row: the one after it)
      const std::size_t k = segment(q).k;
      return (table_force[k] - table_force[k - 1]) / (table_position[k] - table_position[k - 1]);
    }
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
    if (is_table()) return table_integral(q) - table_integral(0.0);
    const double w0 = 2.0 * std::numbers::pi / period, w = w0 * q;
    double u = 0.0;
    for (std::size_t k = 0; k < harmonics(); ++k) {
      const double kw0 = static_cast<double>(k + 1) * w0, kw = static_cast<double>(k + 1) * w;
      if (k < a.size()) u += a[k] * (1.0 - std::cos(kw)) / kw0;
      if (k < b.size()) u += b[k] * std::sin(kw) / kw0;
    }
    return u;
  }

  /// Where q falls in the table: its position wrapped into [q_0, q_0 + P) and the row k (1..n)
  /// that ends its segment [q_{k-1}, q_k], t the fraction along it.
  struct Segment {
    std::size_t k;
    double t;
    double x;  ///< q wrapped into [q_0, q_0 + P) (m or rad)
  };
  Segment segment(double q) const {
    const double q0 = table_position.front();
    double u = std::fmod(q - q0, period);
    if (u < 0) u += period;
    const double x = q0 + u;
    const std::size_t n = table_position.size() - 1;
    const auto it = std::upper_bound(table_position.begin(), table_position.end(), x);
    const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - table_position.begin()), 1, n);
    return {k, (x - table_position[k - 1]) / (table_position[k] - table_position[k - 1]), x};
  }

 private:
  // Integral of the table's r from q_0 to q (N m or J): whole periods times the period's integral,
  // plus the trapezoids up to q's wrapped position.
  double table_integral(double q) const {
    double whole = 0.0;
    for (std::size_t k = 1; k < table_position.size(); ++k)
      whole += 0.5 * (table_force[k - 1] + table_force[k]) * (table_position[k] - table_position[k - 1]);
    const Segment s = segment(q);
    const double periods = std::round((q - s.x) / period);
    double part = 0.0;
    for (std::size_t k = 1; k < s.k; ++k)
      part += 0.5 * (table_force[k - 1] + table_force[k]) * (table_position[k] - table_position[k - 1]);
    const double h = s.x - table_position[s.k - 1];
    const double r_at = table_force[s.k - 1] + s.t * (table_force[s.k] - table_force[s.k - 1]);
    part += 0.5 * (table_force[s.k - 1] + r_at) * h;
    return periods * whole + part;
  }

  void validate_table() const {
    auto refuse = [](const std::string& key, const std::string& why, std::string value = {}) {
      throw InputError(errc::law_parameter, key + ": " + why, {.key = key, .value = std::move(value)});
    };
    if (!a.empty() || !b.empty())
      refuse("ripple_position", "give the ripple as harmonics (ripple_a, ripple_b) or as a table (ripple_position, "
                                "ripple_force), not both");
    if (table_position.size() != table_force.size())
      refuse(table_force.empty() ? "ripple_force" : "ripple_position",
             "the table has " + std::to_string(table_position.size()) + " positions and " + std::to_string(table_force.size()) +
                 " forces; give one force (N or N m) per position (m or rad)");
    if (table_position.size() < 2)
      refuse("ripple_position", "a ripple table needs at least 2 rows (the first and the one a period on)");
    for (const auto* list : {&table_position, &table_force})
      for (std::size_t k = 0; k < list->size(); ++k)
        if (!std::isfinite((*list)[k]))
          refuse(std::string(list == &table_position ? "ripple_position" : "ripple_force") + "[" + std::to_string(k) + "]",
                 detail::format_value((*list)[k]) + " must be finite (" + (list == &table_position ? "m or rad" : "N or N m") + ")",
                 detail::format_value((*list)[k]));
    for (std::size_t k = 1; k < table_position.size(); ++k)
      if (!(table_position[k] > table_position[k - 1]))
        refuse("ripple_position[" + std::to_string(k) + "]",
               detail::format_value(table_position[k]) + " must be > ripple_position[" + std::to_string(k - 1) +
                   "] = " + detail::format_value(table_position[k - 1]) + " (strictly increasing, m or rad)",
               detail::format_value(table_position[k]));
    constexpr double kSpanTolerance = 1e-9;  // relative: rounding in positions written as decimals
    const double span = table_position.back() - table_position.front();
    if (!(std::abs(span - period) <= kSpanTolerance * period))
      refuse("ripple_position",
             "the table spans " + detail::format_value(span) + " (last - first position), not one period ripple_period = " +
                 detail::format_value(period) + " (m or rad): its last row is the first one a period on",
             detail::format_value(span));
    double largest = 0.0;
    for (double f : table_force) largest = std::max(largest, std::abs(f));
    if (!(std::abs(table_force.back() - table_force.front()) <= kSpanTolerance * largest))
      refuse("ripple_force[" + std::to_string(table_force.size() - 1) + "]",
             detail::format_value(table_force.back()) + " must equal ripple_force[0] = " +
                 detail::format_value(table_force.front()) + " (N or N m): the last row is the first one a period on",
             detail::format_value(table_force.back()));
  }
};

}  // namespace frictionlab
