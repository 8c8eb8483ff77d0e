#pragma once
// IDIM-LS: inverse dynamic model least squares on a measured trajectory,
//   force = M qdd + Fv qd + Fc sign(qd) + offset (+ further terms),
// with the EMPS benchmark recipe (Janot, Gautier, Brunot 2019) as the pipeline:
//   1. qf = zero-phase Butterworth low-pass of the position (order 4, cut-off 100 Hz, odd
//      padding of 12 samples, steady-state initial conditions: MATLAB's filtfilt);
//   2. qd, qdd = central differences of qf and qd (one-sided at the ends), dt = mean step;
//   3. regressor columns (one per term) and y = force; drop the first 49 samples (and
//      optionally some at the end);
//   4. every column and y: scipy.signal.decimate(x, 10) (order-8 Chebyshev I, zero phase);
//   5. optionally leave out the rows with |qd| below exclude_below (near standstill, where the
//      sign of the Coulomb column follows noise); ordinary least squares;
//   6. std from the Newey-West covariance (identify/covariance.hpp: VAR(1) prewhitening, Bartlett
//      kernel, Andrews' bandwidth), which holds for the correlated residuals that filtering, decimation and
//      coloured drive noise leave; std_ols = s sqrt(diag((X'X)^-1)), s^2 = ||e||^2 / (N - p),
//      the recipe's figure, alongside (a lower bound when the residuals are correlated).

#include <Eigen/Core>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "frictionlab/identify/idim_workspace.hpp"
#include "frictionlab/identify/options.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/scenario.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Measured signals of one run (SI units).
struct IdimData {
  Eigen::VectorXd time;      ///< s, length N, strictly increasing and regular
  Eigen::VectorXd position;  ///< m or rad, length N; leave empty to use `velocity` instead
  Eigen::VectorXd velocity;  ///< m/s or rad/s, length N; used (filtered, not differentiated) when position is empty
  Eigen::VectorXd force;     ///< applied force or torque (gain * drive input), N or N m, length N
  /// Load force or torque that the contact transmits (a weight on a vertical screw, a gearbox's
  /// output torque), N or N m, length N; needed by the "load" term, else may stay empty.
  Eigen::VectorXd load;
  /// Temperature of the contact (grease, gearbox), degC or K, length N; needed by the
  /// "temperature" term, else may stay empty.
  Eigen::VectorXd temperature;
  /// Reference position of the closed loop the record was taken in, m or rad, length N; needed by
  /// IDIM-IV (IdimOptions::iv), else may stay empty. The controller samples it at the record's
  /// instants (held between them).
  Eigen::VectorXd reference;
  /// Feedforward force the drive added to its controller's output, N or N m, length N (a
  /// function of the reference only: acceleration, velocity or friction feedforward as the drive
  /// logged it); optional for IDIM-IV, empty when the controller has none.
  Eigen::VectorXd feedforward;
  std::string file;          ///< source file, for results and messages
  std::string sha256;        ///< its digest
};

/// Filtered motion the regressor columns are built from (before dropping and decimating).
/// The vectors are views of the pipeline's work buffers, valid while the columns are built.
struct IdimKinematics {
  using View = Eigen::Map<const Eigen::VectorXd>;
  View q{nullptr, 0};    ///< filtered position, m or rad (empty when velocity was given)
  View qd{nullptr, 0};   ///< velocity, m/s or rad/s
  View qdd{nullptr, 0};  ///< acceleration, m/s^2 or rad/s^2
  View load{nullptr, 0};         ///< IdimData::load as measured (not filtered), N or N m; empty when not given
  View temperature{nullptr, 0};  ///< IdimData::temperature as measured, degC or K; empty when not given
};

/// One regressor column and the parameter multiplying it: force = sum(parameter * column).
/// Add your own through IdimOptions::extra_terms (e.g. a position-dependent friction term).
struct IdimTerm {
  std::string parameter;   ///< parameter name in the result ("M", "Fv", ...)
  Quantity quantity;       ///< gives the unit printed
  std::function<Eigen::VectorXd(const IdimKinematics&)> column;  ///< length N, from the kinematics
  /// Optional: the same column written into `out` (length N) instead of returned; the
  /// built-in terms use it so that a repeated identification allocates no new columns.
  std::function<void(const IdimKinematics&, Eigen::Ref<Eigen::VectorXd> out)> fill = {};
};

/// What the regressors are built from when the data has both a position and a velocity.
enum class IdimSource {
  automatic,  ///< the position when given, else the velocity
  position,   ///< the position, low-passed and differentiated twice
  velocity,   ///< the measured velocity, low-passed like the position (not differentiated), then differentiated once
};

/// Cut-off, decimation and skip chosen from the sample rate fs (Hz), so that a record at any
/// rate gets a working recipe and a 1 kHz record gets exactly the EMPS one (100 Hz, 10, 49):
///   cutoff_hz  = min(100 Hz, fs / 10): the motion band of the EMPS recipe, but never above a
///                fifth of the Nyquist frequency, where the Butterworth would shape the signal;
///   decimation = clamp(floor(fs / 100 Hz), 1, 10): a decimated rate near 100 Hz (the EMPS
///                one), at most 10 because one order-8 Chebyshev stage is not accurate beyond
///                that; the decimation's own anti-alias filter (0.8 of the new Nyquist) bounds
///                the band of both sides of the regression alike;
///   skip       = round(5 fs / cutoff_hz) - 1: five periods of the cut-off, the filter's start
///                transient (49 samples at 1 kHz, 100 Hz).
/// E.g. 100 Hz: 10 Hz, 1, 49; 500 Hz: 50 Hz, 5, 49; 8 kHz: 100 Hz, 10, 399. A rate within 0.1 %
/// below 1 kHz (a resampled jittered log's median step, 1.0001 ms) counts as 1 kHz.
/// \throws std::invalid_argument when fs is not a positive finite number.
struct IdimRateDefaults {
  double cutoff_hz = 100;
  int decimation = 10;
  Eigen::Index skip = 49;
};
IdimRateDefaults idim_rate_defaults(double sample_rate_hz);

/// IDIM-IV: instrumental variables for a record taken in a closed loop (Janot, Vandanjon,
/// Gautier, "A generic instrumental variable approach for industrial robot identification",
/// IEEE TCST 2014). In a closed loop the controller reacts to the disturbance, so the measured
/// acceleration and velocity are correlated with the force's error and least squares is biased.
/// Starting from the least-squares estimate theta_0, each iteration simulates the model's own
/// closed loop (M qdd = F - friction(qd) - offset with the current theta, the exact stick/slip
/// engine, the same controller and reference as the experiment, from the measured initial
/// position), builds the instrument matrix Z from the simulated position exactly as the
/// regressor matrix W is built from the measured one (same filter, differences, skip,
/// decimation, same rows kept), and solves theta_{k+1} = (Z'W)^-1 Z'y; it stops when
/// max_j |theta_{k+1,j} - theta_{k,j}| ||W_j|| / ||W theta_k|| (each parameter's change as a share
/// of the model force) is at most `tolerance`.
struct IdimIvOptions {
  bool enabled = false;  ///< run IDIM-IV after the least-squares fit. Default false.
  /// The experiment's controller: a PID (control/pid.hpp; output in N or N m, the force the drive
  /// applies) or the EMPS controller (control/emps_pd.hpp; output in V, times its gtau). Required
  /// when enabled.
  std::optional<Controller> controller;
  /// Largest number of IV iterations (>= 1). Default 20.
  int max_iterations = 20;
  /// Convergence tolerance on the relative change above (> 0). Default 1e-4.
  double tolerance = 1e-4;
  /// Set the controller's sample period (PidParams::Ts, EmpsPdParams::dt) to the record's mean
  /// step: a drive that logs at its control rate (make_idim_options sets it). Default false.
  bool sample_at_record_rate = false;
  /// Where each of the controller's values came from, by option name ("controller", "kp", "kd",
  /// "ki", "kv", "drive-gain", "control-limit", "control-delay"): "--kp", "--kp Kp: scalar of
  /// FILE", "scenario FILE: controller.Kp", "default" (make_idim_options and the command line
  /// fill it). Reported as diagnostics.texts["iv_source_NAME"] (NAME with '-' as '_'). Empty: not
  /// reported.
  std::map<std::string, std::string> sources;
};

/// The experiment's controller as a scenario file gives it to IDIM-IV (`identify idim --iv
/// --scenario FILE`; idim_iv_scenario): the scenario's own reader (scenario/scenario.hpp) reads
/// it, make_idim_options puts the options given over it.
struct IdimIvScenario {
  Controller controller;  ///< the scenario's PID (position loop) or EMPS controller
  std::string file;       ///< the scenario's file (or the name it goes by), for messages and sources
};

/// The controller of a scenario read by the scenario reader, checked for IDIM-IV, which simulates
/// a rigid axis (M qdd = force - friction - offset) closed by a position-loop PID or the EMPS
/// controller: the scenario's plant must be of type axis with a top-level controller, without a
/// compensation block, and move on `axis` (an axis plant is linear: m, N). EMPS pulses are kept
/// (the simulation adds them as the experiment did). The sample period is the record's when
/// IdimIvOptions::sample_at_record_rate is set (the command line and Python set it).
/// 	hrows InputError (scenario.value, naming `file` and the key: controller, controller.loop,
///         controller.compensation, plant.type) for a scenario without a controller, a velocity
///         loop, a compensation, a two-axis plant, a plant other than an axis, or one whose motion
///         axis is not `axis`.
IdimIvScenario idim_iv_scenario(const Scenario& scenario, const std::string& file, Axis axis);

/// Options of identify_idim; defaults are the EMPS recipe.
struct IdimOptions {
  /// Built-in terms, in column order: "inertia" (M, qdd), "viscous" (Fv, qd), "coulomb" (Fc,
  /// sign(qd)), "offset" (offset, 1), "asymmetric" (= viscous_pos, coulomb_pos, viscous_neg,
  /// coulomb_neg: Fv_pos qd (qd>0), Fc_pos (qd>0), Fv_neg qd (qd<0), Fc_neg -(qd<0)), each of
  /// those four alone, and "stribeck" (Fs_minus_Fc, sign(qd) exp(-|qd/vs|^delta), with
  /// stribeck_vs and stribeck_delta). Terms of the conditions, linear in their parameters:
  ///   "load" (IdimData::load L needed): load_gain L (dimensionless: 1 when the load acts on the
  ///     axis like a weight, 0 when it only presses the contact like a preload) and
  ///     mu_load |L| sign(qd) (dimensionless: the Coulomb level grows as Fc + mu_load |L|);
  ///   "temperature" (IdimData::temperature T needed): Fv_per_K qd (T - temperature_ref)
  ///     (N s/m/K or N m s/rad/K: the viscous coefficient is Fv + Fv_per_K (T - T_ref));
  ///   "ripple" (a position needed; ripple_period P): ripple_sin_k sin(2 pi k q / P) and
  ///     ripple_cos_k cos(2 pi k q / P), k = 1 .. ripple_harmonics (N or N m: a force that
  ///     repeats with position, e.g. cogging or a screw's pitch).
  /// Default: inertia, viscous, coulomb, offset.
  std::vector<std::string> terms = {"inertia", "viscous", "coulomb", "offset"};
  /// Further terms appended after `terms`.
  std::vector<IdimTerm> extra_terms;
  /// Position low-pass cut-off, Hz. Default 100.
  double cutoff_hz = 100.0;
  /// Butterworth order. Default 4.
  int filter_order = 4;
  /// Odd padding of the zero-phase low-pass, samples. Default 12 = 3 * (order + 1 - 1) (MATLAB).
  Eigen::Index padlen = 12;
  /// Samples by which the applied force lags the recorded drive input: y(k) = force(k - delay).
  /// EMPS: 1, because its controller output is applied one sample later. Default 0 (recipe).
  Eigen::Index input_delay = 0;
  /// Samples dropped at the start after differentiation. Default 49.
  Eigen::Index skip = 49;
  /// Samples dropped at the end, after differentiation. Default 0 (EMPS ends at rest). Records
  /// that end in motion need some: the one-sided differences there give a wrong acceleration.
  Eigen::Index skip_end = 0;
  /// Decimation factor (1: none). Default 10.
  int decimation = 10;
  /// Stribeck velocity (m/s or rad/s, > 0) and exponent of the "stribeck" term. Defaults 0.01, 2.
  double stribeck_vs = 0.01;
  /// Search the Stribeck velocity instead: the value that minimises the identification residual,
  /// the best of a 40-point log grid from 1e-4 to 0.5 of the top speed refined by a golden-section
  /// search between its neighbours (m/s or rad/s); reported as diagnostics "stribeck_vs".
  bool search_stribeck_vs = false;
  double stribeck_delta = 2.0;
  /// Period P of the "ripple" term, m or rad (> 0 when the term is used). Default 0 (none).
  double ripple_period = 0.0;
  /// Harmonics K of the "ripple" term (>= 1). Default 1.
  int ripple_harmonics = 1;
  /// Reference temperature T_ref of the "temperature" term, in the temperature column's unit
  /// (degC or K); NaN: the mean temperature over the used samples. The result reports the value
  /// used as diagnostics.numbers["temperature_ref"]. Default NaN.
  double temperature_ref = std::numeric_limits<double>::quiet_NaN();
  /// No excitation when max |qd| over the used samples is not above this, m/s or rad/s. Default 0.
  double min_velocity = 0.0;
  /// Leave out of the regression the rows (after decimation) whose filtered |qd| is below this,
  /// m/s or rad/s (0: keep all). Near standstill the Coulomb column's sign follows noise and a
  /// stuck axis's force is anywhere within the static level: such rows bias Fc. The result
  /// reports diagnostics "exclude_below" and "excluded_samples". Default 0 (the EMPS recipe).
  double exclude_below = 0.0;
  /// Status error when the condition number of the column-normalised regressor exceeds this.
  /// Default 1e8.
  double max_condition = 1e8;
  /// Units printed. Default linear.
  Axis axis = Axis::linear;
  /// Take cutoff_hz, decimation and skip from idim_rate_defaults of the data's sample rate
  /// instead of the fields above (the command line sets these for options not given). The
  /// result lists the values so chosen in diagnostics.groups["defaults"]. Default false.
  bool auto_cutoff = false, auto_decimation = false, auto_skip = false;
  /// What the regressors are built from (IdimData may hold both). Default automatic.
  IdimSource source = IdimSource::automatic;
  /// Instrumental variables for closed-loop data (IDIM-IV, above). Default off.
  IdimIvOptions iv;
};

/// The options of an IDIM run from the values of its option table (method_info(MethodId::idim));
/// the table's defaults where a value is not given; cutoff, decimate and skip not given are
/// chosen from the sample rate (auto_cutoff, auto_decimation, auto_skip). The second file of
/// --validate and the axis are the caller's.
IdimOptions make_idim_options(const OptionValues& values);
/// The same, with IDIM-IV's controller from a scenario (idim_iv_scenario; null: none): its type,
/// gains, limit and delay, each replaced by the option when one is given (--controller must then
/// name the scenario's type). IdimIvOptions::sources says where each value came from.
/// 	hrows InputError (option.conflict) for a --controller of another type than the scenario's
///         (naming the file and controller.type), a gain of the other type's, a scenario without
///         --iv; (option.invalid) for a gain that is still a scalar name (the command line resolves
///         those against the data file first) and as make_idim_options.
IdimOptions make_idim_options(const OptionValues& values, const IdimIvScenario* scenario);

/// The regression the recipe builds: decimated regressor matrix, decimated force, and the terms.
struct IdimRegression {
  Eigen::MatrixXd X;                    ///< N_used x p
  Eigen::VectorXd y;                    ///< N_used, N or N m
  std::vector<IdimTerm> terms;          ///< p terms, column order
  double dt = 0;                        ///< s, mean sample step of the raw data
  double max_speed = 0;                 ///< max |qd| over the used raw samples, m/s or rad/s
  /// The raw sample (0-based index into IdimData) of each row of X: skip + k * decimation, less
  /// the rows left out by exclude_below.
  std::vector<Eigen::Index> sample;
  Eigen::Index excluded = 0;  ///< rows left out by exclude_below
};

/// The terms `options` asks for, in column order.
/// \throws std::invalid_argument naming an unknown term (and listing the known ones), a
///         repeated parameter, or a non-positive stribeck_vs.
std::vector<IdimTerm> idim_terms(const IdimOptions& options);

/// Steps 1-4 of the recipe on one data set.
/// \throws std::invalid_argument naming the file and the problem for unequal lengths, non-finite
///         samples, non-increasing or irregular time, no position and no velocity (or not the one
///         options.source asks for), a cut-off at or above Nyquist, or too few samples for the
///         padding, skip and decimation.
IdimRegression idim_regression(const IdimData& data, const IdimOptions& options = {});
/// The same in the caller's work space (identify/idim_workspace.hpp); the same numbers.
IdimRegression idim_regression(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace);

/// Identifies the parameters of the terms by the recipe. Status error (not an exception), with a
/// message naming the cause, when the data cannot give an answer: a regressor column that is zero
/// (no motion, no acceleration), no excitation (velocity never above min_velocity), a force that
/// is zero throughout (e.g. a drive gain of 0), fewer samples than parameters, a condition number
/// above max_condition, or fit figures that are not finite. Standard deviations and the
/// correlation matrix come from identify/uncertainty.hpp (std NaN for undetermined parameters)
/// with the Newey-West covariance of identify/covariance.hpp; each parameter's std_ols is the
/// ordinary least-squares figure. diagnostics.texts["covariance"] is "newey-west-prewhitened"
/// (or "newey-west" on records too short to prewhiten), diagnostics.numbers
/// "covariance_bandwidth" its lag count (decimated samples) and "covariance_rho" the AR(1)
/// coefficient its bandwidth rule used.
/// diagnostics.texts["regressors_from"] is "position" or "velocity".
/// With options.iv.enabled (IDIM-IV, IdimIvOptions): the values are the IV estimate, std its
/// Newey-West IV sandwich and std_ols its ordinary IV figure (identify/uncertainty.hpp,
/// set_uncertainty_from_iv); diagnostics.texts["estimator"] "idim-iv" (else "idim-ls"),
/// numbers "iv_iterations", "iv_relative_change" (the last), "iv_min_canonical_correlation" (the
/// smallest canonical correlation between Z and W: the instruments' relevance, 1 = perfect),
/// groups "iv_instrument_correlation" (per parameter, the correlation of its regressor column
/// with its instrument), "ls_estimate" (the least-squares values) and "iv_controller" (the values
/// the simulation ran: pid kp, kd, ki; emps-pd kp, kv, drive_gain; both control_limit,
/// control_delay, sample_period s), texts "iv_controller_type" (pid or emps-pd) and
/// "iv_source_NAME" (IdimIvOptions::sources: where each value came from). Status error, naming the
/// cause and what to change, when the iteration does not converge in max_iterations, a model's
/// simulation fails or diverges, or an estimate makes no model that can be simulated (M <= 0, a
/// negative friction level).
/// \throws std::invalid_argument on bad input, as idim_regression; with options.iv.enabled also
///         without a controller, without a reference (naming what to give), for a reference or
///         feedforward of another length than time or not finite, and for terms IDIM-IV cannot
///         simulate (load, temperature, ripple, user terms).
Result identify_idim(const IdimData& data, const IdimOptions& options = {});
/// The same in the caller's work space (identify/idim_workspace.hpp), for identifications in a
/// loop; the same result, to the bit. \throws as above; std::bad_alloc when it cannot grow.
Result identify_idim(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace);

/// Relative force error of an identified parameter set on a second run processed by the same
/// pipeline (same options; terms are taken from `options`, values from `identified` by name).
/// \throws std::invalid_argument when `identified` is not ok or lacks a parameter of a term, and
///         as idim_regression for bad data.
ValidationFigures cross_test(const Result& identified, const IdimData& data, const IdimOptions& options = {});
/// The same in the caller's work space (identify/idim_workspace.hpp); the same figures.
ValidationFigures cross_test(const Result& identified, const IdimData& data, const IdimOptions& options,
                             IdimWorkspace& workspace);

}  // namespace frictionlab
