#include "frictionlab/io/json_text.hpp"
#include "frictionlab/analysis/plan/plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "frictionlab/analysis/plan/fisher.hpp"
#include <Eigen/Dense>
#include <random>
#include "frictionlab/budget.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {

namespace {

constexpr int kDefaultRuns = 40;       // sample std to about 11 % (1 / sqrt(2 (R - 1)))
constexpr int kDefaultLugreRuns = 8;   // each LuGre output-error fit takes about a second
constexpr double kBytesPerSample = 30 * 8.0;  // a trajectory's ten columns and the copies a run's fit makes
constexpr double kLimitSlack = 1.02;   // a simulated peak within 2 % of a limit (loop overshoot) passes

// Share of an effect's regressor column that the other columns explain (R^2, uncentred) above
// which the plan cannot separate the effect: its variance inflation 1 / (1 - R^2) exceeds 1000.
// (A good warm-up has about 0.85: T - T_ref keeps a mean, which the qd column explains.)
constexpr double kConfounded = 0.999;
// |correlation| of the condition (temperature, |load|) with the speed |v| over the run above which
// the condition follows the speed schedule: its term and the velocity terms cannot be told apart.
// (A warm-up whose contact heats over many cycles has |corr| about 0.2; one that heats and cools
// with each move, 0.9.)
constexpr double kFollowsSpeed = 0.7;

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const auto n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

// Warnings for the effects' parameters (the load, temperature and ripple columns) that the other
// columns of the clean record's idim regression explain: the design cannot separate them (e.g.
// a temperature that rises with the speed schedule makes qd (T - T_ref) follow qd).
std::vector<std::string> confounding(PlanMethod method, const PlanRig& rig, const ExperimentProfile& p,
                                     const Trajectory& clean, std::vector<PlanFigure>& figures) {
  std::vector<std::string> out;
  if (method != PlanMethod::load_steps && method != PlanMethod::warm_up && method != PlanMethod::ripple_scan) return out;
  // The condition against the speed: a temperature that rises and falls with the moves.
  const std::vector<double>& cond = method == PlanMethod::warm_up ? clean.temperature : clean.load;
  if (method != PlanMethod::ripple_scan && cond.size() == clean.velocity.size() && !cond.empty()) {
    std::vector<double> speed(clean.velocity.size()), level(cond.size());
    for (std::size_t i = 0; i < speed.size(); ++i) speed[i] = std::abs(clean.velocity[i]), level[i] = std::abs(cond[i]);
    const double c = correlation(level, speed);
    const std::string what = method == PlanMethod::warm_up ? "temperature" : "load";
    figures.push_back({what + "_speed_correlation", c, "", "correlation of the " + what + " with |v| over the run"});
    if (std::abs(c) > kFollowsSpeed)
      out.push_back(std::string(method == PlanMethod::warm_up ? "Fv_per_K" : "mu_load") + " is confounded with the speed: the " +
                    what + " follows the speed schedule (correlation " + format_number(c, 3) + " with |v|), so its term and "
                    "the velocity terms (Fv, Fc) cannot be told apart; heat (or load) the contact over many cycles of "
                    "both speeds (a slower thermal response, a longer run)");
  }
  std::mt19937_64 unused(0);
  const PlanMeasurement m = measure(clean, rig, p, SensorNoise{}, unused);
  const IdimRegression reg = idim_regression(plan_idim_data(m), plan_idim_options(rig, method, &p));
  const Eigen::Index n = reg.X.rows(), k = reg.X.cols();
  if (n <= k) return out;
  static const std::vector<std::string> base = {"M", "Fv", "Fc", "offset"};
  for (Eigen::Index j = 0; j < k; ++j) {
    const std::string& name = reg.terms[static_cast<std::size_t>(j)].parameter;
    if (std::find(base.begin(), base.end(), name) != base.end()) continue;
    const Eigen::VectorXd x = reg.X.col(j);
    const double xx = x.squaredNorm();
    if (!(xx > 0)) {
      out.push_back(name + ": its regressor is zero on this plan (nothing excites it)");
      continue;
    }
    Eigen::MatrixXd others(n, k - 1);
    for (Eigen::Index c = 0, o = 0; c < k; ++c)
      if (c != j) others.col(o++) = reg.X.col(c);
    const Eigen::VectorXd r = x - others * others.colPivHouseholderQr().solve(x);
    const double R2 = 1 - r.squaredNorm() / xx;
    figures.push_back({name + "_explained", 100 * R2, "%",
                       "share of its regressor the other terms explain (above " + format_number(100 * kConfounded, 3) +
                           " %: confounded)"});
    if (R2 > kConfounded) {
      std::string most;
      double best = 0;
      for (Eigen::Index c = 0; c < k; ++c) {
        if (c == j) continue;
        const double cn = reg.X.col(c).norm();
        const double corr = cn > 0 ? std::abs(x.dot(reg.X.col(c))) / (std::sqrt(xx) * cn) : 0.0;
        if (corr > best) best = corr, most = reg.terms[static_cast<std::size_t>(c)].parameter;
      }
      out.push_back(name + " is confounded with the other terms on this plan: they explain " + format_number(100 * R2, 4) +
                    " % of its regressor (most with " + most + ", |correlation| " + format_number(best, 3) +
                    "); the design cannot separate them" +
                    (method == PlanMethod::warm_up ? " (the temperature follows the speed schedule)" : ""));
    }
  }
  return out;
}

nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json spread_json(const ParameterSpread& s) {
  nlohmann::json j;
  j["prior"] = number(s.prior);
  j["mean"] = number(s.mean);
  j["bias"] = number(s.mean - s.prior);
  j["std"] = number(s.std_monte_carlo);
  j["std_monte_carlo"] = number(s.std_monte_carlo);
  j["std_fisher"] = number(s.std_fisher);
  j["std_a_priori"] = number(s.std_a_priori);
  const double ref = std::isfinite(s.prior) && s.prior != 0 ? s.prior : s.mean;
  j["relative_std_percent"] = number(100 * s.std_monte_carlo / std::abs(ref));
  j["unit"] = s.unit;
  j["runs"] = s.runs;
  return j;
}

}  // namespace

PlanResult plan_experiment(PlanMethod method, const PlanRig& rig, const PlanOptions& options) {
  PlanResult out;
  out.method = plan_method_name(method);
  out.prior_file = rig.prior_file;
  out.scenario_file = rig.scenario_file;
  out.drive = plan_drive_name(rig.drive);
  out.axis = rig.axis;
  const int runs = options.runs > 0 ? options.runs : (method == PlanMethod::lugre ? kDefaultLugreRuns : kDefaultRuns);
  check_work(runs * kWorkPerRun, "work units", "--runs " + std::to_string(runs) + " (" + format_number(kWorkPerRun, 4) + " units per run before its samples)",
             {.option = "--runs", .value = std::to_string(runs)});
  out.profile = design_experiment(method, rig, options.limits, options.noise, options.design);
  const ExperimentProfile& p = out.profile;
  {
    // The work and memory, before any run: each of the runs and the clean run simulates the
    // profile's samples; one run holds its trajectory (ten columns) and its measurement copies.
    const double samples = std::floor(p.duration * p.sample_rate + 1e-9) + 1.0;
    const std::string what = "the " + out.method + " profile of " + format_number(p.duration, 4) + " s at " +
                             format_number(p.sample_rate, 4) + " Hz (" + format_number(samples, 3) + " samples) and " +
                             std::to_string(runs) + " runs";
    const ErrorFields fields{.option = "--rate", .value = format_number(p.sample_rate, 4)};
    check_memory(samples * kBytesPerSample, what, fields);
    check_work((samples + kWorkPerRun) * (runs + 1.0), "work units (simulated samples and runs)", what, fields);
  }
  const Trajectory clean = simulate_profile(p, rig, rig.law);

  // What the clean run on the prior reaches, against the limits.
  const Axis ax = rig.axis;
  double xmax = 0, vmax = 0, fmax = 0, imax = 0;
  for (std::size_t i = 0; i < clean.rows(); ++i) {
    xmax = std::max(xmax, std::abs(clean.position[i] - clean.position[0]));
    vmax = std::max(vmax, std::abs(clean.velocity[i]));
    fmax = std::max(fmax, std::abs(clean.drive[i]));
    imax = std::max(imax, std::abs(clean.current[i]));
  }
  const std::string xu(unit(Quantity::displacement, ax)), vu(unit(Quantity::velocity, ax)), fu(unit(Quantity::force, ax));
  out.simulated.push_back({"peak_speed", vmax, vu, "largest |velocity| on the prior"});
  out.simulated.push_back({"excursion", xmax, xu, "largest |position - start| on the prior"});
  out.simulated.push_back({"peak_force", fmax, fu, "largest |drive force| on the prior"});
  if (rig.torque_constant > 0) out.simulated.push_back({"peak_current", imax, "A", "largest |motor current| on the prior"});
  const PlanLimits& l = options.limits;
  if (xmax > l.travel)
    throw std::invalid_argument("--limits travel = " + format_number(l.travel, 4) + " " + xu + ": the plan moves the axis " +
                                format_number(xmax, 4) + " " + xu + " from its start on the prior (a " + out.method +
                                " plan needs that travel; a rotary axis without end stops has no travel limit)");
  if (vmax > kLimitSlack * l.speed)
    out.warnings.push_back("the simulated run reaches " + format_number(vmax, 4) + " " + vu + ", above --limits speed = " +
                           format_number(l.speed, 4) + " " + vu + " (the loop overshoots its set point)");
  if (fmax > kLimitSlack * l.force)
    out.warnings.push_back("the simulated run needs " + format_number(fmax, 4) + " " + fu + ", above --limits force");
  if (imax > kLimitSlack * l.current)
    out.warnings.push_back("the simulated run needs " + format_number(imax, 4) + " A, above --limits current");
  for (const auto& s : clean.switches) {
    if (s.kind == SwitchKind::breakaway) {
      out.simulated.push_back({"breakaway_time", s.time, "s", "first breakaway on the prior"});
      break;
    }
  }
  if (method == PlanMethod::breakaway)
    for (auto it = clean.switches.rbegin(); it != clean.switches.rend(); ++it)
      if (it->kind == SwitchKind::stick) {
        out.simulated.push_back({"stop_time", it->time, "s", "return to standstill on the prior"});
        break;
      }

  if (!clean.temperature.empty() && method == PlanMethod::warm_up) {
    const auto [lo, hi] = std::minmax_element(clean.temperature.begin(), clean.temperature.end());
    out.simulated.push_back({"temperature_rise", *hi - *lo, "K", "temperature range of the run on the prior"});
  }
  if (!clean.load.empty()) {
    double lmax = 0;
    for (double x : clean.load) lmax = std::max(lmax, std::abs(x));
    out.simulated.push_back({"peak_load", lmax, fu, "largest |load| of the run"});
  }
  for (auto& w : confounding(method, rig, p, clean, out.simulated)) out.warnings.push_back(std::move(w));

  out.prediction = monte_carlo_spread(method, p, rig, clean, options.noise, runs, options.seed, options.progress);
  // The a-priori (Fisher-information) std of the noise-free plan next to the Monte Carlo one.
  const AprioriSpread apriori = a_priori_spread(method, p, rig, clean, options.noise);
  for (std::size_t k = 0; k < apriori.names.size(); ++k) {
    for (auto& s : out.prediction.parameters) {
      if (s.name != apriori.names[k]) continue;
      s.std_a_priori = s.undetermined ? std::numeric_limits<double>::quiet_NaN() : apriori.std[k];
      const bool singular =
          std::find(apriori.undetermined.begin(), apriori.undetermined.end(), s.name) != apriori.undetermined.end();
      if (singular && !s.undetermined) {
        out.prediction.undetermined.push_back(s.name);
        out.prediction.warnings.push_back(s.name + " is not determined by this plan: its Fisher information on the "
                                                   "prior is (near) singular, the Monte Carlo std " +
                                          format_number(s.std_monte_carlo, 3) + " " + s.unit + " is not to be trusted");
        s.undetermined = true;
        s.std_monte_carlo = s.std_fisher = s.std_a_priori = std::numeric_limits<double>::quiet_NaN();
      }
    }
  }
  out.warnings.insert(out.warnings.begin(), p.warnings.begin(), p.warnings.end());
  out.warnings.insert(out.warnings.end(), out.prediction.warnings.begin(), out.prediction.warnings.end());
  out.undetermined = out.prediction.undetermined;
  if (out.prediction.failed == runs) {
    out.ok = false;
    out.message = "the plan gives no identification on the prior: every one of " + std::to_string(runs) +
                  " simulated runs failed; the first: " + out.prediction.first_failure;
  }
  return out;
}

std::string plan_to_json(const PlanResult& r, const PlanOptions& o, const std::string& profile_file, int indent) {
  nlohmann::json j;
  j["schema"] = 1;
  j["status"] = r.ok ? "ok" : "error";
  j["message"] = r.message;
  j["method"] = r.method;
  j["prior"] = {{"file", r.prior_file}};
  j["scenario"] = {{"file", r.scenario_file}, {"drive", r.drive}};
  j["axis"] = r.axis == Axis::rotary ? "rotary" : "linear";
  const ExperimentProfile& p = r.profile;
  nlohmann::json prof;
  if (!profile_file.empty()) prof["file"] = profile_file;
  prof["columns"] = p.column_names();
  prof["command"] = p.command;
  prof["unit"] = p.command_unit;
  prof["duration_s"] = p.duration;
  prof["sample_rate_hz"] = p.sample_rate;
  prof["samples"] = static_cast<long long>(std::floor(p.duration * p.sample_rate + 1e-9)) + 1;
  nlohmann::json design = nlohmann::json::object();
  for (const auto& f : p.figures) design[f.name] = {{"value", number(f.value)}, {"unit", f.unit}, {"what", f.what}};
  prof["design"] = design;
  nlohmann::json windows = nlohmann::json::array();
  for (const auto& w : p.windows)
    windows.push_back({{"kind", w.kind}, {"t_begin_s", w.t_begin}, {"t_end_s", w.t_end}, {"level", number(w.level)}});
  prof["windows"] = windows;
  j["profile"] = prof;
  nlohmann::json sim = nlohmann::json::object();
  for (const auto& f : r.simulated) sim[f.name] = {{"value", number(f.value)}, {"unit", f.unit}};
  j["simulated"] = sim;
  j["noise"] = {{"position", o.noise.position}, {"velocity", o.noise.velocity}, {"current", o.noise.current},
                {"force", o.noise.force}, {"encoder", o.noise.encoder}};
  j["limits"] = {{"current", number(o.limits.current)}, {"force", number(o.limits.force)},
                 {"speed", number(o.limits.speed)}, {"min_speed", o.limits.min_speed},
                 {"travel", number(o.limits.travel)}};
  nlohmann::json pred;
  pred["runs"] = r.prediction.runs;
  pred["failed"] = r.prediction.failed;
  pred["seed"] = r.prediction.seed;
  nlohmann::json params = nlohmann::json::object();
  for (const auto& s : r.prediction.parameters) params[s.name] = spread_json(s);
  pred["parameters"] = params;
  if (!r.prediction.readoff.empty()) {
    nlohmann::json ro = nlohmann::json::object();
    for (const auto& s : r.prediction.readoff) ro[s.name] = spread_json(s);
    pred["readoff"] = ro;
  }
  j["prediction"] = pred;
  j["undetermined"] = r.undetermined;
  j["warnings"] = r.warnings;
  return json_text(j, indent);
}

}  // namespace frictionlab
