#pragma once
// Honest uncertainty: standard deviations and the correlation matrix of identified parameters,
// with NaN (null in JSON) instead of a tiny number for a parameter that ended at a bound or that
// the data cannot determine. Every identification method reports through this one place.
//
// The rule for "cannot determine" (near-singular information): scale the information matrix
// A = J'J (or X'X) to unit diagonal, C = D A D with D = diag(A)^-1/2. The variance inflation
// factor of parameter i is VIF_i = (C^-1)_ii = 1 / (1 - R_i^2), where R_i^2 is the share of its
// column explained by the other columns. A parameter is undetermined when
//   - its column carries no information (A_ii = 0 or not finite: the data never excites it), or
//   - VIF_i > max_variance_inflation (default 1e8: less than 1e-8 of the parameter's own
//     information is independent of the others, the columns' scaled condition number is then
//     at least 1e4 and the linearised std is no longer a trustworthy figure), or
//   - the caller says so (a method's own test, e.g. a sweep with no points below vs).
// A parameter at a bound is held there by the bound, not by the data: its linearised std is
// meaningless. Both kinds get std NaN, a warning naming them, and are listed in
// diagnostics.undetermined / diagnostics.at_bound. The remaining parameters' covariance is
// s^2 (A_SS)^-1 over the determined set S, i.e. conditional on the excluded parameters' values
// (exact for an unexcited column or a held bound; an underestimate when a parameter was
// excluded for strong correlation, which the warning says).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frictionlab/identify/result.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What a method knows about each parameter before the uncertainty is assessed.
struct ParameterState {
  bool at_bound = false;      ///< the fit ended at (within a tolerance of) a bound
  bool undetermined = false;  ///< the method's own test says the data cannot determine it
  std::string reason;         ///< for the warning, e.g. "no segment is slower than 2 vs"
};

struct UncertaintyOptions {
  /// Variance inflation factor above which a parameter is undetermined (see above). Default 1e8.
  double max_variance_inflation = 1e8;
};

/// True when `value` is within a relative 1e-6 of `lower` or `upper` (infinite bounds never
/// match). `scale` (> 0, the parameter's unit) sets the tolerance at a bound of 0:
/// |value - bound| <= 1e-6 max(|bound|, scale).
bool is_at_bound(double value, double lower, double upper, double scale);

/// Sets the std, flag, warnings, diagnostics.undetermined/at_bound and diagnostics.correlation
/// of the parameters `names` of `r` (each must already be in r.parameters) from the information
/// matrix `information` = J'J (p x p, in the parameters' units, p = names.size(), symmetric) and
/// the residual variance `residual_variance` s^2 (unit of the fitted signal squared; the
/// covariance is s^2 (J'J)^-1). `states` is empty (all free) or has p entries.
/// Parameters of `r` not in `names` keep their std (a derived parameter such as Fs = Fc + dF is
/// set by the caller from the covariance this returns).
/// \returns the p x p covariance (NaN rows and columns for undetermined or at-bound parameters).
/// \throws std::invalid_argument for mismatched sizes or a name not among r.parameters.
Eigen::MatrixXd set_uncertainty_from_information(Result& r, const std::vector<std::string>& names,
                                                 const Eigen::MatrixXd& information, double residual_variance,
                                                 const std::vector<ParameterState>& states = {},
                                                 const UncertaintyOptions& options = {});

/// The same with the sandwich covariance of a least-squares fit whose residuals are correlated
/// (identify/covariance.hpp): over the determined set S (chosen from `information` by the rules
/// above, so the same parameters are undetermined as with the ordinary covariance), std and
/// correlation come from (A_SS)^-1 meat_SS (A_SS)^-1, and each determined parameter's std_ols
/// from residual_variance (A_SS)^-1 (NaN where std is NaN). `meat` is p x p, symmetric positive
/// semi-definite, unit of the fitted signal squared over the parameters' units squared.
/// \returns the p x p sandwich covariance (NaN rows and columns as above).
/// \throws std::invalid_argument for mismatched sizes or a name not among r.parameters.
Eigen::MatrixXd set_uncertainty_from_sandwich(Result& r, const std::vector<std::string>& names,
                                              const Eigen::MatrixXd& information, const Eigen::MatrixXd& meat,
                                              double residual_variance, const std::vector<ParameterState>& states = {},
                                              const UncertaintyOptions& options = {});

/// The same for an instrumental-variable estimate theta = (Z'W)^-1 Z'y (identify/idim.hpp,
/// IDIM-IV): the determined set S is chosen from `information` = W'W by the rules above (the same
/// parameters as the least-squares fit's), std and correlation come from the IV sandwich
/// (Z'W)_SS^-1 meat_SS (W'Z)_SS^-1 with `meat` the Newey-West meat of the scores z_t e_t
/// (identify/covariance.hpp, hac_covariance(Z, e).meat), and std_ols from the ordinary IV form
/// residual_variance (Z'W)_SS^-1 (Z'Z)_SS (W'Z)_SS^-1. `cross` = Z'W and `instruments` = Z'Z are
/// p x p (instrument rows, regressor columns), in the parameters' units.
/// \returns the p x p IV covariance (NaN rows and columns as above).
/// \throws std::invalid_argument for mismatched sizes or a name not among r.parameters.
Eigen::MatrixXd set_uncertainty_from_iv(Result& r, const std::vector<std::string>& names,
                                        const Eigen::MatrixXd& information, const Eigen::MatrixXd& cross,
                                        const Eigen::MatrixXd& instruments, const Eigen::MatrixXd& meat,
                                        double residual_variance, const std::vector<ParameterState>& states = {},
                                        const UncertaintyOptions& options = {});

/// The same from a covariance matrix (p x p, symmetric positive semi-definite, parameters'
/// units squared) when the method has no information matrix: the information is taken as its
/// pseudo-inverse (residual variance 1). A zero or non-finite variance makes the parameter
/// undetermined.
Eigen::MatrixXd set_uncertainty_from_covariance(Result& r, const std::vector<std::string>& names,
                                                const Eigen::MatrixXd& covariance,
                                                const std::vector<ParameterState>& states = {},
                                                const UncertaintyOptions& options = {});

}  // namespace frictionlab
