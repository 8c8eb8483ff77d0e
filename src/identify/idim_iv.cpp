// IDIM-IV: instrumental variables for IDIM on closed-loop records (identify/idim.hpp,
// IdimIvOptions). The instruments are the regressors of the model's own closed loop, simulated
// with the exact stick/slip engine (simulate/) around a rigid axis (plants/axis.hpp) with the
// experiment's controller (control/, closed by simulate/closed_loop.hpp) and reference.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <variant>

#include "frictionlab/control/compensator.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/covariance.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/plants/axis.hpp"
#include "frictionlab/simulate/closed_loop.hpp"
#include "frictionlab/simulate/emps_pd_loop.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "idim_internal.hpp"

namespace frictionlab::detail {
namespace {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

std::string where(const IdimData& d) { return d.file.empty() ? std::string("idim: ") : d.file + ": "; }

// The drive's recorded feedforward force as a "compensator" of the loop: its output is the
// recorded force at the loop's time, added to the controller's command inside the saturation
// (a PID adds it in N, the EMPS controller as F / gtau in V), as a drive adds its feedforward.
class RecordedFeedforward : public Compensator {
 public:
  explicit RecordedFeedforward(InputSignal force) : force_(std::move(force)) {}
  std::string type() const override { return "recorded-feedforward"; }
  double output(const CompensatorInput& in, std::span<const double>) const override { return force_.at(in.t).value; }
  double update(const CompensatorInput& in, std::span<double> z, double) const override { return output(in, z); }

 private:
  InputSignal force_;
};

// A record's column as a piecewise-linear table on the simulation's time (t - t0, at k dt
// exactly, where the sampled controller reads it).
InputSignal table_of(const Vec& v, double dt) {
  InputSignal s;
  s.shape = InputShape::table;
  s.times.resize(static_cast<std::size_t>(v.size()));
  s.values.assign(v.data(), v.data() + v.size());
  for (Eigen::Index k = 0; k < v.size(); ++k) s.times[static_cast<std::size_t>(k)] = static_cast<double>(k) * dt;
  return s;
}

void check_column(const IdimData& d, const Vec& v, const char* name, const char* option) {
  const Eigen::Index n = d.time.size();
  if (v.size() != n)
    throw InputError(errc::data_column_length,
                     where(d) + "the " + name + " (" + option + ") has " + std::to_string(v.size()) +
                         " samples; expected " + std::to_string(n) + " like time",
                     ErrorFields{.file = d.file, .option = option});
  for (Eigen::Index k = 0; k < n; ++k)
    if (!std::isfinite(v(k)))
      throw InputError(errc::data_not_finite,
                       where(d) + "sample " + std::to_string(k + 1) + ": the " + name + " (" + option + ") = " +
                           format_value(v(k), 6) + " is not a finite number",
                       ErrorFields{.file = d.file, .row = static_cast<std::size_t>(k + 1), .option = option});
}

// The controller with its sample period set to the record's step when asked.
Controller controller_for(const IdimIvOptions& iv, double dt) {
  Controller c = *iv.controller;
  if (iv.sample_at_record_rate) {
    if (auto* pid = std::get_if<PidParams>(&c)) pid->Ts = dt;
    if (auto* emps = std::get_if<EmpsPdParams>(&c)) emps->dt = dt;
  }
  return c;
}

// The model's closed loop simulated with the parameters of `model_result`: the position (or the
// velocity, when W is built from it) at the record's samples, or an error message.
struct Simulated {
  IdimData data;
  std::string error;
};

Simulated simulate_model(const Result& model_result, const IdimData& data, const IdimOptions& o, double dt,
                         bool from_velocity) {
  Simulated out;
  IdentifiedModel model;
  try {
    model = model_from_result(model_result);
  } catch (const std::invalid_argument& e) {
    out.error = std::string("the estimate makes no model that can be simulated: ") + e.what();
    return out;
  }
  const Eigen::Index n = data.time.size();
  std::shared_ptr<const Compensator> ff;
  if (data.feedforward.size() == n) ff = std::make_shared<RecordedFeedforward>(table_of(data.feedforward, dt));
  Scenario sc;
  try {
    sc.plant = close_loop(std::make_shared<RigidAxis>(model.axis), controller_for(o.iv, dt), ff);
  } catch (const std::invalid_argument& e) {
    throw InputError(errc::option_out_of_range, std::string("idim: --iv: the controller: ") + e.what(),
                     ErrorFields{.option = "--controller"});
  }
  sc.law = model.law;
  sc.input = table_of(data.reference, dt);
  sc.options.duration = static_cast<double>(n - 1) * dt;
  sc.options.output_rate = 1.0 / dt;
  // From rest at the measured initial position (the skipped start covers the loop's settling).
  sc.options.initial_position = data.position.size() == n ? data.position(0) : 0.0;
  sc.options.initial_velocity = 0.0;
  Trajectory tr;
  try {
    tr = simulate(sc);
  } catch (const std::exception& e) {
    out.error = std::string("the simulation of the model's closed loop failed: ") + e.what();
    return out;
  }
  if (static_cast<Eigen::Index>(tr.rows()) < n) {
    out.error = "the simulation of the model's closed loop gave " + std::to_string(tr.rows()) + " samples; expected " +
                std::to_string(n);
    return out;
  }
  const Eigen::Map<const Vec> q(tr.position.data(), n), v(tr.velocity.data(), n);
  if (!q.allFinite() || !v.allFinite()) {
    out.error = "the simulation of the model's closed loop diverged (a position or velocity that is not finite)";
    return out;
  }
  // A loop that runs away: the simulated motion spans more than ten times the measured one.
  const Vec& measured = from_velocity ? data.velocity : data.position;
  const Eigen::Map<const Vec>& sim = from_velocity ? v : q;
  const double span = measured.maxCoeff() - measured.minCoeff();
  const double sim_span = sim.maxCoeff() - sim.minCoeff();
  constexpr double kRunaway = 10;  // no closed loop that tracks the same reference moves ten times as far
  if (span > 0 && sim_span > kRunaway * span) {
    out.error = "the simulation of the model's closed loop diverged: its " +
                std::string(from_velocity ? "velocity" : "position") + " spans " + format_value(sim_span, 4) +
                ", the record's " + format_value(span, 4) + " (is the controller the experiment's? gains, delay, limit)";
    return out;
  }
  out.data.time = data.time;
  out.data.force = data.force;  // not used by the instruments; the pipeline checks it is there
  if (from_velocity) out.data.velocity = v;
  else out.data.position = q;
  out.data.file = data.file;
  return out;
}

// The instrument matrix: the regression of the simulated record, at the rows W kept.
Mat instruments(const IdimData& sim, const IdimOptions& o, const IdimRegression& reg) {
  IdimOptions so = o;
  so.exclude_below = 0;  // the rows are W's, chosen from the measured velocity
  so.iv.enabled = false;
  so.source = sim.position.size() > 0 ? IdimSource::position : IdimSource::velocity;
  const IdimRegression zreg = idim_regression(sim, so);
  Mat Z(reg.X.rows(), reg.X.cols());
  const Eigen::Index step = std::max(1, o.decimation);
  for (Eigen::Index k = 0; k < reg.X.rows(); ++k) {
    const Eigen::Index row = (reg.sample[static_cast<std::size_t>(k)] - o.skip) / step;
    Z.row(k) = zreg.X.row(row);
  }
  return Z;
}

// theta = (Z'W)^-1 Z'y, columns scaled to unit norm first; empty when Z'W is singular.
Vec iv_solve(const Mat& Z, const Mat& W, const Vec& y) {
  const Vec scale = W.colwise().norm().transpose().cwiseMax(std::numeric_limits<double>::min()).cwiseInverse();
  const Mat Ws = W * scale.asDiagonal();
  const Vec zs = Z.colwise().norm().transpose().cwiseMax(std::numeric_limits<double>::min()).cwiseInverse();
  const Mat Zs = Z * zs.asDiagonal();
  const Eigen::ColPivHouseholderQR<Mat> qr(Zs.transpose() * Ws);
  if (qr.rank() < W.cols()) return {};
  return scale.asDiagonal() * qr.solve(Zs.transpose() * y);
}

// The largest change of one parameter, as its share of the model force's norm.
double relative_change(const Mat& W, const Vec& before, const Vec& after) {
  const double scale = (W * before).norm();
  double worst = 0;
  for (Eigen::Index j = 0; j < W.cols(); ++j) worst = std::max(worst, std::abs(after(j) - before(j)) * W.col(j).norm());
  return scale > 0 ? worst / scale : std::numeric_limits<double>::infinity();
}

// Correlation of two columns; 1 for two constant columns (the offset's), 0 for one.
double column_correlation(const Vec& a, const Vec& b) {
  const Vec ac = a.array() - a.mean(), bc = b.array() - b.mean();
  const double na = ac.norm(), nb = bc.norm();
  constexpr double kConstant = 1e-12;  // relative spread below which a column is a constant
  const bool ca = na <= kConstant * a.norm(), cb = nb <= kConstant * b.norm();
  if (ca || cb) return ca && cb ? 1.0 : 0.0;
  return ac.dot(bc) / (na * nb);
}

// The smallest canonical correlation between the column spaces of Z and W (uncentred).
double min_canonical_correlation(const Mat& Z, const Mat& W) {
  const Eigen::Index n = Z.rows(), p = Z.cols();
  const Mat Qz = Eigen::HouseholderQR<Mat>(Z).householderQ() * Mat::Identity(n, p);
  const Mat Qw = Eigen::HouseholderQR<Mat>(W).householderQ() * Mat::Identity(n, p);
  const Eigen::JacobiSVD<Mat> svd(Qz.transpose() * Qw);
  return svd.singularValues().minCoeff();
}

// The controller the simulation ran, its values (SI, as the options give them) and where each
// came from (IdimIvOptions::sources).
void describe_controller(Result& r, const IdimOptions& o, double dt) {
  const Controller c = controller_for(o.iv, dt);
  auto& g = r.diagnostics.groups["iv_controller"];
  if (const auto* pid = std::get_if<PidParams>(&c)) {
    r.diagnostics.texts["iv_controller_type"] = "pid";
    g = {{"kp", pid->Kp}, {"kd", pid->Kd}, {"ki", pid->Ki}, {"control_limit", pid->limit},
         {"control_delay", static_cast<double>(pid->delay)}, {"sample_period", pid->Ts}};
  } else if (const auto* emps = std::get_if<EmpsPdParams>(&c)) {
    r.diagnostics.texts["iv_controller_type"] = "emps-pd";
    g = {{"kp", emps->kp}, {"kv", emps->kv}, {"drive_gain", emps->gtau}, {"control_limit", emps->limit},
         {"control_delay", static_cast<double>(emps->delay)}, {"sample_period", emps->dt}};
  }
  for (const auto& [name, source] : o.iv.sources) {
    std::string key = name;
    std::replace(key.begin(), key.end(), '-', '_');
    r.diagnostics.texts["iv_source_" + key] = source;
  }
}

Result failed(Result r, const std::string& message) {
  r.status = ResultStatus::error;
  r.message = message;
  r.parameters.clear();
  return r;
}

}  // namespace

void check_idim_iv_inputs(const IdimData& data, const IdimOptions& o) {
  if (!o.iv.controller)
    throw InputError(errc::option_invalid,
                     "idim: IDIM-IV (--iv) needs the experiment's controller: give --controller pid with --kp N/m and "
                     "--kd N s/m, or --controller emps-pd with --kp 1/s, --kv V s/m and --drive-gain N/V (Python: "
                     "controller=..., kp=..., kd=... or kv=...)",
                     ErrorFields{.option = "--controller"});
  if (data.reference.size() == 0)
    throw InputError(errc::option_invalid,
                     where(data) + "IDIM-IV (--iv) needs the closed loop's reference position: give --reference COLUMN "
                                   "(m or rad; Python: reference=array)",
                     ErrorFields{.file = data.file, .option = "--reference"});
  check_column(data, data.reference, "reference", "--reference");
  if (data.feedforward.size() > 0) check_column(data, data.feedforward, "feedforward", "--feedforward");
  if (!(o.iv.max_iterations >= 1))
    throw InputError(errc::option_out_of_range, "idim: --iv-iterations = " + std::to_string(o.iv.max_iterations) + " must be >= 1",
                     ErrorFields{.option = "--iv-iterations"});
  if (!(o.iv.tolerance > 0) || !std::isfinite(o.iv.tolerance))
    throw InputError(errc::option_out_of_range, "idim: --iv-tolerance = " + format_value(o.iv.tolerance, 6) + " must be > 0",
                     ErrorFields{.option = "--iv-tolerance"});
  static const std::set<std::string> simulable = {"inertia",     "viscous",     "coulomb",     "offset",
                                                  "asymmetric",  "viscous_pos", "coulomb_pos", "viscous_neg",
                                                  "coulomb_neg", "stribeck"};
  for (const auto& t : o.terms)
    if (!simulable.count(t))
      throw InputError(errc::option_conflict,
                       "idim: IDIM-IV (--iv) simulates the model, and the term '" + t +
                           "' is not part of a model it can simulate; use inertia, viscous, coulomb, offset, "
                           "asymmetric, stribeck",
                       ErrorFields{.option = "--terms", .value = t});
  if (std::find(o.terms.begin(), o.terms.end(), "inertia") == o.terms.end())
    throw InputError(errc::option_conflict, "idim: IDIM-IV (--iv) simulates the model and needs its inertia: add the term 'inertia'",
                     ErrorFields{.option = "--terms"});
  if (!o.extra_terms.empty())
    throw InputError(errc::option_conflict, "idim: IDIM-IV (--iv) cannot simulate user terms (extra_terms)",
                     ErrorFields{.option = "--terms"});
}

void run_idim_iv(Result& r, const IdimData& data, const IdimOptions& o, double dt) {
  const IdimRegression reg = idim_regression(data, o);
  const Mat& W = reg.X;
  const Vec& y = reg.y;
  const Eigen::Index p = W.cols(), nobs = W.rows();
  const bool from_velocity = r.diagnostics.texts["regressors_from"] == "velocity";
  std::vector<std::string> names;
  for (const auto& t : reg.terms) names.push_back(t.parameter);
  Vec theta(p);
  for (Eigen::Index j = 0; j < p; ++j) theta(j) = r.value(names[static_cast<std::size_t>(j)]);
  auto& ls = r.diagnostics.groups["ls_estimate"];
  for (Eigen::Index j = 0; j < p; ++j) ls[names[static_cast<std::size_t>(j)]] = theta(j);

  Mat Z;
  double change = std::numeric_limits<double>::infinity();
  int iterations = 0;
  Result model = r;  // carries the current values into a law and an axis
  while (iterations < o.iv.max_iterations) {
    for (Eigen::Index j = 0; j < p; ++j)
      for (auto& q : model.parameters)
        if (q.name == names[static_cast<std::size_t>(j)]) q.value = theta(j);
    model.law.reset();
    model.diagnostics.warnings.clear();
    attach_idim_law(model, o, o.stribeck_vs);
    if (!model.law) {
      r = failed(r, where(data) + "IDIM-IV: the estimate of iteration " + std::to_string(iterations) +
                        " makes no friction law to simulate (" +
                        (model.diagnostics.warnings.empty() ? std::string("none") : model.diagnostics.warnings.back()) +
                        "); the least-squares estimate is in diagnostics.ls_estimate");
      return;
    }
    const Simulated sim = simulate_model(model, data, o, dt, from_velocity);
    if (!sim.error.empty()) {
      r = failed(r, where(data) + "IDIM-IV, iteration " + std::to_string(iterations + 1) + ": " + sim.error);
      return;
    }
    Z = instruments(sim.data, o, reg);
    const Vec next = iv_solve(Z, W, y);
    ++iterations;
    if (next.size() != p || !next.allFinite()) {
      r = failed(r, where(data) + "IDIM-IV, iteration " + std::to_string(iterations) +
                        ": the instruments do not determine the parameters (Z'W is singular)");
      return;
    }
    change = relative_change(W, theta, next);
    theta = next;
    if (change <= o.iv.tolerance) break;
  }
  r.diagnostics.texts["estimator"] = "idim-iv";
  describe_controller(r, o, dt);
  r.diagnostics.numbers["iv_iterations"] = iterations;
  r.diagnostics.numbers["iv_relative_change"] = change;
  if (!(change <= o.iv.tolerance)) {
    r = failed(r, where(data) + "IDIM-IV did not converge in " + std::to_string(iterations) +
                      " iterations (--iv-iterations): the last change moved the model force by " + format_value(change, 3) +
                      " of its norm, above --iv-tolerance " + format_value(o.iv.tolerance, 3) +
                      "; check that the controller is the experiment's (gains, delay, limit, feedforward), or allow more "
                      "iterations");
    return;
  }
  // Values, fit and uncertainty of the IV estimate.
  for (Eigen::Index j = 0; j < p; ++j)
    for (auto& q : r.parameters)
      if (q.name == names[static_cast<std::size_t>(j)]) q.value = theta(j);
  const Vec e = y - W * theta;
  const double s2 = e.squaredNorm() / static_cast<double>(nobs - p);
  r.fit.relative_error_percent = 100.0 * e.norm() / y.norm();
  r.fit.rmse = std::sqrt(e.squaredNorm() / static_cast<double>(nobs));
  r.diagnostics.numbers["residual_std"] = std::sqrt(s2);
  std::erase_if(r.diagnostics.warnings, [&](const std::string& w) {
    return std::any_of(names.begin(), names.end(), [&](const std::string& n) { return w.rfind(n + " = ", 0) == 0; }) ||
           w.rfind("the std of the other parameters", 0) == 0;
  });
  r.diagnostics.undetermined.clear();
  r.diagnostics.at_bound.clear();
  const HacCovariance hac = hac_covariance(Z, e);
  set_uncertainty_from_iv(r, names, W.transpose() * W, Z.transpose() * W, Z.transpose() * Z, hac.meat, s2);
  r.diagnostics.texts["covariance"] = hac.prewhitened ? "newey-west-prewhitened" : "newey-west";
  r.diagnostics.numbers["covariance_bandwidth"] = hac.bandwidth;
  r.diagnostics.numbers["covariance_rho"] = hac.rho;
  auto& corr = r.diagnostics.groups["iv_instrument_correlation"];
  for (Eigen::Index j = 0; j < p; ++j) corr[names[static_cast<std::size_t>(j)]] = column_correlation(W.col(j), Z.col(j));
  const double relevance = min_canonical_correlation(Z, W);
  r.diagnostics.numbers["iv_min_canonical_correlation"] = relevance;
  constexpr double kWeak = 0.3;  // below this the instruments explain less than a tenth of a regressor direction
  if (relevance < kWeak)
    r.diagnostics.warnings.push_back("IDIM-IV: weak instruments (smallest canonical correlation " + format_value(relevance, 3) +
                                     "): the simulated loop moves unlike the record in some direction; the IV std is large "
                                     "and its estimate unreliable");
  set_idim_series(r, data, reg, theta, o);
  add_idim_parameter_warnings(r);
}

}  // namespace frictionlab::detail

namespace frictionlab {

IdimIvScenario idim_iv_scenario(const Scenario& scenario, const std::string& file, Axis axis) {
  const auto refuse = [&](const std::string& key, const std::string& why, const std::string& value = "") {
    return InputError(errc::scenario_value, file + ": " + key + ": " + why,
                      ErrorFields{.file = file, .key = key, .option = "--scenario", .value = value});
  };
  const Plant* plant = scenario.plant.get();
  if (!plant) throw refuse("plant", "missing; IDIM-IV takes the experiment's controller from the scenario");
  if (plant->num_inputs() != 1)
    throw refuse("plant.type",
                 "the " + plant->type() + " has " + std::to_string(plant->num_inputs()) +
                     " axes; IDIM-IV identifies one axis closed by the scenario's top-level controller (type axis)",
                 plant->type());
  const auto axis_name = [](Axis x) { return std::string(x == Axis::rotary ? "rotary (rad, N m)" : "linear (m, N)"); };
  if (plant->motion_axis() != axis)
    throw refuse("plant.type",
                 "the " + plant->type() + " plant moves " + axis_name(plant->motion_axis()) + ", but the identification is " +
                     axis_name(axis) + " (--axis); give the controller by options (--controller and its gains) instead",
                 plant->type());
  IdimIvScenario out;
  out.file = file;
  const Plant* inner = nullptr;
  const Compensator* compensator = nullptr;
  if (const auto* loop = dynamic_cast<const ClosedLoop*>(plant)) {
    if (loop->controller().loop != ControlLoop::position)
      throw refuse("controller.loop",
                   "a velocity loop; IDIM-IV simulates a position loop (its reference is a position, --reference)",
                   "velocity");
    out.controller = loop->controller();
    inner = &loop->inner();
    compensator = loop->compensator();
  } else if (const auto* emps = dynamic_cast<const EmpsPdLoop*>(plant)) {
    out.controller = emps->params();
    inner = &emps->inner();
    compensator = emps->compensator();
  } else {
    throw refuse("controller",
                 "missing; IDIM-IV takes the experiment's controller from it (type pid with Kp, Kd, Ki, limit; or type "
                 "emps-pd with kp, kv, gtau, limit, delay)");
  }
  if (inner->type() != "axis")
    throw refuse("plant.type",
                 "'" + inner->type() + "': IDIM-IV simulates a rigid axis (M qdd = force - friction - offset); expected axis",
                 inner->type());
  if (compensator)
    throw refuse("controller.compensation",
                 "IDIM-IV does not simulate a compensator ('" + compensator->type() +
                     "'); give the force the drive added as --feedforward COLUMN, or remove the block",
                 compensator->type());
  return out;
}

}  // namespace frictionlab
