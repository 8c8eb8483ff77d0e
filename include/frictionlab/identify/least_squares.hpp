#pragma once
// Linear least squares y = X theta for the identification methods (idim, breakaway, decay, the
// linear friction-velocity fits): one solve, one set of refusals, the figures the uncertainty
// code needs (identify/uncertainty.hpp).
//
// The solve works on the column-scaled matrix X D, D = diag(1 / ||X_j||), with Eigen's SVD:
// scaling makes the condition number a property of the trajectory, not of the units (a force in
// N against an acceleration in rad/s^2 and a velocity in rad/s), and the rank test a fixed
// relative threshold. theta = D (X D)^+ y, the same estimate as an unscaled solve up to rounding.

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct LeastSquaresOptions {
  /// Refuse (ok false, message naming the parameters) when the condition number of the
  /// column-scaled X exceeds this. Default 1e8: below it the covariance is a trustworthy figure;
  /// infinity accepts any X with non-zero columns (the minimum-norm estimate of X D).
  double max_condition = 1e8;
  /// Samples required beyond the parameter count. Default 1 (a residual variance needs one
  /// degree of freedom); 0 accepts N = p, whose residual variance is then taken over 1.
  Eigen::Index min_redundancy = 1;
};

/// Why linear_least_squares refused a problem.
enum class LeastSquaresRefusal {
  none,             ///< solved
  too_few_samples,  ///< fewer than p + min_redundancy samples
  no_excitation,    ///< a regressor column is zero or not finite
  rank_deficient,   ///< the scaled condition number exceeds max_condition
};

/// What linear_least_squares found. Unless ok, only message, condition numbers (when they could
/// be formed) and the sizes are set.
struct LeastSquaresFit {
  bool ok = false;
  LeastSquaresRefusal refusal = LeastSquaresRefusal::none;
  /// Why not ok, e.g. "no excitation of parameter Fv: its regressor column is zero" or
  /// "rank-deficient regressors: condition number 3.1e+09 (columns normalised) exceeds 1e+08;
  /// Fv and Fv2 cannot be told apart".
  std::string message;
  Eigen::VectorXd theta;        ///< p estimates, in the parameters' units
  Eigen::VectorXd residual;     ///< N residuals y - X theta, unit of y
  Eigen::VectorXd stdev;        ///< p standard deviations sqrt(diag(covariance))
  Eigen::MatrixXd information;  ///< X'X (p x p): unit of y squared over the parameters' units
  Eigen::MatrixXd covariance;   ///< s^2 (X'X)^-1 (p x p), the parameters' units squared
  double residual_variance = 0;  ///< s^2 = ||e||^2 / max(1, N - p), unit of y squared
  double rmse = 0;               ///< ||e|| / sqrt(N), unit of y
  double condition_number = 0;         ///< of X: extreme singular values' ratio (units-dependent)
  double condition_number_scaled = 0;  ///< of X D (unit-norm columns)
};

/// Ordinary least squares y = X theta (X: N x p, y: N, names: p parameter names for messages).
/// Refusals (ok false, not an exception; the caller reports them as the data's fault): fewer
/// than p + min_redundancy samples, a zero or non-finite column ("no excitation of parameter
/// NAME"), a scaled condition number above max_condition (naming the parameters of the
/// least-determined direction).
/// \throws std::invalid_argument when y or names do not match X's size.
LeastSquaresFit linear_least_squares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                                     const std::vector<std::string>& names, const LeastSquaresOptions& options = {});

}  // namespace frictionlab
