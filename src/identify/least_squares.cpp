#include "frictionlab/identify/least_squares.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <cmath>
#include <stdexcept>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

// "A", "A and B", "A, B and C".
std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return s;
}

}  // namespace

LeastSquaresFit linear_least_squares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<std::string>& names,
                                     const LeastSquaresOptions& o) {
  const Eigen::Index n = X.rows(), p = X.cols();
  if (y.size() != n || static_cast<Eigen::Index>(names.size()) != p)
    throw std::invalid_argument("least squares: " + std::to_string(n) + " x " + std::to_string(p) + " regressors with " +
                                std::to_string(y.size()) + " observations and " + std::to_string(names.size()) +
                                " parameter names; expected as many observations as rows and names as columns");
  LeastSquaresFit f;
  if (p == 0 || n < p + std::max<Eigen::Index>(0, o.min_redundancy)) {
    f.refusal = LeastSquaresRefusal::too_few_samples;
    f.message = std::to_string(n) + " samples for " + std::to_string(p) + " parameters; expected more samples than parameters";
    return f;
  }
  // A zero column (an effect never excited) would make the scaling divide by zero.
  const Eigen::VectorXd norms = X.colwise().norm();
  for (Eigen::Index j = 0; j < p; ++j)
    if (!(norms(j) > 0.0) || !std::isfinite(norms(j))) {
      f.refusal = LeastSquaresRefusal::no_excitation;
      f.message = "no excitation of parameter " + names[static_cast<std::size_t>(j)] + ": its regressor column is " +
                  (norms(j) > 0.0 ? "not finite" : "zero");
      return f;
    }
  const Eigen::VectorXd d = norms.cwiseInverse();
  // X = Q R (Householder; Q: N x p with orthonormal columns): X and R have the same singular
  // values, and so have X D and R D, so the SVDs below are of p x p matrices and cost nothing
  // next to the one pass of the QR over the N rows.
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(p).triangularView<Eigen::Upper>();
  const Eigen::JacobiSVD<Eigen::MatrixXd> plain(R);  // the units-dependent figure, for the record
  f.condition_number = plain.singularValues()(0) / plain.singularValues()(p - 1);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R * d.asDiagonal(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  f.condition_number_scaled = s(0) / s(p - 1);
  if (!(f.condition_number_scaled <= o.max_condition)) {
    // The parameters that carry the least-determined direction (right singular vector of the
    // smallest singular value): each with a share of at least 1/(2p) of its squared length.
    std::vector<std::string> involved;
    const Eigen::VectorXd w = svd.matrixV().col(p - 1);
    for (Eigen::Index j = 0; j < p; ++j)
      if (w(j) * w(j) >= 0.5 / static_cast<double>(p)) involved.push_back(names[static_cast<std::size_t>(j)]);
    f.refusal = LeastSquaresRefusal::rank_deficient;
    f.message = "rank-deficient regressors: condition number " + detail::format_value(f.condition_number_scaled, 6) +
                " (columns normalised) exceeds " + detail::format_value(o.max_condition, 6) + "; " + joined(involved) +
                (involved.size() > 1 ? " cannot be told apart" : " is not determined");
    return f;
  }
  // min ||X D u - y|| = min ||R D u - Q'y|| (the rest of y is orthogonal to X's columns).
  const Eigen::VectorXd qty = (qr.householderQ().adjoint() * y).head(p);
  f.theta = d.asDiagonal() * svd.solve(qty);
  f.residual = y - X * f.theta;
  const double ee = f.residual.squaredNorm();
  f.residual_variance = ee / static_cast<double>(std::max<Eigen::Index>(1, n - p));
  f.rmse = std::sqrt(ee / static_cast<double>(n));
  // X = U S V' D^-1: X'X = D^-1 V S^2 V' D^-1 and (X'X)^-1 = D V S^-2 V' D (S is invertible
  // here, its condition below max_condition; with an infinite limit a zero singular value gives
  // infinite entries, as the problem has).
  const Eigen::MatrixXd vs = d.cwiseInverse().asDiagonal() * svd.matrixV() * s.asDiagonal();
  f.information = vs * vs.transpose();
  const Eigen::MatrixXd vi = d.asDiagonal() * svd.matrixV() * s.cwiseInverse().asDiagonal();
  f.covariance = f.residual_variance * (vi * vi.transpose());
  f.stdev = f.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  f.ok = true;
  return f;
}

}  // namespace frictionlab
