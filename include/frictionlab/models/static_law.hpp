#pragma once
// What every static (memoryless) friction law provides, and the stiction rule they share.
//
// Sign convention used throughout frictionlab: the friction force F has the sign of the
// velocity and is subtracted in the equation of motion, M a = applied - F.

#include <algorithm>
#include <concepts>

#include "frictionlab/models/scalar.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A static friction law: `sliding(v)` is the force for v != 0 (N or N m, sign of v);
/// `breakaway_positive()` / `breakaway_negative()` are the largest applied force (magnitude)
/// a stuck contact holds when pushed in the positive / negative direction.
template <class Law>
concept StaticLaw = requires(const Law& law, double v) {
  { law.sliding(v) } -> std::convertible_to<double>;
  { law.breakaway_positive() } -> std::convertible_to<double>;
  { law.breakaway_negative() } -> std::convertible_to<double>;
  law.validate();
};

/// Friction force of a static law including stiction (N or N m).
/// \param v        velocity (m/s or rad/s)
/// \param applied  the net force that would accelerate the body without friction (N or N m);
///                 used only at v == 0: the contact holds it up to the breakaway level.
/// A law with its own member `force(v, applied)` (Karnopp) uses that instead.
/// At v == 0 the result balances `applied` when it is within [-breakaway_negative, breakaway_positive],
/// and is the breakaway level (opposing `applied`) otherwise.
template <class Law, class T>
T friction_force(const Law& law, const T& v, const T& applied) {
  if constexpr (requires { law.force(v, applied); }) {
    return law.force(v, applied);  // laws with their own stiction rule (Karnopp's band)
  }
  if (value_of(v) != 0.0) return law.sliding(v);
  const T hi = T(law.breakaway_positive());
  const T lo = -T(law.breakaway_negative());
  if (applied > hi) return hi;
  if (applied < lo) return lo;
  return applied;
}

}  // namespace frictionlab
