#include "frictionlab/identify/breakaway.hpp"
#include "frictionlab/identify/finite_result.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/identify/covariance.hpp"
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

// The acceleration's central difference: its noise at most this share of the acceleration's
// spread (M's errors-in-variables bias below its square), over at most +-kLongestHalfWidth samples.
constexpr double kAccelerationNoiseShare = 0.05;
constexpr Eigen::Index kLongestHalfWidth = 64;
// With the difference over +-w (w > 1), the Newey-West estimate is made on the scores summed over
// blocks of w / kScoreBlockDivisor rows (see the covariance below).
constexpr Eigen::Index kScoreBlockDivisor = 4;

// The least spread of |load| (max - min, relative to max) with which a load coefficient is fitted.
constexpr double kLeastLoadSpread = 0.01;

// The mean |load| over each motion interval (N or N m): the loads the record slid at, free of
// the load cell's sample noise.
std::vector<double> interval_loads(const Eigen::VectorXd& load, const std::vector<IndexRange>& moving) {
  std::vector<double> out;
  for (const auto& m : moving) {
    const auto b = static_cast<Eigen::Index>(m.begin), e = std::min(static_cast<Eigen::Index>(m.end), load.size());
    if (e > b) out.push_back(load.segment(b, e - b).cwiseAbs().mean());
  }
  return out;
}

// Adequacy of the sliding fit (identify/adequacy.hpp): the sliding samples' residual against
// velocity and time. A static-Coulomb-viscous law leaves a Stribeck dip above it at low speed;
// the remedies are in breakaway's terms. Its std are those of least squares on these residuals,
// so a correlated residual is reported.
void add_breakaway_adequacy(Result& r, const BreakawayData& d, const std::vector<Eigen::Index>& rows,
                            const Eigen::VectorXd& residual, Axis axis) {
  if (rows.size() < kAdequacyMinSamples) return;
  std::vector<double> velocity, time, e;
  double ss = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    velocity.push_back(d.velocity[rows[i]]);
    time.push_back(d.time[rows[i]]);
    e.push_back(residual[static_cast<Eigen::Index>(i)]);
    ss += d.force[rows[i]] * d.force[rows[i]];
  }
  AdequacyOptions ao;
  ao.force_scale = std::sqrt(ss / static_cast<double>(rows.size()));  // the sliding force's rms
  ao.advice.stribeck = "the law has no Stribeck dip between Fs and Fc; map the friction-velocity curve from "
                       "constant-speed runs (sweep) or fit it from a trajectory (idim with the stribeck term)";
  ao.advice.shape = "the friction-velocity curve is not Coulomb plus viscous (sweep maps it point by point)";
  ao.advice.asymmetry = "breakaway fits one level for both directions: use direction-dependent terms (idim: "
                        "--terms inertia,asymmetric) or identify each direction's ramps on their own";
  ao.advice.correlated_std = "breakaway's std_ols of Fc, Fv and M (they assume independent samples)";
  ao.advice.correlated_remedy = "breakaway's std accounts for the correlation";
  ao.advice.standstill = false;  // the rows slide
  add_adequacy(r, assess_residuals(velocity, {}, time, e, std::string(unit(Quantity::force, axis)),
                                   std::string(unit(Quantity::velocity, axis)), ao));
}

// True when `loads` spread by more than kLeastLoadSpread of the largest; sets lo and hi.
bool load_spreads(const std::vector<double>& loads, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = 0;
  for (const double x : loads) lo = std::min(lo, x), hi = std::max(hi, x);
  return !loads.empty() && hi - lo > kLeastLoadSpread * hi;
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
      {.name = "load", .type = OptionType::column, .unit = "N", .rotary_unit = "N m",
       .help = "Column of the load force or torque the contact transmits: the sliding fit gains mu_load_coulomb and "
               "every start from rest gives a breakaway force, fitted against its |load| for Fs at zero load and "
               "mu_load_static (dimensionless); needs 3 starts from rest or more at different loads (Python: an "
               "array of the data's length)"},
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

namespace {

Result identify_breakaway_unchecked(const BreakawayData& d, const BreakawayOptions& o) {
  const Eigen::Index n = d.time.size();
  if (d.force.size() != n || d.velocity.size() != n)
    throw std::invalid_argument("breakaway: time, force and velocity must have equal lengths (have " + std::to_string(n) +
                                ", " + std::to_string(d.force.size()) + ", " + std::to_string(d.velocity.size()) + ")");
  const bool with_load = d.load.size() > 0;
  if (with_load && d.load.size() != n)
    throw std::invalid_argument("breakaway: the load has " + std::to_string(d.load.size()) + " samples; expected " +
                                std::to_string(n) + " like time");
  if (with_load)
    for (Eigen::Index k = 0; k < n; ++k)
      if (!std::isfinite(d.load[k]))
        throw std::invalid_argument("breakaway: load sample " + std::to_string(k + 1) + " (counted from 1) is not finite");
  const double dt = regular_time_step(d.time, method_info(MethodId::breakaway).name);
  Result r = make_result(MethodId::breakaway, "static-coulomb-viscous", o.axis);
  const auto warn = [&](const std::string& w) { r.diagnostics.warnings.push_back(w); };
  const auto add = [&](const std::string& name, double v, double s, Quantity q) { add_parameter(r, name, v, s, q, o.axis); };

  const double vmax = d.velocity.cwiseAbs().maxCoeff();
  // A velocity that overflowed (positions near 1e308 differentiated) would make a threshold of inf.
  if (!std::isfinite(vmax))
    return fail(r, "the velocity exceeds the largest double (about 1.8e308 " +
                       std::string(unit(Quantity::velocity, o.axis)) +
                       ") at some sample; expected the velocity of a measured motion (check the position or velocity "
                       "column's unit, --scale)");
  const double threshold = std::isfinite(o.velocity_threshold) ? o.velocity_threshold : 0.01 * vmax;
  if (!(vmax > threshold) || vmax == 0.0)
    return fail(r, "no motion detected: |velocity| never exceeded " + format_number(threshold) + " " +
                       std::string(unit(Quantity::velocity, o.axis)));
  // A motion is a run above the threshold of at least kMotionSamples samples: a quantised encoder's
  // velocity at rest jumps by a count for a sample or two (2 um at 1 kHz: 2 mm/s, above 1 % of a
  // 0.1 m/s top speed), and such a jump read as the breakaway put Fs at the force of that instant.
  constexpr int kMotionSamples = 5;
  const auto moving = motion_intervals(d.time, d.velocity, threshold, (kMotionSamples - 1.5) * dt);
  if (moving.empty())
    return fail(r, "no motion detected: |velocity| never exceeded " + format_number(threshold) + " " +
                       std::string(unit(Quantity::velocity, o.axis)) + " for " + std::to_string(kMotionSamples) +
                       " samples in a row");
  const std::optional<std::size_t> onset = moving.front().begin;
  if (*onset == 0)
    return fail(r, "the record starts in motion (|velocity| = " + format_number(std::abs(d.velocity[0])) +
                       " > threshold): a trapezoid experiment starts at rest");
  const IndexRange slide = moving.front();
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

  // Dynamic estimate over the sliding samples, away from the stick/slip kinks. The acceleration
  // is a central difference of the velocity over +-w samples: noise in the acceleration regressor
  // biases M towards zero by its variance over the acceleration's (errors in variables), and a
  // velocity differentiated from an encoder carries such noise. w is the smallest power of two
  // whose difference's noise (from the velocity's, estimated on its second differences) is below
  // kAccelerationNoiseShare of the acceleration's own spread, so M's bias stays below its square
  // (0.25 %); an exact velocity keeps w = 1.
  const auto difference = [&](Eigen::Index w) {
    Eigen::VectorXd a = gradient(d.velocity, dt);
    for (Eigen::Index k = w; w > 1 && k + w < n; ++k) a[k] = (d.velocity[k + w] - d.velocity[k - w]) / (2.0 * static_cast<double>(w) * dt);
    return a;
  };
  const auto sliding_rows = [&](Eigen::Index edge) {
    std::vector<Eigen::Index> out;
    for (const auto& m : moving)
      for (auto k = static_cast<Eigen::Index>(m.begin) + edge; k + edge < static_cast<Eigen::Index>(m.end); ++k) out.push_back(k);
    return out;
  };
  const double velocity_noise = [&] {
    std::vector<double> d2;
    for (const auto k : sliding_rows(std::max(1, o.edge_samples)))
      d2.push_back(std::abs(d.velocity[k + 1] - 2 * d.velocity[k] + d.velocity[k - 1]));
    if (d2.empty()) return 0.0;
    std::nth_element(d2.begin(), d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2), d2.end());
    return 1.4826 * d2[d2.size() / 2] / std::sqrt(6.0);  // median absolute second difference, white noise
  }();
  Eigen::Index w = 1;
  Eigen::VectorXd a = difference(1);
  for (Eigen::Index trial = 1; trial <= kLongestHalfWidth; trial *= 2) {
    const std::vector<Eigen::Index> at = sliding_rows(std::max<Eigen::Index>(o.edge_samples, trial));
    if (at.size() < 16) break;
    const Eigen::VectorXd at_w = difference(trial);
    double mean = 0, square = 0;
    for (const auto k : at) mean += at_w[k], square += at_w[k] * at_w[k];
    mean /= static_cast<double>(at.size());
    const double spread = square / static_cast<double>(at.size()) - mean * mean;
    const double noise = velocity_noise / (std::sqrt(2.0) * static_cast<double>(trial) * dt);
    w = trial;
    a = at_w;
    if (noise <= kAccelerationNoiseShare * std::sqrt(std::max(0.0, spread - noise * noise))) break;
  }
  r.diagnostics.numbers["acceleration_half_width"] = static_cast<double>(w);
  r.diagnostics.numbers["velocity_noise"] = velocity_noise;
  const std::vector<Eigen::Index> rows = sliding_rows(std::max<Eigen::Index>(o.edge_samples, w));
  const bool fit_inertia = !(std::isfinite(o.inertia) && o.inertia > 0);
  const int p = (fit_inertia ? 3 : 2) + (with_load ? 1 : 0);
  const std::string force_unit(unit(Quantity::force, o.axis));
  if (with_load) {
    double lo = 0, hi = 0;
    if (!load_spreads(interval_loads(d.load, moving), lo, hi))
      return fail(r, "the mean |load| of the sliding intervals lies between " + format_number(lo) + " and " + format_number(hi) + " " +
                         force_unit + " (within " + format_number(100 * kLeastLoadSpread) +
                         " %): mu_load_coulomb cannot be told from Fc; slide at two loads or more");
  }
  if (static_cast<int>(rows.size()) < 2 * p + 2)
    return fail(r, "only " + std::to_string(rows.size()) + " sliding samples away from stick/slip switches; need at least " +
                       std::to_string(2 * p + 2));
  Eigen::MatrixXd X(static_cast<Eigen::Index>(rows.size()), p);
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto k = rows[i];
    const auto ii = static_cast<Eigen::Index>(i);
    const double sg = d.velocity[k] > 0 ? 1.0 : -1.0;
    X(ii, 0) = sg;
    X(ii, 1) = d.velocity[k];
    if (fit_inertia) X(ii, 2) = a[k];
    if (with_load) X(ii, p - 1) = sg * std::abs(d.load[k]);
    y[ii] = d.force[k] - (fit_inertia ? 0.0 : o.inertia * a[k]);
  }
  std::vector<std::string> names{"Fc", "Fv"};
  if (fit_inertia) names.push_back("M");
  if (with_load) names.push_back("mu_load_coulomb");
  const LeastSquaresFit fit = linear_least_squares(X, y, names, separable());
  if (!fit.ok) return fail(r, "the sliding data cannot separate Coulomb, viscous and inertial forces: " + fit.message);
  const double Fc = fit.theta[0], Fv = fit.theta[1], M = fit_inertia ? fit.theta[2] : o.inertia;
  const double mu_c = with_load ? fit.theta[p - 1] : 0.0;
  if (!(M > 0)) return fail(r, "the estimated inertia " + format_number(M) + " is not positive: the record has too little acceleration");
  // Fs: the force at the instant the axis broke away, from the fitted dynamics (with a load: at
  // each start from rest, with the Coulomb level at that start's load).
  const auto k1 = static_cast<Eigen::Index>(*onset);
  const auto level_at = [&](Eigen::Index k) { return Fc + mu_c * (with_load ? std::abs(d.load[k]) : 0.0); };
  const double tb = breakaway_time(d.time, d.force, d.time[k1], d.velocity[k1], M, level_at(k1), Fv, dt);
  double Fs = interpolate(d.time, d.force, tb);
  // Its sensitivities to Fc, Fv and M (finite differences over one ordinary std of each), for the
  // propagation of their covariance below.
  auto Fs_with = [&](double m, double fc, double fv) {
    return interpolate(d.time, d.force, breakaway_time(d.time, d.force, d.time[k1], d.velocity[k1], m, fc, fv, dt));
  };
  Eigen::VectorXd gradient_Fs = Eigen::VectorXd::Zero(p);
  const auto slope = [&](int j, double fs_step) { return fit.stdev[j] > 0 ? (fs_step - Fs) / fit.stdev[j] : 0.0; };
  gradient_Fs[0] = slope(0, Fs_with(M, level_at(k1) + fit.stdev[0], Fv));
  gradient_Fs[1] = slope(1, Fs_with(M, level_at(k1), Fv + fit.stdev[1]));
  if (fit_inertia) gradient_Fs[2] = slope(2, Fs_with(M + fit.stdev[2], level_at(k1), Fv));
  double Fs_std = std::numeric_limits<double>::quiet_NaN();
  double mu_s = 0, mu_s_std = 0;
  if (with_load) {
    // Every start from rest: its breakaway force against its |load|; Fs (at zero load) and
    // mu_load_static by least squares over the starts, their std from the starts' scatter.
    std::vector<Eigen::Index> starts;
    for (const auto& m : moving)
      if (m.begin > 0) starts.push_back(static_cast<Eigen::Index>(m.begin));
    auto& list = r.diagnostics.lists["breakaways"];
    Eigen::MatrixXd S(static_cast<Eigen::Index>(starts.size()), 2);
    Eigen::VectorXd fs(S.rows());
    std::vector<IndexRange> started;
    for (const auto& m : moving)
      if (m.begin > 0) started.push_back(m);
    for (std::size_t i = 0; i < starts.size(); ++i) {
      const auto k = starts[i];
      const double t_b = breakaway_time(d.time, d.force, d.time[k], d.velocity[k], M, level_at(k), Fv, dt);
      const double load_b = std::abs(interpolate(d.time, d.load, t_b));
      const auto ii = static_cast<Eigen::Index>(i);
      S.row(ii) << 1.0, load_b;
      fs[ii] = interpolate(d.time, d.force, t_b) * (d.velocity[k] > 0 ? 1.0 : -1.0);
      list.push_back({{"time", t_b}, {"load", load_b}, {"force", fs[ii]}});
    }
    double lo = 0, hi = 0;
    if (!load_spreads(interval_loads(d.load, started), lo, hi) || starts.size() < 3)
      return fail(r, std::to_string(starts.size()) + " start(s) from rest" +
                         (starts.empty() ? std::string()
                                         : " at |load| " + format_number(lo) + " to " + format_number(hi) + " " + force_unit) +
                         ": the load's part of the breakaway level (mu_load_static) needs at least 3 starts from rest at "
                         "loads more than " + format_number(100 * kLeastLoadSpread) + " % apart");
    const LeastSquaresFit sf = linear_least_squares(S, fs, {"Fs", "mu_load_static"});
    if (!sf.ok) return fail(r, "the breakaway forces cannot be fitted against the load: " + sf.message);
    Fs = sf.theta[0];
    Fs_std = sf.stdev[0];
    mu_s = sf.theta[1];
    mu_s_std = sf.stdev[1];
  }

  add("Fs", Fs, Fs_std, Quantity::force);
  add("Fc", Fc, fit.stdev[0], Quantity::force);
  add("Fv", Fv, fit.stdev[1], Quantity::viscous);
  if (fit_inertia) add("M", M, fit.stdev[2], Quantity::inertia);
  if (with_load) add("mu_load_coulomb", mu_c, fit.stdev[p - 1], Quantity::dimensionless);
  // The regression's std from the Newey-West covariance (identify/covariance.hpp), as idim's: the
  // sliding residual of a drive's current is coloured, and the ordinary figure (std_ols) is then a
  // lower bound. With a noisy velocity (w > 1) the residual also carries M times the acceleration's
  // noise, a difference over +-w of the velocity's: large beside the force noise, and
  // over-differenced (its sum over any run of rows does not grow with the run; the force noise's
  // does). Row by row it hid the force noise's memory from the VAR(1) prewhitening and the std came
  // out 10 to 25 % small (docs/coverage.md). The scores are therefore summed over blocks of w/4 rows
  // first: enough for the force noise to dominate, short enough to leave hundreds of blocks (on the
  // seeded trapezoids blocks of w/2 covered as well, of w + 1 and 2 (w + 1), with fewer blocks, less).
  const Eigen::Index block = std::max<Eigen::Index>(1, w / kScoreBlockDivisor);
  HacCovariance hac;
  if (block > 1 && X.rows() / block > 2 * p + 2) {
    const Eigen::Index rows_n = X.rows(), blocks = rows_n / block;
    const Eigen::MatrixXd scores = X.array().colwise() * fit.residual.array();
    Eigen::MatrixXd summed = Eigen::MatrixXd::Zero(blocks, p);
    for (Eigen::Index t = 0; t < rows_n; ++t) summed.row(std::min(blocks - 1, t * blocks / rows_n)) += scores.row(t);
    // hac_covariance's meat is that of the score rows X .* e: the block sums with e = 1. Its
    // covariance is not this fit's (its X'X is the blocks'); the sandwich below takes the meat only.
    hac = hac_covariance(summed, Eigen::VectorXd::Ones(blocks));
  } else {
    hac = hac_covariance(X, fit.residual);
  }
  const Eigen::MatrixXd cov = set_uncertainty_from_sandwich(r, names, fit.information, hac.meat, fit.residual_variance);
  r.diagnostics.texts["covariance"] = hac.prewhitened ? "newey-west-prewhitened" : "newey-west";
  r.diagnostics.numbers["covariance_bandwidth"] = hac.bandwidth;  // in blocks when covariance_block > 1
  r.diagnostics.numbers["covariance_block"] = static_cast<double>(block > 1 && X.rows() / block > 2 * p + 2 ? block : 1);
  if (fit_inertia && w > 1) {
    // The systematic error the std do not hold: the acceleration's noise biases M towards zero by
    // its variance over the acceleration's (errors in variables), and the difference over +-w
    // smooths the acceleration at the force's corners, which moves Fc, Fv and M. Both change with
    // w, so the fit is made again on the same rows with the difference over +-w/2: the change of
    // each parameter is the order of that error (on the rig log of tests/rigs/experiment_logs.py M
    // was 0.9 % low and changed by 1.3 %, Fc was 3.5 std low and changed by 1.3 std; Fv, 2.9 std
    // high, changed by 0.8 std and is not named). A change larger than the std is warned of.
    const Eigen::VectorXd narrow = difference(w / 2);
    Eigen::MatrixXd Xn = X;
    for (std::size_t i = 0; i < rows.size(); ++i) Xn(static_cast<Eigen::Index>(i), 2) = narrow[rows[i]];
    const LeastSquaresFit fn = linear_least_squares(Xn, y, names, separable());
    if (fn.ok) {
      auto& change = r.diagnostics.groups["width_change"];
      std::string moved;
      for (int j = 0; j < p; ++j) {
        const Parameter* q = r.find(names[static_cast<std::size_t>(j)]);
        if (q == nullptr) continue;
        const double shift = fit.theta[j] - fn.theta[j];
        change[q->name] = shift;
        if (std::abs(shift) > q->std)
          moved += (moved.empty() ? "" : ", ") + q->name + " by " + format_number(shift, 3) + " " + q->unit + " (" +
                   format_number(100 * shift / q->value, 2) + " %, std " + format_number(q->std, 3) + ")";
      }
      if (!moved.empty())
        warn("the fit changes when the acceleration is differenced over +-" + std::to_string(w / 2) +
             " samples instead of +-" + std::to_string(w) + ": " + moved +
             "; the velocity's noise in the acceleration (errors in variables: M towards zero) and the difference's "
             "smoothing at the force's corners leave a systematic error of that order, which the std do not "
             "include; a less noisy velocity (a finer encoder, or the velocity the drive estimates) reduces it");
    }
  }
  if (!with_load) {
    // Fs: the fitted dynamics' part through the sensitivities and the covariance of Fc, Fv, M, and
    // the noise of the one force sample read at the breakaway instant, whose variance the sliding
    // residual's estimates (s^2). std_ols: the same with the ordinary covariance.
    const double noise = fit.residual_variance;
    const double var = gradient_Fs.dot(cov * gradient_Fs) + noise;
    const double var_ols = gradient_Fs.dot(fit.covariance * gradient_Fs) + noise;
    const auto root = [](double x) { return std::isfinite(x) && x >= 0 ? std::sqrt(x) : std::numeric_limits<double>::quiet_NaN(); };
    for (Parameter& q : r.parameters)
      if (q.name == "Fs") q.std = root(var), q.std_ols = root(var_ols);
  }
  if (with_load) add("mu_load_static", mu_s, mu_s_std, Quantity::dimensionless);
  const Eigen::VectorXd modelled = X * fit.theta;
  set_fit(r, y, modelled);
  add_breakaway_adequacy(r, d, rows, y - modelled, o.axis);
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
  if (with_load) r.series["load"].assign(d.load.data(), d.load.data() + n);
  if (Fs >= Fc && Fc >= 0 && Fv >= 0) {
    r.law = FrictionLaw(StaticCoulombViscous{Fs, Fc, Fv}).to_spec();
    if (with_load) {
      LawSpec with_effect = *r.law;
      with_effect.scalars["mu_load_static"] = mu_s;
      with_effect.scalars["mu_load_coulomb"] = mu_c;
      try {
        FrictionLaw::from_spec(with_effect);  // checked as a law file would be
        r.law = with_effect;
      } catch (const std::invalid_argument& e) {
        warn(std::string("the law is given without its load effect: ") + e.what());
      }
    }
  }
  if (Fs < Fc) warn("Fs = " + format_number(Fs) + " is below Fc = " + format_number(Fc) + ": no stiction peak in this record");
  return r;
}

}  // namespace

// Numbers or an error, never both (identify/finite_result.hpp): figures that overflow double
// precision (a force scaled by 2e158: std(Fc) = inf) make an error, not an ok result with inf.
Result identify_breakaway(const BreakawayData& d, const BreakawayOptions& o) { return finite_or_error(identify_breakaway_unchecked(d, o)); }

}  // namespace frictionlab
