#include "method_support.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/signal/sampling.hpp"

namespace frictionlab::detail {

Result make_result(const std::string& method, const std::string& model, Axis axis) {
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

LinearFit least_squares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
  LinearFit f;
  const Eigen::Index n = X.rows(), p = X.cols();
  if (n <= p) {
    f.message = std::to_string(n) + " samples for " + std::to_string(p) + " parameters";
    return f;
  }
  for (Eigen::Index c = 0; c < p; ++c)
    if (X.col(c).cwiseAbs().maxCoeff() == 0.0) {
      f.message = "regressor column " + std::to_string(c) + " is zero (that effect is not excited)";
      return f;
    }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(X, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  f.condition_number = s[0] / s[p - 1];
  if (!(s[p - 1] > 1e-12 * s[0])) {
    f.message = "the regressors are rank deficient (condition number " + format_number(f.condition_number) + ")";
    return f;
  }
  f.beta = svd.solve(y);
  const Eigen::VectorXd e = y - X * f.beta;
  const double s2 = e.squaredNorm() / static_cast<double>(n - p);
  // diag((X'X)^-1) = sum_k V(i,k)^2 / s_k^2
  const Eigen::MatrixXd V = svd.matrixV();
  f.stdev.resize(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    double d = 0;
    for (Eigen::Index k = 0; k < p; ++k) d += V(i, k) * V(i, k) / (s[k] * s[k]);
    f.stdev[i] = std::sqrt(s2 * d);
  }
  f.rmse = std::sqrt(e.squaredNorm() / static_cast<double>(n));
  const Eigen::MatrixXd vs = V * s.head(p).asDiagonal();
  f.information = vs * vs.transpose();
  f.residual_variance = s2;
  f.ok = true;
  return f;
}

double regular_time_step(const Eigen::VectorXd& t, const std::string& method) {
  RegularSamplingCheck check;  // the one rule of signal/sampling.hpp: 1 % of the median step
  check.min_samples = 3;
  check.where = method + ": ";
  check.requirement = method + " needs regularly sampled data";
  return check_regular_sampling(t, check).mean;
}

}  // namespace frictionlab::detail
