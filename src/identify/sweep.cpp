#include "frictionlab/identify/sweep.hpp"
#include "frictionlab/identify/finite_result.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/signal/segments.hpp"
#include "method_support.hpp"

namespace frictionlab {
using namespace detail;

namespace {
SweepPoint point_of(const SweepData& d, Eigen::Index b, Eigen::Index e) {
  SweepPoint p;
  const Eigen::Index n = e - b;
  const auto v = d.velocity.segment(b, n), f = d.force.segment(b, n);
  p.velocity = v.mean();
  p.force = f.mean();
  const double dn = std::max<double>(1.0, static_cast<double>(n - 1));
  p.velocity_std = std::sqrt((v.array() - p.velocity).square().sum() / dn);
  p.force_std = std::sqrt((f.array() - p.force).square().sum() / dn);
  p.t_begin = d.time[b];
  p.t_end = d.time[e - 1];
  p.samples = static_cast<std::size_t>(n);
  if (d.load.size() > 0) p.load = d.load.segment(b, n).cwiseAbs().mean();
  return p;
}

// The least spread of the points' mean |load| (max - min, relative to max) with which mu_load is fitted.
constexpr double kLeastLoadSpread = 0.01;

// The law fitted to the points with mu_load: minimises the points' residual sum of squares over
// mu (the law refitted to F - mu |load| sign(v) at each trial value) by Newton steps on a
// parabola through three values, h apart; the std of mu from that curvature.
struct LoadFit {
  StaticFit fit;               // the law at mu (its std conditional on mu)
  double mu = 0, mu_std = 0;   // dimensionless
  std::vector<double> dtheta;  // d value / d mu of each law parameter, for the widened std
  std::string error;           // why it could not be made (empty: made)
};

LoadFit fit_with_load(const Eigen::VectorXd& v, const Eigen::VectorXd& f, const Eigen::VectorXd& x,
                      const StaticFitOptions& fo, int law_parameters) {
  LoadFit out;
  const Eigen::Index n = v.size();
  const auto at = [&](double mu) { return fit_static_law(v, f - mu * x, fo); };
  const auto rss = [&](const StaticFit& s) { return s.rmse * s.rmse * static_cast<double>(n); };
  // Start and scale: the coulomb-viscous problem with mu, linear (F = Fc sign v + Fv v + mu x).
  Eigen::MatrixXd X(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) X.row(i) << (v[i] > 0 ? 1.0 : -1.0), v[i], x[i];
  const LeastSquaresFit lin = linear_least_squares(X, f, {"Fc", "Fv", "mu_load"});
  if (!lin.ok) {
    out.error = "the points cannot separate the load's part from the levels: " + lin.message;
    return out;
  }
  double mu = lin.theta[2];
  // The step of the parabola: a few of the linear problem's std of mu (there the residual sum
  // moves by several s^2, far above the nonlinear solver's tolerance), never below rounding.
  const double h = std::max(3.0 * lin.stdev[2], 1e-6 * (std::abs(mu) + 1e-3));
  double curvature = 0;
  for (int it = 0; it < 8; ++it) {
    const double rm = rss(at(mu - h)), r0 = rss(at(mu)), rp = rss(at(mu + h));
    curvature = (rp - 2 * r0 + rm) / (h * h);
    if (!(curvature > 0) || !std::isfinite(curvature)) {
      out.error = "the points' residual does not rise either side of mu_load = " + format_number(mu) +
                  ": the loads do not tell the load's part from the levels";
      return out;
    }
    const double step = -(rp - rm) / (2 * h) / curvature;
    mu += step;
    if (std::abs(step) < 1e-3 * h) break;
  }
  out.mu = mu;
  out.fit = at(mu);
  const int dof = static_cast<int>(n) - law_parameters - 1;
  const double s2 = dof > 0 ? rss(out.fit) / dof : std::numeric_limits<double>::quiet_NaN();
  out.mu_std = std::sqrt(2 * s2 / curvature);
  const StaticFit lo = at(mu - h), hi = at(mu + h);
  for (std::size_t j = 0; j < out.fit.parameters.size(); ++j)
    out.dtheta.push_back(j < lo.parameters.size() && j < hi.parameters.size()
                             ? (hi.parameters[j].value - lo.parameters[j].value) / (2 * h)
                             : 0.0);
  return out;
}

int parameter_count(StaticFitModel m, bool fixed_delta) {
  switch (m) {
    case StaticFitModel::coulomb_viscous: return 2;
    case StaticFitModel::coulomb_viscous_asymmetric: return 4;
    case StaticFitModel::stribeck: return fixed_delta ? 4 : 5;
    case StaticFitModel::stribeck_asymmetric: return fixed_delta ? 8 : 10;
  }
  return 5;
}

std::string model_name(StaticFitModel m) {
  switch (m) {
    case StaticFitModel::coulomb_viscous: return "coulomb-viscous";
    case StaticFitModel::coulomb_viscous_asymmetric: return "coulomb-viscous-asymmetric";
    case StaticFitModel::stribeck: return "stribeck";
    case StaticFitModel::stribeck_asymmetric: return "stribeck-asymmetric";
  }
  return "stribeck";
}
}  // namespace

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::sweep_method_info() {
  const SweepOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "constant-velocity tests: a friction-velocity map and a fitted static law";
  m.fit_signal = "friction force";
  m.fit_quantity = Quantity::force;
  auto& o = m.options;
  o.push_back({.name = "model", .type = OptionType::text, .default_value = model_name(d.fit.model),
               .help = "Law to fit to the steady segments' points",
               .words = {"coulomb-viscous", "coulomb-viscous-asymmetric", "stribeck", "stribeck-asymmetric"},
               .refusal = "cannot be fitted to a friction-velocity map"});
  o.push_back({.name = "delta", .type = OptionType::number, .default_value = d.fit.fixed_delta,
               .help = "Hold the Stribeck exponent at this value; 0: fitted (within 0.5 to 5)", .min = 0,
               .deprecated_keywords = {"fixed_delta"},
               .applies_if = {when_value("model", {"stribeck", "stribeck-asymmetric"})}});
  o.push_back({.name = "tolerance", .type = OptionType::number, .default_value = d.relative_tolerance,
               .help = "Relative velocity band of a steady segment (a fraction of its speed)", .min = 0,
               .deprecated_keywords = {"relative_tolerance"}, .applies_if = {unless_given("segment")}});
  o.push_back({.name = "velocity-tolerance", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
               .default_value = d.velocity_tolerance, .help = "Absolute velocity band of a steady segment", .min = 0,
               .applies_if = {unless_given("segment")}});
  o.push_back({.name = "noise-band", .type = OptionType::number, .default_value = d.noise_band,
               .help = "Half-width of the steady band in standard deviations of the smoothed velocity's measured noise",
               .min = 0, .applies_if = {unless_given("segment"), unless_given("reference")}});
  o.push_back({.name = "smoothing-fraction", .type = OptionType::number, .default_value = d.smoothing_fraction,
               .help = "Moving-average window of the velocity, as a fraction of --min-duration", .min = 0, .min_open = true,
               .applies_if = {unless_given("segment"), unless_given("reference")}});
  o.push_back({.name = "min-duration", .type = OptionType::number, .unit = "s", .default_value = d.min_duration,
               .help = "Shortest steady segment kept", .min = 0, .min_open = true,
               .applies_if = {unless_given("segment")}});
  o.push_back({.name = "settle-fraction", .type = OptionType::number, .default_value = d.settle_fraction,
               .help = "Part of each segment dropped at its start (the settling of the previous speed step)", .min = 0,
               .max = 1, .max_open = true, .applies_if = {unless_given("segment")}});
  o.push_back({.name = "min-speed", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
               .help = "Slower segments are standstill, not sliding. Default: 1e-6 of the largest |velocity| (of "
                       "--reference when given)",
               .min = 0, .applies_if = {unless_given("segment")}});
  o.push_back({.name = "min-segments", .type = OptionType::integer,
               .help = "Fewer steady segments is an error. Default: the law's parameter count + 1", .min = 1});
  o.push_back({.name = "segment", .type = OptionType::list, .unit = "s",
               .help = "T_BEGIN:T_END of a steady segment, instead of detection (repeatable; Python: a list of "
                       "(t_begin, t_end) pairs)",
               .repeatable = true, .deprecated_keywords = {"windows"}});
  o.push_back({.name = "reference", .type = OptionType::column, .unit = "m/s", .rotary_unit = "rad/s",
               .help = "Commanded velocity: steady segments are found on it instead of on the measured velocity "
                       "(which is smoothed, with a band that covers its measured noise). Python: an array of the "
                       "data's length",
               .applies_if = {unless_given("segment")}});
  o.push_back({.name = "load", .type = OptionType::column, .unit = "N", .rotary_unit = "N m",
               .help = "Column of the load force or torque the contact transmits: each steady segment's mean |load| "
                       "goes with its point and mu_load (the Coulomb and static levels' rise per unit of load, "
                       "dimensionless) is fitted; run the speeds at two loads or more (Python: an array of the data's "
                       "length)"});
  return m;
}
#pragma GCC diagnostic pop

SweepOptions make_sweep_options(const OptionValues& v) {
  SweepOptions o;
  o.fit.model = parse_static_fit_model(v.text("model"));
  o.fit.fixed_delta = v.number("delta");
  o.relative_tolerance = v.number("tolerance");
  o.velocity_tolerance = v.number("velocity-tolerance");
  o.noise_band = v.number("noise-band");
  o.smoothing_fraction = v.number("smoothing-fraction");
  o.min_duration = v.number("min-duration");
  o.settle_fraction = v.number("settle-fraction");
  if (v.given("min-speed")) o.min_speed = v.number("min-speed");
  if (v.given("min-segments")) o.min_segments = static_cast<int>(v.integer("min-segments"));
  for (const auto& s : v.list("segment")) {
    const auto colon = s.find(':');
    try {
      std::size_t used = 0;
      if (colon == std::string::npos) throw std::invalid_argument("");
      const double a = std::stod(s.substr(0, colon), &used);
      if (used != colon) throw std::invalid_argument("");
      const double b = std::stod(s.substr(colon + 1), &used);
      if (used != s.size() - colon - 1) throw std::invalid_argument("");
      o.windows.push_back({a, b});
    } catch (const std::exception&) {
      throw std::invalid_argument("--segment '" + s + "': expected T_BEGIN:T_END in seconds, e.g. 2.5:4.0");
    }
  }
  return o;
}

std::vector<SweepPoint> sweep_points(const SweepData& d, const SweepOptions& o) {
  const Eigen::Index n = d.time.size();
  if (d.force.size() != n || d.velocity.size() != n)
    throw std::invalid_argument("sweep: time, force and velocity must have equal lengths (have " + std::to_string(n) + ", " +
                                std::to_string(d.force.size()) + ", " + std::to_string(d.velocity.size()) + ")");
  if (d.load.size() > 0 && d.load.size() != n)
    throw std::invalid_argument("sweep: the load has " + std::to_string(d.load.size()) + " samples; expected " +
                                std::to_string(n) + " like time");
  if (d.load.size() > 0)
    for (Eigen::Index k = 0; k < n; ++k)
      if (!std::isfinite(d.load[k]))
        throw std::invalid_argument("sweep: load sample " + std::to_string(k + 1) + " (counted from 1) is not finite");
  if (n < 2) throw std::invalid_argument("sweep: " + std::to_string(n) + " samples are too few; expected at least 2");
  for (Eigen::Index k = 0; k < n; ++k)
    if (!std::isfinite(d.time[k]) || !std::isfinite(d.force[k]) || !std::isfinite(d.velocity[k]))
      throw std::invalid_argument("sweep: sample " + std::to_string(k + 1) + " (counted from 1) is not finite");
  if (n >= 3) regular_time_step(d.time, method_info(MethodId::sweep).name);  // the time column checked as every method checks it
  std::vector<SweepPoint> points;
  if (!o.windows.empty()) {
    for (const auto& w : o.windows) {
      const auto* t0 = d.time.data();
      const auto b = std::lower_bound(t0, t0 + n, w.t_begin) - t0;
      const auto e = std::upper_bound(t0, t0 + n, w.t_end) - t0;
      if (!(w.t_end > w.t_begin) || e - b < 2)
        throw std::invalid_argument("sweep: window " + format_number(w.t_begin) + ":" + format_number(w.t_end) +
                                    " s holds fewer than 2 samples of the record (" + format_number(d.time[0]) + " to " +
                                    format_number(d.time[n - 1]) + " s)");
      points.push_back(point_of(d, b, e));
    }
    return points;
  }
  const bool by_reference = o.reference.size() > 0;
  if (by_reference && o.reference.size() != n)
    throw std::invalid_argument("sweep: the reference velocity has " + std::to_string(o.reference.size()) +
                                " samples; expected " + std::to_string(n) + " like time");
  if (by_reference && !o.reference.allFinite())
    throw std::invalid_argument("sweep: the reference velocity has a sample that is not finite");
  const double dt = (d.time[n - 1] - d.time[0]) / static_cast<double>(n - 1);
  // Segments are found on the reference as given, or on the smoothed measured velocity with a
  // band that covers its measured noise.
  const auto window = by_reference ? Eigen::Index{1}
                                   : std::max<Eigen::Index>(1, std::lround(o.smoothing_fraction * o.min_duration / dt));
  const Eigen::VectorXd track = by_reference ? o.reference : moving_average(d.velocity, window);
  const double noise = by_reference ? 0.0 : difference_noise_std(d.velocity);
  const double band = std::max(o.velocity_tolerance, o.noise_band * noise / std::sqrt(static_cast<double>(window)));
  SteadySegmentOptions so;
  const double vmax = track.cwiseAbs().maxCoeff();
  so.velocity_tolerance = band;
  so.relative_tolerance = o.relative_tolerance;
  if (!(so.velocity_tolerance > 0) && !(so.relative_tolerance > 0)) so.relative_tolerance = 0.01;
  so.min_duration = o.min_duration;
  // Standstill is told apart by the noise band below (a mean within its band of zero), so the
  // floor is only against rounding: a slow level of a wide sweep (0.05 % of full speed) stays.
  so.min_speed = o.min_speed >= 0 ? o.min_speed : 1e-6 * vmax;
  const auto trim = by_reference ? Eigen::Index{0} : window / 2;  // the average blurs each edge by half a window
  struct Range {
    Eigen::Index b, e;
    double mean;
  };
  std::vector<Range> ranges;
  for (const auto& seg : steady_segments(d.time, track, so)) {
    const auto b0 = static_cast<Eigen::Index>(seg.begin) + trim, e0 = static_cast<Eigen::Index>(seg.end) - trim;
    if (e0 - b0 < 2) continue;
    const double mean = track.segment(b0, e0 - b0).mean();
    // Within its band of zero it cannot be told from standstill.
    if (std::abs(mean) <= std::max(band, o.relative_tolerance * std::abs(mean))) continue;
    // A level whose band broke once (its start still in the settling tail, a noise excursion)
    // comes out as two segments in a row at the same speed: one level, one point. They are one
    // level when the gap is short, or when the velocity never left the level's neighbourhood
    // (within half its speed) in between; a standstill or another speed between them keeps two.
    if (!ranges.empty()) {
      Range& last = ranges.back();
      const double half = std::max(band, o.relative_tolerance * std::max(std::abs(mean), std::abs(last.mean)));
      const double gap = d.time[b0] - d.time[last.e - 1];
      const auto stayed_near = [&] {
        for (Eigen::Index k = last.e; k < b0; ++k)
          if (std::abs(track[k] - mean) > 0.5 * std::abs(mean)) return false;
        return true;
      };
      if (std::abs(mean - last.mean) <= half && (gap <= o.min_duration || stayed_near())) {
        last.e = e0;
        last.mean = track.segment(last.b, last.e - last.b).mean();
        continue;
      }
    }
    ranges.push_back({b0, e0, mean});
  }
  for (const auto& g : ranges) {
    const auto skip = static_cast<Eigen::Index>(o.settle_fraction * static_cast<double>(g.e - g.b));
    points.push_back(point_of(d, g.b + skip, g.e));
  }
  return points;
}

namespace {

// Adequacy of a sweep's law (identify/adequacy.hpp): every sample of the steady segments against
// the fitted law at its own velocity. A law that lacks the Stribeck dip leaves the slow segments'
// samples above it; one with the wrong shape leaves a pattern across the speeds. The law was
// fitted to the segments' means, so its std do not come from these residuals: their correlation
// is not a finding, nor is standstill (segments are in motion by construction).
void add_sweep_adequacy(Result& r, const SweepData& d, const std::vector<SweepPoint>& points, const FrictionLaw& law,
                        double mu_load, const SweepOptions& o) {
  std::vector<double> velocity, residual;
  std::vector<std::size_t> ends;
  std::size_t per_direction[2] = {0, 0};
  double ss = 0, slowest = std::numeric_limits<double>::infinity();
  const double* t0 = d.time.data();
  const double* t1 = t0 + d.time.size();
  for (const auto& p : points) {
    const auto end = static_cast<Eigen::Index>(std::upper_bound(t0, t1, p.t_end) - t0);
    for (auto k = static_cast<Eigen::Index>(std::lower_bound(t0, t1, p.t_begin) - t0); k < end; ++k) {
      const double v = d.velocity[k], sign = v > 0 ? 1.0 : -1.0;
      const double load = d.load.size() > 0 ? mu_load * std::abs(d.load[k]) * sign : 0.0;
      velocity.push_back(v);
      residual.push_back(d.force[k] - law.sliding(v) - load);
      ss += d.force[k] * d.force[k];
    }
    if (ends.empty() ? !residual.empty() : residual.size() > ends.back()) ends.push_back(residual.size());
    ++per_direction[p.velocity > 0 ? 0 : 1];
    slowest = std::min(slowest, std::abs(p.velocity));
  }
  if (residual.size() < kAdequacyMinSamples) return;
  AdequacyOptions ao;
  ao.force_scale = std::sqrt(ss / static_cast<double>(residual.size()));  // the segments' force rms
  ao.segment_ends = ends;
  // About one velocity bin per segment (equal-count bins over segments of similar length), so
  // the slowest bin is the slowest segment, where a missing Stribeck dip shows.
  ao.velocity_bins = std::max(ao.velocity_bins, std::max(per_direction[0], per_direction[1]));
  // Every segment is in motion: none of them counts as standstill.
  double vmax = 0;
  for (double v : velocity) vmax = std::max(vmax, std::abs(v));
  ao.standstill_fraction = 0.5 * slowest / vmax;
  const bool asymmetric = o.fit.model == StaticFitModel::coulomb_viscous_asymmetric ||
                          o.fit.model == StaticFitModel::stribeck_asymmetric;
  ao.advice.stribeck = asymmetric ? "fit the Stribeck law (sweep --model stribeck-asymmetric)"
                                  : "fit the Stribeck law (sweep --model stribeck)";
  ao.advice.shape = "the friction-velocity curve is not the law's shape: compare the laws (sweep --model) on "
                    "held-out data, or look at the points in the figure";
  ao.advice.asymmetry = "fit direction-dependent levels (sweep --model coulomb-viscous-asymmetric or "
                        "stribeck-asymmetric)";
  ao.advice.correlated_std.clear();
  ao.advice.standstill = false;
  // Not against time: a sweep's speeds change with time, so a drift cannot be told from the
  // friction-velocity curve.
  add_adequacy(r, assess_residuals(velocity, {}, {}, residual, std::string(unit(Quantity::force, o.axis)),
                                   std::string(unit(Quantity::velocity, o.axis)), ao));
}

Result identify_sweep_unchecked(const SweepData& d, const SweepOptions& o) {
  const auto points = sweep_points(d, o);
  const std::string model = model_name(o.fit.model);
  Result r = make_result(MethodId::sweep, model, o.axis);
  if (d.time.size() >= 2 && o.windows.empty()) {
    const double dt = (d.time[d.time.size() - 1] - d.time[0]) / static_cast<double>(d.time.size() - 1);
    r.diagnostics.numbers["smoothing_samples"] =
        o.reference.size() > 0 ? 1.0 : std::max(1.0, std::round(o.smoothing_fraction * o.min_duration / dt));
    r.diagnostics.numbers["velocity_noise_std"] = difference_noise_std(d.velocity);
    r.diagnostics.texts["segmented_on"] = o.reference.size() > 0 ? "reference" : "velocity";
  }
  auto& list = r.diagnostics.lists["points"];
  auto& levels = r.diagnostics.lists["levels"];
  const bool with_load = d.load.size() > 0;
  for (const auto& p : points) {
    list.push_back({{"velocity", p.velocity}, {"velocity_std", p.velocity_std}, {"force", p.force},
                    {"force_std", p.force_std}, {"t_begin", p.t_begin}, {"t_end", p.t_end},
                    {"samples", static_cast<double>(p.samples)}});
    if (with_load) list.back()["load"] = p.load;
    levels.push_back({{"speed", p.velocity}, {"duration", p.t_end - p.t_begin}, {"samples", static_cast<double>(p.samples)}});
  }
  r.diagnostics.numbers["segments"] = static_cast<double>(points.size());
  const int p = parameter_count(o.fit.model, o.fit.fixed_delta > 0);
  const int need = o.min_segments > 0 ? o.min_segments : p + 1 + (with_load ? 1 : 0);
  if (static_cast<int>(points.size()) < need)
    return fail(r, "only " + std::to_string(points.size()) + " steady segments found; " + model + " needs at least " +
                       std::to_string(need) + " (relative velocity tolerance " + format_number(o.relative_tolerance) +
                       ", minimum duration " + format_number(o.min_duration) + " s)");
  const auto npos = std::count_if(points.begin(), points.end(), [](const SweepPoint& q) { return q.velocity > 0; });
  if (npos == 0 || npos == static_cast<long>(points.size()))
    r.diagnostics.warnings.push_back(std::string("no ") + (npos == 0 ? "positive" : "negative") +
                                     "-velocity segments: the map covers one direction only");
  Eigen::VectorXd v(static_cast<Eigen::Index>(points.size())), f(v.size()), lx = Eigen::VectorXd::Zero(v.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    v[static_cast<Eigen::Index>(i)] = points[i].velocity;
    f[static_cast<Eigen::Index>(i)] = points[i].force;
    if (with_load) lx[static_cast<Eigen::Index>(i)] = points[i].load * (points[i].velocity > 0 ? 1.0 : -1.0);
  }
  double mean_load = 0, mu_load = 0;
  StaticFit fit;
  LoadFit load_fit;
  if (with_load) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const auto& q : points) lo = std::min(lo, q.load), hi = std::max(hi, q.load), mean_load += q.load;
    mean_load /= static_cast<double>(points.size());
    r.diagnostics.numbers["load_min"] = lo;
    r.diagnostics.numbers["load_max"] = hi;
    // Loads within 1 % of each other leave mu_load to the noise of the levels.
    if (!(hi - lo > kLeastLoadSpread * hi))
      return fail(r, "the steady segments' mean |load| lies between " + format_number(lo) + " and " + format_number(hi) +
                         " " + std::string(unit(Quantity::force, o.axis)) + " (within " +
                         format_number(100 * kLeastLoadSpread) +
                         " %): mu_load cannot be told from the levels; run the speeds at two loads or more");
  }
  try {
    if (with_load) {
      load_fit = fit_with_load(v, f, lx, o.fit, p);
      if (!load_fit.error.empty()) return fail(r, load_fit.error);
      fit = load_fit.fit;
      mu_load = load_fit.mu;
    } else {
      fit = fit_static_law(v, f, o.fit);
    }
  } catch (const std::invalid_argument& e) {
    return fail(r, std::string("the segment means cannot be fitted: ") + e.what());
  }
  for (std::size_t j = 0; j < fit.parameters.size(); ++j) {
    const auto& q = fit.parameters[j];
    double sd = q.std;
    // The law's std at mu_load, widened by how the law moves with mu_load (exact when linear).
    if (with_load && std::isfinite(sd) && sd > 0)
      sd = std::sqrt(sd * sd + load_fit.dtheta[j] * load_fit.dtheta[j] * load_fit.mu_std * load_fit.mu_std);
    add_parameter(r, q.name, q.value, sd, q.quantity, o.axis);
    r.parameters.back().flag = q.flag;
  }
  if (with_load) {
    add_parameter(r, "mu_load", mu_load, load_fit.mu_std, Quantity::dimensionless, o.axis);
    r.diagnostics.numbers["load_mean"] = mean_load;
  }
  if (!std::isfinite(fit.relative_error_percent) || !std::isfinite(fit.rmse))
    return fail(r, "the fit of the segment means gave figures that are not finite numbers (force zero throughout?); "
                   "the data cannot give an answer");
  // With a load the fitted law saw F - mu x: the relative error is taken against the measured F.
  if (with_load && f.norm() > 0) fit.relative_error_percent = 100.0 * fit.rmse * std::sqrt(static_cast<double>(f.size())) / f.norm();
  r.fit.relative_error_percent = fit.relative_error_percent;
  r.fit.rmse = fit.rmse;
  r.fit.samples = fit.samples;
  // The Stribeck part needs slow points: say so in the terms of the sweep (its levels).
  const bool stribeck = o.fit.model == StaticFitModel::stribeck || o.fit.model == StaticFitModel::stribeck_asymmetric;
  if (stribeck) {
    for (const char* side : {"", "_pos", "_neg"}) {
      const auto* vs = r.find(std::string("vs") + side);
      if (!vs) continue;
      const double sgn = std::string(side) == "_neg" ? -1.0 : 1.0;
      double slowest = std::numeric_limits<double>::infinity();
      int below = 0;
      for (const auto& q : points) {
        if (*side && q.velocity * sgn <= 0) continue;
        slowest = std::min(slowest, std::abs(q.velocity));
        below += std::abs(q.velocity) < vs->value ? 1 : 0;
      }
      if (slowest > 2 * vs->value || below < o.fit.min_points_below_vs)
        r.diagnostics.warnings.push_back(
            "the Stribeck part" + std::string(*side ? (sgn > 0 ? " (positive direction)" : " (negative direction)") : "") +
            " is not determined by the data: the slowest segment is at " + format_number(slowest) + " " + vs->unit + " (vs = " +
            format_number(vs->value) + "), " + std::to_string(below) + " segment(s) below vs; add slower speeds");
    }
  }
  for (auto& w : fit.warnings) r.diagnostics.warnings.push_back(w);
  r.diagnostics.undetermined = fit.undetermined;
  r.diagnostics.at_bound = fit.at_bound;
  r.diagnostics.correlation = fit.correlation;
  r.diagnostics.numbers["iterations"] = fit.iterations;
  for (const auto& q : points) {  // figure signals: the measured map and the fitted law over it
    r.series["velocity"].push_back(q.velocity);
    r.series["force"].push_back(q.force);
    r.series["force_std"].push_back(q.force_std);
  }
  const double vlo = v.minCoeff(), vhi = v.maxCoeff();
  constexpr int kCurve = 400;
  for (int i = 0; i < kCurve; ++i) {
    const double x = vlo + (vhi - vlo) * i / (kCurve - 1);
    if (x == 0.0) continue;
    r.series["law_velocity"].push_back(x);
    r.series["law_force"].push_back(fit.law.sliding(x) + mu_load * mean_load * (x > 0 ? 1.0 : -1.0));
  }
  r.law = fit.law.to_spec();
  add_sweep_adequacy(r, d, points, fit.law, with_load ? mu_load : 0.0, o);
  if (with_load) {
    // The law at zero load with its load effect; a negative mu_load is not a law (levels that fall
    // with the load): reported, the law left without it.
    r.diagnostics.texts["law_curve_at"] = "the points' mean |load|, " + format_number(mean_load) + " " +
                                          std::string(unit(Quantity::force, o.axis));
    if (mu_load >= 0) {
      LawSpec with_effect = *r.law;
      with_effect.scalars["mu_load"] = mu_load;
      FrictionLaw::from_spec(with_effect);  // checks it as a law file would be
      r.law = with_effect;
    } else {
      r.diagnostics.warnings.push_back("mu_load = " + format_number(mu_load) +
                                       " is negative (friction falling with the load): the law is given without it");
    }
  }
  r.diagnostics.numbers["max_speed"] = v.cwiseAbs().maxCoeff();
  r.diagnostics.numbers["min_speed"] = v.cwiseAbs().minCoeff();
  return r;
}

}  // namespace

// Numbers or an error, never both (identify/finite_result.hpp): figures that overflow double
// precision (the residual of a force offset of 1e153) make an error, not an ok result with inf.
Result identify_sweep(const SweepData& d, const SweepOptions& o) { return finite_or_error(identify_sweep_unchecked(d, o)); }

}  // namespace frictionlab
