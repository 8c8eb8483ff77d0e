#pragma once
// The exact relaxation of a first-order state over one step, and LuGre's bristles as one: the
// update that LuGre's own step (models/lugre.hpp), the LuGre observer (control/lugre_observer.hpp)
// and the LuGre fit (identify/lugre.hpp) share. Templated on the scalar: double, or a Ceres Jet
// in the fit.

#include <cmath>

#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The exact solution of dz/dt = rate (target - z) over one step in which rate (1/s, >= 0) and
/// target hold: target + (z - target) decay, with decay = exp(-rate dt) in (0, 1] (the caller
/// computes it, so that one exponential may serve several steps). Any step is stable: z moves
/// toward the target and never past it.
template <class T>
T relax(const T& z, const T& target, const T& decay) {
  return target + (z - target) * decay;
}

/// LuGre's bristles at a constant velocity v written as a relaxation, dz/dt = rate (target - z).
template <class T>
struct BristleRelaxation {
  T rate;    ///< sigma0 |v| / g(v) (1/s), >= 0
  T target;  ///< the steady state sign(v) g(v) / sigma0 (m or rad); 0 at v = 0
};

/// The relaxation of `law`'s bristle state at velocity v (m/s or rad/s): with relax(), the exact
/// state after a step at constant v. `law` is any bristle law with a stiffness `sigma0` (N/m or
/// N m/rad, > 0) and a steady sliding level `level(v)` (N or N m, > 0), e.g. LuGreT.
template <class Law, class T>
BristleRelaxation<T> bristle_relaxation(const Law& law, const T& v) {
  using std::abs;
  const T g = law.level(v);
  return {T(law.sigma0) * abs(v) / g, sgn(v) * g / T(law.sigma0)};
}

}  // namespace frictionlab
