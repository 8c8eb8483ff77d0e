#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/finite_result.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "method_support.hpp"

namespace frictionlab {
using namespace detail;
namespace {

// A turning point (velocity zero): time and position, refined between samples.
struct TurningPoint {
  Eigen::Index sample;  // the sample nearest the extremum
  double position;
};

// Position of the extremum near sample m by a parabola through m-1, m, m+1.
double parabolic_peak(const Eigen::VectorXd& x, Eigen::Index m) {
  if (m <= 0 || m + 1 >= x.size()) return x[m];
  const double a = x[m - 1], b = x[m], c = x[m + 1];
  const double den = a - 2 * b + c;
  if (den == 0.0) return b;
  const double delta = 0.5 * (a - c) / den;
  if (std::abs(delta) > 1) return b;
  return b - 0.25 * (a - c) * delta;
}

// The half-cycle energy balance of one record: regressors, losses, fit, turning points.
struct EnergyBalance {
  Eigen::MatrixXd X;
  Eigen::VectorXd y;
  LeastSquaresFit fit;
  std::vector<TurningPoint> turning_points;
  std::string message;  // why it failed; empty when it worked
};

EnergyBalance energy_balance(const Eigen::VectorXd& time, const Eigen::VectorXd& position, double dt,
                             const DecayOptions& o, double k) {
  EnergyBalance eb;
  const Eigen::Index n = time.size();
  const DecayData d{time, position};
  const Eigen::VectorXd v = gradient(d.position, dt);
  const double vmax = v.cwiseAbs().maxCoeff();
  const double stop = std::isfinite(o.stop_threshold) ? o.stop_threshold : 1e-6 * vmax;
  if (!(vmax > stop)) {
    eb.message = "no oscillation: the position never changes";
    return eb;
  }

  // Turning points: where the velocity changes sign (a zero counts as its own sign, so the final
  // standstill of a Coulomb-damped oscillator is one).
  auto sign_of = [&](double x) { return x > stop ? 1 : (x < -stop ? -1 : 0); };
  std::vector<TurningPoint> tp;
  int last = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const int s = sign_of(v[i]);
    if (s == last) continue;
    if (last != 0) {
      // The extremum is the sample with the largest excursion in the direction just travelled.
      Eigen::Index m = i;
      if (i > 0 && (d.position[i - 1] - d.position[i]) * last > 0) m = i - 1;
      tp.push_back({m, parabolic_peak(d.position, m)});
    }
    last = s;
  }
  const Eigen::Index half_cycles = static_cast<Eigen::Index>(tp.size()) - 1;
  if (half_cycles < 3) {
    eb.message = "only " + std::to_string(std::max<Eigen::Index>(0, half_cycles)) +
                 " half cycles found; the energy balance needs at least 3 (record a longer decay)";
    return eb;
  }

  auto potential = [&](double x) { return o.pendulum ? k * (1 - std::cos(x)) : 0.5 * k * x * x; };
  Eigen::MatrixXd X(half_cycles, 2);
  Eigen::VectorXd y(half_cycles);
  for (Eigen::Index h = 0; h < half_cycles; ++h) {
    const auto& a = tp[static_cast<std::size_t>(h)];
    const auto& b = tp[static_cast<std::size_t>(h) + 1];
    double integral = 0;  // trapezoid rule of v^2 between the turning samples
    for (Eigen::Index i = a.sample; i < b.sample; ++i) integral += 0.5 * (v[i] * v[i] + v[i + 1] * v[i + 1]) * dt;
    X(h, 0) = std::abs(a.position - b.position);
    X(h, 1) = integral;
    y[h] = potential(a.position) - potential(b.position);
  }
  const LeastSquaresFit fit = linear_least_squares(X, y, {"Fc", "Fv"}, separable());
  if (!fit.ok) {
    eb.message = "the half cycles cannot separate Coulomb from viscous friction: " + fit.message;
    return eb;
  }

  eb.X = X;
  eb.y = y;
  eb.fit = fit;
  eb.turning_points = tp;
  return eb;
}

// Samples next to a velocity reversal left out of the residual check: the Coulomb force switches
// there, and the central difference that gives the acceleration straddles the switch.
constexpr Eigen::Index kReversalSamples = 2;

// Adequacy of the energy balance (identify/adequacy.hpp), sample by sample: with the fitted Fc
// and Fv, the friction the motion shows, -(restoring force + M a), less the model's Fc sign(v) +
// Fv v, against velocity and time. The balance sums each half cycle, so a friction that is not
// Coulomb plus viscous (a Stribeck rise at low speed) moves both estimates without leaving a
// trace in its own few residuals; here it shows.
// Units: force, or with neither stiffness nor inertia (Fc/k reported) force over stiffness, a
// length. The std of decay come from the half cycles, not from these samples: no claim on them.
void add_decay_adequacy(Result& r, const DecayData& d, double dt, const DecayOptions& o, double k, double Fc,
                        double Fv, bool relative) {
  const Eigen::Index n = d.time.size();
  const Eigen::VectorXd v = gradient(d.position, dt), a = gradient(v, dt);
  const double vmax = v.cwiseAbs().maxCoeff();
  const double moving = 0.02 * vmax;  // the residual check's standstill fraction
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = kReversalSamples; i + kReversalSamples < n; ++i) {
    bool near_reversal = false;
    for (Eigen::Index j = i - kReversalSamples; j < i + kReversalSamples; ++j) near_reversal |= v[j] * v[j + 1] <= 0;
    if (std::abs(v[i]) > moving && !near_reversal) rows.push_back(i);
  }
  if (rows.size() < kAdequacyMinSamples) return;
  const auto restoring = [&](double x) { return o.pendulum ? k * std::sin(x) : k * x; };
  const auto sign = [](double x) { return x > 0 ? 1.0 : -1.0; };
  // M by least squares of this residual's acceleration column, also when the natural frequency is
  // given: it is often estimated from the record (identify auto), and a pendulum's period grows
  // with its amplitude, so k / wn^2 would leave an inertial residual that is no friction's.
  double num = 0, den = 0;
  for (const Eigen::Index i : rows) {
    num += a[i] * (-restoring(d.position[i]) - Fc * sign(v[i]) - Fv * v[i]);
    den += a[i] * a[i];
  }
  const double M = den > 0 ? num / den : 0.0;
  std::vector<double> velocity, time, e;
  double ss = 0;
  for (const Eigen::Index i : rows) {
    const double model = Fc * sign(v[i]) + Fv * v[i];
    velocity.push_back(v[i]);
    time.push_back(d.time[i]);
    e.push_back(-restoring(d.position[i]) - M * a[i] - model);
    ss += model * model;
  }
  AdequacyOptions ao;
  ao.force_scale = std::sqrt(ss / static_cast<double>(rows.size()));  // the modelled friction's rms
  ao.advice.stribeck = "the energy balance fits Coulomb plus viscous friction, so a rise at low speed (a Stribeck "
                       "dip) biases both levels; map the friction-velocity curve from constant-speed runs (sweep) or "
                       "fit it from a driven trajectory (idim with the stribeck term)";
  ao.advice.shape = "the friction-velocity curve is not Coulomb plus viscous (sweep maps it point by point)";
  ao.advice.asymmetry = "decay fits one level for both directions: identify each direction from driven runs (idim: "
                        "--terms inertia,asymmetric)";
  ao.advice.correlated_std = "";  // decay's std come from the half cycles' scatter and the discretisation check
  ao.advice.standstill = false;   // the rows are in motion by construction
  const std::string force_unit = relative ? std::string(unit(Quantity::displacement, o.axis))
                                          : std::string(unit(Quantity::force, o.axis));
  add_adequacy(r, assess_residuals(velocity, {}, time, e, force_unit, std::string(unit(Quantity::velocity, o.axis)), ao));
  r.diagnostics.numbers["adequacy_inertia"] = M;
}

}  // namespace

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
OptionSpec detail::decay_stiffness_option() {
  return {.name = "stiffness", .type = OptionType::number, .unit = "N/m", .rotary_unit = "N m/rad",
          .help = "Restoring stiffness (m g l for a pendulum); give it or --natural-frequency", .min = 0, .min_open = true};
}

MethodInfo detail::decay_method_info() {
  const DecayOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "free oscillation: friction from the energy lost per half cycle";
  m.fit_signal = "energy lost per half cycle";
  m.fit_quantity = Quantity::energy;
  m.options = {
      decay_stiffness_option(),
      {.name = "inertia", .type = OptionType::number, .unit = "kg", .rotary_unit = "kg m^2",
       .help = "Mass or inertia, with --natural-frequency: Fc and Fv in force units", .min = 0, .min_open = true},
      {.name = "natural-frequency", .type = OptionType::number, .unit = "rad/s",
       .help = "sqrt(k/M): without --stiffness, report Fc/k and the damping ratio (with --inertia: Fc and Fv)",
       .min = 0, .min_open = true},
      {.name = "pendulum", .type = OptionType::flag, .default_value = d.pendulum,
       .help = "Restoring torque is stiffness * sin(angle)"},
      {.name = "stop-threshold", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
       .help = "|velocity| below which the oscillation counts as stopped. Default: 1e-6 of the largest |velocity|",
       .min = 0, .min_open = true},
  };
  return m;
}
#pragma GCC diagnostic pop

DecayOptions make_decay_options(const OptionValues& v) {
  DecayOptions o;
  o.stiffness = v.number("stiffness");
  o.inertia = v.number("inertia");
  o.natural_frequency = v.number("natural-frequency");
  o.pendulum = v.flag("pendulum");
  o.stop_threshold = v.number("stop-threshold");
  return o;
}

namespace {

Result identify_decay_unchecked(const DecayData& d, const DecayOptions& o) {
  const Eigen::Index n = d.time.size();
  if (d.position.size() != n)
    throw std::invalid_argument("decay: time has " + std::to_string(n) + " samples but position has " +
                                std::to_string(d.position.size()));
  const bool have_k = std::isfinite(o.stiffness);
  const bool have_wn = std::isfinite(o.natural_frequency);
  if (have_k && !(o.stiffness > 0))
    throw std::invalid_argument("decay: --stiffness = " + format_number(o.stiffness) + " must be > 0 (N/m or N m/rad)");
  if (have_wn && !(o.natural_frequency > 0))
    throw std::invalid_argument("decay: --natural-frequency = " + format_number(o.natural_frequency) + " must be > 0 (rad/s)");
  if (!have_k && !have_wn)
    throw std::invalid_argument("decay: give --stiffness (N/m or N m/rad; m g l for a pendulum) or --natural-frequency (rad/s)");
  const double dt = regular_time_step(d.time, method_info(MethodId::decay).name);
  const bool relative = !have_k && !(std::isfinite(o.inertia) && o.inertia > 0);
  const double k = have_k ? o.stiffness : (relative ? 1.0 : o.inertia * o.natural_frequency * o.natural_frequency);
  Result r = make_result(MethodId::decay, "coulomb-viscous", o.axis);

  const EnergyBalance full = energy_balance(d.time, d.position, dt, o, k);
  if (!full.message.empty()) return fail(r, full.message);
  const LeastSquaresFit& fit = full.fit;
  // The statistical std misses the discretisation error (sampling, differences, peak
  // interpolation), which dominates on clean data. Repeating the balance on every second sample
  // measures it: the difference of the two estimates (an O(dt^2) error quadruples at 2 dt) is
  // added in quadrature, so an absent friction comes out as zero within its uncertainty.
  Eigen::VectorXd discretisation = Eigen::VectorXd::Zero(2);
  if (n >= 64) {
    const Eigen::Index m = (n + 1) / 2;
    Eigen::VectorXd th(m), xh(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      th[i] = d.time[2 * i];
      xh[i] = d.position[2 * i];
    }
    const EnergyBalance half = energy_balance(th, xh, 2 * dt, o, k);
    if (half.message.empty()) discretisation = (half.fit.theta - fit.theta).cwiseAbs();
  }
  Eigen::VectorXd stdev(2);
  for (int i = 0; i < 2; ++i) stdev[i] = std::hypot(fit.stdev[i], discretisation[i]);
  const Eigen::MatrixXd& X = full.X;
  const Eigen::VectorXd& y = full.y;
  const auto& tp = full.turning_points;
  const Axis axis = o.axis;
  if (relative) {
    // Fc / k has the unit of position; zeta = (Fv / k) * wn / 2.
    add_parameter(r, "Fc_over_k", fit.theta[0], stdev[0], Quantity::displacement, axis);
    add_parameter(r, "zeta", fit.theta[1] * o.natural_frequency / 2, stdev[1] * o.natural_frequency / 2,
                  Quantity::dimensionless, axis);
  } else {
    add_parameter(r, "Fc", fit.theta[0], stdev[0], Quantity::force, axis);
    add_parameter(r, "Fv", fit.theta[1], stdev[1], Quantity::viscous, axis);
  }
  {  // Covariance with the statistical correlation and the std widened by the discretisation error.
    const Eigen::MatrixXd& cb = fit.covariance;
    Eigen::Matrix2d cov;
    const double scale1 = relative ? o.natural_frequency / 2 : 1.0;
    const Eigen::Vector2d sd(stdev[0], stdev[1] * scale1);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        cov(i, j) = i == j ? sd[i] * sd[i] : sd[i] * sd[j] * cb(i, j) / std::sqrt(cb(i, i) * cb(j, j));
    if (!cov.allFinite()) cov = Eigen::Vector2d(sd.array().square()).asDiagonal();
    set_uncertainty_from_covariance(r, {r.parameters[0].name, r.parameters[1].name}, cov);
  }
  set_fit(r, y, X * fit.theta);
  if (!std::isfinite(r.fit.relative_error_percent))
    return fail(r, "the energy balance gave figures that are not finite numbers; the data cannot give an answer");
  r.diagnostics.condition_number = fit.condition_number;
  r.diagnostics.numbers["half_cycles"] = static_cast<double>(tp.size() - 1);
  r.diagnostics.numbers["first_amplitude"] = std::abs(tp.front().position);
  r.diagnostics.numbers["last_amplitude"] = std::abs(tp.back().position);
  r.diagnostics.numbers["stiffness"] = k;
  r.series["time"].assign(d.time.data(), d.time.data() + n);
  r.series["position"].assign(d.position.data(), d.position.data() + n);
  for (const auto& q : tp) {
    r.series["peak_time"].push_back(d.time[q.sample]);
    r.series["peak_position"].push_back(q.position);
  }
  add_decay_adequacy(r, d, dt, o, k, fit.theta[0], fit.theta[1], relative);
  if (!relative && fit.theta[0] >= 0 && fit.theta[1] >= 0)
    r.law = FrictionLaw(CoulombViscous{fit.theta[0], fit.theta[1]}).to_spec();
  for (const auto& p : r.parameters)
    if (p.flag.empty() && std::abs(p.value) <= 2 * p.std)
      r.diagnostics.warnings.push_back(p.name + " = " + format_number(p.value) + " is zero within 2 std (" +
                                       format_number(2 * p.std) + "): that friction is not detected");
  return r;
}

}  // namespace

// Numbers or an error, never both (identify/finite_result.hpp): figures that overflow double
// precision (a stiffness of 1e157 N/m: adequacy.residual_std = inf) make an error, not an ok result with inf.
Result identify_decay(const DecayData& d, const DecayOptions& o) { return finite_or_error(identify_decay_unchecked(d, o)); }

}  // namespace frictionlab
