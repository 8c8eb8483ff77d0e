#pragma once
// Numerical derivative of a uniformly sampled signal.

#include <Eigen/Core>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Central differences (x(k+1) - x(k-1)) / (2 dt) inside, one-sided first differences at the
/// two ends, as numpy.gradient(x, dt) (edge_order=1). Units: those of x per second when dt is
/// in s. Shapes: x of length N >= 2; returns length N.
/// \throws std::invalid_argument when N < 2 or dt is not a positive finite number.
Eigen::VectorXd gradient(const Eigen::VectorXd& x, double dt);

/// The same into out (length N, not aliasing x), for pipelines that reuse their buffers.
/// \throws std::invalid_argument as above, or when out's length differs from N.
void gradient(const Eigen::Ref<const Eigen::VectorXd>& x, double dt, Eigen::Ref<Eigen::VectorXd> out);

}  // namespace frictionlab
