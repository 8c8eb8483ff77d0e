#include "frictionlab/identify/static_fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace frictionlab {

StaticFitModel parse_static_fit_model(const std::string& name) {
  if (name == "coulomb-viscous") return StaticFitModel::coulomb_viscous;
  if (name == "coulomb-viscous-asymmetric") return StaticFitModel::coulomb_viscous_asymmetric;
  if (name == "stribeck") return StaticFitModel::stribeck;
  if (name == "stribeck-asymmetric") return StaticFitModel::stribeck_asymmetric;
  throw std::invalid_argument("model '" + name +
                              "' cannot be fitted to a friction-velocity map; expected coulomb-viscous, "
                              "coulomb-viscous-asymmetric, stribeck or stribeck-asymmetric");
}

namespace {

// Parameter vector of the one-sided Stribeck fit: [Fc, dF = Fs - Fc, vs, delta, Fv], so that
// the physical rule Fs >= Fc becomes the box bound dF >= 0 that Ceres supports.
constexpr int kFc = 0, kDF = 1, kVs = 2, kDelta = 3, kFv = 4, kNp = 5;

// Residuals F_model(v_i) - F_i for a contiguous chunk of points, with the analytic Jacobian
// (cheaper than Jets by a factor of about 3 on 1e5 points).
class StribeckChunk final : public ceres::CostFunction {
 public:
  StribeckChunk(const double* v, const double* f, int n) : v_(v), f_(f), n_(n) {
    set_num_residuals(n);
    mutable_parameter_block_sizes()->push_back(kNp);
  }
  bool Evaluate(double const* const* params, double* r, double** jac) const override {
    const double* p = params[0];
    const double Fc = p[kFc], dF = p[kDF], vs = p[kVs], delta = p[kDelta], Fv = p[kFv];
    for (int i = 0; i < n_; ++i) {
      const double v = v_[i];
      const double s = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
      const double x = std::abs(v) / vs;
      const double lx = std::log(x);
      const double u = std::exp(delta * lx);
      // Far past vs the decay and its derivatives are below rounding (see stribeck_decay);
      // skipping exp there also avoids its slow underflow path.
      const double e = u > kNegligibleDecayExponent ? 0.0 : std::exp(-u);
      r[i] = s * (Fc + dF * e) + Fv * v - f_[i];
      if (jac && jac[0]) {
        double* J = jac[0] + i * kNp;
        J[kFc] = s;
        J[kDF] = s * e;
        J[kVs] = s * dF * e * delta * u / vs;
        J[kDelta] = -s * dF * e * u * lx;
        J[kFv] = v;
      }
    }
    return true;
  }

 private:
  const double* v_;
  const double* f_;
  int n_;
};

struct OneSided {
  double p[kNp];
  Eigen::Matrix<double, kNp, kNp> cov;  // covariance of p
  double ssr = 0;
  int iterations = 0;
  bool converged = false;
};

// Linear least squares F = Fc sign(v) + Fv v: exact, no start needed.
void linear_coulomb_viscous(const Eigen::VectorXd& v, const Eigen::VectorXd& f, double& Fc, double& Fv,
                            Eigen::Matrix2d* cov = nullptr, double* ssr = nullptr) {
  Eigen::MatrixXd X(v.size(), 2);
  for (Eigen::Index i = 0; i < v.size(); ++i) X.row(i) << (v[i] > 0 ? 1.0 : -1.0), v[i];
  const Eigen::Vector2d b = X.colPivHouseholderQr().solve(f);
  Fc = b[0];
  Fv = b[1];
  const double r = (f - X * b).squaredNorm();
  if (ssr) *ssr = r;
  if (cov) {
    const double dof = std::max<double>(1.0, static_cast<double>(v.size()) - 2);
    *cov = (r / dof) * (X.transpose() * X).inverse();
  }
}

// Starting values from the data of one direction (v > 0 after folding).
void initial_guess(const Eigen::VectorXd& v, const Eigen::VectorXd& f, double fixed_delta, double* p) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(v.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return v[a] < v[b]; });
  const std::size_t n = order.size();
  // High-speed half: Coulomb + viscous by linear least squares.
  const std::size_t h = n / 2;
  Eigen::VectorXd vh(static_cast<Eigen::Index>(n - h)), fh(static_cast<Eigen::Index>(n - h));
  for (std::size_t k = h; k < n; ++k) {
    vh[static_cast<Eigen::Index>(k - h)] = v[order[k]];
    fh[static_cast<Eigen::Index>(k - h)] = f[order[k]];
  }
  double Fc = 0, Fv = 0;
  if (vh.size() >= 2 && vh.maxCoeff() > vh.minCoeff()) linear_coulomb_viscous(vh, fh, Fc, Fv);
  else Fc = fh.mean();
  Fv = std::max(Fv, 0.0);
  Fc = std::max(Fc, 0.0);
  // Slowest tenth: the static level.
  const std::size_t m = std::max<std::size_t>(1, n / 10);
  double Fs = 0;
  for (std::size_t k = 0; k < m; ++k) Fs += f[order[k]] - Fv * v[order[k]];
  Fs /= static_cast<double>(m);
  const double dF = std::max(Fs - Fc, 1e-3 * std::max(Fc, 1e-12));
  // vs: first speed where the excess over Fc + Fv v falls below dF / e.
  double vs = v[order[n / 2]];
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = order[k];
    if (f[i] - Fc - Fv * v[i] < dF / std::exp(1.0)) {
      vs = std::max(v[i], 1e-12);
      break;
    }
  }
  p[kFc] = Fc;
  p[kDF] = dF;
  p[kVs] = vs;
  p[kDelta] = fixed_delta > 0 ? fixed_delta : 2.0;
  p[kFv] = Fv;
}

OneSided fit_one_sided(const Eigen::VectorXd& v, const Eigen::VectorXd& f, const StaticFitOptions& o) {
  OneSided best;
  best.ssr = std::numeric_limits<double>::infinity();
  double start[kNp];
  // The guess works on the folded map (|v|, F sign(v)): both directions give the same levels.
  const Eigen::VectorXd sign = v.unaryExpr([](double x) { return x > 0 ? 1.0 : -1.0; });
  initial_guess(v.cwiseAbs(), f.cwiseProduct(sign), o.fixed_delta, start);
  // Two exponent starts guard against the wrong minimum a single start can land in.
  std::vector<double> delta_starts = o.fixed_delta > 0 ? std::vector<double>{o.fixed_delta} : std::vector<double>{2.0, 1.0};
  const int n = static_cast<int>(v.size());
  const int chunks = std::max(1, std::min(n / 2000, 4 * std::max(1, o.num_threads)));
  for (double d0 : delta_starts) {
    // The second exponent start is only needed when the first ends badly: not converged, or
    // with the exponent pinned at a bound (a sign of the wrong basin).
    if (d0 != delta_starts.front() && best.converged && best.p[kDelta] > o.delta_min * (1 + 1e-6) &&
        best.p[kDelta] < o.delta_max * (1 - 1e-6))
      break;
    OneSided cur;
    std::copy(start, start + kNp, cur.p);
    cur.p[kDelta] = d0;
    ceres::Problem::Options popts;
    ceres::Problem problem(popts);
    for (int c = 0; c < chunks; ++c) {
      const int b = static_cast<int>(static_cast<long>(n) * c / chunks), e = static_cast<int>(static_cast<long>(n) * (c + 1) / chunks);
      problem.AddResidualBlock(new StribeckChunk(v.data() + b, f.data() + b, e - b), nullptr, cur.p);
    }
    problem.SetParameterLowerBound(cur.p, kFc, 0.0);
    problem.SetParameterLowerBound(cur.p, kDF, 0.0);
    const double vmax = v.cwiseAbs().maxCoeff();
    problem.SetParameterLowerBound(cur.p, kVs, 1e-6 * vmax);
    problem.SetParameterUpperBound(cur.p, kVs, 10 * vmax);
    problem.SetParameterLowerBound(cur.p, kFv, 0.0);
    if (o.fixed_delta > 0) {
      problem.SetManifold(cur.p, new ceres::SubsetManifold(kNp, {kDelta}));
    } else {
      problem.SetParameterLowerBound(cur.p, kDelta, o.delta_min);
      problem.SetParameterUpperBound(cur.p, kDelta, o.delta_max);
    }
    ceres::Solver::Options sopts;
    sopts.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
    sopts.max_num_iterations = o.max_iterations;
    sopts.num_threads = std::max(1, o.num_threads);
    sopts.function_tolerance = 1e-12;
    sopts.gradient_tolerance = 1e-14;
    sopts.parameter_tolerance = 1e-12;
    sopts.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(sopts, &problem, &summary);
    cur.ssr = 2 * summary.final_cost;
    cur.iterations = static_cast<int>(summary.iterations.size());
    cur.converged = summary.termination_type == ceres::CONVERGENCE;
    if (cur.ssr < best.ssr) best = cur;
  }
  // Covariance s^2 (J'J)^-1 at the solution; a held exponent has zero variance.
  Eigen::Matrix<double, kNp, kNp> JtJ = Eigen::Matrix<double, kNp, kNp>::Zero();
  {
    StribeckChunk all(v.data(), f.data(), n);
    std::vector<double> r(static_cast<std::size_t>(n)), J(static_cast<std::size_t>(n) * kNp);
    const double* params[] = {best.p};
    double* jacs[] = {J.data()};
    all.Evaluate(params, r.data(), jacs);
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, kNp, Eigen::RowMajor>> Jm(J.data(), n, kNp);
    JtJ = Jm.transpose() * Jm;
  }
  std::vector<int> free_idx;
  for (int k = 0; k < kNp; ++k)
    if (!(k == kDelta && o.fixed_delta > 0)) free_idx.push_back(k);
  const int nf = static_cast<int>(free_idx.size());
  Eigen::MatrixXd A(nf, nf);
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b) A(a, b) = JtJ(free_idx[a], free_idx[b]);
  const double s2 = best.ssr / std::max(1, n - nf);
  const Eigen::MatrixXd Ainv = A.completeOrthogonalDecomposition().pseudoInverse();
  best.cov.setZero();
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b) best.cov(free_idx[a], free_idx[b]) = s2 * Ainv(a, b);
  return best;
}

void check_input(const Eigen::VectorXd& v, const Eigen::VectorXd& f, Eigen::Index min_points) {
  if (v.size() != f.size())
    throw std::invalid_argument("friction fit: velocity has " + std::to_string(v.size()) + " points but force has " +
                                std::to_string(f.size()) + "; they must be equal");
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i]) || !std::isfinite(f[i]))
      throw std::invalid_argument("friction fit: point " + std::to_string(i) + " is not finite (velocity " +
                                  std::to_string(v[i]) + ", force " + std::to_string(f[i]) + ")");
    if (v[i] == 0.0)
      throw std::invalid_argument("friction fit: point " + std::to_string(i) +
                                  " has velocity 0; a friction-velocity map needs sliding points (v != 0, m/s or rad/s)");
  }
  if (v.size() < min_points)
    throw std::invalid_argument("friction fit: " + std::to_string(v.size()) + " points are too few; the model needs at least " +
                                std::to_string(min_points));
}

// Splits points by direction, folding the negative ones to positive velocity and force.
void split(const Eigen::VectorXd& v, const Eigen::VectorXd& f, Eigen::VectorXd& vp, Eigen::VectorXd& fp,
           Eigen::VectorXd& vn, Eigen::VectorXd& fn) {
  std::vector<double> a, b, c, d;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (v[i] > 0) {
      a.push_back(v[i]);
      b.push_back(f[i]);
    } else {
      c.push_back(-v[i]);
      d.push_back(-f[i]);
    }
  }
  vp = Eigen::Map<Eigen::VectorXd>(a.data(), static_cast<Eigen::Index>(a.size()));
  fp = Eigen::Map<Eigen::VectorXd>(b.data(), static_cast<Eigen::Index>(b.size()));
  vn = Eigen::Map<Eigen::VectorXd>(c.data(), static_cast<Eigen::Index>(c.size()));
  fn = Eigen::Map<Eigen::VectorXd>(d.data(), static_cast<Eigen::Index>(d.size()));
}

void finish(StaticFit& fit, const Eigen::VectorXd& v, const Eigen::VectorXd& f) {
  double ssr = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double r = fit.law.sliding(v[i]) - f[i];
    ssr += r * r;
  }
  fit.samples = static_cast<std::size_t>(v.size());
  fit.rmse = std::sqrt(ssr / static_cast<double>(v.size()));
  fit.relative_error_percent = 100.0 * std::sqrt(ssr) / f.norm();
}

// Stribeck parameters of one side in the law's order (Fc, Fs, vs, delta, Fv) with std.
std::vector<FittedParameter> stribeck_parameters(const OneSided& s, const std::string& suffix) {
  auto sd = [&](int k) { return std::sqrt(std::max(0.0, s.cov(k, k))); };
  const double var_fs = s.cov(kFc, kFc) + s.cov(kDF, kDF) + 2 * s.cov(kFc, kDF);
  return {{"Fc" + suffix, s.p[kFc], sd(kFc), Quantity::force},
          {"Fs" + suffix, s.p[kFc] + s.p[kDF], std::sqrt(std::max(0.0, var_fs)), Quantity::force},
          {"vs" + suffix, s.p[kVs], sd(kVs), Quantity::velocity},
          {"delta" + suffix, s.p[kDelta], sd(kDelta), Quantity::dimensionless},
          {"Fv" + suffix, s.p[kFv], sd(kFv), Quantity::viscous}};
}

void stribeck_warnings(const OneSided& s, const std::string& side, std::vector<std::string>& w) {
  const double sd_df = std::sqrt(std::max(0.0, s.cov(kDF, kDF)));
  if (s.p[kDF] <= 2 * sd_df) {
    std::ostringstream m;
    m << "no clear Stribeck effect" << side << ": Fs - Fc = " << s.p[kDF] << " is within 2 std (" << 2 * sd_df
      << "); vs and delta are poorly determined";
    w.push_back(m.str());
  }
  if (!s.converged) w.push_back("the Stribeck fit" + side + " stopped before converging (" + std::to_string(s.iterations) + " iterations)");
}

}  // namespace

StaticFit fit_static_law(const Eigen::VectorXd& velocity, const Eigen::VectorXd& force, const StaticFitOptions& o) {
  StaticFit fit;
  switch (o.model) {
    case StaticFitModel::coulomb_viscous: {
      check_input(velocity, force, 3);
      double Fc, Fv, ssr;
      Eigen::Matrix2d cov;
      linear_coulomb_viscous(velocity, force, Fc, Fv, &cov, &ssr);
      fit.law = CoulombViscous{std::max(Fc, 0.0), std::max(Fv, 0.0)};
      fit.parameters = {{"Fc", Fc, std::sqrt(cov(0, 0)), Quantity::force}, {"Fv", Fv, std::sqrt(cov(1, 1)), Quantity::viscous}};
      fit.iterations = 1;
      fit.converged = true;
      break;
    }
    case StaticFitModel::coulomb_viscous_asymmetric: {
      check_input(velocity, force, 4);
      Eigen::VectorXd vp, fp, vn, fn;
      split(velocity, force, vp, fp, vn, fn);
      if (vp.size() < 2 || vn.size() < 2)
        throw std::invalid_argument("friction fit: the asymmetric model needs at least 2 points in each direction (has " +
                                    std::to_string(vp.size()) + " positive, " + std::to_string(vn.size()) + " negative)");
      Asymmetric<CoulombViscous> law;
      Eigen::Matrix2d cp, cn;
      double ssr;
      // One direction only: F = Fc + Fv v with v > 0 (the sign column is constant 1).
      linear_coulomb_viscous(vp, fp, law.pos.Fc, law.pos.Fv, &cp, &ssr);
      linear_coulomb_viscous(vn, fn, law.neg.Fc, law.neg.Fv, &cn, &ssr);
      fit.parameters = {{"Fc_pos", law.pos.Fc, std::sqrt(cp(0, 0)), Quantity::force},
                        {"Fv_pos", law.pos.Fv, std::sqrt(cp(1, 1)), Quantity::viscous},
                        {"Fc_neg", law.neg.Fc, std::sqrt(cn(0, 0)), Quantity::force},
                        {"Fv_neg", law.neg.Fv, std::sqrt(cn(1, 1)), Quantity::viscous}};
      law.pos.Fc = std::max(law.pos.Fc, 0.0);
      law.pos.Fv = std::max(law.pos.Fv, 0.0);
      law.neg.Fc = std::max(law.neg.Fc, 0.0);
      law.neg.Fv = std::max(law.neg.Fv, 0.0);
      fit.law = law;
      fit.iterations = 1;
      fit.converged = true;
      break;
    }
    case StaticFitModel::stribeck: {
      check_input(velocity, force, o.fixed_delta > 0 ? 5 : 6);
      const OneSided s = fit_one_sided(velocity, force, o);
      fit.law = Stribeck{s.p[kFc], s.p[kFc] + s.p[kDF], s.p[kVs], s.p[kDelta], s.p[kFv]};
      fit.parameters = stribeck_parameters(s, "");
      fit.iterations = s.iterations;
      fit.converged = s.converged;
      stribeck_warnings(s, "", fit.warnings);
      break;
    }
    case StaticFitModel::stribeck_asymmetric: {
      check_input(velocity, force, 10);
      Eigen::VectorXd vp, fp, vn, fn;
      split(velocity, force, vp, fp, vn, fn);
      const Eigen::Index need = o.fixed_delta > 0 ? 5 : 6;
      if (vp.size() < need || vn.size() < need)
        throw std::invalid_argument("friction fit: stribeck-asymmetric needs at least " + std::to_string(need) +
                                    " points in each direction (has " + std::to_string(vp.size()) + " positive, " +
                                    std::to_string(vn.size()) + " negative)");
      const OneSided p = fit_one_sided(vp, fp, o), n = fit_one_sided(vn, fn, o);
      Asymmetric<Stribeck> law;
      law.pos = Stribeck{p.p[kFc], p.p[kFc] + p.p[kDF], p.p[kVs], p.p[kDelta], p.p[kFv]};
      law.neg = Stribeck{n.p[kFc], n.p[kFc] + n.p[kDF], n.p[kVs], n.p[kDelta], n.p[kFv]};
      fit.law = law;
      fit.parameters = stribeck_parameters(p, "_pos");
      for (auto& q : stribeck_parameters(n, "_neg")) fit.parameters.push_back(q);
      fit.iterations = p.iterations + n.iterations;
      fit.converged = p.converged && n.converged;
      stribeck_warnings(p, " (positive direction)", fit.warnings);
      stribeck_warnings(n, " (negative direction)", fit.warnings);
      break;
    }
  }
  finish(fit, velocity, force);
  return fit;
}

}  // namespace frictionlab
