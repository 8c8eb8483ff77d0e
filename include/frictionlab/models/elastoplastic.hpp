#pragma once
// Elasto-plastic friction (Dupont, Hayward, Armstrong, Altpeter 2002): LuGre with a purely
// elastic zone |z| <= zba, so that small oscillating forces cause no drift.
//   dz/dt = v (1 - a(z, v) z / zss(v)),   zss(v) = sign(v) g(v) / sigma0,   F = sigma0 z + sigma1 dz/dt + sigma2 v
//   a = 0 for |z| <= zba or sign(z) != sign(v); 1 for |z| >= zmax = g(v)/sigma0;
//   a = (1 + sin(pi (|z| - (zmax + zba)/2) / (zmax - zba))) / 2 in between.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <string_view>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/stribeck.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

template <class S = double>
struct ElastoPlasticT {
  S sigma0{1e5};                 ///< bristle stiffness (N/m or N m/rad), > 0
  S sigma1{316.22776601683796};  ///< bristle damping (N s/m or N m s/rad), >= 0
  S sigma2{0.4};                 ///< viscous coefficient (N s/m or N m s/rad), >= 0
  S Fc{1.0};                     ///< Coulomb level (N or N m), > 0
  S Fs{1.5};                     ///< static level (N or N m), >= Fc
  S vs{0.001};                   ///< Stribeck velocity (m/s or rad/s), > 0
  S delta{2.0};                  ///< Stribeck exponent, > 0
  S zba{5e-6};                   ///< breakaway (elastic) deflection (m or rad), 0 < zba < Fc/sigma0

  static constexpr std::string_view kName = "elastoplastic";

  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("sigma0", Quantity::stiffness, self.sigma0);
    visit("sigma1", Quantity::viscous, self.sigma1);
    visit("sigma2", Quantity::viscous, self.sigma2);
    visit("Fc", Quantity::force, self.Fc);
    visit("Fs", Quantity::force, self.Fs);
    visit("vs", Quantity::velocity, self.vs);
    visit("delta", Quantity::dimensionless, self.delta);
    visit("zba", Quantity::displacement, self.zba);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    detail::require(std::isfinite(sigma0) && sigma0 > 0, kName, "sigma0", sigma0, "> 0 (N/m or N m/rad)");
    detail::require(std::isfinite(sigma1) && sigma1 >= 0, kName, "sigma1", sigma1, ">= 0 (N s/m or N m s/rad)");
    detail::require(std::isfinite(sigma2) && sigma2 >= 0, kName, "sigma2", sigma2, ">= 0 (N s/m or N m s/rad)");
    detail::validate_stribeck_level(kName, Fc, Fs, vs, delta, true);
    detail::require(std::isfinite(zba) && zba > 0 && zba < Fc / sigma0, kName, "zba", zba,
                    "> 0 and < Fc / sigma0 = " + detail::format_value(Fc / sigma0) + " (m or rad)");
  }

  int num_states() const { return 1; }

  template <class T>
  T level(const T& v) const {
    return StribeckT<S>{Fc, Fs, vs, delta, S(0)}.level(v);
  }

  /// The plasticity weight a(z, v) in [0, 1].
  template <class T>
  T weight(const T& z, const T& v) const {
    using std::abs;
    using std::sin;
    if (value_of(z) * value_of(v) <= 0.0) return T(0);
    const T az = abs(z);
    const T zmax = level(v) / T(sigma0);
    if (value_of(az) <= value_of(zba)) return T(0);
    if (value_of(az) >= value_of(zmax)) return T(1);
    return T(0.5) * sin(T(std::numbers::pi) * (az - (zmax + T(zba)) / T(2)) / (zmax - T(zba))) + T(0.5);
  }

  /// dz/dt = v - a(z, v) sigma0 |v| z / g(v) (m/s or rad/s): z relaxes toward g(v) sign(v) / sigma0.
  template <class T>
  T state_derivative(const T& z, const T& v) const {
    using std::abs;
    return v - weight(z, v) * T(sigma0) * abs(v) * z / level(v);
  }
  template <class T>
  T force(const T& z, const T& v) const {
    return T(sigma0) * z + T(sigma1) * state_derivative(z, v) + T(sigma2) * v;
  }
  template <class T>
  void derivative(std::span<const T> z, const T& v, std::span<T> dz) const {
    dz[0] = state_derivative(z[0], v);
  }
  template <class T>
  T force(std::span<const T> z, const T& v) const {
    return force(z[0], v);
  }

  /// Update over dt at constant v, in the travelled distance x = |v| dt and the deflection
  /// w = z sign(v) along the motion: exact in the elastic zone and above zmax, one implicit
  /// Euler step (solved by safeguarded Newton) in the transition zone. Never overshoots zmax,
  /// so it is stable for any dt. Returns the force at the end of the step.
  double step(std::span<double> z, double v, double dt) const {
    if (v == 0.0 || dt <= 0.0) return force(z[0], v);
    const double s = v > 0 ? 1.0 : -1.0;
    double x = std::abs(v) * dt;
    double w = z[0] * s;
    const double zmax = level(v) / sigma0;
    if (w > zmax) {  // above the bound (g fell as |v| rose): exact relaxation dw/dx = 1 - w/zmax
      w = zmax + (w - zmax) * std::exp(-x / zmax);
    } else {
      const double elastic = std::min(x, std::max(0.0, zba - w));  // a = 0 below zba
      w += elastic;
      x -= elastic;
      if (x > 0) w = implicit_transition(w, x, zmax);
    }
    z[0] = w * s;
    return force(z[0], v);
  }

  void steady_state(double v, std::span<double> z) const { z[0] = sgn(v) * level(v) / sigma0; }

 private:
  // Solves w1 = w + h (1 - a(w1) w1 / zmax) for w1 in [w, zmax] by Newton's method kept inside
  // a bracket. phi(y) = y - w - h (1 - a(y) y / zmax) is increasing there (a, a' >= 0), with
  // phi'(y) = 1 + h (a'(y) y + a(y)) / zmax; a rises as half a sine from zba to zmax.
  double implicit_transition(double w, double h, double zmax) const {
    const double k = std::numbers::pi / (zmax - zba), mid = (zmax + zba) / 2;
    const auto phi_and_slope = [&](double y, double& slope) {
      double a = y >= zmax ? 1.0 : 0.0, da = 0.0;
      if (y > zba && y < zmax) {
        a = 0.5 * std::sin(k * (y - mid)) + 0.5;
        da = 0.5 * k * std::cos(k * (y - mid));
      }
      slope = 1.0 + h * (da * y + a) / zmax;
      return y - w - h * (1.0 - a * y / zmax);
    };
    double slope = 0.0;
    double lo = w, hi = zmax;
    if (phi_and_slope(lo, slope) >= 0) return lo;
    double y = std::min(w + h, zmax);
    constexpr int kMaxIterations = 60;      // bisection alone would need ~50 at double precision
    constexpr double kStepTolerance = 1e-14;  // relative to zmax: a few ulps of the state
    for (int it = 0; it < kMaxIterations && hi - lo > 1e-15 * zmax; ++it) {
      const double f = phi_and_slope(y, slope);
      (f > 0 ? hi : lo) = y;
      const double newton = y - f / slope;
      // A Newton step below the tolerance ends the search, checked before the bracket: at the
      // root that step is rounding-sized and may land on the bracket's end, where a bisection
      // would otherwise take over and halve its way down for another 40 iterations.
      if (std::abs(newton - y) < kStepTolerance * zmax) return std::clamp(newton, lo, hi);
      y = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    }
    return y;
  }
};
using ElastoPlastic = ElastoPlasticT<double>;

}  // namespace frictionlab
