#include "frictionlab/analysis/plan/predict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "frictionlab/cancellation.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

InputSignal scaled(InputSignal s, double k) {
  if (k == 1.0) return s;
  s.value *= k;
  s.initial *= k;
  s.rate *= k;
  s.limit *= k;
  s.level *= k;
  s.rate_down *= k;
  s.amplitude *= k;
  s.offset *= k;
  for (auto& v : s.values) v *= k;
  return s;
}

Eigen::VectorXd column(const std::vector<double>& c) {
  return Eigen::Map<const Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size()));
}

struct Collect {
  std::vector<double> values, stds;
  int flagged = 0;
  std::string unit;
};

ParameterSpread spread(const std::string& name, const Collect& c, double prior, bool fisher) {
  ParameterSpread s;
  s.name = name;
  s.unit = c.unit;
  s.prior = prior;
  s.runs = static_cast<int>(c.values.size());
  s.mean = kNaN;
  s.std_monte_carlo = kNaN;
  s.std_fisher = kNaN;
  if (s.runs >= 1) {
    double sum = 0;
    for (double v : c.values) sum += v;
    s.mean = sum / s.runs;
  }
  if (s.runs >= 2) {
    double ss = 0;
    for (double v : c.values) ss += (v - s.mean) * (v - s.mean);
    s.std_monte_carlo = std::sqrt(ss / (s.runs - 1));
  }
  if (fisher && !c.stds.empty()) {
    double ss = 0;
    for (double v : c.stds) ss += v * v;
    s.std_fisher = std::sqrt(ss / static_cast<double>(c.stds.size()));
  }
  return s;
}

}  // namespace

const ParameterSpread& MonteCarloSpread::parameter(const std::string& name) const {
  std::string names;
  for (const auto& p : parameters) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw std::invalid_argument("plan prediction: no parameter '" + name + "'; the parameters are " + names);
}

Trajectory simulate_profile(const ExperimentProfile& profile, const PlanRig& rig, const FrictionLaw& law) {
  Scenario sc = rig.scenario;
  sc.law = law;
  sc.input = scaled(profile.signal, rig.input_per_command);
  sc.inputs.clear();
  sc.options.duration = profile.duration;
  sc.options.output_rate = profile.sample_rate;
  if (profile.load) {
    if (sc.options.environments.empty()) sc.options.environments.resize(1);
    sc.options.environments[0].load = LoadSource{};
    sc.options.environments[0].load.signal = *profile.load;
  }
  return simulate(sc);
}

PlanMeasurement measure(const Trajectory& clean, const PlanRig& rig, const ExperimentProfile& profile,
                        const SensorNoise& noise, std::mt19937_64& rng) {
  PlanMeasurement m;
  m.time = column(clean.time);
  m.position = add_noise(column(clean.position), noise.position, rng, noise.encoder);
  m.velocity = add_noise(column(clean.velocity), noise.velocity, rng);
  if (rig.torque_constant > 0)
    m.force = rig.torque_constant * add_noise(column(clean.current), noise.current, rng);
  else
    m.force = add_noise(column(clean.drive), noise.force, rng);
  m.reference.resize(m.time.size());
  for (Eigen::Index i = 0; i < m.time.size(); ++i) m.reference[i] = profile.signal.at(m.time[i]).value;
  if (!clean.load.empty()) m.load = column(clean.load);
  if (!clean.temperature.empty()) m.temperature = column(clean.temperature);
  return m;
}

SweepOptions plan_sweep_options(const PlanRig& rig, const Eigen::VectorXd& reference) {
  SweepOptions o;
  o.fit.model = std::isfinite(rig.prior("vs")) ? StaticFitModel::stribeck : StaticFitModel::coulomb_viscous;
  o.fit.num_threads = 1;
  o.reference = reference;
  o.axis = rig.axis;
  return o;
}

IdimOptions plan_idim_options(const PlanRig& rig, PlanMethod method, const ExperimentProfile* profile) {
  IdimOptions o;
  o.auto_cutoff = o.auto_decimation = o.auto_skip = true;
  o.axis = rig.axis;
  const LawEffects& e = rig.law.effects();
  switch (method) {
    case PlanMethod::load_steps: o.terms.push_back("load"); break;
    case PlanMethod::warm_up:
      o.terms.push_back("temperature");
      if (e.temperature) o.temperature_ref = e.temperature->T_ref;
      break;
    case PlanMethod::ripple_scan:
      o.terms.push_back("ripple");
      if (e.ripple) {
        o.ripple_period = e.ripple->period;
        o.ripple_harmonics = static_cast<int>(std::max<std::size_t>(e.ripple->harmonics(), 1));
      }
      break;
    default: break;
  }
  if (profile)
    for (const auto& f : profile->figures)
      if (f.name == "exclude_below") o.exclude_below = f.value;
  return o;
}

IdimData plan_idim_data(const PlanMeasurement& m) {
  IdimData data;
  data.time = m.time;
  data.position = m.position;
  data.force = m.force;
  data.load = m.load;
  data.temperature = m.temperature;
  return data;
}

Result identify_measurement(PlanMethod method, const PlanMeasurement& d, const PlanRig& rig,
                            const ExperimentProfile& profile) {
  switch (method) {
    case PlanMethod::breakaway: {
      BreakawayOptions o;
      o.axis = rig.axis;
      return identify_breakaway(BreakawayData{d.time, d.force, d.velocity, {}}, o);
    }
    case PlanMethod::sweep:
      return identify_sweep(SweepData{d.time, d.force, d.velocity, {}}, plan_sweep_options(rig, d.reference));
    case PlanMethod::idim:
    case PlanMethod::load_steps:
    case PlanMethod::warm_up:
    case PlanMethod::ripple_scan:
      return identify_idim(plan_idim_data(d), plan_idim_options(rig, method, &profile));
    case PlanMethod::lugre: {
      LugreOptions o;
      o.inertia = rig.inertia;
      o.axis = rig.axis;
      return identify_lugre(LugreData{d.time, d.force, d.position}, o);
    }
  }
  throw std::logic_error("identify_measurement: unknown method");
}

MonteCarloSpread monte_carlo_spread(PlanMethod method, const ExperimentProfile& profile, const PlanRig& rig,
                                    const Trajectory& clean, const SensorNoise& noise, int runs, std::uint64_t seed,
                                    const PlanProgress& progress) {
  if (runs < 2) throw std::invalid_argument("plan: runs = " + std::to_string(runs) + " must be >= 2 (Monte Carlo runs)");
  MonteCarloSpread out;
  out.runs = runs;
  out.seed = seed;
  std::vector<std::string> order, readoff_order;
  std::map<std::string, Collect> params, readoff;
  const bool fisher = method == PlanMethod::sweep || is_idim_plan(method);
  for (int k = 1; k <= runs; ++k) {
    throw_if_cancelled();
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(k)};
    std::mt19937_64 rng(seq);
    const PlanMeasurement m = measure(clean, rig, profile, noise, rng);
    const Result r = identify_measurement(method, m, rig, profile);
    if (progress) progress(k, runs);
    if (!r.ok()) {
      if (out.failed++ == 0) out.first_failure = r.message;
      continue;
    }
    for (const auto& p : r.parameters) {
      if (!params.count(p.name)) order.push_back(p.name);
      auto& c = params[p.name];
      c.unit = p.unit;
      if (std::isfinite(p.value)) c.values.push_back(p.value);
      if (std::isfinite(p.std)) c.stds.push_back(p.std);
      else if (!p.flag.empty()) ++c.flagged;
    }
    const auto g = r.diagnostics.groups.find("readoff");
    if (g != r.diagnostics.groups.end())
      for (const auto& [name, v] : g->second) {
        if (!readoff.count(name)) readoff_order.push_back(name);
        auto& c = readoff[name];
        c.unit = r.find(name) ? r.find(name)->unit : "";
        if (std::isfinite(v)) c.values.push_back(v);
      }
  }
  const int ok = runs - out.failed;
  for (const auto& name : order) {
    ParameterSpread s = spread(name, params[name], rig.prior(name), fisher);
    const bool named = std::find(profile.undetermined.begin(), profile.undetermined.end(), name) != profile.undetermined.end();
    if (named || 2 * params[name].flagged > ok || s.runs < 2) {
      s.undetermined = true;
      s.std_monte_carlo = kNaN;
      s.std_fisher = kNaN;
      out.undetermined.push_back(name);
      if (!named)  // the design's warning already says why
        out.warnings.push_back(name + " is not determined by this plan: " + std::to_string(params[name].flagged) +
                               " of " + std::to_string(ok) + " identifications could not determine it");
    }
    // A bias the runs' spread cannot explain (beyond 4 standard errors of the mean and 1 % of
    // the prior): the method, not the noise, limits this parameter on this plan.
    if (!s.undetermined && std::isfinite(s.prior) && s.prior != 0 &&
        std::abs(s.mean - s.prior) > std::max(4 * s.std_monte_carlo / std::sqrt(double(s.runs)), 0.01 * std::abs(s.prior)))
      out.warnings.push_back(name + ": the estimates are biased by " + format_number(s.mean - s.prior, 3) + " " + s.unit +
                             " (" + format_number(100 * (s.mean - s.prior) / std::abs(s.prior), 3) +
                             " % of the prior), more than their spread explains");
    out.parameters.push_back(s);
  }
  for (const auto& name : readoff_order) out.readoff.push_back(spread(name, readoff[name], rig.prior(name), false));
  if (out.failed > 0)
    out.warnings.push_back(std::to_string(out.failed) + " of " + std::to_string(runs) +
                           " identifications gave no answer; the first: " + out.first_failure);
  return out;
}

}  // namespace frictionlab
