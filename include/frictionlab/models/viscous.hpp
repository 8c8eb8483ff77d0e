#pragma once
// Viscous friction: proportional to velocity, F = Fv v. No stiction.

#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Linear viscous friction F = Fv v. A stuck contact holds no force.
template <class S = double>
struct ViscousT {
  S Fv{0.1};  ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.1.

  static constexpr std::string_view kName = "viscous";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fv", Quantity::viscous, self.Fv);
  }

  /// Throws std::invalid_argument when Fv < 0 or not finite.
  void validate() const { detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)"); }

  template <class T>
  T sliding(const T& v) const {
    return T(Fv) * v;
  }
  S breakaway_positive() const { return S(0); }
  S breakaway_negative() const { return S(0); }
};
using Viscous = ViscousT<double>;

}  // namespace frictionlab
