#pragma once
// What every dynamic friction law (one with internal state: Dahl, LuGre, elasto-plastic, GMS)
// provides. The state z (bristle or element deflections, m or rad) evolves with velocity;
// the force follows from state and velocity.

#include <concepts>
#include <span>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A dynamic law with `num_states()` states:
/// - `derivative(z, v, dz)`: dz/dt (m/s or rad/s per state) for the continuous model (the integrators);
/// - `force(z, v)`: friction force (N or N m, sign of motion) at state z and velocity v;
/// - `step(z, v, dt)`: advances z in place over dt seconds at constant v, stable for any dt >= 0
///   and any v, without allocation, and returns the force at the end of the step (the fixed-step
///   form a controller runs);
/// - `steady_state(v, z)`: the state reached after sliding long enough at constant v != 0.
template <class Law>
concept DynamicLaw = requires(const Law& law, std::span<const double> zc, std::span<double> z, double v) {
  { law.num_states() } -> std::convertible_to<int>;
  law.derivative(zc, v, z);
  { law.force(zc, v) } -> std::convertible_to<double>;
  { law.step(z, v, v) } -> std::convertible_to<double>;
  law.steady_state(v, z);
  law.validate();
};

}  // namespace frictionlab
