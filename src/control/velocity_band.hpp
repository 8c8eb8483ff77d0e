#pragma once
// The band region shared by the feedforward and feedback compensations: which side of [-b, b] a
// velocity is on, and how a located crossing of one of the band's edges changes it.

#include <cmath>

namespace frictionlab::detail {

/// -1 below -b, +1 above b, 0 inside (the edges belong to the inside). As a double: it is stored in
/// the compensator's state vector.
inline double band_region(double s, double b) { return s > b ? 1.0 : (s < -b ? -1.0 : 0.0); }

/// The region after the located sign change of edge k (0: s - b, 1: s + b) from region `mode`.
/// At the root s sits on the edge (to the root finder's tolerance), where band_region cannot tell
/// the side: the region crosses the edge. When s is clearly off that edge (more than 1 % of b: two
/// edges crossed at once by a jump of the reference's rate, or a repeated report), the region is
/// read from s itself.
inline double band_region_after(double mode, double s, double b, int k) {
  constexpr double kEdgeFraction = 0.01;  // far above a root finder's tolerance, far below the band
  const double edge = k == 0 ? b : -b;
  if (std::abs(s - edge) > kEdgeFraction * b) return band_region(s, b);
  if (k == 0) {
    if (mode == 1.0) return 0.0;
    if (mode == 0.0) return 1.0;
  } else {
    if (mode == -1.0) return 0.0;
    if (mode == 0.0) return -1.0;
  }
  return band_region(s, b);
}

}  // namespace frictionlab::detail
