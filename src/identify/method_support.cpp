#include "method_support.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/signal/sampling.hpp"

namespace frictionlab::detail {

Result make_result(MethodId method, const std::string& model, Axis axis) {
  return new_result(method_info(method), model, axis);
}

Result fail(Result& r, const std::string& message) {
  r.status = ResultStatus::error;
  r.message = message;
  r.parameters.clear();
  return r;
}

void add_parameter(Result& r, const std::string& name, double value, double std, Quantity q, Axis axis) {
  r.parameters.emplace_back(name, value, std, q, axis);
}

void set_fit(Result& r, const Eigen::VectorXd& y, const Eigen::VectorXd& y_hat) {
  const double e = (y - y_hat).norm();
  r.fit.samples = static_cast<std::size_t>(y.size());
  r.fit.rmse = e / std::sqrt(static_cast<double>(std::max<Eigen::Index>(1, y.size())));
  r.fit.relative_error_percent = 100.0 * e / y.norm();
}

double regular_time_step(const Eigen::VectorXd& t, const std::string& method) {
  RegularSamplingCheck check;  // the one rule of signal/sampling.hpp: 1 % of the median step
  check.min_samples = 3;
  check.where = method + ": ";
  check.requirement = method + " needs regularly sampled data";
  return check_regular_sampling(t, check);
}

}  // namespace frictionlab::detail
