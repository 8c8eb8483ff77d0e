#pragma once
// Generalized Maxwell-Slip friction (Al-Bender, Lampaert, Swevers 2005): N elastoplastic
// elements in parallel, element i with stiffness k_i and slip level alpha_i s(v), where
// s(v) = Fc + (Fs - Fc) exp(-|v/vs|^delta) is the Stribeck level and sum(alpha) = 1.
//   element sticks (|F_i| < alpha_i s(v), or F_i opposes v):  dF_i/dt = k_i v
//   element slips  (F_i with v, |F_i| >= alpha_i s(v)):        dF_i/dt = sign(v) C (alpha_i - |F_i| / s(v))
//   F = sum F_i + sigma2 v,   with F_i = k_i z_i (state z_i in m or rad).
// Its hysteresis has non-local memory: a minor loop closes where it started.

#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/models/parameter.hpp"
#include "frictionlab/models/scalar.hpp"
#include "frictionlab/models/stribeck.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

template <class S = double>
struct GmsT {
  std::vector<S> k{S(1e5), S(5e4), S(2e4)};  ///< element stiffnesses (N/m or N m/rad), each > 0
  std::vector<S> alpha{S(0.5), S(0.3), S(0.2)};  ///< element fractions of s(v), each > 0, sum 1
  S Fc{1.0};       ///< Coulomb level (N or N m), > 0
  S Fs{1.5};       ///< static level (N or N m), >= Fc
  S vs{0.001};     ///< Stribeck velocity (m/s or rad/s), > 0
  S delta{2.0};    ///< Stribeck exponent, > 0
  S C{20.0};       ///< attraction rate of a slipping element toward its level (N/s or N m/s), > 0
  S sigma2{0.4};   ///< viscous coefficient (N s/m or N m s/rad), >= 0

  static constexpr std::string_view kName = "gms";

  /// Scalar parameters only; the element arrays `k` and `alpha` are set directly.
  template <class Self, class Visit>
  static void visit(Self& self, Visit&& visit) {
    visit("Fc", Quantity::force, self.Fc);
    visit("Fs", Quantity::force, self.Fs);
    visit("vs", Quantity::velocity, self.vs);
    visit("delta", Quantity::dimensionless, self.delta);
    visit("C", Quantity::force_rate, self.C);
    visit("sigma2", Quantity::viscous, self.sigma2);
  }

  /// Throws std::invalid_argument naming the first parameter that breaks its rule.
  void validate() const {
    if (k.empty() || k.size() != alpha.size())
      throw std::invalid_argument("gms: k has " + std::to_string(k.size()) + " elements and alpha " +
                                  std::to_string(alpha.size()) + "; they must be equal and at least 1");
    double sum = 0;
    for (std::size_t i = 0; i < k.size(); ++i) {
      detail::require(std::isfinite(k[i]) && k[i] > 0, kName, "k[" + std::to_string(i) + "]", k[i], "> 0 (N/m or N m/rad)");
      detail::require(std::isfinite(alpha[i]) && alpha[i] > 0, kName, "alpha[" + std::to_string(i) + "]", alpha[i], "> 0");
      sum += alpha[i];
    }
    detail::require(std::abs(sum - 1.0) <= 1e-9, kName, "sum(alpha)", sum, "1 (the elements share the Stribeck level)");
    detail::validate_stribeck_level(kName, Fc, Fs, vs, delta, true);
    detail::require(std::isfinite(C) && C > 0, kName, "C", C, "> 0 (N/s or N m/s)");
    detail::require(std::isfinite(sigma2) && sigma2 >= 0, kName, "sigma2", sigma2, ">= 0 (N s/m or N m s/rad)");
  }

  int num_states() const { return static_cast<int>(k.size()); }

  template <class T>
  T level(const T& v) const {
    return StribeckT<S>{Fc, Fs, vs, delta, S(0)}.level(v);
  }

  template <class T>
  void derivative(std::span<const T> z, const T& v, std::span<T> dz) const {
    using std::abs;
    const T s = level(v);
    for (std::size_t i = 0; i < k.size(); ++i) {
      const T Fi = T(k[i]) * z[i];
      const bool with_motion = value_of(Fi) * value_of(v) > 0;
      if (with_motion && value_of(abs(Fi)) >= value_of(T(alpha[i]) * s)) {
        dz[i] = sgn(v) * T(C) * (T(alpha[i]) - abs(Fi) / s) / T(k[i]);
      } else {
        dz[i] = v;
      }
    }
  }

  template <class T>
  T force(std::span<const T> z, const T& v) const {
    T f = T(sigma2) * v;
    for (std::size_t i = 0; i < k.size(); ++i) f += T(k[i]) * z[i];
    return f;
  }

  /// Update over dt at constant v: each element moves with v, is clamped at its slip level
  /// when it reaches it (the stick-slip switch), and an element above its level (s fell as |v|
  /// rose) relaxes exactly as exp(-C dt / s). Stable for any dt; no allocation.
  double step(std::span<double> z, double v, double dt) const {
    if (dt > 0 && v != 0.0) {
      const double s = level(v);
      const double sign = v > 0 ? 1.0 : -1.0;
      const double decay = std::exp(-C * dt / s);
      for (std::size_t i = 0; i < k.size(); ++i) {
        const double bound = alpha[i] * s / k[i];  // slip deflection (m or rad)
        const double w = z[i] * sign;               // deflection along the motion
        double w1;
        if (w > bound) {
          w1 = bound + (w - bound) * decay;
        } else {
          w1 = std::min(w + std::abs(v) * dt, bound);
        }
        z[i] = w1 * sign;
      }
    }
    return force(std::span<const double>(z.data(), z.size()), v);
  }

  void steady_state(double v, std::span<double> z) const {
    const double s = level(v);
    for (std::size_t i = 0; i < k.size(); ++i) z[i] = sgn(v) * alpha[i] * s / k[i];
  }
};
using Gms = GmsT<double>;

}  // namespace frictionlab
