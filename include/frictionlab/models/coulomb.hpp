#pragma once
// Coulomb friction: a constant level opposing motion, F = Fc sign(v).

#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Coulomb (kinetic) friction F = Fc sign(v). A stuck contact holds up to Fc.
template <class S = double>
struct CoulombT {
  S Fc{1.0};  ///< Coulomb level (N or N m), >= 0. Default 1.

  static constexpr std::string_view kName = "coulomb";

  /// Calls visit(name, quantity, value&) for each parameter, in a fixed order.
  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fc", Quantity::force, self.Fc);
  }

  /// Throws std::invalid_argument when Fc < 0 or not finite.
  void validate() const { detail::require(std::isfinite(Fc) && Fc >= 0, kName, "Fc", Fc, ">= 0 (N or N m)"); }

  /// Force for v != 0 (N or N m); v in m/s or rad/s.
  template <class T>
  T sliding(const T& v) const {
    return T(Fc) * sgn(v);
  }
  S breakaway_positive() const { return Fc; }
  S breakaway_negative() const { return Fc; }
};
using Coulomb = CoulombT<double>;

}  // namespace frictionlab
