#pragma once
// Private helpers shared by the identification methods: building a Result, their least-squares
// settings (identify/least_squares.hpp), and the time-step check of in-memory signals.

#include <Eigen/Core>
#include <string>

#include "frictionlab/format.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/identify/least_squares.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab::detail {

/// Each method's description (summary, fitted signal, options), from its own file; the registry
/// (identify/method.cpp) adds its name and id from FRICTIONLAB_METHODS.
#define FRICTIONLAB_METHOD_INFO_DECL(id) MethodInfo id##_method_info();
FRICTIONLAB_METHODS(FRICTIONLAB_METHOD_INFO_DECL)
#undef FRICTIONLAB_METHOD_INFO_DECL

/// decay's --stiffness option (N/m or N m/rad), declared once: auto's table (identify/auto.hpp)
/// holds the same entry, so a decay found by auto reports Fc and Fv in force units with it.
OptionSpec decay_stiffness_option();

/// An empty ok Result of `method` (identify/method.hpp) fitting `model` on `axis`: the axis and
/// the fit's quantity and unit set (new_result).
Result make_result(MethodId method, const std::string& model, Axis axis);



/// Sets status error with `message` and returns the result (for `return fail(r, "...")`).
Result fail(Result& r, const std::string& message);

void add_parameter(Result& r, const std::string& name, double value, double std, Quantity q, Axis axis);

/// Fills r.fit from measured y and reconstructed y_hat (same length).
void set_fit(Result& r, const Eigen::VectorXd& y, const Eigen::VectorXd& y_hat);

/// The least-squares settings of the methods that separate a few effects from sliding data
/// (breakaway, decay): refuse only what is singular to working precision (scaled condition
/// number above 1e12); their own tests judge the estimates' spread.
inline LeastSquaresOptions separable() {
  LeastSquaresOptions o;
  o.max_condition = 1e12;
  return o;
}

/// Mean step of a strictly increasing, regular time vector (s): check_regular_sampling of
/// signal/sampling.hpp with at least 3 samples.
/// \throws SamplingError (a std::invalid_argument) "METHOD: sample K: ..." naming the sample
///         (1-based) of the first non-finite, non-increasing or irregular (more than 1 % off the
///         median step) time stamp.
double regular_time_step(const Eigen::VectorXd& time, const std::string& method);

}  // namespace frictionlab::detail
