#pragma once
// Least-squares fit of a static friction law to friction-velocity points (a sweep's segment
// means, or raw samples): coulomb-viscous (linear, exact), stribeck and stribeck-asymmetric
// (nonlinear, Ceres with analytic Jacobians and bounds that keep the law physical).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/friction_law.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The static laws a friction-velocity map can be fitted with.
enum class StaticFitModel { coulomb_viscous, coulomb_viscous_asymmetric, stribeck, stribeck_asymmetric };

/// Parses "coulomb-viscous", "coulomb-viscous-asymmetric", "stribeck", "stribeck-asymmetric";
/// throws std::invalid_argument listing these otherwise.
StaticFitModel parse_static_fit_model(const std::string& name);

struct StaticFitOptions {
  StaticFitModel model = StaticFitModel::stribeck;
  /// Stribeck exponent: fitted when <= 0 (default), held at this value otherwise (2 = Gaussian).
  double fixed_delta = 0.0;
  /// Bounds of a fitted exponent; outside them the shape is not identifiable from typical data.
  double delta_min = 0.5, delta_max = 5.0;
  int max_iterations = 200;
  /// The Stribeck part (vs, delta) counts as determined by the points only when at least this
  /// many points (per direction) are slower than the fitted vs and the slowest point is below
  /// 2 vs; otherwise vs and delta get std NaN and a warning. Default 3.
  int min_points_below_vs = 3;
  /// Threads Ceres may use to evaluate residuals (the fit of 1e5 points profits from 2).
  int num_threads = 2;
};

struct StaticFit {
  FrictionLaw law;                          ///< the fitted law, ready to simulate
  /// In the law's order (Fc, Fs, vs, delta, Fv, ...): value, standard deviation (from the residual
  /// variance and the Jacobian at the solution, s^2 (J'J)^-1; NaN when the fit ended at a bound or
  /// the points do not determine it, see identify/uncertainty.hpp; 0 for a held exponent), the
  /// quantity that gives the unit, flag "", "undetermined" or "at bound". `unit` is left empty.
  std::vector<Parameter> parameters;
  double relative_error_percent = 0;        ///< 100 ||F - F_hat|| / ||F||
  double rmse = 0;                          ///< root mean square residual (N or N m)
  std::size_t samples = 0;
  int iterations = 0;
  bool converged = false;
  std::vector<std::string> warnings;        ///< e.g. "no Stribeck effect: Fs - Fc = 0.001 N is within 2 std"
  std::vector<std::string> undetermined;    ///< parameters the points cannot determine (std NaN)
  std::vector<std::string> at_bound;        ///< parameters that ended at a bound (std NaN)
  ParameterCorrelation correlation;         ///< of the estimated parameters (a held exponent left out)
};

/// Fits `options.model` to points (v_i, F_i). Shapes: velocity and force of equal length N.
/// Units: v in m/s or rad/s, F in N or N m, friction with the sign of v.
/// Starting values come from the data (high-speed half gives Fc and Fv by linear least squares,
/// the slowest points give Fs, the decay of the excess gives vs), so no start is needed.
/// \throws std::invalid_argument on unequal lengths, non-finite values, zero velocities, or too
///         few points (fewer than the parameters, or a direction without points for asymmetric models).
StaticFit fit_static_law(const Eigen::VectorXd& velocity, const Eigen::VectorXd& force,
                         const StaticFitOptions& options = {});

}  // namespace frictionlab
