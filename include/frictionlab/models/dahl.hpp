#pragma once
// Dahl friction (Dahl 1968): a rate-independent hysteresis,
//   dz/dt = v |1 - sigma0 z sign(v) / Fc|^alpha  (with the sign of the bracket),   F = sigma0 z.

#include <cmath>
#include <span>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Dahl model: stiffness sigma0 at rest, saturating at Fc while sliding. No stiction peak.
template <class S = double>
struct DahlT {
  S sigma0{1e5};  ///< rest stiffness (N/m or N m/rad), > 0. Default 1e5.
  S Fc{1.0};      ///< Coulomb level reached while sliding (N or N m), > 0. Default 1.
  S alpha{1.0};   ///< shape exponent, > 0 (1 = exponential approach). Default 1.

  static constexpr std::string_view kName = "dahl";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("sigma0", Quantity::stiffness, self.sigma0);
    visit("Fc", Quantity::force, self.Fc);
    visit("alpha", Quantity::dimensionless, self.alpha);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    detail::require(std::isfinite(sigma0) && sigma0 > 0, kName, "sigma0", sigma0, "> 0 (N/m or N m/rad)");
    detail::require(std::isfinite(Fc) && Fc > 0, kName, "Fc", Fc, "> 0 (N or N m)");
    detail::require(std::isfinite(alpha) && alpha > 0, kName, "alpha", alpha, "> 0");
  }

  int num_states() const { return 1; }

  template <class T>
  T state_derivative(const T& z, const T& v) const {
    using std::abs;
    using std::pow;
    const T u = T(1) - T(sigma0) * z * sgn(v) / T(Fc);
    if (value_of(u) == 0.0) return T(0);
    return v * sgn(u) * pow(abs(u), T(alpha));
  }
  template <class T>
  T force(const T& z, const T& /*v*/) const {
    return T(sigma0) * z;
  }
  template <class T>
  void derivative(std::span<const T> z, const T& v, std::span<T> dz) const {
    dz[0] = state_derivative(z[0], v);
  }
  template <class T>
  T force(std::span<const T> z, const T& v) const {
    return force(z[0], v);
  }

  /// Exact update: Dahl is rate independent, so it is integrated in the travelled distance
  /// |v| dt in closed form (u = 1 - sigma0 z sign(v)/Fc obeys du/dx = -(sigma0/Fc) |u|^alpha sign(u)).
  double step(std::span<double> z, double v, double dt) const {
    if (v == 0.0 || dt <= 0.0) return force(z[0], v);
    const double s = v > 0 ? 1.0 : -1.0;
    const double dx = std::abs(v) * dt;
    const double k = sigma0 / Fc;
    const double u0 = 1.0 - k * z[0] * s;
    const double a = std::abs(u0);
    double b;  // |u| after the step
    if (alpha == 1.0) {
      b = a * std::exp(-k * dx);
    } else {
      const double w = std::pow(a, 1.0 - alpha) + (alpha - 1.0) * k * dx;
      b = (alpha < 1.0 && w <= 0.0) ? 0.0 : std::pow(w, 1.0 / (1.0 - alpha));
      if (alpha > 1.0 && a == 0.0) b = 0.0;
    }
    const double u = u0 < 0 ? -b : b;
    z[0] = (1.0 - u) * s / k;
    return force(z[0], v);
  }

  /// Steady state at constant v: z = Fc sign(v) / sigma0.
  void steady_state(double v, std::span<double> z) const { z[0] = sgn(v) * Fc / sigma0; }
};
using Dahl = DahlT<double>;

}  // namespace frictionlab
