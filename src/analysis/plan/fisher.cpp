#include "frictionlab/analysis/plan/fisher.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "frictionlab/analysis/plan/predict.hpp"
#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/static_fit.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace frictionlab {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Relative step of the central differences of the static law in its parameters and in v: the
// law is smooth (exp, powers), so 1e-6 leaves a truncation and rounding error near 1e-10.
constexpr double kStep = 1e-6;
// Impulse-response samples below this fraction of the largest are dropped from the
// autocorrelation (the filters' tails: their contribution to the variance is below 1e-12).
constexpr double kTail = 1e-6;

// The std of the estimates cov = (J'J)^-1 J' S J (J'J)^-1, where S J is given as `SJ` (N x p),
// and the parameters whose direction of the column-normalised information is singular.
void solve(const Eigen::MatrixXd& J, const Eigen::MatrixXd& SJ, const std::vector<std::string>& names,
           AprioriSpread& out) {
  const Eigen::Index p = J.cols();
  out.names = names;
  out.std.assign(static_cast<std::size_t>(p), kNaN);
  Eigen::VectorXd scale = J.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < p; ++j)
    if (!(scale[j] > 0)) scale[j] = 1;  // a zero column: its parameter is undetermined below
  const Eigen::MatrixXd Jn = J * scale.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Jn.transpose() * Jn);
  const Eigen::VectorXd& lambda = eig.eigenvalues();  // ascending
  const double top = lambda[p - 1];
  std::vector<bool> singular(static_cast<std::size_t>(p), false);
  for (Eigen::Index k = 0; k < p; ++k) {
    if (lambda[k] > kSingularInformation * top && top > 0) continue;
    for (Eigen::Index j = 0; j < p; ++j)
      if (std::abs(eig.eigenvectors()(j, k)) > 0.1) singular[static_cast<std::size_t>(j)] = true;
  }
  const bool any = std::find(singular.begin(), singular.end(), true) != singular.end();
  for (Eigen::Index j = 0; j < p; ++j)
    if (singular[static_cast<std::size_t>(j)]) out.undetermined.push_back(names[static_cast<std::size_t>(j)]);
  if (any) {  // the others' std with the singular ones held
    std::vector<Eigen::Index> keep;
    std::vector<std::string> kept;
    for (Eigen::Index j = 0; j < p; ++j)
      if (!singular[static_cast<std::size_t>(j)]) keep.push_back(j), kept.push_back(names[static_cast<std::size_t>(j)]);
    if (keep.empty()) return;
    Eigen::MatrixXd Jk(J.rows(), static_cast<Eigen::Index>(keep.size())), SJk(J.rows(), Jk.cols());
    for (std::size_t c = 0; c < keep.size(); ++c) {
      Jk.col(static_cast<Eigen::Index>(c)) = J.col(keep[c]);
      SJk.col(static_cast<Eigen::Index>(c)) = SJ.col(keep[c]);
    }
    AprioriSpread sub;
    solve(Jk, SJk, kept, sub);
    for (std::size_t c = 0; c < keep.size(); ++c) out.std[static_cast<std::size_t>(keep[c])] = sub.std[c];
    for (const auto& u : sub.undetermined) out.undetermined.push_back(u);
    return;
  }
  // (J'J)^-1 through the normalised information: (J'J)^-1 = D^-1 (Jn'Jn)^-1 D^-1.
  const Eigen::MatrixXd inv_n = eig.eigenvectors() * lambda.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  const Eigen::MatrixXd inv = scale.cwiseInverse().asDiagonal() * inv_n * scale.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd cov = inv * (J.transpose() * SJ) * inv;
  for (Eigen::Index j = 0; j < p; ++j) out.std[static_cast<std::size_t>(j)] = std::sqrt(std::max(0.0, cov(j, j)));
}

double force_noise_std(const PlanRig& rig, const SensorNoise& noise) {
  return rig.torque_constant > 0 ? rig.torque_constant * noise.current : noise.force;
}

AprioriSpread sweep_spread(const PlanMeasurement& m, const PlanRig& rig, const SensorNoise& noise) {
  AprioriSpread out;
  const SweepOptions o = plan_sweep_options(rig, m.reference);
  const auto points = sweep_points(SweepData{m.time, m.force, m.velocity, {}}, o);
  const auto n = static_cast<Eigen::Index>(points.size());
  if (n == 0) return out;
  Eigen::VectorXd v(n), f(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    v[i] = points[static_cast<std::size_t>(i)].velocity;
    f[i] = points[static_cast<std::size_t>(i)].force;
  }
  StaticFit fit;
  try {
    fit = fit_static_law(v, f, o.fit);  // the noise-free fit: the linearisation point
  } catch (const std::invalid_argument&) {
    return out;  // too few points: the Monte Carlo runs report why
  }
  const LawSpec spec = fit.law.to_spec();
  auto law_with = [&](const std::string& name, double value) {
    LawSpec s = spec;
    s.scalars[name] = value;
    return FrictionLaw::from_spec(s);
  };
  std::vector<std::string> names;
  std::vector<Eigen::VectorXd> columns;
  auto listed = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  for (const auto& p : fit.parameters) {
    // A held exponent is not estimated. Parameters the fit's own rule leaves undetermined (vs
    // and delta with too few points below vs) stay in J: the fit still moves them, so the
    // parameters confounded with them (Fs) show as singular too.
    if (!spec.scalars.count(p.name) || (p.name == "delta" && o.fit.fixed_delta > 0)) continue;
    const double h = kStep * std::max(std::abs(p.value), 1e-12);
    const FrictionLaw up = law_with(p.name, p.value + h), down = law_with(p.name, p.value - h);
    Eigen::VectorXd c(n);
    for (Eigen::Index i = 0; i < n; ++i) c[i] = (up.sliding(v[i]) - down.sliding(v[i])) / (2 * h);
    names.push_back(p.name);
    columns.push_back(c);
  }
  Eigen::MatrixXd J(n, static_cast<Eigen::Index>(names.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) J.col(static_cast<Eigen::Index>(j)) = columns[j];
  // Each point's noise: the mean of its samples' force noise and, through the law's slope, of
  // their velocity noise (the point's velocity is the measured mean): independent across points.
  const double sf = force_noise_std(rig, noise), sv = noise.velocity;
  Eigen::VectorXd var(n);
  double sum = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double h = kStep * std::max(std::abs(v[i]), 1e-12);
    const double slope = (fit.law.sliding(v[i] + h) - fit.law.sliding(v[i] - h)) / (2 * h);
    const double samples = std::max<double>(1.0, static_cast<double>(points[static_cast<std::size_t>(i)].samples));
    var[i] = (sf * sf + slope * slope * sv * sv) / samples;
    sum += std::sqrt(var[i]);
  }
  out.signal_noise_std = sum / static_cast<double>(n);
  solve(J, var.asDiagonal() * J, names, out);
  for (const auto& u : fit.undetermined) {
    const auto it = std::find(out.names.begin(), out.names.end(), u);
    if (it != out.names.end()) out.std[static_cast<std::size_t>(it - out.names.begin())] = kNaN;
    if (!listed(out.undetermined, u)) out.undetermined.push_back(u);
  }
  return out;
}

// The idim pipeline's output for a unit impulse on the position or the force at raw sample k:
// the fitted signal's noise e = y - (M qdd + Fv qd) at the decimated samples.
Eigen::VectorXd idim_impulse(const PlanMeasurement& m, const IdimOptions& o, bool on_position, Eigen::Index k,
                             const std::vector<std::string>& names, const Eigen::VectorXd& theta) {
  IdimData d = plan_idim_data(m);  // the load and temperature columns as measured (noise-free)
  d.position = Eigen::VectorXd::Zero(m.time.size());
  d.force = Eigen::VectorXd::Zero(m.time.size());
  (on_position ? d.position : d.force)[k] = 1.0;
  const IdimRegression r = idim_regression(d, o);
  Eigen::VectorXd e = r.y;
  // The columns linear in the position: qdd, qd and qd (T - T_ref). The sign and ripple columns
  // are taken as noise-free, as the Coulomb column.
  for (std::size_t j = 0; j < names.size(); ++j)
    if (names[j] == "M" || names[j] == "Fv" || names[j] == "Fv_per_K")
      e -= theta[static_cast<Eigen::Index>(j)] * r.X.col(static_cast<Eigen::Index>(j));
  return e;
}

// Autocorrelation at decimated lags 0..L of the full-rate impulse response whose D phases are
// `phases` (each the decimated output of an impulse one raw sample later).
std::vector<double> autocorrelation(const std::vector<Eigen::VectorXd>& phases) {
  double peak = 0;
  for (const auto& h : phases) peak = std::max(peak, h.cwiseAbs().maxCoeff());
  std::vector<double> R;
  for (const auto& h : phases) {
    Eigen::Index lo = h.size(), hi = -1;
    for (Eigen::Index i = 0; i < h.size(); ++i)
      if (std::abs(h[i]) > kTail * peak) lo = std::min(lo, i), hi = i;
    for (Eigen::Index a = lo; a <= hi; ++a)
      for (Eigen::Index b = a; b <= hi; ++b) {
        const auto lag = static_cast<std::size_t>(b - a);
        if (R.size() <= lag) R.resize(lag + 1, 0.0);
        R[lag] += h[a] * h[b];
      }
  }
  return R;
}

AprioriSpread idim_spread(PlanMethod method, const PlanMeasurement& m, const PlanRig& rig, const ExperimentProfile& profile,
                          const SensorNoise& noise) {
  AprioriSpread out;
  IdimOptions o = plan_idim_options(rig, method, &profile);
  IdimData d = plan_idim_data(m);
  // The temperature term's T_ref as the identification takes it (the mean over the used samples
  // when the prior gives none), fixed here so that the impulses' regressions use the same one.
  if (!std::isfinite(o.temperature_ref) && d.temperature.size() > 0) o.temperature_ref = d.temperature.mean();
  const IdimRegression reg = idim_regression(d, o);
  const Eigen::MatrixXd& J = reg.X;
  const Eigen::Index p = J.cols(), n = J.rows();
  if (n <= p) return out;
  std::vector<std::string> names;
  for (const auto& t : reg.terms) names.push_back(t.parameter);
  const Eigen::VectorXd theta = J.colPivHouseholderQr().solve(reg.y);  // the noise-free fit
  // The autocorrelation of the fitted signal's noise at decimated lags, from the impulse
  // responses of the pipeline (time-invariant away from the record's ends).
  const int D = idim_rate_defaults(profile.sample_rate).decimation;
  const Eigen::Index k0 = m.time.size() / 2;
  const double sx2 = noise.position * noise.position + noise.encoder * noise.encoder / 12;  // quantisation: uniform
  const double sf = force_noise_std(rig, noise);
  // The impulses run the pipeline on every row: the rows a plan leaves out (exclude_below) are a
  // choice of rows, not a change of the filter; the kept rows' noise is then taken as correlated as
  // neighbours' (conservative across a gap).
  IdimOptions all_rows = o;
  all_rows.exclude_below = 0.0;
  std::vector<Eigen::VectorXd> pos, frc;
  for (int r = 0; r < D; ++r) {
    if (sx2 > 0) pos.push_back(idim_impulse(m, all_rows, true, k0 + r, names, theta));
    if (sf > 0) frc.push_back(idim_impulse(m, all_rows, false, k0 + r, names, theta));
  }
  const std::vector<double> Rx = autocorrelation(pos), Rf = autocorrelation(frc);
  std::vector<double> R(std::max(Rx.size(), Rf.size()), 0.0);
  for (std::size_t l = 0; l < R.size(); ++l)
    R[l] = (l < Rx.size() ? sx2 * Rx[l] : 0.0) + (l < Rf.size() ? sf * sf * Rf[l] : 0.0);
  if (R.empty()) R.push_back(0.0);  // no noise: std 0
  out.signal_noise_std = std::sqrt(R[0]);
  // S J with S Toeplitz, S(i, j) = R(|i - j|).
  Eigen::MatrixXd SJ = R[0] * J;
  const auto L = static_cast<Eigen::Index>(R.size()) - 1;
  for (Eigen::Index lag = 1; lag <= std::min(L, n - 1); ++lag) {
    SJ.topRows(n - lag) += R[static_cast<std::size_t>(lag)] * J.bottomRows(n - lag);
    SJ.bottomRows(n - lag) += R[static_cast<std::size_t>(lag)] * J.topRows(n - lag);
  }
  solve(J, SJ, names, out);
  AprioriSpread white;
  solve(J, R[0] * J, names, white);
  out.std_white = white.std;
  return out;
}

}  // namespace

AprioriSpread a_priori_spread(PlanMethod method, const ExperimentProfile& profile, const PlanRig& rig,
                              const Trajectory& clean, const SensorNoise& noise) {
  if (method != PlanMethod::sweep && !is_idim_plan(method)) return {};
  std::mt19937_64 unused(0);  // no noise is drawn: a zero std draws nothing
  const PlanMeasurement m = measure(clean, rig, profile, SensorNoise{}, unused);
  return method == PlanMethod::sweep ? sweep_spread(m, rig, noise) : idim_spread(method, m, rig, profile, noise);
}

}  // namespace frictionlab
