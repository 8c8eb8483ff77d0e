// Validation by simulation: see include/frictionlab/identify/validate.hpp.
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/identify/validate.hpp"
#include "frictionlab/identify/method.hpp"
#include "method_support.hpp"

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

std::string where(const std::string& file) { return file.empty() ? std::string("validate: ") : file + ": "; }

void check_signal(const std::string& file, const Vec& v, const std::string& name, Eigen::Index n) {
  if (v.size() != n)
    throw std::invalid_argument(where(file) + name + " has " + std::to_string(v.size()) + " samples; expected " +
                                std::to_string(n) + " like time");
  for (Eigen::Index k = 0; k < n; ++k)
    if (!std::isfinite(v(k)))
      throw std::invalid_argument(where(file) + "sample " + std::to_string(k + 1) + ": " + name + " = " + detail::format_value(v(k), 6) +
                                  " is not a finite number");
}

// Mean step (s) after checking time is increasing and regular within 1 % of the median step.
double checked_step(const Vec& time, const std::string& file) {
  RegularSamplingCheck check;  // the one rule of signal/sampling.hpp
  check.where = where(file);
  check.requirement = "validation needs regularly sampled data";
  return check_regular_sampling(time, check);
}

// The IDIM pipeline's skip and decimation must leave enough samples for the filter and decimate.
void check_processing(Eigen::Index n, const IdimOptions& po, const std::string& file) {
  if (po.decimation < 1 || po.skip < 0)
    throw std::invalid_argument("validate: decimation = " + std::to_string(po.decimation) + " must be >= 1 and skip = " +
                                std::to_string(po.skip) + " >= 0 (samples)");
  constexpr Eigen::Index kMinUsed = 64;  // decimate's padding needs 28 samples; ask for a few more
  if (n - po.skip < kMinUsed * std::max(1, po.decimation) / 2 || n <= po.padlen)
    throw std::invalid_argument(where(file) + std::to_string(n) + " samples are too few for skip = " +
                                std::to_string(po.skip) + ", padlen = " + std::to_string(po.padlen) +
                                " and decimation = " + std::to_string(po.decimation));
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

// The relative error of `y_sim` against `y` (%) on the IDIM grid (first `skip` samples dropped,
// then decimated) into v.signal_errors_percent[key], and at every sample into the diagnostics.
void compare(const std::string& key, const Vec& y, const Vec& y_sim, const IdimOptions& po, ValidationFigures& v, Result& r) {
  const Eigen::Index used = y.size() - po.skip;
  const Vec a = y.segment(po.skip, used), b = y_sim.segment(po.skip, used);
  const Vec ad = po.decimation == 1 ? a : decimate(a, po.decimation);
  const Vec bd = po.decimation == 1 ? b : decimate(b, po.decimation);
  v.signal_errors_percent[key] = relative_error(ad, bd);
  v.samples = static_cast<std::size_t>(ad.size());
  r.diagnostics.groups["relative_error_percent_full_rate"][key] = relative_error(y, y_sim);
}

// The law's parameters with their units on `axis` (from each parameter's quantity: vs in m/s,
// sigma0 in N/m, ...), names prefixed (e.g. "x."), values without std. Spec values the law does
// not list as parameters follow, without a unit.
void add_law_parameters(Result& r, const FrictionLaw& law, const std::string& prefix, Axis axis) {
  const LawSpec spec = law.to_spec();
  std::vector<std::string> listed;
  for (const Parameter& p : law.parameters()) {
    if (!spec.scalars.count(p.name)) continue;
    listed.push_back(p.name);
    r.parameters.emplace_back(prefix + p.name, spec.scalars.at(p.name), std::numeric_limits<double>::quiet_NaN(), p.quantity, axis);
  }
  for (const auto& [name, value] : spec.scalars)
    if (std::find(listed.begin(), listed.end(), name) == listed.end())
      r.parameters.emplace_back(prefix + name, value, std::numeric_limits<double>::quiet_NaN(), std::string());
}

void add_run_numbers(Result& r, double dt, Eigen::Index n, const IdimOptions& po, const Trajectory& tr) {
  r.diagnostics.numbers["dt"] = dt;
  r.diagnostics.numbers["samples_full_rate"] = static_cast<double>(n);
  r.diagnostics.numbers["skipped_samples"] = static_cast<double>(po.skip);
  r.diagnostics.numbers["decimation"] = po.decimation;
  r.diagnostics.numbers["simulation_steps"] = static_cast<double>(tr.stats.steps);
  r.diagnostics.numbers["mode_switches"] = static_cast<double>(tr.switches.size());
}

void check_rows(const Trajectory& tr, Eigen::Index n) {
  if (static_cast<Eigen::Index>(tr.rows()) != n)
    throw std::runtime_error("validate: the simulation gave " + std::to_string(tr.rows()) + " samples; expected " +
                             std::to_string(n));
}

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

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::validate_method_info() {
  MethodInfo m;
  m.summary = "simulation of an identified model against a measured run";
  const char* xy = "two-axis plant (xy-table): ";
  m.options = {
      {.name = "scenario", .type = OptionType::file,
       .help = "Scenario YAML: plant (axis), controller and input (e.g. examples/emps_closed_loop.yaml); its data "
               "inputs read the data, its M, offset and friction come from the model",
       .required = true},
      {.name = "x", .type = OptionType::column, .unit = "m", .default_value = std::string("x.position"),
       .help = std::string(xy) + "measured x position"},
      {.name = "y", .type = OptionType::column, .unit = "m", .default_value = std::string("y.position"),
       .help = std::string(xy) + "measured y position"},
      {.name = "x-force", .type = OptionType::column, .unit = "N", .default_value = std::string("x.drive"),
       .help = std::string(xy) + "x drive force (--scale NAME=N_PER_UNIT converts a command); compared when present"},
      {.name = "y-force", .type = OptionType::column, .unit = "N", .default_value = std::string("y.drive"),
       .help = std::string(xy) + "y drive force; compared when present"},
  };
  return m;
}
#pragma GCC diagnostic pop

Result validate_model(const IdentifiedModel& model, const Scenario& scenario, const ValidationData& data,
                      const ValidateOptions& options) {
  if (!scenario.plant) throw std::invalid_argument("validate: the scenario has no plant");
  const Eigen::Index n = data.time.size();
  const double dt = checked_step(data.time, data.file);
  check_signal(data.file, data.position, "position", n);
  check_signal(data.file, data.force, "force", n);
  const IdimOptions& po = options.processing;
  check_processing(n, po, data.file);

  const Motion meas = derive(data.position, dt, po);

  Scenario sc = scenario;
  sc.options.duration = static_cast<double>(n - 1) * dt;
  sc.options.output_rate = 1.0 / dt;
  if (options.initial_state_from_data) {
    sc.options.initial_position = data.position[0];
    sc.options.initial_velocity = meas.qd[0];
  }
  const Trajectory tr = simulate(sc);
  check_rows(tr, n);
  const Vec q_sim = Eigen::Map<const Vec>(tr.position.data(), n);
  // The force the drive commands (an open axis: its input; a loop: its controller's output).
  const Vec f_sim = Eigen::Map<const Vec>(tr.drive.data(), n);
  const Motion sim = derive(q_sim, dt, po);

  Result r = new_result(method_info(MethodId::validate), "", options.processing.axis);
  r.model = model.law.name();
  r.data_file = model.source;
  const char* names[] = {"position", "velocity", "acceleration", "force"};
  const Vec* y[] = {&data.position, &meas.qd, &meas.qdd, &data.force};
  const Vec* ys[] = {&q_sim, &sim.qd, &sim.qdd, &f_sim};
  ValidationFigures v;
  v.file = data.file;
  v.sha256 = data.sha256;
  for (int i = 0; i < 4; ++i) compare(names[i], *y[i], *ys[i], po, v, r);
  {
    const Vec e = data.force - f_sim;
    v.rmse = std::sqrt(e.squaredNorm() / static_cast<double>(n));  // of the force, N or N m, full rate
  }
  r.validation = v;
  add_run_numbers(r, dt, n, po, tr);

  const Axis axis = po.axis;
  r.parameters.push_back({"M", model.axis.M, std::numeric_limits<double>::quiet_NaN(), std::string(unit(Quantity::inertia, axis)), ""});
  r.parameters.push_back({"offset", -model.axis.offset, std::numeric_limits<double>::quiet_NaN(), std::string(unit(Quantity::force, axis)), ""});
  add_law_parameters(r, model.law, "", axis);

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

Result validate_axes(const Scenario& scenario, const MultiAxisValidationData& data,
                     const std::map<std::string, IdentifiedModel>& models, const ValidateOptions& options) {
  if (!scenario.plant) throw std::invalid_argument("validate: the scenario has no plant");
  const Plant& plant = *scenario.plant;
  if (data.axes.empty()) throw std::invalid_argument(where(data.file) + "no axes to compare; expected at least one");
  std::string contacts;
  for (int k = 0; k < plant.num_contacts(); ++k) contacts += (k ? ", " : "") + plant.contact(k).name;
  // Each record's contact index; every contact is simulated, the records name those compared.
  std::vector<int> index;
  for (const AxisRecord& a : data.axes) {
    int found = -1;
    for (int k = 0; k < plant.num_contacts(); ++k)
      if (!a.name.empty() && plant.contact(k).name == a.name) found = k;
    if (found < 0)
      throw std::invalid_argument("validate: the " + plant.type() + " has no axis '" + a.name + "'; its axes: " + contacts);
    if (std::find(index.begin(), index.end(), found) != index.end())
      throw std::invalid_argument("validate: axis '" + a.name + "' is given twice");
    index.push_back(found);
  }
  for (const auto& [name, m] : models) {
    (void)m;
    bool known = false;
    for (int k = 0; k < plant.num_contacts(); ++k) known = known || plant.contact(k).name == name;
    if (!known) throw std::invalid_argument("validate: a model for axis '" + name + "', which the " + plant.type() + " lacks; its axes: " + contacts);
  }
  const Eigen::Index n = data.time.size();
  const double dt = checked_step(data.time, data.file);
  for (const AxisRecord& a : data.axes) {
    check_signal(data.file, a.position, a.name + ".position", n);
    if (a.force.size() > 0) check_signal(data.file, a.force, a.name + ".force", n);
  }
  const IdimOptions& po = options.processing;
  check_processing(n, po, data.file);

  std::vector<Motion> meas;
  for (const AxisRecord& a : data.axes) meas.push_back(derive(a.position, dt, po));
  Scenario sc = scenario;
  sc.options.duration = static_cast<double>(n - 1) * dt;
  sc.options.output_rate = 1.0 / dt;
  if (options.initial_state_from_data) {
    // Every contact starts where the scenario puts it, unless the record measured it.
    const std::size_t nc = static_cast<std::size_t>(plant.num_contacts());
    std::vector<double>& q0 = sc.options.initial_positions;
    std::vector<double>& v0 = sc.options.initial_velocities;
    if (q0.size() != nc) q0.assign(nc, sc.options.initial_position);
    if (v0.size() != nc) v0.assign(nc, sc.options.initial_velocity);
    for (std::size_t i = 0; i < data.axes.size(); ++i) {
      q0[static_cast<std::size_t>(index[i])] = data.axes[i].position[0];
      v0[static_cast<std::size_t>(index[i])] = meas[i].qd[0];
    }
  }
  const Trajectory tr = simulate(sc);
  check_rows(tr, n);

  Result r = new_result(method_info(MethodId::validate), "", po.axis);
  ValidationFigures v;
  v.file = data.file;
  v.sha256 = data.sha256;
  v.rmse = 0.0;
  std::size_t force_axes = 0;
  r.series["time"] = to_std(data.time);
  for (std::size_t i = 0; i < data.axes.size(); ++i) {
    const AxisRecord& a = data.axes[i];
    const ContactColumns& c = tr.contact(index[i]);
    const Vec q_sim = Eigen::Map<const Vec>(c.position.data(), n);
    const Vec f_sim = Eigen::Map<const Vec>(c.drive.data(), n);
    const Motion sim = derive(q_sim, dt, po);
    compare(a.name + ".position", a.position, q_sim, po, v, r);
    compare(a.name + ".velocity", meas[i].qd, sim.qd, po, v, r);
    compare(a.name + ".acceleration", meas[i].qdd, sim.qdd, po, v, r);
    const std::string p = a.name + ".";
    if (a.force.size() > 0) {
      compare(p + "force", a.force, f_sim, po, v, r);
      v.rmse += (a.force - f_sim).squaredNorm();
      ++force_axes;
      r.series[p + "force"] = to_std(a.force);
    }
    r.series[p + "position"] = to_std(a.position);
    r.series[p + "position_sim"] = to_std(q_sim);
    r.series[p + "velocity"] = to_std(meas[i].qd);
    r.series[p + "velocity_sim"] = to_std(sim.qd);
    r.series[p + "acceleration"] = to_std(meas[i].qdd);
    r.series[p + "acceleration_sim"] = to_std(sim.qdd);
    r.series[p + "reference"] = c.reference;
    r.series[p + "force_sim"] = to_std(f_sim);
  }
  // Of the drive forces, every measured axis's samples together (N or N m, full rate); NaN without.
  v.rmse = force_axes ? std::sqrt(v.rmse / static_cast<double>(force_axes * static_cast<std::size_t>(n)))
                      : std::numeric_limits<double>::quiet_NaN();
  r.validation = v;
  add_run_numbers(r, dt, n, po, tr);

  const Axis axis = po.axis;
  std::string laws;
  for (int k = 0; k < plant.num_contacts(); ++k) {
    const Contact c = plant.contact(k);
    const FrictionLaw& law = c.law ? *c.law : sc.law;
    const std::string p = c.name + ".";
    laws += (k ? ", " : "") + c.name + ": " + law.name();
    r.parameters.push_back({p + "M", plant.inertia(k), std::numeric_limits<double>::quiet_NaN(),
                            std::string(unit(Quantity::inertia, axis)), ""});
    const auto m = models.find(c.name);
    const double offset = m != models.end() ? m->second.axis.offset : 0.0;
    if (m != models.end())
      r.parameters.push_back({p + "offset", -offset, std::numeric_limits<double>::quiet_NaN(),  // as identified
                              std::string(unit(Quantity::force, axis)), ""});
    add_law_parameters(r, law, p, axis);
    r.diagnostics.texts[p + "model"] = m != models.end() ? (m->second.source.empty() ? "given" : m->second.source) : "scenario";
  }
  r.model = laws;
  return r;
}

}  // namespace frictionlab
