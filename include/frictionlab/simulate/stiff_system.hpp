#pragma once
// The ODE the stiff engine integrates for a dynamic friction law, y = [plant states, law states],
// and its analytic Jacobian (the Newton matrix of CVODE's BDF steps).

#include <span>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/simulate/input.hpp"

namespace frictionlab {

/// A plant with a dynamic friction law as one first-order system of n = np + nz states:
///   d/dt x = plant.derivatives(t, x, u, F),  d/dt z = law.derivative(z, v),  F = law.force(z, v),
/// with v = x[1]. Holds references to plant and law (they must outlive it) and its own scratch
/// space, so one object serves one thread; no call allocates for laws of up to 16 states (GMS
/// with more elements uses heap scratch for its derivatives).
class StiffSystem {
 public:
  /// \throws std::invalid_argument when the law is not dynamic.
  StiffSystem(const Plant& plant, const FrictionLaw& law);

  /// Number of states n = plant.num_states() + law.num_states().
  int size() const { return np_ + nz_; }

  /// True when jacobian() has an analytic form: the plant provides Plant::jacobian and does not
  /// impose its velocity (a velocity drive is not a free state).
  bool has_jacobian() const { return has_jacobian_; }

  /// dy/dt (n entries) at time t (s), state y (n entries) and input u.
  void rhs(double t, std::span<const double> y, const InputValue& u, std::span<double> dy) const;

  /// d(dy/dt)/dy at (t, y, u), column-major (jac[i + j * n] = d dy[i] / d y[j], n * n entries;
  /// the layout of a SUNDIALS dense matrix). The law's partial derivatives come from forward-mode
  /// automatic differentiation of its own formulas (ceres::Jet), so they are exact.
  /// \throws std::logic_error when has_jacobian() is false.
  void jacobian(double t, std::span<const double> y, const InputValue& u, std::span<double> jac);

 private:
  const Plant& plant_;
  const FrictionLaw& law_;
  int np_ = 2, nz_ = 0;
  bool has_jacobian_ = false;
  // Scratch: plant partials (np x np row-major, np), law partials d dz / d(z, v) (nz x (nz + 1)
  // row-major) and dF / d(z, v) (nz + 1).
  std::vector<double> dfdx_, dfdF_, dh_, dF_;
};

}  // namespace frictionlab
