#pragma once
// The ODE the stiff engine integrates for a dynamic friction law, y = [plant states, law states],
// and its analytic Jacobian (the Newton matrix of CVODE's BDF steps).

#include <span>
#include <vector>

#include "frictionlab/models/friction_law.hpp"
#include "frictionlab/plants/plant.hpp"
#include "frictionlab/core/input.hpp"

namespace frictionlab {

/// A plant whose contacts all have dynamic friction laws as one first-order system of
/// n = np + sum_k nz_k states, y = [plant states, contact 0's law states, contact 1's, ...]:
///   d/dt x = plant.derivatives(t, x, u, F),  d/dt z_k = law_k.derivative(z_k, v_k),
///   F_k = law_k.force(z_k, v_k),  v_k = x[plant.contact(k).velocity],
/// law_k = *plant.contact(k).law, or `law` where that is null. Holds references to plant and laws
/// (they must outlive it) and its own scratch space, so one object serves one thread; no call
/// allocates for laws of up to 16 states (GMS with more elements uses heap scratch).
class StiffSystem {
 public:
  /// \throws std::invalid_argument when a contact's law is not dynamic.
  StiffSystem(const Plant& plant, const FrictionLaw& law);

  /// Number of states n = plant.num_states() + the contacts' law states.
  int size() const { return n_; }

  /// True when jacobian() has an analytic form: the plant provides Plant::jacobian and does not
  /// impose its velocity (a velocity drive is not a free state).
  bool has_jacobian() const { return has_jacobian_; }

  /// dy/dt (n entries) at time t (s), state y (n entries) and inputs u (plant.num_inputs()).
  void rhs(double t, std::span<const double> y, Inputs u, std::span<double> dy) const;
  /// The same for a one-input plant.
  void rhs(double t, std::span<const double> y, const InputValue& u, std::span<double> dy) const {
    rhs(t, y, Inputs(&u, 1), dy);
  }

  /// d(dy/dt)/dy at (t, y, u), column-major (jac[i + j * n] = d dy[i] / d y[j], n * n entries;
  /// the layout of a SUNDIALS dense matrix). The laws' partial derivatives come from forward-mode
  /// automatic differentiation of their own formulas (ceres::Jet), so they are exact.
  /// \throws std::logic_error when has_jacobian() is false.
  void jacobian(double t, std::span<const double> y, Inputs u, std::span<double> jac);
  /// The same for a one-input plant.
  void jacobian(double t, std::span<const double> y, const InputValue& u, std::span<double> jac) {
    jacobian(t, y, Inputs(&u, 1), jac);
  }

 private:
  struct Part {              // one contact
    const FrictionLaw* law;  // never null
    int velocity;            // state index of its velocity
    int z;                   // offset of its law states in y
    int nz;
  };
  const Plant& plant_;
  std::vector<Part> parts_;
  int np_ = 2, n_ = 2, nc_ = 1;
  bool has_jacobian_ = false;
  // Scratch: plant partials (np x np row-major, np x nc), friction forces (nc), one law's partials
  // d dz / d(z, v) (nz x (nz + 1) row-major) and dF / d(z, v) (nz + 1).
  std::vector<double> dfdx_, dfdF_, force_, dh_, dF_;
};

}  // namespace frictionlab
