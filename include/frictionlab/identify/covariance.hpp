#pragma once
// The covariance of a linear least-squares estimate when the residuals are not white.
//
// The ordinary least-squares covariance s^2 (X'X)^-1 assumes independent residuals of one
// variance. After a zero-phase low-pass, a decimation and a drive's coloured current noise the
// residuals of an identification are autocorrelated, and that covariance is a lower bound: on
// logs with AR(1) current noise its 95 % intervals held the true Coulomb level in 1 of 12 runs.
// The heteroskedasticity-and-autocorrelation-consistent (HAC) covariance of Newey and West
// (1987) is the sandwich
//   cov = n/(n-p) (X'X)^-1 Omega (X'X)^-1,
//   Omega = G_0 + sum_{l=1..L} w_l (G_l + G_l'),   G_l = sum_t u_t u_{t-l}',   u_t = x_t e_t,
// with Bartlett weights w_l = 1 - l/(L+1) (Omega is then positive semi-definite) and a bandwidth
// L chosen from the data by the AR(1) plug-in rule of Andrews (1991, eq. 6.4):
//   rho_a, sigma_a^2 = AR(1) fit of each column a of u (not the constant),
//   alpha = sum 4 rho^2 sigma^4 / ((1-rho)^6 (1+rho)^2) / sum sigma^4 / (1-rho)^4,
//   L = 1.1447 (alpha n)^(1/3),
// never below `min_bandwidth` (a floor the caller ties to the memory its filters leave in the
// residual) and at most n/4. The factor n/(n-p) makes it the OLS covariance for white
// residuals and L = 0 (the usual small-sample correction, HC1).
// By default the scores are prewhitened first (Andrews and Monahan 1992): a VAR(1)
// u_t = B u_{t-1} + v_t is fitted by least squares, the kernel estimate above is made on v (its
// bandwidth from v) and recoloured, Omega = (I - B)^-1 Omega_v (I - B)^-T, with B's singular
// values held at or below 0.97. Measured on the synthetic rigs of tests/rigs (docs/coverage.md):
// with AR(1) drive noise the plain Bartlett estimate at Andrews' bandwidth covered 86 to 92 % of
// the true values with its 95 % intervals (twice or three times the bandwidth did not help), the
// prewhitened one 92 to 97 %.

#include <Eigen/Core>
#include <string>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct HacOptions {
  /// Bartlett bandwidth L in samples (lags), >= 0; negative: automatic (Andrews' rule above).
  /// Default automatic.
  double bandwidth = -1;
  /// Least bandwidth of the automatic rule, samples (>= 0): the residual correlation the caller
  /// knows its own filters leave (e.g. the decimation filter's memory). Default 0.
  double min_bandwidth = 0;
  /// Prewhiten the scores by a VAR(1) before the kernel estimate (see above). Default true.
  bool prewhiten = true;
};

/// The HAC covariance and how it was made.
struct HacCovariance {
  Eigen::MatrixXd covariance;  ///< p x p, the parameters' units squared
  /// Omega scaled by n/(n-p) (p x p, unit of y squared over the parameters' units squared): the
  /// "meat" of the sandwich; covariance = A^-1 meat A^-1 with A = X'X.
  Eigen::MatrixXd meat;
  double bandwidth = 0;  ///< L used, samples (an integer), on the prewhitened scores when prewhitened
  bool prewhitened = false;  ///< the VAR(1) prewhitening was applied (asked for, and n > 2 p + 2)
  /// The AR(1) coefficient of Andrews' rule, a weighted mean over the columns (NaN when the
  /// bandwidth was given).
  double rho = 0;
};

/// The Newey-West covariance of the least-squares estimate of y = X theta from the regressor
/// matrix `X` (n x p, n > p, columns in any units) and the residuals `residual` = y - X theta
/// (n, unit of y), with the options above. A constant column (an offset) is left out of the
/// bandwidth rule, not of the covariance or the prewhitening.
/// (X'X)^-1 is taken as the pseudo-inverse of the unit-diagonal scaled X'X, so a singular X'X
/// gives a covariance, not an error (identify/uncertainty.hpp tells which parameters it leaves
/// undetermined).
/// \throws std::invalid_argument when residual.size() != X.rows(), n <= p, a value is not
///         finite, or options.bandwidth / min_bandwidth is not finite (min_bandwidth < 0).
HacCovariance hac_covariance(const Eigen::MatrixXd& X, const Eigen::VectorXd& residual, const HacOptions& options = {});

/// The meat Omega (p x p, without the n/(n-p) factor) of the Newey-West covariance for the score
/// rows u = X .* residual (n x p) at the bandwidth `bandwidth` (samples, >= 0; rounded down).
/// \throws std::invalid_argument for a negative or non-finite bandwidth.
Eigen::MatrixXd newey_west_meat(const Eigen::MatrixXd& scores, double bandwidth);

/// Andrews' AR(1) plug-in Bartlett bandwidth (samples, not rounded, not capped) for the score
/// rows u (n x p) with a weight per column (p, >= 0; Andrews weights the constant's column 0);
/// `rho`, when given, gets the weighted mean AR(1) coefficient. Columns of zero variance or
/// weight are left out; 0 when none is left. AR(1) coefficients are held within +-0.97, where
/// the rule's (1 - rho)^-6 would otherwise make the bandwidth the whole record.
/// \throws std::invalid_argument when weights.size() != scores.cols().
double andrews_bandwidth(const Eigen::MatrixXd& scores, const Eigen::VectorXd& weights, double* rho = nullptr);

}  // namespace frictionlab
