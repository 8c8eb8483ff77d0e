#pragma once
// The band region shared by the feedforward and feedback compensations: which side of [-b, b] a
// velocity is on, how a located crossing of one of the band's edges changes it, and when the
// stored region is trusted.

#include <cmath>

namespace frictionlab::detail {

/// How far (a fraction of b) past an edge the stored region still holds: far above a root
/// finder's tolerance, so an integrator's trial step beyond an edge keeps the region's smooth
/// formula until the event is located; far below the band, so a region that does not fit the
/// velocity (a run started without its inputs, an event that was never reported) is not used.
inline constexpr double kEdgeFraction = 0.01;

/// -1 below -b, +1 above b, 0 inside (the edges belong to the inside). As a double: it is stored in
/// the compensator's state vector.
inline double band_region(double s, double b) { return s > b ? 1.0 : (s < -b ? -1.0 : 0.0); }

/// The stored region `mode` while s lies in it (its interval widened by kEdgeFraction b at each
/// edge), else the region of s itself.
inline double band_region_held(double mode, double s, double b) {
  const double m = kEdgeFraction * b;
  const bool fits = (mode == 1.0 && s >= b - m) || (mode == -1.0 && s <= -b + m) ||
                    (mode == 0.0 && std::abs(s) <= b + m);
  return fits ? mode : band_region(s, b);
}

/// The region after the located sign change of edge k (0: s - b, 1: s + b) from region `mode`;
/// `ds` is the sign of ds/dt when known (the reference's acceleration), else 0.
/// At the root s sits on the edge (to the root finder's tolerance), where band_region cannot tell
/// the side: the region goes to the side ds points to, or, without it, crosses the edge. When s is
/// clearly off that edge (two edges crossed at once by a jump of the reference's rate, or a
/// repeated report), the region is read from s itself.
inline double band_region_after(double mode, double s, double b, int k, double ds = 0.0) {
  const double edge = k == 0 ? b : -b;
  if (std::abs(s - edge) > kEdgeFraction * b) return band_region(s, b);
  const double above = k == 0 ? 1.0 : 0.0, below = k == 0 ? 0.0 : -1.0;  // the regions either side
  if (ds > 0) return above;
  if (ds < 0) return below;
  if (mode == above) return below;
  if (mode == below) return above;
  return band_region(s, b);
}

}  // namespace frictionlab::detail
