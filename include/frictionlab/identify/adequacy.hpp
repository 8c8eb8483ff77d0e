#pragma once
// Model adequacy: does the identified model fit the data, or is something left in the residual?
// The residual (measured less modelled force) of a fit that captures the physics is noise: no
// trend against velocity, position or time, and little memory. Friction that the model lacks
// shows as structure: a Stribeck dip as a residual of the velocity's sign at low speed, an
// asymmetry as a mean that differs by direction, a ripple as a pattern against position. These
// checks bin the residual and compare each bin's mean with its standard error, computed from an
// effective sample size that accounts for the residual's autocorrelation (filtered, decimated
// and closed-loop data are never white).

#include <cstddef>
#include <string>
#include <vector>

#include "frictionlab/identify/result.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// What the findings advise, in the terms of the method whose residual is checked. The defaults
/// are idim's (a trajectory fitted sample by sample).
struct AdequacyAdvice {
  /// Friction at low speed above the model.
  std::string stribeck = "add the Stribeck term (idim: --terms inertia,viscous,coulomb,offset,stribeck) or identify "
                         "from constant-speed runs (sweep)";
  /// Friction at low speed below the model, both directions.
  std::string shape = "the friction-velocity curve is not the model's shape (sweep maps it point by point)";
  /// A friction level that differs by direction.
  std::string asymmetry = "use direction-dependent terms (idim: --terms inertia,asymmetric)";
  /// A residual correlated from sample to sample: the std that assume these residuals independent
  /// (named in the finding, which says how many times too small they are) and what to do. Empty
  /// `correlated_std`: not reported (a method whose std do not come from these residuals, such as
  /// sweep's, fitted to its segments' means).
  std::string correlated_std = "standard deviations that assume independent residuals (idim's std_ols)";
  std::string correlated_remedy = "idim's std accounts for the correlation";
  /// Report a large share of samples near standstill (with idim's --exclude-below remedy); false
  /// for a method whose samples are in motion by construction.
  bool standstill = true;
};

/// Settings of the residual checks.
struct AdequacyOptions {
  /// Bins of |velocity| per direction, equal counts each. Default 6.
  std::size_t velocity_bins = 6;
  /// Bins of position, equal counts each. Default 8.
  std::size_t position_bins = 8;
  /// Autocorrelation lags reported (samples). Default 10.
  std::size_t max_lag = 10;
  /// A bin's mean counts as structure when it is more than this many standard errors from zero
  /// (standard errors from the effective sample size). Default 4: with some 20 bins, a white
  /// residual passes with probability above 0.999.
  double significance = 4.0;
  /// ... and when it is also more than this fraction of the residual's standard deviation over the
  /// moving samples (|v| above the standstill speed): with many samples a tiny, harmless trend is
  /// significant. Default 0.25.
  double relevance = 0.25;
  /// The fitted force's scale (N or N m, e.g. its rms), and the share of it below which a trend is
  /// too small to matter whatever its significance. Defaults 0 (unused) and 0.02.
  double force_scale = 0.0;
  double force_share = 0.02;
  /// Velocities with |v| below this fraction of the largest |v| count as near standstill, where
  /// Coulomb friction's sign is not known. Default 0.02.
  double standstill_fraction = 0.02;
  /// The residual as consecutive segments (a sweep's steady runs): the end (exclusive) of each,
  /// the last equal to the residual's length. The autocorrelation, and so the effective sample
  /// size, is then taken within segments around each segment's mean, so that a segment's offset
  /// from the model counts as structure, not as memory of the noise. Empty (default): one series.
  std::vector<std::size_t> segment_ends{};
  /// The remedies the findings name.
  AdequacyAdvice advice{};
};

/// One bin of the residual against a signal.
struct ResidualBin {
  double centre = 0;          ///< the signal's median in the bin (its unit)
  double mean = 0;            ///< the residual's mean in the bin (force unit)
  double standard_error = 0;  ///< of that mean, from the effective sample size (force unit)
  std::size_t samples = 0;
};

/// The residual checks of one fit.
struct Adequacy {
  std::vector<ResidualBin> by_velocity;  ///< negative velocities first, by increasing velocity
  /// Against position and time: the residual less its velocity bin's mean (a velocity effect of
  /// moves made at different places and times is not counted twice).
  std::vector<ResidualBin> by_position;
  std::vector<ResidualBin> by_time;
  std::vector<double> autocorrelation;   ///< lags 1..max_lag
  double residual_std = 0;               ///< force unit
  std::size_t samples = 0;
  double effective_samples = 0;          ///< samples / (1 + 2 sum of positive-lag autocorrelations)
  double standstill_speed = 0;           ///< the |v| below which a sample is near standstill
  double standstill_share = 0;           ///< fraction of samples near standstill
  /// Findings in words an engineer acts on: what is wrong and what to do. Empty: no structure found.
  std::vector<std::string> findings;
};

/// The fewest samples assess_residuals checks (fewer: the fits skip the check).
inline constexpr std::size_t kAdequacyMinSamples = 20;

/// Checks the residual of a fit against velocity, position and time.
/// \param velocity, position, time  the fit's samples (m/s or rad/s, m or rad, s), one per residual;
///        position and time may be empty (those checks are then skipped).
/// \param residual  measured less modelled force (N or N m), the fit's samples.
/// \param force_unit, velocity_unit  units for the findings' text ("N", "m/s").
/// \param options  the checks' settings.
/// \throws std::invalid_argument when the lengths differ, there are fewer than 20 samples, or
///         options.segment_ends do not end at the residual's length.
Adequacy assess_residuals(const std::vector<double>& velocity, const std::vector<double>& position,
                          const std::vector<double>& time, const std::vector<double>& residual,
                          const std::string& force_unit, const std::string& velocity_unit,
                          const AdequacyOptions& options = {});

/// Writes the checks into a result: diagnostics.lists "residual_by_velocity", "residual_by_position",
/// "residual_by_time" (centre, mean, standard_error, samples each), diagnostics.groups["adequacy"]
/// (residual_std, samples, effective_samples, standstill_speed, standstill_share, lag-1
/// autocorrelation), the autocorrelation as list "residual_autocorrelation", and each finding as a
/// warning.
void add_adequacy(Result& result, const Adequacy& adequacy);

}  // namespace frictionlab
