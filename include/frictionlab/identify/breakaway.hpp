#pragma once
// The friction lecture's torque-mode trapezoid experiment: drive a motor with a slow current
// ramp up, a hold and a ramp down, record velocity, and read off static friction (at motion
// onset), Coulomb friction (at the return to standstill) and the viscous coefficient (from
// the hold). The read-offs ignore inertia and so bias Fc and Fv by a few percent; this method
// also fits the rotor dynamics over the whole sliding record, which does not.

#include <Eigen/Core>
#include <limits>

#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Samples of a trapezoid experiment. Shapes: all of length N, time strictly increasing and
/// regularly sampled (s). `force` is the drive torque or force (N m or N: Kt times current).
struct BreakawayData {
  Eigen::VectorXd time;      ///< s
  Eigen::VectorXd force;     ///< N m or N
  Eigen::VectorXd velocity;  ///< rad/s or m/s
  /// The load the contact transmits (N m or N), optional (empty: none; else length N). When
  /// given, the levels grow with |load| (models/load_dependence.hpp): see identify_breakaway.
  Eigen::VectorXd load;
};

struct BreakawayOptions {
  /// Inertia (kg m^2 or kg): held at this value when finite and > 0; estimated with Fc and Fv
  /// (reported as M) when NaN (the default).
  double inertia = std::numeric_limits<double>::quiet_NaN();
  /// |v| above which the axis counts as moving (rad/s or m/s). Default (NaN): 1 % of max |v|.
  /// Trade-off: too low and sensor noise looks like motion; too high delays the onset read-off.
  double velocity_threshold = std::numeric_limits<double>::quiet_NaN();
  /// Samples skipped at each end of a sliding interval in the dynamic fit: the velocity has a
  /// kink at a stick/slip switch, where a central difference is wrong. Default 2.
  int edge_samples = 2;
  Axis axis = Axis::linear;  ///< units of the report. Default linear, as every method (Axis::rotary for a motor)
};

/// The options of a breakaway run from the values of its option table
/// (method_info(MethodId::breakaway)); the table's defaults where a value is not given. The axis
/// is the caller's to set.
BreakawayOptions make_breakaway_options(const OptionValues& values);

/// Identifies Fs, Fc, Fv (and M when no inertia is given) from a trapezoid experiment.
/// parameters: the dynamic estimate (Fc, Fv by least squares of M a + Fv v + Fc sign(v) = force
/// over the sliding samples; Fs as the force at the instant motion began, found by integrating
/// that fitted model back from the first moving sample to v = 0). The acceleration is the
/// velocity's central difference over +-w samples, w (diagnostics "acceleration_half_width") the
/// smallest power of two, up to 64, whose noise (from the velocity's, "velocity_noise", m/s or
/// rad/s, on its second differences) is below 5 % of the acceleration's spread: a velocity
/// differentiated from an encoder would otherwise bias M towards zero (errors in variables).
/// std: Fc, Fv (and M) from the Newey-West covariance of the sliding fit (identify/covariance.hpp,
/// diagnostics "covariance", "covariance_bandwidth"), the ordinary least-squares figure as std_ols;
/// with w > 1 the estimate is made on the fit's scores summed over blocks of w/4 rows (diagnostics
/// "covariance_block", rows; "covariance_bandwidth" is then in blocks), which the acceleration's
/// noise would otherwise make some 10 to 25 % small. With w > 1 and M fitted, the fit is made
/// again with the difference over +-w/2: each parameter's change (diagnostics "width_change",
/// its unit) measures the systematic error the difference leaves (M's errors-in-variables bias,
/// the smoothing at the force's corners), which the std do not include; a warning names every
/// parameter whose change exceeds its std.
/// Fs's from that covariance through the backward integration plus the variance of the force
/// sample read at the breakaway instant (the sliding residual's variance); with data.load, Fs's
/// and mu_load_static's from the starts' scatter. The sliding residual is checked for adequacy
/// (identify/adequacy.hpp).
/// diagnostics.readoff: the lecture's read-offs {"Fs", "Fc", "Fv"}, and the times of onset,
/// hold and stop. A record without a stuck start, without motion or without a return to
/// standstill gives status "error" with a message saying which.
///
/// With data.load: the sliding fit gains the column |load| sign(v) (mu_load_coulomb, dimensionless;
/// Fc is then the Coulomb level at zero load), and every start from rest in the record gives a
/// breakaway force (the fitted dynamics integrated back, at that start's load); the breakaway
/// forces against the |load| at each start give Fs at zero load and mu_load_static by least
/// squares. Needs at least 3 starts from rest whose loads differ by more than 1 % of the largest,
/// and sliding samples whose |load| differs as much, or status "error" says which is missing.
/// diagnostics.lists["breakaways"]: each start's time, load and breakaway force. result.law
/// carries mu_load_static and mu_load_coulomb when they form a law (mu_load_static >=
/// mu_load_coulomb >= 0), else a warning says why not.
/// Figures that overflow double precision (values or scales beyond what it holds) give status
/// "error" with code "output.not_finite" naming the figure (finite_or_error,
/// identify/finite_result.hpp), never an ok result with inf in it.
/// \throws std::invalid_argument on unequal lengths (the load's included), non-finite samples or
///         irregular time.
Result identify_breakaway(const BreakawayData& data, const BreakawayOptions& options = {});

}  // namespace frictionlab
