#include "frictionlab/identify/breakaway.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/identify/uncertainty.hpp"
#include "method_support.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/signal/segments.hpp"

namespace frictionlab {
using namespace detail;
namespace {

// Linear interpolation of y at time t (t inside the record).
double interpolate(const Eigen::VectorXd& time, const Eigen::VectorXd& y, double t) {
  const auto* begin = time.data();
  const auto* end = begin + time.size();
  const auto* it = std::upper_bound(begin, end, t);
  if (it == begin) return y[0];
  if (it == end) return y[time.size() - 1];
  const auto k = static_cast<Eigen::Index>(it - begin) - 1;
  const double w = (t - time[k]) / (time[k + 1] - time[k]);
  return (1 - w) * y[k] + w * y[k + 1];
}

// Integrates M dv/dt = force(t) - Fc sign(v) - Fv v backwards from (t1, v1) until v = 0 and
// returns that time: the instant the axis broke away. Step: a hundredth of the sample time.
double breakaway_time(const Eigen::VectorXd& time, const Eigen::VectorXd& force, double t1, double v1, double M,
                      double Fc, double Fv, double dt) {
  const double s = v1 > 0 ? 1.0 : -1.0;
  auto accel = [&](double t, double v) { return (interpolate(time, force, t) - Fc * s - Fv * v) / M; };
  const double h = -dt / 100;
  double t = t1, v = v1;
  for (int k = 0; k < 100000 && t > time[0]; ++k) {
    const double k1 = accel(t, v), k2 = accel(t + h / 2, v + h / 2 * k1), k3 = accel(t + h / 2, v + h / 2 * k2),
                 k4 = accel(t + h, v + h * k3);
    const double vn = v + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (vn * s <= 0) return t + h * v / (v - vn);  // zero crossing within this step
    t += h;
    v = vn;
  }
  return t;
}

}  // namespace

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::breakaway_method_info() {
  const BreakawayOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "torque-mode trapezoid experiment: breakaway, Coulomb and viscous levels";
  m.fit_signal = "applied force";
  m.fit_quantity = Quantity::force;
  m.options = {
      {.name = "inertia", .type = OptionType::number, .unit = "kg", .rotary_unit = "kg m^2",
       .help = "Inertia held fixed; estimated with Fc and Fv (reported as M) when not given", .min = 0, .min_open = true},
      {.name = "velocity-threshold", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
       .help = "Speed above which the axis moves. Default: 1 % of the largest |velocity|", .min = 0, .min_open = true},
      {.name = "edge-samples", .type = OptionType::integer, .default_value = static_cast<long long>(d.edge_samples),
       .help = "Samples skipped at each end of a sliding interval in the dynamic fit (the velocity has a kink there)",
       .min = 0},
  };
  return m;
}
#pragma GCC diagnostic pop

BreakawayOptions make_breakaway_options(const OptionValues& v) {
  BreakawayOptions o;
  o.inertia = v.number("inertia");
  o.velocity_threshold = v.number("velocity-threshold");
  o.edge_samples = static_cast<int>(v.integer("edge-samples"));
  return o;
}

Result identify_breakaway(const BreakawayData& d, const BreakawayOptions& o) {
  const Eigen::Index n = d.time.size();
  if (d.force.size() != n || d.velocity.size() != n)
    throw std::invalid_argument("breakaway: time, force and velocity must have equal lengths (have " + std::to_string(n) +
                                ", " + std::to_string(d.force.size()) + ", " + std::to_string(d.velocity.size()) + ")");
  const double dt = regular_time_step(d.time, method_info(MethodId::breakaway).name);
  Result r = make_result(MethodId::breakaway, "static-coulomb-viscous", o.axis);
  const auto warn = [&](const std::string& w) { r.diagnostics.warnings.push_back(w); };
  const auto add = [&](const std::string& name, double v, double s, Quantity q) { add_parameter(r, name, v, s, q, o.axis); };

  const double vmax = d.velocity.cwiseAbs().maxCoeff();
  const double threshold = std::isfinite(o.velocity_threshold) ? o.velocity_threshold : 0.01 * vmax;
  if (!(vmax > threshold) || vmax == 0.0)
    return fail(r, "no motion detected: |velocity| never exceeded " + format_number(threshold) + " " +
                       std::string(unit(Quantity::velocity, o.axis)));
  const auto onset = motion_onset(d.velocity, threshold);
  if (*onset == 0)
    return fail(r, "the record starts in motion (|velocity| = " + format_number(std::abs(d.velocity[0])) +
                       " > threshold): a trapezoid experiment starts at rest");
  const auto moving = motion_intervals(d.time, d.velocity, threshold);
  const IndexRange slide = *std::find_if(moving.begin(), moving.end(), [&](const IndexRange& m) { return m.begin == *onset; });
  if (slide.end >= static_cast<std::size_t>(n))
    return fail(r, "the axis never returned to standstill (|velocity| <= " + format_number(threshold) + " " +
                       std::string(unit(Quantity::velocity, o.axis)) + "): extend the ramp down to zero");

  // The lecture's read-offs.
  const double Fs_readoff = d.force[static_cast<Eigen::Index>(*onset)];
  const double Fc_readoff = d.force[static_cast<Eigen::Index>(slide.end)];
  SteadySegmentOptions so;
  so.velocity_tolerance = 0.002 * vmax;
  so.min_duration = 10 * dt;
  so.min_speed = threshold;
  const auto steady = steady_segments(d.time, d.velocity, so);
  double Fv_readoff = std::numeric_limits<double>::quiet_NaN(), v_hold = 0, t_hold = 0;
  for (const auto& seg : steady) {
    const auto b = static_cast<Eigen::Index>(seg.begin), len = static_cast<Eigen::Index>(seg.size());
    const double vm = d.velocity.segment(b, len).mean();
    if (std::abs(vm) > std::abs(v_hold)) {
      v_hold = vm;
      t_hold = seg.t_begin;
      Fv_readoff = (d.force.segment(b, len).mean() - Fc_readoff * (vm > 0 ? 1 : -1)) / vm;
    }
  }
  if (!std::isfinite(Fv_readoff)) warn("no steady hold found: the viscous read-off is not available");

  // Dynamic estimate over the sliding samples, away from the stick/slip kinks.
  const Eigen::VectorXd a = gradient(d.velocity, dt);
  std::vector<Eigen::Index> rows;
  for (const auto& m : moving)
    for (auto k = static_cast<Eigen::Index>(m.begin) + o.edge_samples; k + o.edge_samples < static_cast<Eigen::Index>(m.end); ++k)
      rows.push_back(k);
  const bool fit_inertia = !(std::isfinite(o.inertia) && o.inertia > 0);
  const int p = fit_inertia ? 3 : 2;
  if (static_cast<int>(rows.size()) < 2 * p + 2)
    return fail(r, "only " + std::to_string(rows.size()) + " sliding samples away from stick/slip switches; need at least " +
                       std::to_string(2 * p + 2));
  Eigen::MatrixXd X(static_cast<Eigen::Index>(rows.size()), p);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto k = rows[i];
    const auto ii = static_cast<Eigen::Index>(i);
    const double sg = d.velocity[k] > 0 ? 1.0 : -1.0;
    if (fit_inertia) X.row(ii) << sg, d.velocity[k], a[k];
    else X.row(ii) << sg, d.velocity[k];
    y[ii] = d.force[k] - (fit_inertia ? 0.0 : o.inertia * a[k]);
  }
  const LeastSquaresFit fit = linear_least_squares(X, y, fit_inertia ? std::vector<std::string>{"Fc", "Fv", "M"} : std::vector<std::string>{"Fc", "Fv"}, separable());
  if (!fit.ok) return fail(r, "the sliding data cannot separate Coulomb, viscous and inertial forces: " + fit.message);
  const double Fc = fit.theta[0], Fv = fit.theta[1], M = fit_inertia ? fit.theta[2] : o.inertia;
  if (!(M > 0)) return fail(r, "the estimated inertia " + format_number(M) + " is not positive: the record has too little acceleration");

  // Fs: the force at the instant the axis broke away, from the fitted dynamics.
  const auto k1 = static_cast<Eigen::Index>(*onset);
  const double tb = breakaway_time(d.time, d.force, d.time[k1], d.velocity[k1], M, Fc, Fv, dt);
  const double Fs = interpolate(d.time, d.force, tb);
  // Its uncertainty, propagated from Fc, Fv and M one at a time (their covariance is ignored).
  auto Fs_with = [&](double m, double fc, double fv) {
    return interpolate(d.time, d.force, breakaway_time(d.time, d.force, d.time[k1], d.velocity[k1], m, fc, fv, dt));
  };
  const double dFc = Fs_with(M, Fc + fit.stdev[0], Fv) - Fs, dFv = Fs_with(M, Fc, Fv + fit.stdev[1]) - Fs;
  const double dM = fit_inertia ? Fs_with(M + fit.stdev[2], Fc, Fv) - Fs : 0.0;
  const double Fs_std = std::sqrt(dFc * dFc + dFv * dFv + dM * dM);

  add("Fs", Fs, Fs_std, Quantity::force);
  add("Fc", Fc, fit.stdev[0], Quantity::force);
  add("Fv", Fv, fit.stdev[1], Quantity::viscous);
  if (fit_inertia) add("M", M, fit.stdev[2], Quantity::inertia);
  // Fs keeps its propagated std; the regression's parameters get the common rules.
  set_uncertainty_from_information(r, fit_inertia ? std::vector<std::string>{"Fc", "Fv", "M"} : std::vector<std::string>{"Fc", "Fv"},
                                   fit.information, fit.residual_variance);
  set_fit(r, y, X * fit.theta);
  if (!std::isfinite(r.fit.relative_error_percent) || !std::isfinite(Fs))
    return fail(r, "the fit gave figures that are not finite numbers (force zero throughout?); the data cannot give an answer");
  r.diagnostics.condition_number = fit.condition_number;
  r.diagnostics.groups["readoff"] = {{"Fs", Fs_readoff}, {"Fc", Fc_readoff}, {"Fv", Fv_readoff}};
  auto& num = r.diagnostics.numbers;
  num["onset_time"] = d.time[k1];
  num["breakaway_time"] = tb;
  num["stop_time"] = d.time[static_cast<Eigen::Index>(slide.end)];
  num["hold_velocity"] = v_hold;
  num["hold_start_time"] = t_hold;
  num["velocity_threshold"] = threshold;
  num["sliding_samples"] = static_cast<double>(rows.size());
  r.series["time"].assign(d.time.data(), d.time.data() + n);
  r.series["velocity"].assign(d.velocity.data(), d.velocity.data() + n);
  r.series["force"].assign(d.force.data(), d.force.data() + n);
  if (Fs >= Fc && Fc >= 0 && Fv >= 0) r.law = FrictionLaw(StaticCoulombViscous{Fs, Fc, Fv}).to_spec();
  if (Fs < Fc) warn("Fs = " + format_number(Fs) + " is below Fc = " + format_number(Fc) + ": no stiction peak in this record");
  return r;
}

}  // namespace frictionlab
