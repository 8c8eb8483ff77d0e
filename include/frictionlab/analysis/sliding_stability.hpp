#pragma once
// Linearised stability of steady sliding on a Stribeck law: the spring-block (stick-slip rig)
//   m x'' + c (x' - V0) + k (x - x0 - V0 t) + F(x') = 0
// slides steadily at x' = V0 with a constant spring force; a small perturbation obeys
//   m d'' + (c + F'(V0)) d' + k d = 0,
// which decays when the effective damping c + F'(V0) > 0 and grows (towards stick-slip) when it
// is < 0, whatever m > 0 and k > 0 (they set the frequency sqrt(k / m), not the sign). F'(V0), the
// slope of the friction-velocity curve at the drive speed, is negative on the falling (Stribeck)
// part of the curve: that negative slope against the viscous damping (c and the law's Fv) is the
// stick-slip boundary. The criterion is local: a start from rest (stuck) may still fall into
// stick-slip just on the stable side (the limit cycle and steady sliding coexist there), so maps
// agree with it well inside each side, not at the line itself.

#include <vector>

#include "frictionlab/models/stribeck.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Slope dF/dv of the Stribeck law's sliding force at velocity v (N s/m or N m s/rad):
/// Fv - (Fs - Fc) delta |v|^(delta-1) / vs^delta exp(-|v/vs|^delta) for v != 0 (even in v).
/// \throws std::invalid_argument when v == 0 or not finite (the slope at rest is not defined
///         for delta < 1), or the law is invalid.
double stribeck_slope(const Stribeck& law, double v);

/// Effective damping of steady sliding at the drive speed V0 (N s/m): c + dF/dv(V0). > 0:
/// steady sliding is stable; < 0: it is unstable (stick-slip or another oscillation).
/// \param c damper between body and drive (N s/m), >= 0.
/// \param V0 drive speed (m/s), != 0.
/// \throws std::invalid_argument naming c or V0 when out of range.
double sliding_damping_margin(const Stribeck& law, double c, double V0);

/// Drive speeds in [v_min, v_max] (m/s, 0 < v_min < v_max) where the margin changes sign (the
/// boundary at damping c), each located to a relative 1e-10 by bisection between samples of a
/// log-spaced scan of 2000 points; in increasing order (empty when the margin keeps its sign).
/// \throws std::invalid_argument naming the bad bound.
std::vector<double> critical_drive_speeds(const Stribeck& law, double c, double v_min, double v_max);

}  // namespace frictionlab
