#pragma once
// Stribeck friction with a free exponent:
//   F(v) = sign(v) (Fc + (Fs - Fc) exp(-|v/vs|^delta)) + Fv v.

#include <cmath>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

namespace detail FRICTIONLAB_NO_EXPORT {
/// The rules of a Stribeck level Fc + (Fs - Fc) exp(-|v/vs|^delta), shared by every law built on
/// it (stribeck, smooth, lugre, elasto-plastic, gms): Fc >= 0 (> 0 when `Fc_positive`, as the
/// bristle laws divide by it), Fs >= Fc, vs > 0, delta > 0, all finite.
/// \throws std::invalid_argument naming `law`, the first parameter that breaks its rule and the rule.
inline void validate_stribeck_level(std::string_view law, double Fc, double Fs, double vs, double delta,
                                    bool Fc_positive = false) {
  require(std::isfinite(Fc) && (Fc_positive ? Fc > 0 : Fc >= 0), law, "Fc", Fc, Fc_positive ? "> 0 (N or N m)" : ">= 0 (N or N m)");
  require(std::isfinite(Fs) && Fs >= Fc, law, "Fs", Fs, ">= Fc = " + format_value(Fc) + " (N or N m)");
  require(std::isfinite(vs) && vs > 0, law, "vs", vs, "> 0 (m/s or rad/s)");
  require(std::isfinite(delta) && delta > 0, law, "delta", delta, "> 0");
}
}  // namespace detail

/// Stribeck curve: F falls from Fs at rest to Fc over about vs, plus viscous Fv v.
/// A stuck contact holds up to Fs. delta = 2 is the usual (Gaussian) shape, 1 the exponential one.
template <class S = double>
struct StribeckT {
  S Fc{1.0};     ///< Coulomb level (N or N m), >= 0. Default 1.
  S Fs{1.5};     ///< static level (N or N m), >= Fc. Default 1.5.
  S vs{0.001};   ///< Stribeck velocity (m/s or rad/s), > 0. Default 0.001.
  S delta{2.0};  ///< Stribeck exponent (dimensionless), > 0. Default 2.
  S Fv{0.4};     ///< viscous coefficient (N s/m or N m s/rad), >= 0. Default 0.4.

  static constexpr std::string_view kName = "stribeck";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fc", Quantity::force, self.Fc);
    visit("Fs", Quantity::force, self.Fs);
    visit("vs", Quantity::velocity, self.vs);
    visit("delta", Quantity::dimensionless, self.delta);
    visit("Fv", Quantity::viscous, self.Fv);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule
  /// (Fc >= 0, Fs >= Fc, vs > 0, delta > 0, Fv >= 0, all finite).
  void validate() const {
    detail::validate_stribeck_level(kName, Fc, Fs, vs, delta);
    detail::require(std::isfinite(Fv) && Fv >= 0, kName, "Fv", Fv, ">= 0 (N s/m or N m s/rad)");
  }

  /// The Stribeck level g(v) = Fc + (Fs - Fc) exp(-|v/vs|^delta) (N or N m), without sign or viscous part.
  template <class T>
  T level(const T& v) const {
    using std::exp;
    return T(Fc) + (T(Fs) - T(Fc)) * stribeck_decay(v, vs, delta);
  }

  template <class T>
  T sliding(const T& v) const {
    return sgn(v) * level(v) + T(Fv) * v;
  }
  S breakaway_positive() const { return Fs; }
  S breakaway_negative() const { return Fs; }
};
using Stribeck = StribeckT<double>;

}  // namespace frictionlab
