#include "frictionlab/identify/lugre.hpp"
#include "frictionlab/identify/finite_result.hpp"
#include "identify/ceres_cancel.hpp"
#include "identify/ceres_quiet.hpp"
#include "frictionlab/budget.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/identify/adequacy.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/uncertainty.hpp"
#include "frictionlab/models/lugre.hpp"
#include "frictionlab/models/relaxation.hpp"
#include "frictionlab/models/scalar.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "method_support.hpp"

namespace frictionlab {
using namespace detail;
namespace {

// Parameter blocks of the output-error fit. Dynamic: [log sigma0, log sigma1] (logs keep them
// positive and make the steps relative: sigma0 spans decades between rigs). Static:
// [sigma2, log Fc, dF = Fs - Fc, log vs] (dF >= 0 and sigma2 >= 0 are box bounds).
constexpr int kLogS0 = 0, kLogS1 = 1, kNd = 2;
constexpr int kS2 = 0, kLogFc = 1, kDF = 2, kLogVs = 3, kNs = 4;

// What the simulation of a record needs besides the parameters.
struct Record {
  const double* u = nullptr;  // applied force at the samples (N)
  const double* x = nullptr;  // measured position (m)
  const double* v = nullptr;  // velocity by central differences (m/s), for the window starts
  double dt = 0;              // sample time (s)
  int substeps = 1;
  double M = 1;               // inertia (kg)
  double delta = 2;           // Stribeck exponent (held)
  double vd = 0;              // damping decay velocity (m/s; held, 0 = constant damping)
  double scale = 1;           // residuals are (x_sim - x) / scale (m / m)
};

// One simulated window [begin, end] of samples. It starts from the measured position and
// velocity at `begin` with the bristles at rest (z = 0) when v = 0 (the record's start) or in
// their steady state g(v) sign(v) / sigma0 otherwise (windows start at velocity peaks, in steady
// sliding).
struct Window {
  int begin = 0, end = 0;
  bool at_rest = false;
  int residuals() const { return end - begin; }
};

// The law of a trial parameter vector: [log sigma0, log sigma1] and [sigma2, log Fc, dF, log vs]
// with delta and vd held. Every force, level and bristle rate of the fit's simulation comes from
// this LuGreT<T> (T = double or a Ceres Jet), so the fit simulates exactly the law the library
// simulates, vd (the damping that decays with speed) included.
template <class T, class S>
LuGreT<T> trial_law(const T* dyn, const S* sta, const Record& r) {
  using std::exp;
  LuGreT<T> lg;
  lg.sigma0 = exp(dyn[kLogS0]);
  lg.sigma1 = exp(dyn[kLogS1]);
  lg.sigma2 = T(sta[kS2]);
  lg.Fc = T(exp(sta[kLogFc]));
  lg.Fs = lg.Fc + T(sta[kDF]);
  lg.vs = T(exp(sta[kLogVs]));
  lg.delta = T(r.delta);
  lg.vd = T(r.vd);
  return lg;
}

// Bristle state at the middle and the end of one substep h at constant velocity v, from z: the
// exact relaxation of models/relaxation.hpp (as LuGreT::step, which serves doubles only). One g(v)
// and one exponential serve both: exp(-rate h) = exp(-rate h / 2)^2.
template <class T>
std::pair<T, T> relax_substep(const LuGreT<T>& lg, const T& z, const T& v, double h) {
  using std::exp;
  if (value_of(v) == 0.0) return {z, z};
  const BristleRelaxation<T> r = bristle_relaxation(lg, v);
  const T e_half = exp(-r.rate * (0.5 * h));
  const T e_full = e_half * e_half;
  return {relax(z, r.target, e_half), relax(z, r.target, e_full)};
}

// Simulates M x'' = u - F_lugre over window w and writes (x_sim[k] - x[k]) / scale for
// k = begin+1 .. end. Per substep h a second-order predictor-corrector (a fixed step, so that the
// cost is one smooth computation of the parameters and Jets can carry its derivative):
//  - predictor: v* = v + h (u(t) - F(z, v)) / M;
//  - corrector: at the midpoint velocity vm = (v + v*) / 2 the bristles relax exactly (z over h/2
//    for the force, over h for the new state): the relaxation rate sigma0 |v| / g(v) reaches
//    1e5 1/s in sliding, far beyond any explicit step; v1 = v + h (u(t + h/2) - F(z_mid, vm)) / M;
//  - x: trapezoidal in v.
// Written by hand rather than through simulate(): CVODE's adaptive steps would make the cost a
// non-smooth function of the parameters, and Ceres needs its derivative. A first-order version
// (explicit v, exact z) was 70 um off CVODE per 1 s window of Table I sliding at 8 substeps,
// enough to bias sigma1 by far more than 5 %.
// `start` is the window's initial state [x, v] (m, m/s): the bristles start unloaded at rest or in
// their steady state g(v) sign(v) / sigma0 (windows start at velocity peaks, in steady sliding).
template <class T, class X>
void simulate_residuals(const LuGreT<T>& lg, const Record& r, const Window& w, const X* start, T* out) {
  const double h = r.dt / r.substeps;
  const double inv_m = 1.0 / r.M;
  T x(start[0]), v(start[1]), z(0.0);
  if (!w.at_rest && value_of(v) != 0.0) z = sgn(v) * lg.level(v) / lg.sigma0;
  for (int k = w.begin; k < w.end; ++k) {
    const double u0 = r.u[k], du = r.u[k + 1] - r.u[k];
    for (int j = 0; j < r.substeps; ++j) {
      const double ua = u0 + du * (static_cast<double>(j) / r.substeps);
      const double um = u0 + du * ((j + 0.5) / r.substeps);
      const T vp = v + h * inv_m * (ua - lg.force(z, v));
      const T vm = 0.5 * (v + vp);
      const auto [z_mid, z_end] = relax_substep(lg, z, vm, h);
      const T vn = v + h * inv_m * (um - lg.force(z_mid, vm));
      x += (0.5 * h) * (v + vn);
      v = vn;
      z = z_end;
    }
    out[k - w.begin] = (x - r.x[k + 1]) / r.scale;
  }
}

template <class T, class S, class X>
void simulate_residuals(const T* dyn, const S* sta, const Record& r, const Window& w, const X* start, T* out) {
  simulate_residuals(trial_law(dyn, sta, r), r, w, start, out);
}

// The output error of one window. Parameters: the law's [log sigma0, log sigma1], its static
// part, and the window's own initial state [x, v] (m, m/s). The initial state is estimated with
// the law: taken from the measured samples it carries their noise (central differences of a
// position with 0.2 um noise at 1 kHz are 1.4e-4 m/s off), which grows linearly over the window
// into tens of micrometres of error, far above the noise itself, and biases the static levels.
struct OutputError {
  const Record* r;
  Window w;
  template <class T>
  bool operator()(const T* dyn, const T* sta, const T* start, T* residuals) const {
    simulate_residuals(dyn, sta, *r, w, start, residuals);
    return true;
  }
};

// The same with the static part given: [log sigma0, log sigma1] and the initial state.
struct OutputErrorStaticGiven {
  const Record* r;
  Window w;
  const double* sta;  // [sigma2, log Fc, dF, log vs], fixed
  template <class T>
  bool operator()(const T* dyn, const T* start, T* residuals) const {
    simulate_residuals(dyn, sta, *r, w, start, residuals);
    return true;
  }
};

// The initial state [x, v] of window w from the measured samples: the position, and the velocity
// by central differences (zero for a window that starts at rest).
std::array<double, 2> measured_start(const Record& r, const Window& w) {
  return {r.x[w.begin], w.at_rest ? 0.0 : r.v[w.begin]};
}

// Windows of the output error: from the record's start to the first velocity peak, then from
// each peak to the next (one reversal each), then to the end. A peak is the sample of largest
// |v| in a run of one sign whose largest |v| exceeds `peak_speed`. Short windows keep the error
// of a wrong trial parameter from growing over the whole record (a simulated axis that slid
// once too far stays off by that much for ever), which is what made one long window fail.
std::vector<Window> make_windows(const Eigen::VectorXd& vel, double peak_speed, bool start_at_rest) {
  const auto n = static_cast<int>(vel.size());
  std::vector<int> peaks;
  int k = 0;
  while (k < n) {
    const int sign = vel[k] > 0 ? 1 : (vel[k] < 0 ? -1 : 0);
    int e = k, best = k;
    while (e < n && (vel[e] > 0 ? 1 : (vel[e] < 0 ? -1 : 0)) == sign) {
      if (std::abs(vel[e]) > std::abs(vel[best])) best = e;
      ++e;
    }
    if (sign != 0 && std::abs(vel[best]) > peak_speed && best > 0 && best < n - 1) peaks.push_back(best);
    k = e;
  }
  std::vector<Window> w;
  int begin = 0;
  bool rest = start_at_rest;
  for (int p : peaks) {
    if (p - begin >= 2) {
      w.push_back({begin, p, rest});
      begin = p;
      rest = false;
    }
  }
  if (n - 1 - begin >= 1) w.push_back({begin, n - 1, rest});
  return w;
}

class Progress final : public ceres::IterationCallback {
 public:
  Progress(const LugreProgress& f, double scale, std::chrono::steady_clock::time_point t0) : f_(f), scale2_(scale * scale), t0_(t0) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    f_(s.iteration, s.cost * scale2_, elapsed);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const LugreProgress& f_;
  double scale2_;
  std::chrono::steady_clock::time_point t0_;
};

// The static part of a given law: Fc, Fs, vs, delta, sigma2.
struct StaticPart {
  double Fc = 0, Fs = 0, vs = 0, delta = 2, sigma2 = 0, vd = 0;
};

StaticPart static_part_of(const FrictionLaw& law, const LugreOptions& o) {
  const LawSpec s = law.to_spec();
  const auto get = [&](const char* name) { return s.scalars.at(name); };
  StaticPart p;
  if (s.name == "stribeck") {
    p = {get("Fc"), get("Fs"), get("vs"), get("delta"), get("Fv"), o.vd};
  } else if (s.name == "lugre") {
    p = {get("Fc"), get("Fs"), get("vs"), get("delta"), get("sigma2"), s.scalars.count("vd") && get("vd") > 0 ? get("vd") : o.vd};
  } else if (s.name == "static-coulomb-viscous") {
    p = {get("Fc"), get("Fs"), o.stribeck_velocity, o.delta, get("Fv"), o.vd};
  } else if (s.name == "coulomb-viscous") {
    p = {get("Fc"), get("Fc"), o.stribeck_velocity, o.delta, get("Fv"), o.vd};
  } else {
    throw std::invalid_argument("lugre: the static law '" + s.name +
                                "' cannot give the LuGre static part; expected stribeck, lugre, static-coulomb-viscous "
                                "or coulomb-viscous");
  }
  if (!(p.Fc > 0))
    throw std::invalid_argument("lugre: the static law's Coulomb level Fc = " + format_number(p.Fc) +
                                " must be > 0 (N or N m) for a LuGre model");
  return p;
}

// Near standstill for the position-noise estimate: |v| at most this share of the largest (the
// residual check's standstill fraction).
constexpr double kStandstillShare = 0.02;
constexpr double kMadToNormal = 1.4826;  // median absolute deviation to std of a normal distribution
// Half-width of the play (backlash) operator that the bristle state's velocity is taken from, in
// standard deviations of the position's noise. The state relaxes at sigma0 |v| / g: along the raw
// differenced position the noise, rectified, relaxes it as a slow slide would (10 nm of white noise
// on the Canudas de Wit record made the checks warn on every record whose model is right). The play
// operator moves only when the position leaves a band around its output, so noise at standstill
// no longer moves it, while a slide passes through with a lag of the half-width (tens of nm, against
// the bristles' micrometres). Measured on 40 seeded records with 10 nm of noise: half-widths of 2,
// 2.5 and 3 std gave no false warning, 3.5 and 4 one and two (the lag starts to show).
constexpr double kPlayWidth = 2.5;
// The smallest residual trend that counts, against the residual's noise floor: the robust std of
// the residual's first differences over the moving samples, / sqrt(2) (a slow structure, however
// large, hardly moves from sample to sample, so it does not raise the bar it is judged against).
// The shared check's default judges relevance against the residual's whole std, which a fit gone
// wrong inflates with its own structure: a 0.3 N force the model lacks then went unseen on 11 of
// 100 records.
constexpr double kRelevance = 0.25;

// Adequacy of the fit (identify/adequacy.hpp) on the force: the friction the motion shows,
// u - M a (a the position's second central difference), less the identified LuGre's along the
// measured motion (its bristle state integrated exactly over each sample with the velocity held,
// from z = 0 at the record's start at rest; the velocity from the position passed through a play
// operator of kPlayWidth noise std), against velocity, position and time. The fit itself is on the
// position, whose residual hides a friction of the wrong shape in the integration; the force shows
// it. The std of lugre come from the position residuals: no claim on them here.
void add_lugre_adequacy(Result& r, const LugreData& d, double M, const LuGre& lg, double dt, Axis axis) {
  const Eigen::Index n = d.time.size();
  if (n < static_cast<Eigen::Index>(kAdequacyMinSamples) + 4) return;
  const Eigen::VectorXd v = gradient(d.position, dt), a = gradient(v, dt);
  // The position's noise: the second differences' median absolute value over the samples near
  // standstill, where the motion's own is negligible (white noise of std s gives 6 s^2 there).
  double noise = 0;
  {
    std::vector<double> d2;
    const double vmax = v.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 1; i + 1 < n; ++i)
      if (std::abs(v[i]) <= kStandstillShare * vmax)
        d2.push_back(std::abs(d.position[i + 1] - 2 * d.position[i] + d.position[i - 1]));
    if (d2.size() >= kAdequacyMinSamples) {
      std::nth_element(d2.begin(), d2.begin() + static_cast<std::ptrdiff_t>(d2.size() / 2), d2.end());
      noise = kMadToNormal * d2[d2.size() / 2] / std::sqrt(6.0);  // m or rad per sample
    }
  }
  Eigen::VectorXd played(n);
  {
    const double w = kPlayWidth * noise;
    double y = d.position[0];
    for (Eigen::Index i = 0; i < n; ++i) {
      const double x = d.position[i];
      if (x > y + w) y = x - w;
      else if (x < y - w) y = x + w;
      played[i] = y;
    }
  }
  const Eigen::VectorXd vz = gradient(played, dt);
  // The force residual (measured less modelled) at the interior samples for the law's static part
  // and the bristle pair (sigma0, sigma1); the ends have one-sided differences and are left out.
  const auto g = [&](double vel) { return lg.Fc + (lg.Fs - lg.Fc) * std::exp(-std::pow(std::abs(vel / lg.vs), lg.delta)); };
  const auto force_residual = [&](double sigma0, double sigma1) {
    const auto damping = [&](double vel) { return lg.vd > 0 ? sigma1 * std::exp(-(vel / lg.vd) * (vel / lg.vd)) : sigma1; };
    Eigen::VectorXd out(n - 4);
    double z = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double vi = vz[i], rate = sigma0 * std::abs(vi) / g(vi);  // 1/s
      const double zdot = vi - rate * z;
      const double model = sigma0 * z + damping(vi) * zdot + lg.sigma2 * vi;
      if (i >= 2 && i + 2 < n) out[i - 2] = d.force[i] - M * a[i] - model;
      if (rate > 0) {
        const double steady = vi / rate;
        z = steady + (z - steady) * std::exp(-rate * dt);
      }
    }
    return out;
  };
  // The residual the fit's own parameter error leaves is not the model's fault: sigma0 and sigma1 of
  // a fit on the position scatter by tens of percent under coloured force noise (AR(1), 20 ms), and a
  // sigma0 40 % off leaves a presliding residual of 0.04 N, which the checks called a drift on 12 of
  // 40 records whose model was right. So the pair is refitted to the force first (one Gauss-Newton
  // step in log sigma, each step at most a factor 2), and the checks judge the residual less its
  // linear projection on the pair's sensitivities there: what no nearby sigma0, sigma1 can explain.
  // The static part is not refitted (a wrong friction curve is what the checks look for).
  constexpr double kLogStep = 0.01;  // finite-difference step in log sigma
  constexpr double kMaxLogStep = 0.6931471805599453;  // ln 2
  double s0 = lg.sigma0, s1 = lg.sigma1;
  Eigen::VectorXd e0;
  for (int pass = 0; pass < 2; ++pass) {
    e0 = force_residual(s0, s1);
    Eigen::MatrixXd J(e0.size(), 2);
    J.col(0) = (force_residual(s0 * std::exp(kLogStep), s1) - e0) / kLogStep;
    J.col(1) = (force_residual(s0, s1 * std::exp(kLogStep)) - e0) / kLogStep;
    if (!J.allFinite() || !e0.allFinite()) break;
    const Eigen::Vector2d step = J.colPivHouseholderQr().solve(-e0);
    if (!step.allFinite()) break;
    if (pass == 1) {
      e0 += J * step;
      break;
    }
    s0 *= std::exp(std::clamp(step[0], -kMaxLogStep, kMaxLogStep));
    s1 *= std::exp(std::clamp(step[1], -kMaxLogStep, kMaxLogStep));
  }
  std::vector<double> velocity, position, time, e(e0.data(), e0.data() + e0.size());
  double ss = 0;
  for (Eigen::Index i = 2; i + 2 < n; ++i) {
    velocity.push_back(v[i]);
    position.push_back(d.position[i]);
    time.push_back(d.time[i]);
    ss += d.force[i] * d.force[i];
  }
  // The residual's noise floor over the moving samples (the check's standstill speed).
  double noise_floor = 0;
  {
    double vmax = 0;
    for (double x : velocity) vmax = std::max(vmax, std::abs(x));
    const AdequacyOptions defaults;
    std::vector<double> de;
    for (std::size_t i = 1; i < e.size(); ++i)
      if (std::abs(velocity[i]) > defaults.standstill_fraction * vmax && std::abs(velocity[i - 1]) > defaults.standstill_fraction * vmax)
        de.push_back(std::abs(e[i] - e[i - 1]));
    if (!de.empty()) {
      std::nth_element(de.begin(), de.begin() + static_cast<std::ptrdiff_t>(de.size() / 2), de.end());
      noise_floor = kMadToNormal * de[de.size() / 2] / std::sqrt(2.0);
    }
  }
  AdequacyOptions ao;
  ao.force_scale = std::sqrt(ss / static_cast<double>(e.size()));  // the applied force's rms
  // The bar: the larger of the shared share of the force's scale and kRelevance noise floors (in
  // place of the shared relevance against the residual's std).
  ao.relevance = 0;
  if (ao.force_scale > 0) ao.force_share = std::max(ao.force_share, kRelevance * noise_floor / ao.force_scale);
  ao.advice.stribeck = "the identified Stribeck curve (Fs, vs, delta) does not reach it: fit with another exponent "
                       "(--delta), or identify the static part from constant-speed runs (sweep) and give it (--static)";
  ao.advice.shape = "the friction-velocity curve is not LuGre's static curve (sweep maps it point by point; give it "
                    "with --static)";
  ao.advice.asymmetry = "LuGre has one level for both directions: a force the model lacks (gravity on an inclined "
                        "axis, a drive offset) or direction-dependent friction; remove the offset from the force, or "
                        "identify each direction from driven runs (idim: --terms inertia,asymmetric)";
  ao.advice.correlated_std = "";  // lugre's std come from the position residuals, not these
  ao.advice.standstill = false;   // presliding is the model's own: samples at rest belong to the fit
  add_adequacy(r, assess_residuals(velocity, position, time, e, std::string(unit(Quantity::force, axis)),
                                   std::string(unit(Quantity::velocity, axis)), ao));
  r.diagnostics.numbers["position_noise"] = noise;
  auto& group = r.diagnostics.groups["adequacy"];
  group["play_width"] = kPlayWidth * noise;  // m or rad
  group["noise_floor"] = noise_floor;             // N or N m
  group["relevance_threshold"] = ao.force_share * ao.force_scale;
  group["refit_sigma0"] = s0;  // N/m or N m/rad: the pair the force residual was judged at
  group["refit_sigma1"] = s1;  // N s/m or N m s/rad
}

}  // namespace

// The table names only the fields an option sets (designated initializers).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
MethodInfo detail::lugre_method_info() {
  const LugreOptions d;  // every default of the table is the struct's
  MethodInfo m;
  m.summary = "LuGre parameters by output error on the position";
  m.fit_signal = "position";
  m.fit_quantity = Quantity::displacement;
  m.options = {
      {.name = "inertia", .type = OptionType::number, .unit = "kg", .rotary_unit = "kg m^2",
       .help = "Mass or inertia of the axis", .min = 0, .min_open = true, .required = true},
      {.name = "static", .type = OptionType::file,
       .help = "The static law (stribeck, lugre, static-coulomb-viscous, coulomb-viscous), e.g. from identify sweep: "
               "held fixed instead of identified. Command line: a MODEL.json (or .yaml); Python: a FrictionLaw or "
               "its dict",
       .deprecated_keywords = {"static_law"}},
      {.name = "delta", .type = OptionType::number, .default_value = d.delta,
       .help = "Stribeck exponent of the identified law, held fixed", .min = 0, .min_open = true},
      {.name = "stribeck-velocity", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s",
       .default_value = d.stribeck_velocity,
       .help = "Stribeck velocity used with a --static static-coulomb-viscous law, which has none", .min = 0,
       .min_open = true, .applies_if = {when_given("static")}},
      {.name = "vd", .type = OptionType::number, .unit = "m/s", .rotary_unit = "rad/s", .default_value = d.vd,
       .help = "Damping decay velocity of the damping sigma1 exp(-(v/vd)^2), held fixed; 0 = constant damping. A "
               "--static lugre model with vd > 0 gives its own",
       .min = 0},
      {.name = "substeps", .type = OptionType::integer, .default_value = static_cast<long long>(d.substeps),
       .help = "Simulation steps per sample interval of the fit (error ~ 1/substeps^2; run time grows linearly)",
       .min = 1},
      {.name = "max-iterations", .type = OptionType::integer, .default_value = static_cast<long long>(d.max_iterations),
       .help = "Iteration limit of the output-error fit", .min = 1},
  };
  return m;
}
#pragma GCC diagnostic pop

LugreOptions make_lugre_options(const OptionValues& v) {
  LugreOptions o;
  o.inertia = v.number("inertia");
  o.delta = v.number("delta");
  o.stribeck_velocity = v.number("stribeck-velocity");
  o.vd = v.number("vd");
  o.substeps = static_cast<int>(v.integer("substeps"));
  o.max_iterations = static_cast<int>(v.integer("max-iterations"));
  return o;
}

void check_lugre_work(double samples, const LugreOptions& o) {
  // The fit's work before it starts: each cost evaluation simulates every sample interval in
  // substeps steps, at most once per iteration and once more at the start.
  check_work(samples * o.substeps * (o.max_iterations + 1.0), "simulation steps",
             "lugre: " + format_number(samples, 12) + " samples x --substeps " + std::to_string(o.substeps) +
                 " x (--max-iterations " + std::to_string(o.max_iterations) + " + 1)",
             {.option = "--substeps", .value = std::to_string(o.substeps)});
}

namespace {

Result identify_lugre_unchecked(const LugreData& d, const LugreOptions& o) {
  const auto t_start = std::chrono::steady_clock::now();
  const Eigen::Index n = d.time.size();
  if (!(std::isfinite(o.inertia) && o.inertia > 0))
    throw std::invalid_argument("lugre: the inertia (--inertia) must be > 0 (kg or kg m^2), got " + format_number(o.inertia));
  if (d.force.size() != n || d.position.size() != n)
    throw std::invalid_argument("lugre: time, force and position must have equal lengths (have " + std::to_string(n) + ", " +
                                std::to_string(d.force.size()) + ", " + std::to_string(d.position.size()) + ")");
  if (o.substeps < 1) throw std::invalid_argument("lugre: substeps = " + std::to_string(o.substeps) + " must be >= 1");
  check_lugre_work(static_cast<double>(n), o);
  if (!(std::isfinite(o.delta) && o.delta > 0))
    throw std::invalid_argument("lugre: delta = " + format_number(o.delta) + " must be > 0");
  if (!(std::isfinite(o.vd) && o.vd >= 0))
    throw std::invalid_argument("lugre: vd = " + format_number(o.vd) + " must be >= 0 (m/s or rad/s; 0 = constant damping)");
  const double dt = regular_time_step(d.time, method_info(MethodId::lugre).name);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(d.force[k]))
      throw std::invalid_argument("lugre: force at sample " + std::to_string(k) + " is not finite");
    if (!std::isfinite(d.position[k]))
      throw std::invalid_argument("lugre: position at sample " + std::to_string(k) + " is not finite");
  }
  const bool given = o.static_law.has_value();
  StaticPart st;
  st.vd = o.vd;
  if (given) st = static_part_of(*o.static_law, o);

  Result r = make_result(MethodId::lugre, "lugre", o.axis);
  const auto warn = [&](const std::string& w) { r.diagnostics.warnings.push_back(w); };
  const auto vunit = std::string(unit(Quantity::velocity, o.axis));
  const auto punit = std::string(unit(Quantity::displacement, o.axis));
  const auto funit = std::string(unit(Quantity::force, o.axis));
  const double M = o.inertia;

  // Velocity and acceleration by central differences (noise-free enough for starting values;
  // the output error below does not use them).
  const Eigen::VectorXd vel = gradient(d.position, dt);
  const Eigen::VectorXd acc = gradient(vel, dt);
  const double range = d.position.maxCoeff() - d.position.minCoeff();
  const double vmax = vel.cwiseAbs().maxCoeff();
  if (!(range > 0) || !(vmax > 0))
    return fail(r, "no motion: the position never changes (range " + format_number(range) + " " + punit +
                       "); the record must contain presliding and sliding");
  // Sliding samples: |v| above 1 % of the largest speed, two samples away from any slower sample
  // (a reversal's kink spoils the differences there).
  // Positions near the range of a double (1e308) overflow in their differences: the velocity,
  // and every threshold made of it, would be inf ("|velocity| > inf").
  if (!std::isfinite(range) || !std::isfinite(vmax))
    return fail(r, "the positions are too far apart to differentiate: their range or the velocity between two "
                   "samples exceeds the largest double (about 1.8e308 " + punit + " or " + vunit +
                   "); expected positions of a measured motion (check the position column's unit, --scale)");
  const double threshold = 0.01 * vmax;
  std::vector<Eigen::Index> sliding;
  constexpr Eigen::Index kEdge = 2;
  for (Eigen::Index k = kEdge; k + kEdge < n; ++k) {
    bool ok = true;
    for (Eigen::Index j = k - kEdge; j <= k + kEdge && ok; ++j) ok = std::abs(vel[j]) > threshold;
    if (ok) sliding.push_back(k);
  }

  // (1) Static part.
  if (!given) {
    constexpr std::size_t kMinSliding = 20;  // a Stribeck fit has 4 free parameters; ask for 5 per parameter
    if (sliding.size() < kMinSliding)
      return fail(r, "no sliding: only " + std::to_string(sliding.size()) + " samples with |velocity| > " +
                         format_number(threshold) + " " + vunit + " (need " + std::to_string(kMinSliding) +
                         ") to identify Fc, Fs, vs and sigma2; give the static law (--static MODEL.json) or a record that slides");
    Eigen::VectorXd v_slide(static_cast<Eigen::Index>(sliding.size())), f_slide(v_slide.size());
    for (std::size_t i = 0; i < sliding.size(); ++i) {
      const auto k = sliding[i];
      v_slide[static_cast<Eigen::Index>(i)] = vel[k];
      f_slide[static_cast<Eigen::Index>(i)] = d.force[k] - M * acc[k];
    }
    StaticFitOptions so;
    so.model = StaticFitModel::stribeck;
    so.fixed_delta = o.delta;
    try {
      const StaticFit sf = fit_static_law(v_slide, f_slide, so);
      for (const auto& p : sf.parameters) {
        if (p.name == "Fc") st.Fc = p.value;
        if (p.name == "Fs") st.Fs = p.value;
        if (p.name == "vs") st.vs = p.value;
        if (p.name == "Fv") st.sigma2 = p.value;
      }
      st.delta = o.delta;
      r.diagnostics.groups["static_fit"] = {{"Fc", st.Fc}, {"Fs", st.Fs}, {"vs", st.vs}, {"sigma2", st.sigma2},
                                            {"relative_error_percent", sf.relative_error_percent}};
    } catch (const std::invalid_argument& e) {
      return fail(r, std::string("the static fit on the sliding samples failed: ") + e.what() +
                         "; give the static law (--static MODEL.json)");
    }
    if (!(st.Fc > 0))
      return fail(r, "the sliding samples give a Coulomb level Fc = " + format_number(st.Fc) + " " + funit +
                         ", not > 0: the record does not show sliding friction; give the static law (--static MODEL.json) or a "
                         "record that slides");
    // A record's sliding samples are mostly far above vs, where a Stribeck fit cannot see Fs and vs:
    // keep them physical as starting values.
    if (!(st.vs > 0) || st.vs > 0.5 * vmax) st.vs = 0.01 * vmax;
    // Nor may vs start collapsed (a sliver of the top speed: the fit could not leave it); the
    // multi-start below ranks this pair among others anyway.
    constexpr double kLowestVsStart = 1e-4;  // of the top speed: the multi-start grid's lowest
    st.vs = std::max(st.vs, kLowestVsStart * vmax);
    if (!(st.Fs >= st.Fc) || st.Fs > 3 * st.Fc) st.Fs = st.Fc;
    st.sigma2 = std::max(st.sigma2, 0.0);
    // The contact held every force before the first sliding sample: the static level is at least
    // their largest magnitude (slightly above it: a force ramp breaks away just past that level).
    // A start below it would let the simulation slide where the record did not, far from the data.
    constexpr double kAboveHeld = 1.02;
    double held = 0;
    for (Eigen::Index k = 0; k < sliding.front(); ++k) held = std::max(held, std::abs(d.force[k]));
    if (kAboveHeld * held > st.Fs && held < 3 * st.Fc) st.Fs = kAboveHeld * held;
  }

  // (2) Starting values of the dynamic part. sigma0 from the presliding before the first
  // sliding: quasi-static loading from rest gives x - x0 = -(Fs / sigma0) ln(1 - u / Fs)
  // (dz/dx = 1 - sigma0 z / Fs), so sigma0 is the least-squares slope of -Fs ln(1 - u / Fs)
  // against the displacement, on the samples with |u| below half the static level.
  // A function of the static level, as the multi-start below tries several.
  const Eigen::Index first_slide = sliding.empty() ? n : sliding.front();
  const auto presliding_sigma0 = [&](double Fs, int& used) {
    double sxy = 0, sxx = 0;
    used = 0;
    for (Eigen::Index k = 1; k < first_slide; ++k) {
      const double u = d.force[k], dx = d.position[k] - d.position[0];
      if (std::abs(u) > 0.5 * Fs) break;
      const double a = -(u > 0 ? 1.0 : -1.0) * Fs * std::log1p(-std::abs(u) / Fs);
      sxy += a * dx;
      sxx += dx * dx;
      ++used;
    }
    constexpr int kMinPresliding = 10;
    return used >= kMinPresliding && sxx > 0 && sxy > 0 ? sxy / sxx : std::numeric_limits<double>::quiet_NaN();
  };
  double sigma0 = std::numeric_limits<double>::quiet_NaN();
  {
    int used = 0;
    sigma0 = presliding_sigma0(st.Fs, used);
    r.diagnostics.numbers["presliding_samples"] = used;
  }
  if (!std::isfinite(sigma0)) {
    // Typical bristle deflection at the static level: 10 um (steel contacts, Canudas de Wit 1995).
    constexpr double kTypicalDeflection = 1e-5;  // m
    sigma0 = st.Fs / kTypicalDeflection;
    warn("no presliding before the first sliding (the record should start at rest under a force below Fs): sigma0 "
         "starts from a 10 um deflection at Fs, " + format_number(sigma0) + " " + std::string(unit(Quantity::stiffness, o.axis)));
  }
  // A record that never moves further than a few bristle deflections Fs / sigma0 did not slide,
  // whatever its velocity samples say (presliding creeps at um/s): its "sliding" samples cannot
  // give the static part.
  constexpr double kSlideDeflections = 10;
  if (!given && range < kSlideDeflections * st.Fs / sigma0)
    return fail(r, "no sliding: the position spans only " + format_number(range) + " " + punit + ", within " +
                       format_number(kSlideDeflections) + " bristle deflections Fs / sigma0 = " +
                       format_number(st.Fs / sigma0) + " " + punit +
                       "; give the static law (--static MODEL.json) or a record that slides");
  double sigma1 = 2 * std::sqrt(sigma0 * M);  // critical damping of the bristle-mass resonance

  // (3) Output error.
  Record rec;
  rec.u = d.force.data();
  rec.x = d.position.data();
  rec.v = vel.data();
  rec.dt = dt;
  rec.substeps = o.substeps;
  rec.M = M;
  rec.delta = st.delta;
  rec.vd = st.vd;
  // Residuals relative to a micrometre-sized unit: Ceres's gradient tolerance is absolute, and
  // presliding displacements are micrometres.
  constexpr double kResidualUnit = 1e-6;  // m
  rec.scale = kResidualUnit;
  // Stability limits of the fit's explicit velocity update (see the bounds below).
  const double s0_limit = 0.5 * M / ((dt / o.substeps) * (dt / o.substeps)), s1_limit = 0.5 * M * o.substeps / dt;
  // Windows start at velocity peaks in steady sliding only: below a tenth of the top speed, or
  // below a few Stribeck velocities, the bristles lag behind their steady state (presliding creep
  // has velocity peaks too).
  constexpr double kPeakFraction = 0.1, kPeakStribeck = 3.0;
  const bool starts_at_rest = std::abs(vel[0]) <= threshold;
  const auto windows_for = [&](double vs) {
    return make_windows(vel, std::max(kPeakFraction * vmax, kPeakStribeck * vs), starts_at_rest);
  };

  // (2b) Multi-start of the static levels (static part identified only). The sliding samples of a
  // record driven fast, the usual case, lie far above vs, where the Stribeck fit above cannot see
  // Fs and vs: its vs collapses to a sliver of the slowest speed (or runs to a bound) and a fit
  // started there never recovers, as Fs and vs decide where and how the simulated axis breaks
  // away and the output error is far from quadratic in them. So each pair of a grid (Fs / Fc from
  // 1.1 to 3, vs from 1e-4 to 0.1 of the top speed) and the Stribeck fit's own pair is simulated
  // once over the record, with sigma0 from the presliding at that Fs and sigma1 critical, and the
  // fits below start from the two best-ranked pairs. About 50 simulations of the record in double:
  // a few iterations' worth of the fit.
  struct Start {
    double Fs, vs, sigma0, cost;
  };
  std::vector<Start> candidates;  // starting points of the fit, best-ranked first
  if (!given) {
    const auto start_cost = [&](double Fs, double vs, double s0) {
      const double s1 = std::min(2 * std::sqrt(s0 * M), s1_limit);
      const double dy[kNd] = {std::log(std::min(s0, s0_limit)), std::log(s1)};
      const double sa[kNs] = {st.sigma2, std::log(st.Fc), Fs - st.Fc, std::log(vs)};
      throw_if_cancelled();  // about 50 simulations of the whole record
      double cost = 0;
      Eigen::VectorXd e;
      for (const Window& w : windows_for(vs)) {
        const int m = w.residuals();
        e.resize(m);
        simulate_residuals(dy, sa, rec, w, measured_start(rec, w).data(), e.data());
        // The measured start of a window carries the position noise, and its velocity error grows
        // into a drift over the window: the line a + b t that best fits the residuals is taken out
        // (to first order what fitting the start, as the fit below does, would remove), so that the
        // candidates are ranked on what the law explains.
        Eigen::MatrixXd X(m, 2);
        X.col(0).setOnes();
        X.col(1) = Eigen::VectorXd::LinSpaced(m, 1.0, static_cast<double>(m));
        if (w.at_rest) X.col(1).setZero();
        const Eigen::VectorXd coef = X.colPivHouseholderQr().solve(e);
        cost += (e - X * coef).squaredNorm();
      }
      return std::isfinite(cost) ? cost : std::numeric_limits<double>::infinity();
    };
    const double deflection_s0 = sigma0 * st.Fs;  // sigma0 = this / Fs when no presliding is seen
    const auto s0_at = [&](double Fs) {
      int used = 0;
      const double s0 = presliding_sigma0(Fs, used);
      return std::isfinite(s0) ? s0 : deflection_s0 / Fs;
    };
    candidates.push_back({st.Fs, st.vs, sigma0, start_cost(st.Fs, st.vs, sigma0)});
    const double fit_cost = candidates.back().cost;
    constexpr double kFsRatios[] = {1.1, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0};
    constexpr double kVsFractions[] = {1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1};
    for (double ratio : kFsRatios) {
      const double Fs = ratio * st.Fc, s0 = s0_at(Fs);
      for (double fraction : kVsFractions) candidates.push_back({Fs, fraction * vmax, s0, start_cost(Fs, fraction * vmax, s0)});
    }
    std::sort(candidates.begin(), candidates.end(), [](const Start& a, const Start& b) { return a.cost < b.cost; });
    constexpr std::size_t kStarts = 2;  // pairs kept, best-ranked first; each fitted at most twice (below)
    candidates.resize(std::min(candidates.size(), kStarts));
    const Start& best = candidates.front();
    r.diagnostics.groups["multistart"] = {{"Fs", best.Fs}, {"vs", best.vs}, {"sigma0", best.sigma0},
                                          {"cost", best.cost * kResidualUnit * kResidualUnit},
                                          {"cost_static_fit_start", fit_cost * kResidualUnit * kResidualUnit}};
    st.Fs = best.Fs;
    st.vs = best.vs;
    sigma0 = best.sigma0;
    sigma1 = 2 * std::sqrt(sigma0 * M);
  }
  const std::vector<Window> windows = windows_for(st.vs);

  // Starts inside the stability bounds set below (a stiffer contact than the sample rate and
  // substeps can follow: the warning says so).
  {
    if (sigma0 > s0_limit || sigma1 > s1_limit)
      warn("the starting sigma0 = " + format_number(sigma0) + " or sigma1 = " + format_number(sigma1) +
           " is beyond what the fit's simulation step resolves; raise substeps or the sample rate");
    sigma0 = std::min(sigma0, s0_limit);
    sigma1 = std::min(sigma1, s1_limit);
  }
  double dyn[kNd] = {std::log(sigma0), std::log(sigma1)};
  double sta[kNs] = {st.sigma2, std::log(st.Fc), st.Fs - st.Fc, std::log(st.vs)};
  r.diagnostics.groups["start"] = {{"sigma0", sigma0}, {"sigma1", sigma1}, {"sigma2", st.sigma2},
                                   {"Fc", st.Fc},      {"Fs", st.Fs},       {"vs", st.vs}};

  ceres::Problem problem;
  std::vector<ceres::CostFunction*> costs;
  std::vector<std::array<double, 2>> starts;  // initial state [x, v] of each window
  starts.reserve(windows.size());
  for (const Window& w : windows) {
    starts.push_back(measured_start(rec, w));
    double* start = starts.back().data();
    if (given) {
      costs.push_back(new ceres::AutoDiffCostFunction<OutputErrorStaticGiven, ceres::DYNAMIC, kNd, 2>(
          new OutputErrorStaticGiven{&rec, w, sta}, w.residuals()));
      problem.AddResidualBlock(costs.back(), nullptr, dyn, start);
    } else {
      costs.push_back(new ceres::AutoDiffCostFunction<OutputError, ceres::DYNAMIC, kNd, kNs, 2>(new OutputError{&rec, w},
                                                                                                w.residuals()));
      problem.AddResidualBlock(costs.back(), nullptr, dyn, sta, start);
    }
    // A window from rest starts at rest: only its position is free.
    if (w.at_rest) problem.SetManifold(start, new ceres::SubsetManifold(2, {1}));
  }
  const double h = dt / o.substeps;
  // The explicit velocity update is stable for sigma1 h / M < 2 and sqrt(sigma0 / M) h < 2; keep a
  // factor 2 from both so that no trial step of the solver blows the simulation up.
  problem.SetParameterUpperBound(dyn, kLogS0, std::log(M / (h * h)));
  problem.SetParameterUpperBound(dyn, kLogS1, std::log(M / h));
  if (!given) {
    problem.SetParameterLowerBound(sta, kS2, 0.0);
    problem.SetParameterLowerBound(sta, kDF, 0.0);
    // Keep the static levels within a decade of their starting values and vs within the speeds of
    // the record: outside, the position no longer depends on them and the solver can wander off.
    problem.SetParameterLowerBound(sta, kLogFc, std::log(0.1 * st.Fc));
    problem.SetParameterUpperBound(sta, kLogFc, std::log(10 * st.Fc));
    problem.SetParameterUpperBound(sta, kDF, 10 * st.Fc);
    problem.SetParameterLowerBound(sta, kLogVs, std::log(1e-6 * vmax));
    problem.SetParameterUpperBound(sta, kLogVs, std::log(vmax));
  }

  detail::quiet_ceres_logging();
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = o.max_iterations;
  so.function_tolerance = 1e-10;
  so.parameter_tolerance = 1e-10;
  so.gradient_tolerance = 1e-14;
  so.logging_type = ceres::SILENT;
  so.num_threads = 2;  // windows are independent residual blocks
  detail::CancelCallback cancel;
  so.callbacks.push_back(&cancel);
  std::unique_ptr<Progress> progress;
  if (o.progress) {
    progress = std::make_unique<Progress>(o.progress, kResidualUnit, t_start);
    so.callbacks.push_back(progress.get());
  }
  ceres::Solver::Summary summary;
  int iterations = 0, fits = 0;
  double initial_cost = 0;
  // One fit from a start `c` (null: the values in place, the static part given), joint or staged.
  // Staged: stage 1 fits sigma0, sigma1 and the windows' starts with the static part held at the
  // start's pair (sigma1 starts at critical damping, up to several times off, and a joint first
  // step from there can push the static levels far away to make up for it: sigma1 then collapses
  // and vs runs to its bound, as seen on a light axis driven at 1 Hz); stage 2 fits everything.
  const auto fit_from = [&](const Start* c, bool staged) {
    if (c != nullptr) {
      dyn[kLogS0] = std::log(std::min(c->sigma0, s0_limit));
      dyn[kLogS1] = std::log(std::min(2 * std::sqrt(c->sigma0 * M), s1_limit));
      sta[kDF] = c->Fs - st.Fc;
      sta[kLogVs] = std::log(c->vs);
      sta[kS2] = st.sigma2;
      sta[kLogFc] = std::log(st.Fc);
      for (std::size_t i = 0; i < windows.size(); ++i) starts[i] = measured_start(rec, windows[i]);
    }
    if (staged) {
      problem.SetParameterBlockConstant(sta);
      ceres::Solve(so, &problem, &summary);
      throw_if_cancelled();
      iterations += static_cast<int>(summary.iterations.size()) - 1;
      initial_cost = summary.initial_cost;
      problem.SetParameterBlockVariable(sta);
    }
    ceres::Solve(so, &problem, &summary);
    throw_if_cancelled();
    if (!staged) initial_cost = summary.initial_cost;
    iterations += static_cast<int>(summary.iterations.size()) - 1;
    ++fits;
    return summary.final_cost;
  };
  if (given) {
    fit_from(nullptr, false);
  } else {
    // Multi-start: the fits from the best-ranked starts, until one reproduces the record to its
    // noise: the residual RMS within twice the position noise, estimated from the fourth
    // differences of the position (white noise of variance s^2 gives 70 s^2 there; the motion
    // itself adds its fourth derivative times dt^4, negligible at the sample rates this method
    // needs), or within 1e-4 of the position's RMS excursion for noise-free records (the fixed
    // step's own error). The best fit of those tried is kept.
    Eigen::VectorXd d4(std::max<Eigen::Index>(n - 4, 1));
    d4.setZero();
    for (Eigen::Index k = 0; k + 4 < n; ++k)
      d4[k] = std::abs(d.position[k] - 4 * d.position[k + 1] + 6 * d.position[k + 2] - 4 * d.position[k + 3] +
                       d.position[k + 4]);
    std::nth_element(d4.data(), d4.data() + d4.size() / 2, d4.data() + d4.size());
    constexpr double kMadToStd = 1.4826;  // median absolute deviation to std of a normal distribution
    const double noise_std = kMadToStd * d4[d4.size() / 2] / std::sqrt(70.0);
    const double excursion = std::sqrt((d.position.array() - d.position.mean()).square().mean());
    constexpr double kNoiseFactor = 2.0, kNoiseFreeFraction = 1e-4;
    const double good_rms = std::max(kNoiseFactor * noise_std, kNoiseFreeFraction * excursion);
    r.diagnostics.numbers["position_noise_std"] = noise_std;
    double best_cost = std::numeric_limits<double>::infinity();
    std::array<double, kNd> best_dyn{};
    std::array<double, kNs> best_sta{};
    std::vector<std::array<double, 2>> best_starts;
    ceres::Solver::Summary best_summary;
    double best_initial = 0;
    // Each start is fitted jointly, then staged when that fails: neither alone reached the noise
    // on every record tried. At most kMaxFits fits.
    constexpr int kMaxFits = 4;
    for (int attempt = 0; attempt < kMaxFits && attempt / 2 < static_cast<int>(candidates.size()); ++attempt) {
      const double cost = fit_from(&candidates[static_cast<std::size_t>(attempt / 2)], attempt % 2 == 1);
      if (cost < best_cost) {
        best_cost = cost;
        std::copy(dyn, dyn + kNd, best_dyn.begin());
        std::copy(sta, sta + kNs, best_sta.begin());
        best_starts = starts;
        best_summary = summary;
        best_initial = initial_cost;
      }
      const double rms = kResidualUnit * std::sqrt(2 * cost / static_cast<double>(n - 1));
      if (rms <= good_rms) break;
    }
    std::copy(best_dyn.begin(), best_dyn.end(), dyn);
    std::copy(best_sta.begin(), best_sta.end(), sta);
    starts = best_starts;
    summary = best_summary;
    initial_cost = best_initial;
    r.diagnostics.numbers["fits"] = fits;
  }

  // Jacobian at the solution: standard deviations s^2 A^-1 over the free law parameters, where
  // A is J'J with the windows' initial states eliminated (their Schur complement: the law's
  // parameters must explain the record whatever each window's start).
  // Residuals (m) and Jacobian (m per internal unit) over all windows; sample 0 has none.
  const Eigen::Index nr = n - 1;
  const int p_free = given ? kNd : kNd + kNs;
  Eigen::VectorXd e(nr);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nr, p_free);
  Eigen::MatrixXd A_int = Eigen::MatrixXd::Zero(p_free, p_free);
  int nuisance = 0;
  for (std::size_t i = 0; i < windows.size(); ++i) {
    const Window& w = windows[i];
    const int m = w.residuals();
    Eigen::Matrix<double, Eigen::Dynamic, kNd, Eigen::RowMajor> Jd(m, kNd);
    Eigen::Matrix<double, Eigen::Dynamic, kNs, Eigen::RowMajor> Js = Eigen::MatrixXd::Zero(m, kNs);
    Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> Jx(m, 2);
    const double* params_full[3] = {dyn, sta, starts[i].data()};
    const double* params_given[2] = {dyn, starts[i].data()};
    double* jac_full[3] = {Jd.data(), Js.data(), Jx.data()};
    double* jac_given[2] = {Jd.data(), Jx.data()};
    if (!costs[i]->Evaluate(given ? params_given : params_full, e.data() + w.begin, given ? jac_given : jac_full))
      return fail(r, "the simulation of the identified model failed");
    Eigen::MatrixXd Jw(m, p_free);
    Jw.leftCols(kNd) = Jd;
    if (!given) Jw.rightCols(kNs) = Js;
    J.middleRows(w.begin, m) = Jw;
    const Eigen::MatrixXd Jn = w.at_rest ? Eigen::MatrixXd(Jx.leftCols(1)) : Eigen::MatrixXd(Jx);
    nuisance += static_cast<int>(Jn.cols());
    const Eigen::MatrixXd cross = Jw.transpose() * Jn;
    A_int += Jw.transpose() * Jw - cross * (Jn.transpose() * Jn).ldlt().solve(cross.transpose());
  }
  e *= kResidualUnit;
  J *= kResidualUnit;
  A_int *= kResidualUnit * kResidualUnit;
  const double dof = std::max<double>(1.0, static_cast<double>(nr - p_free - nuisance));
  const double s2 = e.squaredNorm() / dof;
  {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
    const auto& sv = svd.singularValues();
    // An exactly singular Jacobian (a parameter that moves no simulated position of this record, as
    // a Stribeck velocity beyond every speed the record reaches) has no finite condition number: it
    // is left undefined (JSON null, not printed) and said in words, never an inf in an ok result.
    // A smallest singular value so small that the ratio overflows (record 43 of the coloured-noise
    // rate test, sigma0 run to its bound) is as singular as a zero one.
    if (sv[p_free - 1] > 0 && std::isfinite(sv[0] / sv[p_free - 1])) {
      r.diagnostics.condition_number = sv[0] / sv[p_free - 1];
    } else {
      r.diagnostics.condition_number = std::numeric_limits<double>::quiet_NaN();
      r.diagnostics.warnings.push_back(
          "the fit's Jacobian is singular: at least one parameter has no effect on the simulated position of this "
          "record (no condition number); its std does not bound its error (see undetermined and at_bound)");
    }
  }

  // Physical values, and the map T from them to the internal parameters (d internal / d physical;
  // the internal ones are logs and dF = Fs - Fc): the information in [sigma0, sigma1, sigma2, Fc,
  // Fs, vs] is T' A T.
  const double S0 = std::exp(dyn[kLogS0]), S1 = std::exp(dyn[kLogS1]);
  const double S2 = sta[kS2], FC = std::exp(sta[kLogFc]), FS = FC + sta[kDF], VS = std::exp(sta[kLogVs]);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(p_free, p_free);
  T(kLogS0, 0) = 1 / S0;
  T(kLogS1, 1) = 1 / S1;
  if (!given) {
    T(kNd + kS2, 2) = 1;
    T(kNd + kLogFc, 3) = 1 / FC;
    T(kNd + kDF, 3) = -1;
    T(kNd + kDF, 4) = 1;
    T(kNd + kLogVs, 5) = 1 / VS;
  }
  const Eigen::MatrixXd information = T.transpose() * A_int * T;

  // Parameters held from `static_law` (and delta, vd) keep std 0.
  const auto add = [&](const std::string& name, double v, Quantity q) { add_parameter(r, name, v, 0.0, q, o.axis); };
  add("sigma0", S0, Quantity::stiffness);
  add("sigma1", S1, Quantity::viscous);
  add("sigma2", S2, Quantity::viscous);
  add("Fc", FC, Quantity::force);
  add("Fs", FS, Quantity::force);
  add("vs", VS, Quantity::velocity);
  add("delta", st.delta, Quantity::dimensionless);
  if (st.vd > 0) add("vd", st.vd, Quantity::velocity);
  {
    // Standard deviations s^2 (T' A T)^-1 through the shared rule (identify/uncertainty.hpp): a
    // parameter at a bound of the fit or not determined by the record gets std NaN and a warning.
    const std::vector<std::string> all = {"sigma0", "sigma1", "sigma2", "Fc", "Fs", "vs"};
    const std::vector<std::string> names(all.begin(), all.begin() + p_free);
    std::vector<ParameterState> states(names.size());
    // Each internal parameter against its bounds (Ceres stops exactly on a bound it hits); the
    // scale sets the tolerance at a bound of 0: sigma2 against the viscous coefficient that would
    // carry Fc at the top speed, dF = Fs - Fc against Fc. Internal i is physical i.
    for (int i = 0; i < p_free; ++i) {
      double* block = i < kNd ? dyn : sta;
      const int j = i < kNd ? i : i - kNd;
      const double scale = i == kNd + kS2 ? FC / vmax : (i == kNd + kDF ? FC : 1.0);
      if (is_at_bound(block[j], problem.GetParameterLowerBound(block, j), problem.GetParameterUpperBound(block, j), scale))
        states[static_cast<std::size_t>(i)].at_bound = true;
    }
    // A first pass finds the parameters whose std would exceed their value: the record does not
    // give even their order of magnitude (all six are >= 0), so they count as undetermined.
    Result probe = r;
    set_uncertainty_from_information(probe, names, information, s2, states);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const Parameter* p = probe.find(names[i]);
      if (!states[i].at_bound && std::isfinite(p->std) && p->std > std::abs(p->value)) {
        states[i].undetermined = true;
        states[i].reason = "its linearised std " + format_number(p->std) + " exceeds its value";
      }
    }
    set_uncertainty_from_information(r, names, information, s2, states);
  }

  Eigen::VectorXd x_sim = d.position;
  x_sim.tail(nr) += e;
  set_fit(r, d.position.array() - d.position[0], x_sim.array() - d.position[0]);

  auto& num = r.diagnostics.numbers;
  num["iterations"] = iterations;
  num["cost_initial"] = initial_cost * kResidualUnit * kResidualUnit;
  num["cost_final"] = summary.final_cost * kResidualUnit * kResidualUnit;
  num["substeps"] = o.substeps;
  num["windows"] = static_cast<double>(windows.size());
  num["dt"] = dt;
  num["inertia"] = M;
  num["static_given"] = given ? 1.0 : 0.0;
  if (summary.termination_type == ceres::NO_CONVERGENCE)
    warn("the output-error fit stopped at its iteration limit (" + std::to_string(o.max_iterations) +
         ") before converging: the estimates may be off");
  else if (summary.termination_type == ceres::FAILURE || !std::isfinite(summary.final_cost))
    // A solver failure is never ok: its numbers are not a fit (a record whose one cell is 1e308).
    return fail(r, "the output-error fit failed: " + summary.message);

  LuGre lg;
  lg.sigma0 = S0;
  lg.sigma1 = S1;
  lg.sigma2 = S2;
  lg.Fc = FC;
  lg.Fs = FS;
  lg.vs = VS;
  lg.delta = st.delta;
  lg.vd = st.vd;
  try {
    r.law = FrictionLaw(lg).to_spec();
    const Passivity pv = lg.passivity();
    num["passive"] = pv.passive ? 1.0 : 0.0;
    if (!pv.passive) warn(pv.message);
  } catch (const std::invalid_argument& ex) {
    warn(std::string("the estimates do not make a valid LuGre law: ") + ex.what());
  }

  r.series["time"].assign(d.time.data(), d.time.data() + n);
  r.series["position"].assign(d.position.data(), d.position.data() + n);
  r.series["position_sim"].assign(x_sim.data(), x_sim.data() + n);
  r.series["force"].assign(d.force.data(), d.force.data() + n);
  {
    // The identified model run freely over the whole record (one window from the start): the
    // stricter figure, since errors carry over from reversal to reversal.
    const Window whole{0, static_cast<int>(n) - 1, windows.front().at_rest};
    Eigen::VectorXd free_run = d.position;
    simulate_residuals(dyn, sta, rec, whole, starts.front().data(), free_run.data() + 1);
    free_run.tail(nr) = free_run.tail(nr) * kResidualUnit + d.position.tail(nr);
    const Eigen::VectorXd dx = d.position.array() - d.position[0];
    num["free_run_relative_error_percent"] = 100.0 * (free_run - d.position).norm() / dx.norm();
    r.series["position_free_run"].assign(free_run.data(), free_run.data() + n);
  }
  add_lugre_adequacy(r, d, M, lg, dt, o.axis);
  return r;
}

}  // namespace

// Numbers or an error, never both (identify/finite_result.hpp): figures that overflow double
// precision (forces and inertia scaled by 1e160: adequacy.residual_std = inf) make an error, not an
// ok result with inf.
Result identify_lugre(const LugreData& d, const LugreOptions& o) { return finite_or_error(identify_lugre_unchecked(d, o)); }

}  // namespace frictionlab
