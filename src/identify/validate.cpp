// Validation by simulation: see include/frictionlab/identify/validate.hpp.
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/identify/method.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/signal/butterworth.hpp"
#include "frictionlab/signal/decimate.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/signal/filtfilt.hpp"
#include "frictionlab/signal/sampling.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab {
namespace {

using Vec = Eigen::VectorXd;

std::string where(const ValidationData& d) { return d.file.empty() ? std::string("validate: ") : d.file + ": "; }


void check_signal(const ValidationData& d, const Vec& v, const char* name, Eigen::Index n) {
  if (v.size() != n)
    throw std::invalid_argument(where(d) + name + " has " + std::to_string(v.size()) + " samples; expected " +
                                std::to_string(n) + " like time");
  for (Eigen::Index k = 0; k < n; ++k)
    if (!std::isfinite(v(k)))
      throw std::invalid_argument(where(d) + "sample " + std::to_string(k + 1) + ": " + name + " = " + detail::format_value(v(k), 6) +
                                  " is not a finite number");
}

// Mean step (s) after checking time is increasing and regular within 1 % of the median step.
double checked_step(const ValidationData& d) {
  RegularSamplingCheck check;  // the one rule of signal/sampling.hpp
  check.where = where(d);
  check.requirement = "validation needs regularly sampled data";
  return check_regular_sampling(d.time, check).mean;
}

struct Motion {
  Vec qd, qdd;  // m/s, m/s^2
};

Motion derive(const Vec& q, double dt, const IdimOptions& o) {
  const TransferFunction lp = butter(o.filter_order, normalized_cutoff(o.cutoff_hz, dt));
  const Vec qf = filtfilt(lp, q, FiltfiltOptions{o.padlen});
  Motion m;
  m.qd = gradient(qf, dt);
  m.qdd = gradient(m.qd, dt);
  return m;
}

double relative_error(const Vec& y, const Vec& y_sim) {
  const double ny = y.norm();
  return ny > 0 ? 100.0 * (y - y_sim).norm() / ny : std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> to_std(const Vec& v) { return {v.data(), v.data() + v.size()}; }

}  // namespace

IdentifiedModel model_from_result(const Result& r) {
  if (!r.ok()) throw std::invalid_argument("model: the identification failed (" + r.message + "); nothing to validate");
  if (!r.law)
    throw std::invalid_argument("model: the " + r.method + " result has no friction law ('law'); expected one to simulate");
  IdentifiedModel m{FrictionLaw::from_spec(*r.law), AxisParams{}, r.method, r.data_file};
  const Parameter* M = r.find("M");
  if (!M) throw std::invalid_argument("model: no parameter 'M' (inertia, kg or kg m^2); expected one to simulate");
  m.axis.M = M->value;
  // The identification's model is u = M a + F + offset (offset: a constant force the drive
  // spends), the plant's a = (u + offset - F) / M (offset: a force added to the drive): one is
  // the negative of the other.
  if (const auto* off = r.find("offset")) m.axis.offset = -off->value;
  RigidAxis check(m.axis);  // throws naming M or offset when out of range
  (void)check;
  return m;
}

Result validate_model(const IdentifiedModel& model, const Scenario& scenario, const ValidationData& data,
                      const ValidateOptions& options) {
  if (!scenario.plant) throw std::invalid_argument("validate: the scenario has no plant");
  const Eigen::Index n = data.time.size();
  const double dt = checked_step(data);
  check_signal(data, data.position, "position", n);
  check_signal(data, data.force, "force", n);
  const IdimOptions& po = options.processing;
  if (po.decimation < 1 || po.skip < 0)
    throw std::invalid_argument("validate: decimation = " + std::to_string(po.decimation) + " must be >= 1 and skip = " +
                                std::to_string(po.skip) + " >= 0 (samples)");
  constexpr Eigen::Index kMinUsed = 64;  // decimate's padding needs 28 samples; ask for a few more
  if (n - po.skip < kMinUsed * std::max(1, po.decimation) / 2 || n <= po.padlen)
    throw std::invalid_argument(where(data) + std::to_string(n) + " samples are too few for skip = " +
                                std::to_string(po.skip) + ", padlen = " + std::to_string(po.padlen) +
                                " and decimation = " + std::to_string(po.decimation));

  const Motion meas = derive(data.position, dt, po);

  Scenario sc = scenario;
  sc.options.duration = static_cast<double>(n - 1) * dt;
  sc.options.output_rate = 1.0 / dt;
  if (options.initial_state_from_data) {
    sc.options.initial_position = data.position[0];
    sc.options.initial_velocity = meas.qd[0];
  }
  const Trajectory tr = simulate(sc);
  if (static_cast<Eigen::Index>(tr.rows()) != n)
    throw std::runtime_error("validate: the simulation gave " + std::to_string(tr.rows()) + " samples; expected " +
                             std::to_string(n));
  const Vec q_sim = Eigen::Map<const Vec>(tr.position.data(), n);
  // The force the drive commands (an open axis: its input; a loop: its controller's output).
  const Vec f_sim = Eigen::Map<const Vec>(tr.drive.data(), n);
  const Motion sim = derive(q_sim, dt, po);

  Result r = new_result(method_info("validate"), "", options.processing.axis);
  r.method = "validate";
  r.model = model.law.name();
  r.data_file = model.source;
  const char* names[] = {"position", "velocity", "acceleration", "force"};
  const Vec* y[] = {&data.position, &meas.qd, &meas.qdd, &data.force};
  const Vec* ys[] = {&q_sim, &sim.qd, &sim.qdd, &f_sim};
  ValidationFigures v;
  v.file = data.file;
  v.sha256 = data.sha256;
  const Eigen::Index used = n - po.skip;
  for (int i = 0; i < 4; ++i) {
    const Vec a = y[i]->segment(po.skip, used), b = ys[i]->segment(po.skip, used);
    const Vec ad = po.decimation == 1 ? a : decimate(a, po.decimation);
    const Vec bd = po.decimation == 1 ? b : decimate(b, po.decimation);
    v.signal_errors_percent[names[i]] = relative_error(ad, bd);
    v.samples = static_cast<std::size_t>(ad.size());
    r.diagnostics.groups["relative_error_percent_full_rate"][names[i]] = relative_error(*y[i], *ys[i]);
  }
  {
    const Vec e = data.force - f_sim;
    v.rmse = std::sqrt(e.squaredNorm() / static_cast<double>(n));  // of the force, N or N m, full rate
  }
  r.validation = v;
  r.diagnostics.numbers["dt"] = dt;
  r.diagnostics.numbers["samples_full_rate"] = static_cast<double>(n);
  r.diagnostics.numbers["skipped_samples"] = static_cast<double>(po.skip);
  r.diagnostics.numbers["decimation"] = po.decimation;
  r.diagnostics.numbers["simulation_steps"] = static_cast<double>(tr.stats.steps);
  r.diagnostics.numbers["mode_switches"] = static_cast<double>(tr.switches.size());

  const Axis axis = po.axis;
  r.parameters.push_back({"M", model.axis.M, std::numeric_limits<double>::quiet_NaN(), std::string(unit(Quantity::inertia, axis)), ""});
  r.parameters.push_back({"offset", -model.axis.offset, std::numeric_limits<double>::quiet_NaN(), std::string(unit(Quantity::force, axis)), ""});
  for (const auto& [name, value] : model.law.to_spec().scalars) {
    const bool viscous = name.rfind("Fv", 0) == 0 || name == "sigma1" || name == "sigma2";
    const bool force = !viscous && name.rfind("F", 0) == 0;
    const std::string u = viscous ? std::string(unit(Quantity::viscous, axis)) : force ? std::string(unit(Quantity::force, axis)) : "";
    r.parameters.push_back({name, value, std::numeric_limits<double>::quiet_NaN(), u, ""});
  }

  r.series["time"] = to_std(data.time);
  r.series["position"] = to_std(data.position);
  r.series["position_sim"] = to_std(q_sim);
  r.series["velocity"] = to_std(meas.qd);
  r.series["velocity_sim"] = to_std(sim.qd);
  r.series["acceleration"] = to_std(meas.qdd);
  r.series["acceleration_sim"] = to_std(sim.qdd);
  r.series["force"] = to_std(data.force);
  r.series["force_sim"] = to_std(f_sim);
  return r;
}

}  // namespace frictionlab
