#pragma once
// Automatic identification: look at a record, say what experiment it holds, fit every candidate
// structure the data support, and choose among them by the error with which each predicts
// held-out data (identify/selection.hpp): K contiguous time blocks of the record, or a second
// record. First, on the raw samples, the experiments a trajectory method must not be fitted to:
//   a free decay (the drive force constant or unrelated to the motion, 3 reversals or more):
//     decay, with the natural frequency from the half periods (Fc/k and zeta; Fc and Fv with the
//     stiffness); a coast-down (fewer reversals) is refused with the reason
//   a slow ramp of force with stick (at rest for 5 % of the record or more while |force| rises):
//     breakaway; if it refuses the record, the trajectory candidates below
//   presliding (displacement a monotone function of the force): sigma0 from the steady presliding
//     curve, and a warning naming lugre for the rest
// Otherwise the trajectory candidates (constant-speed plateaus a sweep can use; a trajectory with
// accelerations the inverse dynamic model can use):
//   idim coulomb-viscous      terms inertia, viscous, coulomb, offset
//   idim stribeck             the same and stribeck, vs searched (on the training blocks only)
//   idim asymmetric           terms inertia, asymmetric
//   sweep coulomb-viscous + M  a law fitted to the plateaus' means, then M and offset by least
//   sweep stribeck + M         squares of the drive force less that law (sweep alone has no M)
// The sweep candidates need constant-speed plateaus (identify/sweep.hpp finds them on the
// filtered velocity); each candidate's held-out error is on the drive force, so all compare alike.
// A candidate whose estimates are not physical (Fs below Fc, vs <= 0, a negative Fc, Fv or M) is
// refused with the reason and never returned.

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/models/parameter.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of identify_auto.
struct AutoOptions {
  /// The IDIM recipe the trajectory candidates share (filter, decimation, skip, delay, source);
  /// its terms are ignored (each candidate sets its own). Default: idim's defaults with cut-off,
  /// decimation and skip chosen from the sample rate.
  IdimOptions idim = [] {
    IdimOptions o;
    o.auto_cutoff = o.auto_decimation = o.auto_skip = true;
    return o;
  }();
  /// How plateaus are found (its fit.model is set per candidate). Default: sweep's defaults.
  SweepOptions sweep;
  /// Contiguous time blocks of the cross-validation, >= 2. Default 4: each block a quarter of the
  /// record, so every fit sees three quarters of the moves (fewer blocks: less data per fit;
  /// more: blocks too short to hold a whole move).
  int folds = 4;
  /// Samples whose filtered speed is at most this fraction of the largest are left out of every
  /// candidate's fit and held-out error (as the residual check's standstill speed,
  /// identify/adequacy.hpp): at standstill friction is any value within +-Fs and the sign of the
  /// velocity follows noise, so no friction structure predicts them. Default 0.02.
  double standstill_fraction = 0.02;
  /// A second record of the same axis: when given, each candidate (fitted on the whole first
  /// record) is judged by its error on this one instead of by the blocks.
  std::optional<IdimData> heldout;
  /// Stiffness of a free decay's restoring force (N/m, or N m/rad; m g l for a pendulum), as
  /// decay's --stiffness: with it a decay found in the record reports Fc and Fv in force units
  /// instead of Fc/k and zeta. Not used by the other experiments (a warning says so). NaN: not given.
  double stiffness = std::numeric_limits<double>::quiet_NaN();
  /// Units printed. Default linear.
  Axis axis = Axis::linear;
};

/// The options from the values of auto's option table (method_info(MethodId::automatic)); the second
/// record and the axis are the caller's.
AutoOptions make_auto_options(const OptionValues& values);

/// A free decay, a breakaway ramp or presliding (see above): the Result is that method's (decay,
/// breakaway, or the presliding fit: sigma0 in N/m or N m/rad) with method auto, texts
/// "experiment" and "choice", its candidate first in the selection, chosen (refused with the
/// method's message when it failed); on a decay and a breakaway ramp the selection goes on with
/// the trajectory candidates as runners-up (breakaway: each fitted and judged as below; decay:
/// each with the reason it was not run); a coast-down: status error with the reason.
/// Otherwise identifies `data` by the candidate with the lowest held-out drive-force error. The Result is
/// the chosen candidate's (parameters with std and units, law, fit figures, signals), with method
/// auto; diagnostics.texts "experiment" (what the record holds), "choice" (the candidate and why),
/// "candidate N" (each one: held-out and training error, status, the refusal reason);
/// diagnostics.lists["selection"] one record per candidate (candidate, heldout_error_percent,
/// training_error_percent, chosen, refused, block_N_percent); json_sections["diagnostics.selection"]
/// the same with names and reasons (selection_json; MODEL.json diagnostics.selection, schema 2). An
/// idim candidate's result is identify_idim's own on the samples in motion (exclude_below at the
/// standstill speed, reported; vs searched as by search_stribeck_vs), so its std is idim's
/// Newey-West std; with options.heldout, `validation` holds the chosen
/// candidate's error on the second record (samples in motion). Status error naming each candidate's refusal when
/// none can be chosen.
/// \throws std::invalid_argument for bad data, as identify_idim (naming the file) or as decay
///         (irregular time), or folds < 2.
Result identify_auto(const IdimData& data, const AutoOptions& options = {});

}  // namespace frictionlab
