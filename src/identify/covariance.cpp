#include "frictionlab/identify/covariance.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {

Eigen::MatrixXd newey_west_meat(const Eigen::MatrixXd& u, double bandwidth) {
  if (!(bandwidth >= 0) || !std::isfinite(bandwidth))
    throw std::invalid_argument("newey_west_meat: bandwidth = " + detail::format_value(bandwidth, 6) +
                                " samples must be a finite number >= 0");
  const Eigen::Index n = u.rows();
  const auto lags = std::min<Eigen::Index>(static_cast<Eigen::Index>(std::floor(bandwidth)), std::max<Eigen::Index>(n - 1, 0));
  Eigen::MatrixXd omega = u.transpose() * u;
  for (Eigen::Index l = 1; l <= lags; ++l) {
    const double w = 1.0 - static_cast<double>(l) / (static_cast<double>(lags) + 1.0);  // Bartlett
    const Eigen::MatrixXd g = u.bottomRows(n - l).transpose() * u.topRows(n - l);
    omega += w * (g + g.transpose());
  }
  return omega;
}

double andrews_bandwidth(const Eigen::MatrixXd& u, const Eigen::VectorXd& weights, double* rho_out) {
  if (weights.size() != u.cols())
    throw std::invalid_argument("andrews_bandwidth: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(u.cols()) + " score columns");
  constexpr double kMaxRho = 0.97;  // (1 - 0.97)^-6 is already 1e9: the cap of n/4 takes over
  const Eigen::Index n = u.rows();
  double num = 0, den = 0, rho_sum = 0, w_sum = 0;
  for (Eigen::Index a = 0; a < u.cols(); ++a) {
    if (!(weights(a) > 0) || n < 3) continue;
    const auto x = u.col(a);
    const double lag0 = x.head(n - 1).squaredNorm();
    if (!(lag0 > 0)) continue;
    const double rho = std::clamp(x.tail(n - 1).dot(x.head(n - 1)) / lag0, -kMaxRho, kMaxRho);
    const double s2 = (x.tail(n - 1) - rho * x.head(n - 1)).squaredNorm() / static_cast<double>(n - 1);
    if (!(s2 > 0)) continue;
    const double s4 = s2 * s2;
    num += weights(a) * 4 * rho * rho * s4 / (std::pow(1 - rho, 6) * std::pow(1 + rho, 2));
    den += weights(a) * s4 / std::pow(1 - rho, 4);
    rho_sum += weights(a) * rho;
    w_sum += weights(a);
  }
  if (rho_out != nullptr) *rho_out = w_sum > 0 ? rho_sum / w_sum : std::numeric_limits<double>::quiet_NaN();
  if (!(den > 0)) return 0.0;
  return 1.1447 * std::cbrt(num / den * static_cast<double>(n));
}

HacCovariance hac_covariance(const Eigen::MatrixXd& X, const Eigen::VectorXd& e, const HacOptions& o) {
  const Eigen::Index n = X.rows(), p = X.cols();
  if (e.size() != n)
    throw std::invalid_argument("hac_covariance: " + std::to_string(e.size()) + " residuals for " + std::to_string(n) +
                                " regressor rows");
  if (n <= p)
    throw std::invalid_argument("hac_covariance: " + std::to_string(n) + " rows for " + std::to_string(p) +
                                " parameters; expected more rows than parameters");
  if (!X.allFinite() || !e.allFinite())
    throw std::invalid_argument("hac_covariance: the regressors or residuals hold a value that is not a finite number");
  if (!std::isfinite(o.bandwidth) || !(o.min_bandwidth >= 0) || !std::isfinite(o.min_bandwidth))
    throw std::invalid_argument("hac_covariance: bandwidth = " + detail::format_value(o.bandwidth, 6) +
                                " and min_bandwidth = " + detail::format_value(o.min_bandwidth, 6) +
                                " must be finite (min_bandwidth >= 0)");
  const Eigen::MatrixXd u = X.array().colwise() * e.array();
  HacCovariance h;
  // Prewhitening (Andrews and Monahan 1992): u_t = B u_{t-1} + v_t by least squares, the kernel
  // estimate on v, recoloured by (I - B)^-1. B's singular values are held at or below 0.97, as
  // theirs, so that I - B stays well away from singular.
  Eigen::MatrixXd v = u;
  Eigen::MatrixXd recolour = Eigen::MatrixXd::Identity(p, p);
  h.prewhitened = o.prewhiten && n > 2 * p + 2;
  if (h.prewhitened) {
    const Eigen::MatrixXd lagged = u.topRows(n - 1), next = u.bottomRows(n - 1);
    Eigen::MatrixXd B = lagged.completeOrthogonalDecomposition().solve(next).transpose();  // p x p
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
    constexpr double kMaxSingular = 0.97;
    if (svd.singularValues().maxCoeff() > kMaxSingular)
      B = svd.matrixU() * svd.singularValues().cwiseMin(kMaxSingular).asDiagonal() * svd.matrixV().transpose();
    v = next - lagged * B.transpose();
    recolour = (Eigen::MatrixXd::Identity(p, p) - B).inverse();
  }
  if (o.bandwidth >= 0) {
    h.bandwidth = std::floor(o.bandwidth);
    h.rho = std::numeric_limits<double>::quiet_NaN();
  } else {
    Eigen::VectorXd weights = Eigen::VectorXd::Ones(p);
    for (Eigen::Index a = 0; a < p; ++a) {  // a constant column (an offset): weight 0, as Andrews
      const auto c = X.col(a);
      if (c.maxCoeff() == c.minCoeff()) weights(a) = 0;
    }
    if (!(weights.sum() > 0)) weights.setOnes();
    const double cap = std::floor(static_cast<double>(n) / 4);
    h.bandwidth = std::min(cap, std::floor(std::max(o.min_bandwidth, andrews_bandwidth(v, weights, &h.rho))));
  }
  h.meat = recolour * newey_west_meat(v, h.bandwidth) * recolour.transpose() *
           (static_cast<double>(n) / static_cast<double>(n - p));
  h.meat = 0.5 * (h.meat + h.meat.transpose()).eval();
  // (X'X)^-1 on the unit-diagonal scaled matrix, a pseudo-inverse (a zero column gives zeros).
  const Eigen::MatrixXd A = X.transpose() * X;
  Eigen::VectorXd d(p);
  for (Eigen::Index a = 0; a < p; ++a) d(a) = A(a, a) > 0 ? 1.0 / std::sqrt(A(a, a)) : 0.0;
  const Eigen::MatrixXd scaled = d.asDiagonal() * A * d.asDiagonal();
  const Eigen::MatrixXd Ainv = d.asDiagonal() * scaled.completeOrthogonalDecomposition().pseudoInverse() * d.asDiagonal();
  h.covariance = Ainv * h.meat * Ainv;
  h.covariance = 0.5 * (h.covariance + h.covariance.transpose()).eval();
  return h;
}

}  // namespace frictionlab
