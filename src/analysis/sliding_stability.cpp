#include "frictionlab/analysis/sliding_stability.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "frictionlab/format.hpp"

namespace frictionlab {

double stribeck_slope(const Stribeck& law, double v) {
  law.validate();
  if (!std::isfinite(v) || v == 0.0)
    throw std::invalid_argument("stribeck_slope: v = " + format_number(v) + " must be finite and != 0 (m/s)");
  const double a = std::abs(v) / law.vs;
  const double decay = std::exp(-std::pow(a, law.delta));
  return law.Fv - (law.Fs - law.Fc) * law.delta * std::pow(a, law.delta - 1.0) / law.vs * decay;
}

double sliding_damping_margin(const Stribeck& law, double c, double V0) {
  if (!std::isfinite(c) || c < 0)
    throw std::invalid_argument("sliding stability: c = " + format_number(c) + " must be >= 0 (N s/m)");
  if (!std::isfinite(V0) || V0 == 0.0)
    throw std::invalid_argument("sliding stability: V0 = " + format_number(V0) +
                                " must be finite and != 0 (m/s): steady sliding needs a moving drive");
  return c + stribeck_slope(law, V0);
}

std::vector<double> critical_drive_speeds(const Stribeck& law, double c, double v_min, double v_max) {
  if (!(std::isfinite(v_min) && v_min > 0))
    throw std::invalid_argument("critical_drive_speeds: v_min = " + format_number(v_min) + " must be > 0 (m/s)");
  if (!(std::isfinite(v_max) && v_max > v_min))
    throw std::invalid_argument("critical_drive_speeds: v_max = " + format_number(v_max) + " must be > v_min = " +
                                format_number(v_min) + " (m/s)");
  constexpr int kScan = 2000;        // samples per scan: resolves the Stribeck dip over 10 decades
  constexpr double kRelTol = 1e-10;  // bisection stops at this relative width
  std::vector<double> roots;
  const double ratio = std::log(v_max / v_min) / (kScan - 1);
  double a = v_min, fa = sliding_damping_margin(law, c, a);
  for (int i = 1; i < kScan; ++i) {
    const double b = i == kScan - 1 ? v_max : v_min * std::exp(ratio * i);
    const double fb = sliding_damping_margin(law, c, b);
    if ((fa < 0) != (fb < 0)) {
      double lo = a, hi = b, flo = fa;
      while (hi - lo > kRelTol * hi) {
        const double mid = 0.5 * (lo + hi), fm = sliding_damping_margin(law, c, mid);
        if ((fm < 0) == (flo < 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

}  // namespace frictionlab
