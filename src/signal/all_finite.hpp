#pragma once
// One check shared by the signal pipelines (private to the library): every value finite, in
// vector instructions. A plain loop over std::isfinite stops at each element; Eigen vectorises a
// sum, and inf * 0 and NaN * 0 are NaN, so the sum of v * 0 is NaN exactly when a value is not
// finite. Callers that must name the offending sample look for it only when this fails.

#include <Eigen/Core>
#include <cmath>

namespace frictionlab::detail {

inline bool all_finite(const Eigen::Ref<const Eigen::VectorXd>& v) { return !std::isnan((v.array() * 0.0).sum()); }

}  // namespace frictionlab::detail
