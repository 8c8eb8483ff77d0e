#pragma once
// Coulomb and viscous friction from the decaying free oscillation of a pendulum or a
// spring-mass, by an energy balance over each half cycle: between two turning points
// (velocity zero, so all energy is potential) the potential energy lost equals
//   Fc * (distance travelled) + Fv * integral(v^2 dt).
// Linear in Fc and Fv, exact for the model, and valid at large pendulum angles (the potential
// is k (1 - cos th) there), so the estimate does not depend on the amplitude.

#include <Eigen/Core>
#include <limits>

#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

struct DecayData {
  Eigen::VectorXd time;      ///< s, strictly increasing, regular
  Eigen::VectorXd position;  ///< m or rad, measured from the equilibrium
};

struct DecayOptions {
  /// Restoring stiffness (N/m, or N m/rad; for a pendulum m g l). NaN: use natural_frequency.
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  /// Inertia (kg or kg m^2); only used with natural_frequency to report Fc and Fv in force units.
  double inertia = std::numeric_limits<double>::quiet_NaN();
  /// Natural frequency sqrt(k/M) (rad/s). With it alone the result is Fc relative to the
  /// stiffness (Fc/k, m or rad) and the damping ratio zeta = Fv / (2 M wn).
  double natural_frequency = std::numeric_limits<double>::quiet_NaN();
  /// true: pendulum, restoring force k sin(th); false: linear spring k x.
  bool pendulum = false;
  /// |v| below which the oscillation counts as stopped (m/s or rad/s). NaN: 1e-6 of max |v|.
  double stop_threshold = std::numeric_limits<double>::quiet_NaN();
  Axis axis = Axis::linear;
};

/// The options of a decay run from the values of its option table (method_info(MethodId::decay));
/// the table's defaults where a value is not given. The axis is the caller's to set.
DecayOptions make_decay_options(const OptionValues& values);

/// Estimates Fc and Fv (or Fc/k and zeta) with standard deviations from a free decay.
/// Needs at least 3 half cycles; fewer gives status "error" with the count found.
/// The adequacy of the Coulomb-viscous model is checked sample by sample (identify/adequacy.hpp):
/// the friction the motion shows, -(restoring force + M a) with M by least squares, less
/// Fc sign(v) + Fv v, over the samples in motion away from reversals (diagnostics.adequacy,
/// residual_by_velocity, residual_by_time, warnings; "adequacy_inertia" the M used; units of Fc).
/// Figures that overflow double precision (values or scales beyond what it holds) give status
/// "error" with code "output.not_finite" naming the figure (finite_or_error,
/// identify/finite_result.hpp), never an ok result with inf in it.
/// \throws std::invalid_argument on unequal lengths, irregular time, or neither stiffness nor
///         natural_frequency given (or not positive).
Result identify_decay(const DecayData& data, const DecayOptions& options);

}  // namespace frictionlab
