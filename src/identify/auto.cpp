#include "frictionlab/identify/auto.hpp"
#include "frictionlab/identify/finite_result.hpp"

#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/covariance.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/selection.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "idim_stribeck.hpp"
#include "method_support.hpp"

namespace frictionlab {
using namespace detail;

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::auto_method_info() {
  const AutoOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "model selection: every method and structure the record supports, chosen by held-out error";
  m.fit_signal = "drive force";
  m.fit_quantity = Quantity::force;
  m.options = {
      {.name = "folds", .type = OptionType::integer, .default_value = static_cast<long long>(d.folds),
       .help = "Contiguous time blocks of the cross-validation: each candidate is fitted on all blocks but one and "
               "predicts the drive force of that one, in turn (more blocks: more data per fit, shorter held-out "
               "blocks)",
       .min = 2, .applies_if = {unless_given("validate")}},
      {.name = "from", .type = OptionType::text,
       .help = "What the trajectory candidates' regressors are built from when the data has both: position or "
               "velocity. Default: position, or velocity when only a velocity is given",
       .words = {"position", "velocity"}},
      {.name = "delay", .type = OptionType::integer, .unit = "samples",
       .default_value = static_cast<long long>(d.idim.input_delay),
       .help = "Samples by which the applied force lags the recorded input", .min = 0},
      {.name = "skip-end", .type = OptionType::integer, .default_value = static_cast<long long>(d.idim.skip_end),
       .help = "Samples dropped at the end (a record that ends in motion needs some)", .min = 0},
      {.name = "min-duration", .type = OptionType::number, .unit = "s", .default_value = d.sweep.min_duration,
       .help = "Shortest constant-speed plateau that counts for the sweep candidates", .min = 0, .min_open = true},
      {.name = "validate", .type = OptionType::file,
       .help = "Second data file of the same axis: candidates are judged by their drive-force error on it instead "
               "of by the time blocks (Python: a dict with time, force and position or velocity)"},
      [] {  // decay's own entry: the same name, unit and range
        OptionSpec s = decay_stiffness_option();
        s.help = "Restoring stiffness (m g l for a pendulum) of a free decay found in the record: decay then reports "
                 "Fc and Fv in force units instead of Fc/k and zeta; not used by the other experiments";
        return s;
      }(),
  };
  return m;
}
#pragma GCC diagnostic pop

AutoOptions make_auto_options(const OptionValues& v) {
  AutoOptions o;
  o.folds = static_cast<int>(v.integer("folds"));
  const std::string from = v.text("from");
  o.idim.source = from == "position" ? IdimSource::position : from == "velocity" ? IdimSource::velocity : IdimSource::automatic;
  o.idim.input_delay = static_cast<Eigen::Index>(v.integer("delay"));
  o.idim.skip_end = static_cast<Eigen::Index>(v.integer("skip-end"));
  o.sweep.min_duration = v.number("min-duration");
  o.stiffness = v.number("stiffness");
  return o;
}

namespace {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

const std::vector<std::string> kCoulombViscous = {"inertia", "viscous", "coulomb", "offset"};
const std::vector<std::string> kStribeck = {"inertia", "viscous", "coulomb", "offset", "stribeck"};
const std::vector<std::string> kAsymmetric = {"inertia", "asymmetric"};

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ",") + w;
  return s;
}

Eigen::Index column_of(const IdimRegression& reg, const std::string& parameter) {
  for (std::size_t j = 0; j < reg.terms.size(); ++j)
    if (reg.terms[j].parameter == parameter) return static_cast<Eigen::Index>(j);
  throw std::logic_error("identify_auto: no regressor column for " + parameter);
}

// Rows of X and y outside [b, e).
void training_rows(const Mat& X, const Vec& y, Eigen::Index b, Eigen::Index e, Mat& Xt, Vec& yt) {
  const Eigen::Index n = X.rows();
  Xt.resize(n - (e - b), X.cols());
  yt.resize(n - (e - b));
  Xt << X.topRows(b), X.bottomRows(n - e);
  yt << y.head(b), y.tail(n - e);
}

// Held-out errors of idim with the stribeck term, vs searched on each training set alone.
HeldOutErrors stribeck_heldout(const std::vector<IdimRegression>& regs, const std::vector<SampleBlock>& blocks) {
  HeldOutErrors out;
  Mat Xt;
  Vec yt;
  for (const auto& [b, e] : blocks) {
    const Vec& y = regs.front().y;
    out.signal_squares.push_back(y.segment(b, e - b).squaredNorm());
    out.samples += static_cast<std::size_t>(e - b);
    double best_train = std::numeric_limits<double>::infinity(), best_test = std::numeric_limits<double>::quiet_NaN();
    for (const auto& reg : regs) {
      training_rows(reg.X, reg.y, b, e, Xt, yt);
      const Eigen::ColPivHouseholderQR<Mat> qr(Xt);
      if (qr.rank() < Xt.cols()) continue;
      const Vec theta = qr.solve(yt);
      const double train = (yt - Xt * theta).squaredNorm();
      if (train < best_train) {
        best_train = train;
        best_test = (reg.y.segment(b, e - b) - reg.X.middleRows(b, e - b) * theta).squaredNorm();
      }
    }
    out.error_squares.push_back(best_test);
  }
  return out;
}

// The friction of `law` at each velocity (0 at rest: the sign convention of idim's columns).
Vec law_force(const FrictionLaw& law, const Vec& v) {
  Vec F(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) F(i) = v(i) == 0.0 ? 0.0 : law.sliding(v(i));
  return F;
}

// M and offset by least squares of (y - friction) on [qdd, 1] over the rows `use` (all when
// empty); their std from the residual variance. Returns {theta, std}.
std::pair<Eigen::Vector2d, Eigen::Vector2d> inertia_offset(const Vec& qdd, const Vec& rest,
                                                           const std::vector<Eigen::Index>& rows) {
  Mat A(static_cast<Eigen::Index>(rows.size()), 2);
  Vec b(A.rows());
  for (Eigen::Index k = 0; k < A.rows(); ++k) {
    A(k, 0) = qdd(rows[static_cast<std::size_t>(k)]);
    A(k, 1) = 1.0;
    b(k) = rest(rows[static_cast<std::size_t>(k)]);
  }
  const Eigen::ColPivHouseholderQR<Mat> qr(A);
  Eigen::Vector2d theta = qr.solve(b);
  Eigen::Vector2d sd = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (A.rows() > 2 && qr.rank() == 2) {
    const double s2 = (b - A * theta).squaredNorm() / static_cast<double>(A.rows() - 2);
    const Mat cov = s2 * (A.transpose() * A).inverse();
    sd = cov.diagonal().cwiseSqrt();
  }
  return {theta, sd};
}

std::vector<Eigen::Index> all_rows_but(Eigen::Index n, Eigen::Index b, Eigen::Index e) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < n; ++i)
    if (i < b || i >= e) rows.push_back(i);
  return rows;
}

// A sweep candidate: the law fitted to the plateau points, M and offset from the trajectory.
SelectionCandidate sweep_candidate(StaticFitModel model, const std::string& model_name,
                                   const std::vector<SweepPoint>& points, const IdimRegression& cv,
                                   const std::vector<double>& row_time, const std::vector<SampleBlock>& blocks,
                                   const std::optional<IdimRegression>& second, Axis axis) {
  SelectionCandidate c;
  const MethodInfo& sweep = method_info(MethodId::sweep);
  c.method = sweep.name;
  c.name = sweep.name + " " + model_name + " + M";
  c.structure = model_name + " law on the plateaus; M, offset by least squares on the trajectory";
  const Eigen::Index iM = column_of(cv, "M"), iv = column_of(cv, "Fv");
  const Vec qdd = cv.X.col(iM), qd = cv.X.col(iv);
  StaticFitOptions fo;
  fo.model = model;
  const auto fit_points = [&](const std::vector<const SweepPoint*>& pts) {
    Vec v(static_cast<Eigen::Index>(pts.size())), F(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = pts[static_cast<std::size_t>(i)]->velocity, F(i) = pts[static_cast<std::size_t>(i)]->force;
    return fit_static_law(v, F, fo);
  };
  std::vector<const SweepPoint*> all;
  for (const auto& p : points) all.push_back(&p);
  Result& r = c.result;
  r = new_result(sweep, model_name, axis);
  try {
    const StaticFit fit = fit_points(all);
    const Vec friction = law_force(fit.law, qd);
    std::vector<Eigen::Index> rows = all_rows_but(cv.y.size(), 0, 0);
    const auto [theta, sd] = inertia_offset(qdd, cv.y - friction, rows);
    for (Parameter p : fit.parameters) {
      p.unit = std::string(unit(p.quantity, axis));
      r.parameters.push_back(p);
    }
    add_parameter(r, "M", theta(0), sd(0), Quantity::inertia, axis);
    add_parameter(r, "offset", theta(1), sd(1), Quantity::force, axis);
    const Vec model_force = qdd * theta(0) + Vec::Constant(qdd.size(), theta(1)) + friction;
    set_fit(r, cv.y, model_force);
    r.law = fit.law.to_spec();
    r.diagnostics.warnings = fit.warnings;
    r.diagnostics.undetermined = fit.undetermined;
    r.diagnostics.at_bound = fit.at_bound;
    r.diagnostics.correlation = fit.correlation;
    r.diagnostics.numbers["plateaus"] = static_cast<double>(points.size());
    r.series["time"] = row_time;
    r.series["force"].assign(cv.y.data(), cv.y.data() + cv.y.size());
    r.series["force_model"].assign(model_force.data(), model_force.data() + model_force.size());
    c.training_error_percent = r.fit.relative_error_percent;
  } catch (const std::invalid_argument& e) {
    fail(r, std::string("the law could not be fitted to the plateaus: ") + e.what());
    return c;
  }
  HeldOutErrors h;
  if (second) {
    const FrictionLaw law = FrictionLaw::from_spec(*r.law);
    const Vec q2 = second->X.col(column_of(*second, "Fv")), a2 = second->X.col(column_of(*second, "M"));
    const Vec pred = a2 * r.value("M") + Vec::Constant(a2.size(), r.value("offset")) + law_force(law, q2);
    h.error_squares.push_back((second->y - pred).squaredNorm());
    h.signal_squares.push_back(second->y.squaredNorm());
    h.samples = static_cast<std::size_t>(second->y.size());
  } else {
    for (const auto& [b, e] : blocks) {
      h.signal_squares.push_back(cv.y.segment(b, e - b).squaredNorm());
      h.samples += static_cast<std::size_t>(e - b);
      // Plateaus wholly outside the held-out block's time span.
      const double tb = row_time[static_cast<std::size_t>(b)], te = row_time[static_cast<std::size_t>(e - 1)];
      std::vector<const SweepPoint*> pts;
      for (const auto& p : points)
        if (p.t_end < tb || p.t_begin > te) pts.push_back(&p);
      try {
        const StaticFit fit = fit_points(pts);
        const Vec friction = law_force(fit.law, qd);
        const auto [theta, sd] = inertia_offset(qdd, cv.y - friction, all_rows_but(cv.y.size(), b, e));
        const Vec pred = qdd.segment(b, e - b) * theta(0) + Vec::Constant(e - b, theta(1)) + friction.segment(b, e - b);
        h.error_squares.push_back((cv.y.segment(b, e - b) - pred).squaredNorm());
      } catch (const std::invalid_argument&) {
        h.error_squares.push_back(std::numeric_limits<double>::quiet_NaN());  // too few plateaus outside the block
      }
    }
  }
  c.heldout_error_percent = h.relative_error_percent();
  c.block_errors_percent = h.block_errors_percent();
  return c;
}

std::string percent(double x) { return std::isfinite(x) ? format_number(x, 3) + " %" : "n/a"; }

// The rows of `reg` in `rows` (same terms).
IdimRegression select_rows(const IdimRegression& reg, const std::vector<Eigen::Index>& rows) {
  IdimRegression out;
  out.terms = reg.terms;
  out.dt = reg.dt;
  out.max_speed = reg.max_speed;
  out.X.resize(static_cast<Eigen::Index>(rows.size()), reg.X.cols());
  out.y.resize(out.X.rows());
  for (Eigen::Index k = 0; k < out.X.rows(); ++k) {
    out.X.row(k) = reg.X.row(rows[static_cast<std::size_t>(k)]);
    out.y(k) = reg.y(rows[static_cast<std::size_t>(k)]);
  }
  return out;
}

// The rows in motion: |qd| above `fraction` of the largest |qd| (the residual check's standstill
// speed, identify/adequacy.hpp). At standstill friction is any value within +-Fs and the sign of
// the filtered velocity follows noise: no friction structure predicts those samples.
std::vector<Eigen::Index> moving_rows(const IdimRegression& cv, double fraction) {
  const Vec qd = cv.X.col(column_of(cv, "Fv"));
  const double limit = fraction * qd.cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < qd.size(); ++i)
    if (std::abs(qd(i)) > limit) rows.push_back(i);
  return rows;
}

// Fs = Fc + Fs_minus_Fc of an idim result with the Stribeck term, its std from the two std and
// their correlation (the result's Newey-West covariance); NaN when either is undetermined.
void add_static_level(Result& r, Axis axis) {
  const Parameter *fc = r.find("Fc"), *dF = r.find("Fs_minus_Fc");
  if (fc == nullptr || dF == nullptr || r.find("Fs") != nullptr) return;
  double rho = std::numeric_limits<double>::quiet_NaN();
  const auto& names = r.diagnostics.correlation.names;
  const auto ia = std::find(names.begin(), names.end(), "Fc"), ib = std::find(names.begin(), names.end(), "Fs_minus_Fc");
  if (ia != names.end() && ib != names.end())
    rho = r.diagnostics.correlation.matrix[static_cast<std::size_t>(ia - names.begin())][static_cast<std::size_t>(ib - names.begin())];
  const double var = fc->std * fc->std + dF->std * dF->std + 2 * rho * fc->std * dF->std;
  const double value = fc->value + dF->value;
  add_parameter(r, "Fs", value, var >= 0 ? std::sqrt(var) : std::numeric_limits<double>::quiet_NaN(), Quantity::force, axis);
}

// The trajectory path: idim and sweep candidates chosen by held-out error; `seen` opens the
// experiment text (what the record was checked for before).
// `out`, when given, receives the candidates with their verdicts (another experiment's runners-up).
Result trajectory_choice(const IdimData& data, const AutoOptions& options, const std::vector<std::string>& seen,
                         std::vector<SelectionCandidate>* out = nullptr) {
  const MethodInfo& idim = method_info(MethodId::idim);
  IdimOptions base = options.idim;
  base.axis = options.axis;
  base.search_stribeck_vs = false;

  // The Coulomb-viscous regression first: bad data are refused here, naming the file.
  IdimOptions cv_options = base;
  cv_options.terms = kCoulombViscous;
  const IdimRegression cv_all = idim_regression(data, cv_options);
  const Result cv_full = identify_idim(data, cv_options);  // the recipe on every sample: its signals, its verdict
  std::vector<double> time_all;
  if (const auto it = cv_full.series.find("time");
      it != cv_full.series.end() && static_cast<Eigen::Index>(it->second.size()) == cv_all.y.size())
    time_all = it->second;
  else
    for (Eigen::Index k = 0; k < cv_all.y.size(); ++k) time_all.push_back(static_cast<double>(k));
  // Every candidate is fitted and judged on the samples in motion (moving_rows).
  const std::vector<Eigen::Index> rows = moving_rows(cv_all, options.standstill_fraction);
  const IdimRegression cv = select_rows(cv_all, rows);
  std::vector<double> row_time;
  for (const Eigen::Index i : rows) row_time.push_back(time_all[static_cast<std::size_t>(i)]);
  const std::vector<SampleBlock> blocks = contiguous_blocks(cv.y.size(), options.folds);
  // moving_rows's limit as idim's exclude_below: |qd| >= the next double above the limit is
  // |qd| > limit, so identify_idim keeps exactly `rows`.
  const double standstill_speed =
      std::nextafter(options.standstill_fraction * cv_all.X.col(column_of(cv_all, "Fv")).cwiseAbs().maxCoeff(),
                     std::numeric_limits<double>::infinity());
  std::optional<IdimRegression> second_cv;
  std::vector<Eigen::Index> second_rows;
  if (options.heldout) {
    const IdimRegression all2 = idim_regression(*options.heldout, cv_options);
    second_rows = moving_rows(all2, options.standstill_fraction);
    second_cv = select_rows(all2, second_rows);
  }

  std::vector<SelectionCandidate> candidates;
  std::vector<std::string> experiment = seen;

  // The trajectory candidates (idim).
  const auto add_idim = [&](const std::string& label, const std::vector<std::string>& terms, bool search) {
    SelectionCandidate c;
    c.method = idim.name;
    c.name = idim.name + " " + label;
    c.structure = joined(terms) + (search ? " (vs searched)" : "");
    IdimOptions o = base;
    o.terms = terms;
    // The regressions the held-out errors are computed on: one, or with the Stribeck term one per
    // vs of idim's search grid, its column remade from one filter pass (idim_stribeck.hpp).
    std::vector<IdimRegression> regs;
    if (search) {
      IdimWorkspace workspace;
      StribeckColumns columns(data, o, workspace);
      for (double vs : stribeck_vs_grid(columns.regression().max_speed)) regs.push_back(select_rows(columns.at(vs), rows));
    } else {
      regs.push_back(select_rows(idim_regression(data, o), rows));
    }
    // The candidate's result is idim's own on the samples in motion (exclude_below at the
    // standstill speed), vs searched as by --vs search: its std is idim's Newey-West figure.
    IdimOptions fit = o;
    fit.exclude_below = standstill_speed;
    fit.search_stribeck_vs = search;
    c.result = identify_idim(data, fit);
    if (c.result.ok()) add_static_level(c.result, options.axis);
    const auto vs_used = c.result.diagnostics.numbers.find("stribeck_vs");
    const double chosen_vs = vs_used != c.result.diagnostics.numbers.end() ? vs_used->second : o.stribeck_vs;
    c.training_error_percent = c.result.fit.relative_error_percent;
    HeldOutErrors h;
    if (!c.result.ok()) {
    } else if (options.heldout) {
      o.stribeck_vs = chosen_vs;
      const IdimRegression r2 = select_rows(idim_regression(*options.heldout, o), second_rows);
      Vec theta(r2.X.cols());
      for (std::size_t j = 0; j < r2.terms.size(); ++j) theta(static_cast<Eigen::Index>(j)) = c.result.value(r2.terms[j].parameter);
      h.error_squares.push_back((r2.y - r2.X * theta).squaredNorm());
      h.signal_squares.push_back(r2.y.squaredNorm());
      h.samples = static_cast<std::size_t>(r2.y.size());
    } else if (search) {
      h = stribeck_heldout(regs, blocks);  // vs chosen on each training set alone
    } else {
      h = linear_heldout_errors(regs.front().X, regs.front().y, blocks);
    }
    if (!h.error_squares.empty()) {
      c.heldout_error_percent = h.relative_error_percent();
      c.block_errors_percent = h.block_errors_percent();
    }
    candidates.push_back(std::move(c));
  };
  const Result& cv_result = cv_full;
  if (cv_result.ok()) {
    const double amax = cv_all.X.col(column_of(cv_all, "M")).cwiseAbs().maxCoeff();
    experiment.push_back("a trajectory with accelerations up to " + format_number(amax, 3) + " " +
                         std::string(unit(Quantity::acceleration, options.axis)) + " and speeds up to " +
                         format_number(cv_all.max_speed, 3) + " " + std::string(unit(Quantity::velocity, options.axis)) +
                         ": the inverse dynamic model (" + idim.name + ") applies; " + std::to_string(rows.size()) +
                         " of its " + std::to_string(cv_all.y.size()) + " samples are in motion (speed above " +
                         format_number(100 * options.standstill_fraction, 3) +
                         " % of the largest) and are the ones every candidate is fitted and judged on");
  } else {
    experiment.push_back("no trajectory the inverse dynamic model can use (" + cv_result.message + ")");
  }
  add_idim("coulomb-viscous", kCoulombViscous, false);
  add_idim("stribeck (vs searched)", kStribeck, true);
  add_idim("asymmetric", kAsymmetric, false);

  // Constant-speed plateaus, found on the filtered velocity the trajectory candidates use.
  const MethodInfo& sweep = method_info(MethodId::sweep);
  std::vector<SweepPoint> points;
  if (cv_result.ok()) {
    const auto& v = cv_result.series.at("velocity");
    SweepData sd;
    sd.time = Eigen::Map<const Vec>(time_all.data(), static_cast<Eigen::Index>(time_all.size()));
    sd.velocity = Eigen::Map<const Vec>(v.data(), static_cast<Eigen::Index>(v.size()));
    sd.force = cv_all.y;
    if (sd.velocity.size() == sd.force.size() && sd.time.size() == sd.force.size()) {
      SweepOptions so = options.sweep;
      so.axis = options.axis;
      try {
        for (const auto& p : sweep_points(sd, so))
          if (p.velocity != 0.0) points.push_back(p);
      } catch (const std::invalid_argument&) {
        points.clear();
      }
    }
  }
  // Enough plateaus for a Stribeck law (5 parameters) and both directions.
  const bool both = std::any_of(points.begin(), points.end(), [](const SweepPoint& p) { return p.velocity > 0; }) &&
                    std::any_of(points.begin(), points.end(), [](const SweepPoint& p) { return p.velocity < 0; });
  if (points.size() >= 6 && both) {
    experiment.push_back(std::to_string(points.size()) + " constant-speed plateaus of at least " +
                         format_number(options.sweep.min_duration, 3) + " s: the friction-velocity map (" + sweep.name +
                         ") applies");
    candidates.push_back(sweep_candidate(StaticFitModel::coulomb_viscous, "coulomb-viscous", points, cv, row_time,
                                         blocks, second_cv, options.axis));
    candidates.push_back(sweep_candidate(StaticFitModel::stribeck, "stribeck", points, cv, row_time, blocks,
                                         second_cv, options.axis));
  } else {
    experiment.push_back(std::to_string(points.size()) + " constant-speed plateaus" +
                         (points.empty() || both ? "" : ", all in one direction") + ": too few for a friction map (" +
                         sweep.name + " not run; it needs 6 in both directions)");
  }

  // Refusals, then the choice.
  for (auto& c : candidates) {
    if (!c.refusal.empty()) continue;
    c.refusal = physical_refusal(c.result);
    if (c.refusal.empty() && !std::isfinite(c.heldout_error_percent))
      c.refusal = "no held-out error: a training set could not be fitted (too few plateaus or samples outside a block)";
  }
  const std::optional<std::size_t> chosen = select_candidate(candidates);
  if (out != nullptr) *out = candidates;

  Result r = chosen ? candidates[*chosen].result : Result{};
  const std::string model = chosen ? r.model : std::string("none");
  {
    Result stamp = new_result(method_info(MethodId::automatic), model, options.axis);
    r.method = stamp.method;
    r.model = stamp.model;
    r.axis = stamp.axis;
    r.fit.quantity = stamp.fit.quantity;
    r.fit.unit = stamp.fit.unit;
  }
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  const std::string judged = options.heldout ? "its drive-force error on " + options.heldout->file
                                             : "its drive-force error on held-out data (" + std::to_string(options.folds) +
                                                   " contiguous time blocks, each predicted by a fit on the others)";
  std::ostringstream ex;
  for (std::size_t i = 0; i < experiment.size(); ++i) ex << (i ? "; " : "") << experiment[i];
  r.diagnostics.texts["experiment"] = ex.str();
  auto& list = r.diagnostics.lists["selection"];
  list.clear();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    std::map<std::string, double> rec{{"candidate", static_cast<double>(i + 1)},
                                      {"heldout_error_percent", c.heldout_error_percent},
                                      {"training_error_percent", c.training_error_percent},
                                      {"chosen", chosen && *chosen == i ? 1.0 : 0.0},
                                      {"refused", c.refused() ? 1.0 : 0.0}};
    for (std::size_t k = 0; k < c.block_errors_percent.size(); ++k)
      rec["block_" + std::to_string(k + 1) + "_percent"] = c.block_errors_percent[k];
    list.push_back(rec);
    std::string line = c.name + " [" + c.structure + "]: held-out " + percent(c.heldout_error_percent) + ", training " +
                       percent(c.training_error_percent) + ", ";
    line += chosen && *chosen == i ? "chosen" : c.refused() ? "refused: " + c.refusal : "runner-up";
    r.diagnostics.texts["candidate " + std::to_string(i + 1)] = line;
  }
  // Every candidate with its name, errors, verdict and estimates: MODEL.json diagnostics.selection.
  r.json_sections["diagnostics.selection"] = selection_json(candidates, chosen);
  if (!chosen) {
    std::string why;
    for (const auto& c : candidates) why += (why.empty() ? "" : "; ") + c.name + ": " + c.refusal;
    r.status = ResultStatus::error;
    r.message = "no candidate structure can be chosen: " + why;
    r.parameters.clear();
    r.law.reset();
    return r;
  }
  const SelectionCandidate& best = candidates[*chosen];
  if (options.heldout) {  // the chosen candidate's error on the second record, as idim's cross-test
    ValidationFigures v;
    v.file = options.heldout->file;
    v.sha256 = options.heldout->sha256;
    v.relative_error_percent = best.heldout_error_percent;
    v.samples = second_cv ? static_cast<std::size_t>(second_cv->y.size()) : 0;
    if (second_cv && second_cv->y.size() > 0)
      v.rmse = best.heldout_error_percent / 100.0 * second_cv->y.norm() / std::sqrt(static_cast<double>(second_cv->y.size()));
    r.validation = v;
  }
  std::string runners;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (i != *chosen && !candidates[i].refused())
      runners += (runners.empty() ? "" : ", ") + candidates[i].name + " " + percent(candidates[i].heldout_error_percent);
  std::string choice = best.name + ": the simplest structure within one standard error of the lowest held-out error; its error " + percent(best.heldout_error_percent) + " (" +
                       judged + "; training error " + percent(best.training_error_percent) + ")";
  if (!runners.empty()) choice += "; runners-up: " + runners;
  if (best.method == sweep.name)
    choice += "; the law is the sweep's (plateau means), M and offset are fitted to the trajectory's drive force less "
              "that law (a sweep alone has no M)";
  r.diagnostics.texts["choice"] = choice;
  return r;
}

// What a record holds besides a trajectory, seen on its raw samples before any filter.
enum class Experiment { trajectory, free_decay, coast_down, presliding, breakaway_ramp };

struct Seen {
  Experiment kind = Experiment::trajectory;
  std::string text;          // what was seen, in words (the experiment text's opening)
  Vec velocity, position;    // raw: the position differentiated (or the velocity integrated)
  double natural_frequency = 0;  // rad/s, of a free oscillation (pi over the mean half period)
  double equilibrium = 0;        // position the oscillation centres on (m or rad)
  double stiffness = 0, stiffness_std = 0;  // presliding: initial slope of force against displacement
  double limit = 0;                         // presliding: the force the deflection saturates at
  double start_force = 0;                   // presliding: the force read at the start (an offset)
  Vec presliding_model;                     // presliding: the curve's force at each sample
  double lower = 0, upper = 0, difference_std = 0;  // presliding: sigma0 of each half (PreslidingFit)
  double offset = 0, structure_z = 0, structure_mean = 0, structure_centre = 0;  // presliding (PreslidingFit)
  bool structure_time = true;
};

// The fewest samples a record is checked on for the experiments below (fewer: a trajectory).
constexpr Eigen::Index kLeastSamplesSeen = 50;
// |correlation| below which the drive force counts as not driving the motion (free decay): a
// force that drives the axis correlates with its acceleration, velocity, direction or position.
constexpr double kUndriven = 0.2;
// Rank correlation of displacement and force above which the record is presliding: the
// displacement a monotone function of the force (bristles), where a slide runs on at a held force.
constexpr double kElastic = 0.98;
// A breakaway ramp: the axis at rest for at least this share of the record before it moves, while
// the force's magnitude rises with time (correlation at least kRamp).
constexpr double kStuckShare = 0.05;
constexpr double kRamp = 0.9;
// Velocity sign changes (at kTurnFraction of the largest speed, with hysteresis) that make a free
// oscillation: 3, the energy balance's fewest half cycles (identify/decay.hpp).
constexpr int kLeastHalfCycles = 3;
constexpr double kTurnFraction = 0.02;

double correlation(const Vec& a, const Vec& b) {
  const Vec x = a.array() - a.mean(), y = b.array() - b.mean();
  const double den = std::sqrt(x.squaredNorm() * y.squaredNorm());
  return den > 0 ? x.dot(y) / den : 0.0;
}

// Ranks 0..n-1 of x (ties in sample order).
Vec ranks(const Vec& x) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(x.size()));
  for (Eigen::Index i = 0; i < x.size(); ++i) order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return x(a) < x(b); });
  Vec r(x.size());
  for (std::size_t k = 0; k < order.size(); ++k) r(order[k]) = static_cast<double>(k);
  return r;
}

// The steady presliding curve of the bristle models (LuGre at vanishing speed):
//   f = A (1 - exp(-sigma0 x / A)),
// with f the force and x the displacement from the start, both in the direction of the largest
// force, f less the force read at the start (the mean of its first kStartSamples samples): the
// curve starts with relaxed bristles, so what a sensor reads there is its offset (a drive's
// current offset would otherwise bend the curve's start: +8 % on sigma0 for a 0.1 N offset on the
// presliding log of tests/rigs/experiment_logs.py); sigma0 the bristles' stiffness (the curve's initial slope), A the force they saturate at
// (LuGre's g(0) = Fs when the ramp reaches it). For each A the exponent is linear in x (-ln(1 -
// f/A) = (sigma0/A) x, least squares through the origin over the samples with f < A); A by a
// golden-section search of the force residual over [1.001, 100] times the largest f (at the upper
// end the curve is a straight line). The std of sigma0: Newey-West (identify/covariance.hpp) on the
// curve's Jacobian at the optimum.
constexpr Eigen::Index kStartSamples = 5;

struct PreslidingFit {
  bool ok = false;
  double stiffness = 0, stiffness_std = 0, limit = 0;
  double start_force = 0;  // N or N m: the force read at the start, taken as the offset
  Vec model;  // the curve's force at each sample (N or N m, the data's sign)
  // sigma0 of the samples below and above half the largest force (A shared), and the Newey-West
  // std of their difference: the curve's model error shows as the difference (NaN: a half too small).
  double lower = std::numeric_limits<double>::quiet_NaN(), upper = lower, difference_std = lower;
  double offset = 0;  // N or N m: the offset fitted with the curve (the start force's estimate refined)
  // The residual's most significant bin mean (N or N m, the data's sign) against time or position,
  // its centre (s or m) and its standard errors; structure_z 0: none beyond 4 standard errors.
  double structure_z = 0, structure_mean = 0, structure_centre = 0;
  bool structure_time = true;
};

// Stretches of time and of position the presliding residual is checked over.
constexpr std::size_t kStructureBins = 8;

// Samples a half of the presliding curve needs for its own sigma0.
constexpr Eigen::Index kLeastHalfSamples = 20;

PreslidingFit presliding_fit(const Vec& F_read, const Vec& position, const Vec& time) {
  PreslidingFit out;
  out.start_force = F_read.head(std::min(kStartSamples, F_read.size())).mean();
  const Vec F = F_read.array() - out.start_force;
  Eigen::Index top = 0;
  F.cwiseAbs().maxCoeff(&top);
  const double dir = F(top) > 0 ? 1.0 : -1.0;
  const Vec f = dir * F, x = dir * (position.array() - position(0)).matrix();
  const double fmax = f.maxCoeff();
  if (!(fmax > 0)) return out;
  const auto slope_at = [&](double A) {
    double num = 0, den = 0;
    for (Eigen::Index i = 0; i < f.size(); ++i)
      if (f(i) > 0 && f(i) < A && x(i) > 0) num += x(i) * -std::log1p(-f(i) / A), den += x(i) * x(i);
    return den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN();
  };
  const auto cost = [&](double logA) {
    const double A = std::exp(logA), c = slope_at(A);
    if (!std::isfinite(c)) return std::numeric_limits<double>::infinity();
    return (f.array() - A * (1 - (-c * x.array().max(0.0)).exp())).matrix().squaredNorm();
  };
  double lo = std::log(1.001 * fmax), hi = std::log(100 * fmax);
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = hi - g * (hi - lo), b = lo + g * (hi - lo), fa = cost(a), fb = cost(b);
  for (int k = 0; k < 60; ++k) {
    if (fa < fb) hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = cost(a);
    else lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = cost(b);
  }
  const double A = std::exp(0.5 * (lo + hi)), c = slope_at(A);
  if (!std::isfinite(c) || !(c > 0)) return out;
  // The offset: the force read at the start is noisy (its 5 samples' mean), and held as exact it
  // left sigma0's std covering 3 of 100 seeded exact curves (white noise 0.01 N). So the curve is
  // refitted with an offset c of its own, f = c + A (1 - exp(-sigma0 x / A)), by Gauss-Newton from
  // the search's answer (c = 0), and the std of sigma0 comes from the three's covariance.
  Eigen::Vector3d q(c * A, A, 0.0);  // sigma0, A, c
  Mat J(f.size(), 3);
  Vec e(f.size());
  const auto evaluate = [&](const Eigen::Vector3d& p) {
    for (Eigen::Index i = 0; i < f.size(); ++i) {
      const double xi = std::max(0.0, x(i)), ex = std::exp(-p[0] * xi / p[1]);
      J(i, 0) = xi * ex;
      J(i, 1) = 1 - ex - p[0] * xi / p[1] * ex;
      J(i, 2) = 1;
      e(i) = f(i) - p[2] - p[1] * (1 - ex);
    }
  };
  constexpr int kSteps = 20;
  for (int it = 0; it < kSteps; ++it) {
    evaluate(q);
    if (!J.allFinite() || !e.allFinite()) break;
    const Eigen::Vector3d step = J.colPivHouseholderQr().solve(e);
    if (!step.allFinite() || !(q[0] + step[0] > 0 && q[1] + step[1] > 0)) break;
    q += step;
    if (std::abs(step[0]) <= 1e-12 * q[0] && std::abs(step[1]) <= 1e-12 * q[1]) break;
  }
  evaluate(q);
  const double sigma0 = q[0], A_fit = q[1];
  out.model = (dir * (f - e)).array() + out.start_force;
  if (!J.allFinite() || !e.allFinite() || f.size() <= 3) return out;
  const HacCovariance hac = hac_covariance(J, e);
  out.ok = true;
  out.stiffness = sigma0;
  out.stiffness_std = std::sqrt(std::max(0.0, hac.covariance(0, 0)));
  out.limit = dir * A_fit;
  out.offset = out.start_force + dir * q[2];
  // Structure in the residual: its means over kStructureBins stretches of time and of position,
  // against their standard errors (the shared residual check, identify/adequacy.hpp, with the
  // effective sample size taken within the time stretches, so that a slow structure does not pass
  // for memory of the noise, and no relevance bar: any significant trend is a model error here).
  if (time.size() == f.size() && f.size() >= static_cast<Eigen::Index>(kAdequacyMinSamples)) {
    const auto n = static_cast<std::size_t>(f.size());
    AdequacyOptions ao;
    ao.velocity_bins = 0;
    ao.position_bins = kStructureBins;
    ao.relevance = 0;
    ao.force_share = 0;
    for (std::size_t k = 1; k <= kStructureBins; ++k) ao.segment_ends.push_back(k * n / kStructureBins);
    const std::vector<double> zero(n, 0.0), xs(x.data(), x.data() + n), ts(time.data(), time.data() + n),
        es(e.data(), e.data() + n);
    const Adequacy ad = assess_residuals(zero, xs, ts, es, "N", "m/s", ao);
    for (const auto* bins : {&ad.by_time, &ad.by_position})
      for (const ResidualBin& bin : *bins)
        if (bin.standard_error > 0 && std::abs(bin.mean) > ao.significance * bin.standard_error &&
            std::abs(bin.mean) / bin.standard_error > out.structure_z) {
          out.structure_z = std::abs(bin.mean) / bin.standard_error;
          out.structure_mean = dir * bin.mean;
          out.structure_time = bins == &ad.by_time;
          out.structure_centre = bins == &ad.by_time ? bin.centre : dir * bin.centre;
        }
  }
  // The halves: f = c + A (1 - exp(-s_h x / A)) with its own s_h on each half, A and an offset c
  // shared, by Gauss-Newton from the whole fit, and the Newey-West covariance of the four (A's error
  // and the start force's, which the offset c takes up, move both halves' s_h: the difference's std
  // must come from their joint covariance; without them an exact curve's halves differed beyond
  // 2.58 std in 12 of 20 seeded records).
  Eigen::Index lower_count = 0;
  for (Eigen::Index i = 0; i < f.size(); ++i) lower_count += f(i) < 0.5 * fmax ? 1 : 0;
  if (lower_count < kLeastHalfSamples || f.size() - lower_count < kLeastHalfSamples) return out;
  Eigen::Vector4d p(sigma0, sigma0, A_fit, q[2]);  // s_lower, s_upper, A, c
  Mat Jh = Mat::Zero(f.size(), 4);
  Vec eh(f.size());
  const auto evaluate_halves = [&](const Eigen::Vector4d& w) {
    for (Eigen::Index i = 0; i < f.size(); ++i) {
      const int h = f(i) < 0.5 * fmax ? 0 : 1;
      const double xi = std::max(0.0, x(i)), ex = std::exp(-w[h] * xi / w[2]);
      Jh.row(i).setZero();
      Jh(i, h) = xi * ex;
      Jh(i, 2) = 1 - ex - w[h] * xi / w[2] * ex;
      Jh(i, 3) = 1;
      eh(i) = f(i) - w[3] - w[2] * (1 - ex);
    }
  };
  for (int it = 0; it < kSteps; ++it) {
    evaluate_halves(p);
    if (!Jh.allFinite() || !eh.allFinite()) return out;
    const Eigen::Vector4d step = Jh.colPivHouseholderQr().solve(eh);
    if (!step.allFinite()) return out;
    p += step;
    if (step.head<3>().cwiseAbs().maxCoeff() <= 1e-12 * p.head<3>().cwiseAbs().maxCoeff()) break;
  }
  evaluate_halves(p);
  if (!(p[0] > 0 && p[1] > 0 && p[2] > 0) || !Jh.allFinite() || !eh.allFinite()) return out;
  const Mat C = hac_covariance(Jh, eh).covariance;
  out.lower = p[0];
  out.upper = p[1];
  out.difference_std = std::sqrt(std::max(0.0, C(0, 0) + C(1, 1) - 2 * C(0, 1)));
  return out;
}

Seen look_at(const IdimData& d, Axis axis) {
  Seen s;
  const Eigen::Index n = d.time.size();
  const bool from_position = d.position.size() > 0;
  // Anything inconsistent is the trajectory path's to refuse, naming the file.
  if (n < kLeastSamplesSeen || d.force.size() != n || (from_position ? d.position.size() : d.velocity.size()) != n ||
      !d.time.allFinite() || !d.force.allFinite() || !(from_position ? d.position.allFinite() : d.velocity.allFinite()))
    return s;
  const double dt = (d.time(n - 1) - d.time(0)) / static_cast<double>(n - 1);
  if (!(dt > 0)) return s;
  if (from_position) {
    s.position = d.position;
    s.velocity = gradient(d.position, dt);
  } else {
    s.velocity = d.velocity;
    s.position.resize(n);
    s.position(0) = 0;
    for (Eigen::Index i = 1; i < n; ++i) s.position(i) = s.position(i - 1) + 0.5 * (s.velocity(i) + s.velocity(i - 1)) * dt;
  }
  const double vmax = s.velocity.cwiseAbs().maxCoeff();
  if (!(vmax > 0) || !std::isfinite(vmax)) return s;
  const std::string vu(unit(Quantity::velocity, axis)), fu(unit(Quantity::force, axis)), xu(unit(Quantity::displacement, axis));
  const Vec& F = d.force;
  const double fspread = std::sqrt((F.array() - F.mean()).square().mean());

  // Free decay: the force constant, or unrelated to the motion.
  const Vec a = gradient(s.velocity, dt);
  const Vec sg = s.velocity.unaryExpr([](double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; });
  const double drive = fspread == 0 ? 0.0
                                    : std::max({std::abs(correlation(F, a)), std::abs(correlation(F, s.velocity)),
                                                std::abs(correlation(F, sg)), std::abs(correlation(F, s.position))});
  if (drive < kUndriven) {
    // Turning points: sign changes of the velocity beyond +-kTurnFraction of the largest speed.
    std::vector<double> turns;
    std::vector<Eigen::Index> turn_samples;
    int last = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double v = s.velocity(i);
      const int sign = v > kTurnFraction * vmax ? 1 : v < -kTurnFraction * vmax ? -1 : 0;
      if (sign == 0 || sign == last) continue;
      if (last != 0) {
        // The turning point: where the velocity crossed zero since the last sample beyond the band.
        Eigen::Index k = i;
        while (k > 0 && s.velocity(k - 1) * sign > 0) --k;
        turns.push_back(d.time(k));
        turn_samples.push_back(k);
      }
      last = sign;
    }
    const std::string force_words = fspread == 0 ? "the drive force is constant"
                                                 : "the drive force does not follow the motion (correlation " +
                                                       format_number(drive, 2) + " at most)";
    if (static_cast<int>(turns.size()) >= kLeastHalfCycles) {
      s.kind = Experiment::free_decay;
      s.natural_frequency = std::numbers::pi * static_cast<double>(turns.size() - 1) / (turns.back() - turns.front());
      // The centre: the mean over consecutive turning positions x0, x1, x2 of (x0 + 2 x1 + x2) / 4,
      // which Coulomb friction's steps of 2 Fc/k cancel from exactly and a viscous decay by the
      // ratio r per half cycle leaves (1 - r)^2 / 4 of the amplitude in, alternating in sign.
      double sum = 0;
      std::size_t triples = 0;
      for (std::size_t k = 0; k + 2 < turn_samples.size(); ++k, ++triples)
        sum += 0.25 * (s.position(turn_samples[k]) + 2 * s.position(turn_samples[k + 1]) + s.position(turn_samples[k + 2]));
      s.equilibrium = triples > 0 ? sum / static_cast<double>(triples) : 0.0;
      s.text = "a free decay: " + force_words + " while the axis oscillates (" + std::to_string(turns.size()) +
               " reversals, natural frequency about " + format_number(s.natural_frequency, 4) +
               " rad/s from the mean half period): the energy lost per half cycle gives the friction (decay)";
    } else {
      s.kind = Experiment::coast_down;
      s.text = "a free coast-down: " + force_words + " while the axis moves with " + std::to_string(turns.size()) +
               " reversal(s)";
    }
    return s;
  }

  // A slow ramp of force from rest: stuck for a while, the force's magnitude rising, then motion.
  const double threshold = 0.01 * vmax;  // breakaway's default motion threshold
  Eigen::Index onset = 0;
  while (onset < n && std::abs(s.velocity(onset)) <= threshold) ++onset;
  if (onset >= std::max<Eigen::Index>(20, static_cast<Eigen::Index>(kStuckShare * static_cast<double>(n))) && onset < n) {
    const Vec t = d.time.head(onset), f = F.head(onset).cwiseAbs();
    const double rise = correlation(t, f);
    if (rise >= kRamp) {
      s.kind = Experiment::breakaway_ramp;
      s.text = "a slow ramp of force with stick: the axis stays at rest for " + format_number(d.time(onset) - d.time(0), 3) +
               " s while |force| rises to " + format_number(std::abs(F(onset)), 3) + " " + fu +
               ", then moves (speeds up to " + format_number(vmax, 3) + " " + vu +
               "): the breakaway experiment (breakaway) applies";
    }
  }
  // Presliding: the displacement a monotone function of the force (rank correlation), so that it
  // holds while the force holds and the axis never slides (a slide runs on at a held force).
  if (fspread > 0 && s.kind == Experiment::trajectory) {
    const double rank = correlation(ranks(F), ranks(s.position));
    if (rank >= kElastic) {
      const PreslidingFit fit = presliding_fit(F, s.position, d.time);
      if (fit.ok) {
        s.kind = Experiment::presliding;
        s.stiffness = fit.stiffness;
        s.stiffness_std = fit.stiffness_std;
        s.limit = fit.limit;
        s.start_force = fit.start_force;
        s.presliding_model = fit.model;
        s.lower = fit.lower;
        s.upper = fit.upper;
        s.difference_std = fit.difference_std;
        s.offset = fit.offset;
        s.structure_z = fit.structure_z;
        s.structure_mean = fit.structure_mean;
        s.structure_centre = fit.structure_centre;
        s.structure_time = fit.structure_time;
        const double xspan = s.position.maxCoeff() - s.position.minCoeff();
        s.text = "presliding: the displacement (" + format_number(xspan, 3) + " " + xu +
                 " at most) follows the force (rank correlation " + format_number(rank, 4) + ", up to " +
                 format_number(F.cwiseAbs().maxCoeff(), 3) + " " + fu +
                 ") and holds while the force holds: the axis never slides";
      }
    }
  }
  return s;
}

// A Result of one method chosen for what the record holds, stamped as auto's: the experiment, the
// choice and the one candidate in the selection.
// `others`: the trajectory candidates after it, runners-up (fitted and judged by their held-out
// error) or refused with the reason they were not run or not admitted.
Result single_choice(Result inner, const std::string& method, const std::string& name, const std::string& structure,
                     const Seen& seen, std::string choice, const IdimData& data, Axis axis,
                     const std::vector<SelectionCandidate>& others = {}) {
  std::vector<SelectionCandidate> candidates(1);
  SelectionCandidate& c = candidates.front();
  c.method = method;
  c.name = name;
  c.structure = structure;
  c.training_error_percent = inner.fit.relative_error_percent;
  c.result = inner;
  if (!inner.ok()) c.refusal = inner.message;
  const std::optional<std::size_t> chosen = inner.ok() ? std::optional<std::size_t>(0) : std::nullopt;
  Result r = std::move(inner);
  const Result stamp = new_result(method_info(MethodId::automatic), r.model, axis);
  r.method = stamp.method;
  r.axis = stamp.axis;
  r.data_file = data.file;
  r.data_sha256 = data.sha256;
  r.diagnostics.texts["experiment"] = seen.text;
  const std::string first_line = c.name + " [" + structure + "]: " + (chosen ? "chosen" : "refused: " + c.refusal);
  r.diagnostics.lists["selection"] = {{{"candidate", 1.0},
                                       {"heldout_error_percent", c.heldout_error_percent},
                                       {"training_error_percent", c.training_error_percent},
                                       {"chosen", chosen ? 1.0 : 0.0},
                                       {"refused", chosen ? 0.0 : 1.0}}};
  r.diagnostics.texts["candidate 1"] = first_line;
  std::string runners;
  for (const SelectionCandidate& o : others) {
    candidates.push_back(o);
    const std::size_t i = candidates.size();
    std::map<std::string, double> rec{{"candidate", static_cast<double>(i)},
                                      {"heldout_error_percent", o.heldout_error_percent},
                                      {"training_error_percent", o.training_error_percent},
                                      {"chosen", 0.0},
                                      {"refused", o.refused() ? 1.0 : 0.0}};
    for (std::size_t k = 0; k < o.block_errors_percent.size(); ++k)
      rec["block_" + std::to_string(k + 1) + "_percent"] = o.block_errors_percent[k];
    r.diagnostics.lists["selection"].push_back(rec);
    std::string line = o.name + " [" + o.structure + "]: ";
    if (std::isfinite(o.heldout_error_percent) || std::isfinite(o.training_error_percent))
      line += "held-out " + percent(o.heldout_error_percent) + ", training " + percent(o.training_error_percent) + ", ";
    line += o.refused() ? "refused: " + o.refusal : "runner-up";
    r.diagnostics.texts["candidate " + std::to_string(i)] = line;
    if (!o.refused()) runners += (runners.empty() ? "" : ", ") + o.name + " " + percent(o.heldout_error_percent);
  }
  if (!runners.empty())
    choice += "; runners-up (held-out drive-force error on the samples in motion; they cannot give what the chosen "
              "method gives): " + runners;
  r.diagnostics.texts["choice"] = choice;
  r.json_sections["diagnostics.selection"] = selection_json(candidates, chosen);
  return r;
}

// The trajectory candidates of a free decay, each with the reason it is not run: the drive force
// does not drive the motion, so the inverse dynamic model and a sweep have no force to fit.
std::vector<SelectionCandidate> not_run_on_decay(Axis axis) {
  const std::string idim = method_info(MethodId::idim).name, sweep = method_info(MethodId::sweep).name;
  const std::string why = "not run: the record is a free decay, its drive force does not drive the motion, so the "
                          "inverse dynamic model has no force to fit";
  std::vector<SelectionCandidate> out;
  const auto add = [&](const std::string& name, const std::string& method, const std::string& structure,
                       const std::string& reason) {
    SelectionCandidate c;
    c.name = name;
    c.method = method;
    c.structure = structure;
    c.result = new_result(method_info(MethodId::automatic), "none", axis);
    c.refusal = reason;
    out.push_back(std::move(c));
  };
  add(idim + " coulomb-viscous", idim, joined(kCoulombViscous), why);
  add(idim + " stribeck (vs searched)", idim, joined(kStribeck) + " (vs searched)", why);
  add(idim + " asymmetric", idim, joined(kAsymmetric), why);
  add(sweep + " laws + M", sweep, "a law on constant-speed plateaus",
      "not run: a free decay passes every speed in a moment and holds none (no constant-speed plateaus)");
  return out;
}

Result auto_by_experiment(const IdimData& data, const AutoOptions& options);

}  // namespace

Result identify_auto(const IdimData& data, const AutoOptions& options) {
  if (options.folds < 2)
    throw std::invalid_argument("identify auto: --folds = " + std::to_string(options.folds) + " must be at least 2");
  if (std::isfinite(options.stiffness) && !(options.stiffness > 0))
    throw std::invalid_argument("identify auto: --stiffness = " + format_number(options.stiffness) + " must be > 0 (" +
                                std::string(unit(Quantity::stiffness, options.axis)) + ")");
  Result r = auto_by_experiment(data, options);
  if (std::isfinite(options.stiffness) && r.diagnostics.numbers.count("stiffness") == 0)
    r.diagnostics.warnings.push_back("--stiffness = " + format_number(options.stiffness) + " " +
                                     std::string(unit(Quantity::stiffness, options.axis)) +
                                     " is not used: the record holds no free decay");
  return finite_or_error(std::move(r));  // the chosen candidate as the methods return theirs
}

namespace {

Result auto_by_experiment(const IdimData& data, const AutoOptions& options) {
  const Seen seen = look_at(data, options.axis);
  const Axis axis = options.axis;
  switch (seen.kind) {
    case Experiment::free_decay: {
      DecayOptions o;
      o.natural_frequency = seen.natural_frequency;
      o.stiffness = options.stiffness;  // NaN unless given: then Fc and Fv in force units
      o.axis = axis;
      const std::string& name = method_info(MethodId::decay).name;
      // The centre enters the energy balance linearly (a column of signed half-cycle travel), so
      // its residual is a parabola in it: a golden-section search of decay's own fit error, over a
      // quarter of the swing's span either side of the turning points' estimate, finds it. The
      // restoring force is a linear spring's or a pendulum's (k sin x, x in rad from the bottom):
      // the one whose balance fits better (the same two parameters, so the training error decides).
      const auto decay_at = [&](double centre, bool pendulum) {
        DecayOptions op = o;
        op.pendulum = pendulum;
        return identify_decay({data.time, (seen.position.array() - centre).matrix()}, op);
      };
      const auto misfit_of = [](const Result& t) { return t.ok() ? t.fit.rmse : std::numeric_limits<double>::infinity(); };
      const auto best_centre = [&](bool pendulum) {
        const auto misfit = [&](double centre) { return misfit_of(decay_at(centre, pendulum)); };
        const double span = 0.25 * (seen.position.maxCoeff() - seen.position.minCoeff());
        double lo = seen.equilibrium - span, hi = seen.equilibrium + span;
        const double g = (std::sqrt(5.0) - 1) / 2;
        double c1 = hi - g * (hi - lo), c2 = lo + g * (hi - lo), m1 = misfit(c1), m2 = misfit(c2);
        for (int k = 0; k < 50; ++k) {
          if (m1 < m2) hi = c2, c2 = c1, m2 = m1, c1 = hi - g * (hi - lo), m1 = misfit(c1);
          else lo = c1, c1 = c2, m1 = m2, c2 = lo + g * (hi - lo), m2 = misfit(c2);
        }
        return misfit(0.5 * (lo + hi)) <= misfit(seen.equilibrium) ? 0.5 * (lo + hi) : seen.equilibrium;
      };
      const double centre_spring = best_centre(false), centre_pendulum = best_centre(true);
      const Result spring = decay_at(centre_spring, false), pendulum = decay_at(centre_pendulum, true);
      const bool is_pendulum = misfit_of(pendulum) < misfit_of(spring);
      const double centre = is_pendulum ? centre_pendulum : centre_spring;
      Result inner = is_pendulum ? pendulum : spring;
      inner.diagnostics.texts["restoring_force"] =
          std::string(is_pendulum ? "pendulum, k sin(x)" : "linear spring, k x") + ": its energy balance fits with rmse " +
          format_number(misfit_of(is_pendulum ? pendulum : spring), 3) + " against " +
          format_number(misfit_of(is_pendulum ? spring : pendulum), 3) + " for the " +
          (is_pendulum ? "linear spring" : "pendulum");
      inner.diagnostics.numbers["decay_centre"] = centre;
      const std::string given_k = std::isfinite(options.stiffness)
                                      ? "with the stiffness given (--stiffness " + format_number(options.stiffness) + " " +
                                            std::string(unit(Quantity::stiffness, axis)) +
                                            ") Fc and Fv follow in force units (the centre (decay_centre) that fits the "
                                            "balance best)"
                                      : "without the stiffness only Fc/k and the damping ratio zeta follow (the natural "
                                        "frequency from the oscillation's half periods, the centre (decay_centre) that "
                                        "fits the balance best; --stiffness K gives Fc and Fv in force units)";
      return single_choice(
          std::move(inner), name, name + " coulomb-viscous", "coulomb-viscous energy balance per half cycle", seen,
          name + ": the record is a free decay, where the energy lost between turning points measures the friction; " +
              given_k + ". The trajectory methods are not run: with no drive force the inverse dynamic model has "
              "nothing to fit",
          data, axis, not_run_on_decay(axis));
    }
    case Experiment::coast_down: {
      Result r = make_result(MethodId::automatic, "none", axis);
      fail(r, seen.text + ": without a restoring force or a known drive only friction over inertia shows, and no "
                          "method of frictionlab identifies that; record a free oscillation (" +
                  method_info(MethodId::decay).name + ") or drive the axis (idim, sweep)");
      r.data_file = data.file;
      r.data_sha256 = data.sha256;
      r.diagnostics.texts["experiment"] = seen.text;
      return r;
    }
    case Experiment::presliding: {
      const std::string& lugre = method_info(MethodId::lugre).name;
      Result inner = make_result(MethodId::automatic, "presliding", axis);
      add_parameter(inner, "sigma0", seen.stiffness, seen.stiffness_std, Quantity::stiffness, axis);
      inner.diagnostics.texts["covariance"] = "newey-west";
      // The force the deflection saturates at: LuGre's Fs when the ramp came near it, else a bound.
      inner.diagnostics.numbers["presliding_limit"] = seen.limit;
      // The force read at the start, taken as the sensor's offset and subtracted (relaxed bristles).
      inner.diagnostics.numbers["presliding_start_force"] = seen.start_force;
      set_fit(inner, data.force, seen.presliding_model);
      inner.series["time"].assign(data.time.data(), data.time.data() + data.time.size());
      inner.series["force"].assign(data.force.data(), data.force.data() + data.force.size());
      inner.series["force_model"].assign(seen.presliding_model.data(), seen.presliding_model.data() + seen.presliding_model.size());
      inner.series["position"].assign(seen.position.data(), seen.position.data() + seen.position.size());
      // sigma0's std counts the force's noise (and the offset's, fitted with the curve) only. The
      // steady curve leaves out the bristles' damping and the mass, an error the same in every
      // repetition that no std of the curve's fit holds (on the presliding log of
      // tests/rigs/experiment_logs.py: 0.4 % error against a std of 0.03 %). It shows as structure
      // in the curve's residual (a bin mean beyond 4 standard errors) or as different sigma0 from
      // the curve's two halves (beyond 2.58 std of their difference, two-sided 1 %): either, and the
      // result says the std excludes a model error, with the halves' difference as its estimate.
      constexpr double kHalvesDiffer = 2.58;
      inner.diagnostics.numbers["presliding_offset"] = seen.offset;
      const bool halves = std::isfinite(seen.lower) && std::isfinite(seen.upper);
      const double diff = halves ? seen.upper - seen.lower : 0.0;
      if (halves) {
        inner.diagnostics.numbers["presliding_sigma0_lower_half"] = seen.lower;
        inner.diagnostics.numbers["presliding_sigma0_upper_half"] = seen.upper;
      }
      const bool halves_differ = halves && std::abs(diff) > kHalvesDiffer * seen.difference_std;
      if (seen.structure_z > 0 || halves_differ) {
        const std::string su(unit(Quantity::stiffness, axis)), fu(unit(Quantity::force, axis)),
            xu(unit(Quantity::displacement, axis));
        std::string why;
        if (seen.structure_z > 0)
          why = "its residual has structure (" + format_number(seen.structure_mean, 2) + " " + fu + " near " +
                (seen.structure_time ? "t = " + format_number(seen.structure_centre, 3) + " s"
                                     : "a displacement of " + format_number(seen.structure_centre, 3) + " " + xu) +
                ", " + format_number(seen.structure_z, 2) + " standard errors)";
        if (halves_differ) why += std::string(why.empty() ? "" : "; ") + "sigma0 from the samples below and above half the largest force differs beyond its noise";
        const std::string estimate =
            halves ? "; sigma0 from the samples below and above half the largest force: " + format_number(seen.lower, 6) +
                         " and " + format_number(seen.upper, 6) + " " + su + ", " +
                         format_number(100 * std::abs(diff) / seen.stiffness, 2) +
                         " % apart, an estimate of that error (it can be larger)"
                   : "";
        inner.diagnostics.warnings.push_back(
            "the steady presliding curve does not describe the record to its noise (" + why + "): sigma0's std (" +
            format_number(seen.stiffness_std, 2) + " " + su +
            ") counts the noise only and excludes this model error (the bristles' damping and the mass the curve "
            "leaves out)" + estimate + "; the whole model is " + lugre + "'s, on a record that also slides");
      }
      inner.diagnostics.warnings.push_back(
          "only the bristle stiffness (sigma0) can be seen in presliding: the Coulomb and static levels, vs and the "
          "viscous term need the axis to slide; identify the full model with " + lugre +
          " on a record that also slides");
      return single_choice(std::move(inner), "presliding", "presliding stiffness",
                           "force = A (1 - exp(-sigma0 x / A)) (bristles)", seen,
                           "presliding: sigma0 is the initial slope of the force against the displacement (the bristles' "
                           "stiffness, LuGre's sigma0), from the steady presliding curve f = A (1 - exp(-sigma0 x / A)); " + lugre + " is the method for the whole LuGre model. The trajectory "
                           "methods are not run: without sliding they would fit friction to an elastic force",
                           data, axis);
    }
    case Experiment::breakaway_ramp: {
      BreakawayData bd{data.time, data.force, seen.velocity, data.load};
      BreakawayOptions o;
      o.axis = axis;
      const std::string& name = method_info(MethodId::breakaway).name;
      Result inner = identify_breakaway(bd, o);
      if (inner.ok()) {
        // The trajectory candidates on the same record, as runners-up: their held-out errors say how
        // well the sliding part alone is described, but none of them sees the force at rest (Fs).
        std::vector<SelectionCandidate> others;
        try {
          (void)trajectory_choice(data, options, {}, &others);
        } catch (const std::invalid_argument& e) {
          SelectionCandidate c;
          c.name = method_info(MethodId::idim).name + " coulomb-viscous";
          c.method = method_info(MethodId::idim).name;
          c.structure = joined(kCoulombViscous);
          c.result = new_result(method_info(MethodId::automatic), "none", axis);
          c.refusal = std::string("not run: ") + e.what();
          others.push_back(std::move(c));
        }
        return single_choice(std::move(inner), name, name + " static-coulomb-viscous", "static-coulomb-viscous with M", seen,
                             name + ": the record is a breakaway experiment, and only its onset of motion shows the "
                                    "static level Fs (the force at which the stuck axis broke away); Fc, Fv and M are "
                                    "fitted to the sliding samples. The trajectory candidates are fitted too, as "
                                    "runners-up: they see no force at rest, so no Fs",
                             data, axis, others);
      }
      return trajectory_choice(data, options,
                               {seen.text + ", but " + name + " refused it (" + inner.message + ")"});
    }
    case Experiment::trajectory:
      break;
  }
  return trajectory_choice(data, options, {});
}

}  // namespace

}  // namespace frictionlab
