#include "frictionlab/identify/static_fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "identify/ceres_cancel.hpp"
#include "identify/ceres_quiet.hpp"
#include "frictionlab/identify/least_squares.hpp"
#include "frictionlab/identify/uncertainty.hpp"

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
// log of kNegligibleDecayExponent, rounded up so that the test on the exponent's log keeps every
// point the test u > kNegligibleDecayExponent keeps.
const double kLogNegligibleDecayExponent = std::log(kNegligibleDecayExponent) * (1 + 1e-12);

// The points of one Stribeck fit, folded to positive velocity: a = |v|, g = F sign(v), and
// log a once per fit rather than once per point and evaluation. Folding flips the sign of a
// point's residual and Jacobian row together, which leaves r'r, J'J and J'r (all the solver
// uses) unchanged.
struct FoldedPoints {
  Eigen::ArrayXd a, log_a, g;  // log_a serves the start as work space first
  FoldedPoints(const Eigen::VectorXd& v, const Eigen::VectorXd& f)
      : a(v.array().abs()), log_a(v.size()), g(f.array() * v.array().sign()) {}
};

// One pass over points [b, e) at parameters p: the 6x6 Gram matrix G = [J r]'[J r] of the
// residuals r_i = Fc + dF exp(-(a_i/vs)^delta) + Fv a_i - g_i and their analytic Jacobian, or,
// without G, only the sum of squares r'r. Hand-written because Ceres has no reduction of many
// residuals to their normal equations; the work per point is vectorised with Eigen arrays
// (exp included) over blocks of kBlock points.
double stribeck_pass(const double* p, const FoldedPoints& d, Eigen::Index b, Eigen::Index e,
                     Eigen::Matrix<double, 6, 6>* G) {
  constexpr Eigen::Index kBlock = 256;
  using BlockArray = Eigen::Array<double, Eigen::Dynamic, 1, 0, kBlock, 1>;  // no heap
  const double Fc = p[kFc], dF = p[kDF], vs = p[kVs], delta = p[kDelta], Fv = p[kFv];
  const double log_vs = std::log(vs);
  Eigen::Matrix<double, kBlock, 6> J;  // columns: d r / d(Fc, dF, vs, delta, Fv), then r
  double ssr = 0;
  if (G) G->setZero();
  for (Eigen::Index s = b; s < e; s += kBlock) {
    const Eigen::Index m = std::min(kBlock, e - s);
    const BlockArray lx = d.log_a.segment(s, m) - log_vs;
    // u = (a/vs)^delta and the decay exp(-u). Far past vs (u > kNegligibleDecayExponent) the
    // decay and its derivatives are below rounding (see stribeck_decay), so both exps are taken
    // only of the points before the cut-off, gathered without branches, in vectorised form.
    BlockArray u = BlockArray::Zero(m), ex = BlockArray::Zero(m);
    Eigen::Array<Eigen::Index, kBlock, 1> near;
    BlockArray t(m);
    Eigen::Index k = 0;
    for (Eigen::Index i = 0; i < m; ++i) {
      t[k] = delta * lx[i];
      near[k] = i;
      k += t[k] <= kLogNegligibleDecayExponent ? 1 : 0;
    }
    const BlockArray uk = t.head(k).exp();
    const BlockArray ek = (-uk).exp();
    for (Eigen::Index j = 0; j < k; ++j) {
      u[near[j]] = uk[j];
      ex[near[j]] = uk[j] > kNegligibleDecayExponent ? 0.0 : ek[j];  // Eigen's exp clamps, never 0
    }
    const BlockArray r = Fc + dF * ex + Fv * d.a.segment(s, m) - d.g.segment(s, m);
    if (!G) {
      ssr += r.square().sum();
      continue;
    }
    auto Jm = J.topRows(m);
    Jm.col(kFc).setOnes();
    Jm.col(kDF) = ex.matrix();
    Jm.col(kVs) = ((dF * delta / vs) * ex * u).matrix();
    Jm.col(kDelta) = (-dF * ex * u * lx).matrix();
    Jm.col(kFv) = d.a.segment(s, m).matrix();
    Jm.col(kNp) = r.matrix();
    // The 21 distinct entries as column dot products: for 6 columns these beat Eigen's
    // rank-update kernel, whose packing dominates at this size.
    for (int j = 0; j <= kNp; ++j)
      for (int i = j; i <= kNp; ++i) (*G)(i, j) += Jm.col(i).dot(Jm.col(j));
  }
  if (G) {
    *G = G->template selfadjointView<Eigen::Lower>();
    ssr = (*G)(kNp, kNp);
  }
  return ssr;
}

// A chunk of points reduced to 6 residuals for Ceres: with any R such that R'R = G = [J r]'[J r],
// the residuals R.col(5) with Jacobian R.leftCols(5) have the chunk's r'r, J'J and J'r exactly,
// so Ceres's Levenberg-Marquardt steps, cost decrease, scaling and convergence tests are those of
// the 1e5-residual problem while it stores and multiplies a 6x5 Jacobian per chunk.
class StribeckGramChunk final : public ceres::SizedCostFunction<kNp + 1, kNp> {
 public:
  using Vec6 = Eigen::Matrix<double, kNp + 1, 1>;
  using Mat6 = Eigen::Matrix<double, kNp + 1, kNp + 1>;
  StribeckGramChunk(const FoldedPoints& d, Eigen::Index b, Eigen::Index e) : d_(d), b_(b), e_(e) {}
  // Ceres evaluates each parameter vector up to three times (the projected line search that
  // bounds switch on, the trial cost, the accepted step); the last pass is kept and reused
  // when the parameters are bitwise the same. Safe: Ceres never evaluates one residual block
  // on two threads at once.
  bool Evaluate(double const* const* params, double* r, double** jac) const override {
    const double* p = params[0];
    const bool want_jacobian = jac != nullptr && jac[0] != nullptr;
    const bool hit = cached_ && std::equal(p, p + kNp, cached_p_) && (cached_has_G_ || !want_jacobian);
    if (!hit) {
      std::copy(p, p + kNp, cached_p_);
      cached_ = true;
      cached_has_G_ = want_jacobian;
      cached_ssr_ = stribeck_pass(p, d_, b_, e_, want_jacobian ? &cached_G_ : nullptr);
      if (want_jacobian) square_root(cached_G_, cached_R_);
    }
    if (!std::isfinite(cached_ssr_) || (want_jacobian && !cached_R_.allFinite())) return false;
    Eigen::Map<Vec6> res(r);
    if (!want_jacobian) {  // cost only (a trial step): any vector of norm sqrt(r'r)
      res.setZero();
      res[0] = std::sqrt(cached_ssr_);
      return true;
    }
    res = cached_R_.col(kNp);
    Eigen::Map<Eigen::Matrix<double, kNp + 1, kNp, Eigen::RowMajor>> jacobian(jac[0]);
    jacobian = cached_R_.leftCols(kNp);
    return true;
  }

  /// The Gram matrix of the last pass if it was at `p` with the Jacobian, else nullptr.
  const Mat6* gram_at(const double* p) const {
    return cached_ && cached_has_G_ && std::equal(p, p + kNp, cached_p_) ? &cached_G_ : nullptr;
  }

 private:
  // R with R'R = G: R = sqrt(D) L' P S from the pivoted LDLT of the diagonally scaled G, stable
  // also when G is singular (a chunk with every point far past vs, or dF = 0, has zero decay
  // columns).
  static void square_root(const Mat6& G, Mat6& R) {
    Vec6 scale = G.diagonal().cwiseSqrt();
    for (auto& x : scale) x = x > 0 ? x : 1.0;
    const Mat6 Gs = scale.cwiseInverse().asDiagonal() * G * scale.cwiseInverse().asDiagonal();
    const Eigen::LDLT<Mat6> ldlt(Gs);
    const Mat6 P = ldlt.transpositionsP() * Mat6::Identity();  // Gs = P' L D L' P
    R = ldlt.vectorD().cwiseMax(0.0).cwiseSqrt().asDiagonal() * Mat6(ldlt.matrixU()) * P * scale.asDiagonal();
  }

  const FoldedPoints& d_;
  Eigen::Index b_, e_;
  mutable bool cached_ = false, cached_has_G_ = false;
  mutable double cached_p_[kNp] = {};
  mutable double cached_ssr_ = 0;
  mutable Mat6 cached_G_, cached_R_;
};

struct OneSided {
  double p[kNp];
  Eigen::Matrix<double, kNp, kNp> cov;  // covariance of p
  double ssr = 0;        // 2 x Ceres's final cost
  double point_ssr = 0;  // sum of squared residuals over the points at p, from G
  Eigen::Matrix<double, kNp + 1, kNp + 1> G = Eigen::Matrix<double, kNp + 1, kNp + 1>::Zero();  // [J r]'[J r] at p
  int iterations = 0;
  bool converged = false;
  double s2 = 0;           // residual variance
  double vmax = 0;         // fastest |v|, m/s or rad/s (sets vs's bounds)
  double slowest = 0;      // slowest |v|
  double force_scale = 0;  // max |F|, sets the tolerance of the bounds at 0
  int below_vs = 0;        // points slower than the fitted vs
};

// Linear least squares F = Fc sign(v) + Fv v: exact, no start needed. Every point counts (two
// points on a side make an exact fit, its covariance then zero) and nothing is refused: the
// velocity column is never zero, and a map at one speed (collinear columns) gives the
// minimum-norm estimate with a covariance that is not finite, which the caller reports as such.
void linear_coulomb_viscous(const Eigen::VectorXd& v, const Eigen::VectorXd& f, double& Fc, double& Fv,
                            Eigen::Matrix2d* cov = nullptr, double* ssr = nullptr) {
  Eigen::MatrixXd X(v.size(), 2);
  for (Eigen::Index i = 0; i < v.size(); ++i) X.row(i) << (v[i] > 0 ? 1.0 : -1.0), v[i];
  LeastSquaresOptions lso;
  lso.max_condition = std::numeric_limits<double>::infinity();
  lso.min_redundancy = 0;
  const LeastSquaresFit fit = linear_least_squares(X, f, {"Fc", "Fv"}, lso);
  if (!fit.ok) throw std::logic_error("friction fit: " + fit.message);  // excluded by check_input
  Fc = fit.theta[0];
  Fv = fit.theta[1];
  if (ssr) *ssr = fit.residual.squaredNorm();
  if (cov) *cov = fit.covariance;
}

// Starting values from the folded points (a = |v| > 0, g = F sign(v)). The rules need only
// order statistics (the faster half, the slowest tenth, the slowest point below a level), so two
// nth_element calls on a copy of the speeds replace a full sort of 1e5 points; ties at a
// boundary speed are taken in index order (a sort would take them in an arbitrary one).
// `scratch` (n doubles) is overwritten.
void initial_guess(const Eigen::Ref<const Eigen::ArrayXd>& a, const Eigen::Ref<const Eigen::ArrayXd>& g,
                   double fixed_delta, double* p, Eigen::Ref<Eigen::ArrayXd> scratch) {
  const Eigen::Index n = a.size();
  const Eigen::Index h = n / 2, m = std::max<Eigen::Index>(1, n / 10);
  scratch = a;
  double* sorted = scratch.data();
  std::nth_element(sorted, sorted + h, sorted + n);
  const double a_median = sorted[h];  // the slowest of the faster half
  std::nth_element(sorted, sorted + (m - 1), sorted + std::max(h, m));
  const double a_tenth = sorted[m - 1];  // the fastest of the slowest tenth
  // Membership weights (1 or 0) of the faster half (n - h points from a_median up) and of the
  // slowest tenth (m points up to a_tenth), ties at the edge taken in index order; the sums
  // below are then vectorised Eigen reductions instead of branches on random data.
  Eigen::Ref<Eigen::ArrayXd>& w = scratch;
  const auto weigh = [&](bool upper, double edge, Eigen::Index count) {
    if (upper) w = (a > edge).cast<double>();
    else w = (a < edge).cast<double>();
    Eigen::Index ties = count - static_cast<Eigen::Index>(w.sum());
    for (Eigen::Index i = 0; i < n && ties > 0; ++i)
      if (a[i] == edge) {
        w[i] = 1.0;
        --ties;
      }
  };
  // High-speed half: Coulomb + viscous by linear least squares, the line g = Fc + Fv a in
  // centred form.
  weigh(true, a_median, n - h);
  const double nf = static_cast<double>(n - h);
  const double am = (w * a).sum() / nf, gm = (w * g).sum() / nf;
  const double saa = (w * (a - am).square()).sum(), sag = (w * (a - am) * (g - gm)).sum();
  double Fc = gm, Fv = 0;
  if (n - h >= 2 && a.maxCoeff() > a_median) {  // the faster half is not a single speed
    Fv = sag / saa;
    Fc = gm - Fv * am;
  }
  Fv = std::max(Fv, 0.0);
  Fc = std::max(Fc, 0.0);
  // Slowest tenth: the static level.
  weigh(false, a_tenth, m);
  const double Fs = (w * (g - Fv * a)).sum() / static_cast<double>(m);
  const double dF = std::max(Fs - Fc, 1e-3 * std::max(Fc, 1e-12));
  // vs: first speed where the excess over Fc + Fv v falls below dF / e (the median speed if none).
  const double inf = std::numeric_limits<double>::infinity();
  double vs = (g - Fc - Fv * a < dF / std::exp(1.0)).select(a, inf).minCoeff();
  vs = std::isfinite(vs) ? std::max(vs, 1e-12) : a_median;
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
  FoldedPoints d(v, f);
  initial_guess(d.a, d.g, o.fixed_delta, start, d.log_a);
  d.log_a = d.a.log();
  // Two exponent starts guard against the wrong minimum a single start can land in.
  std::vector<double> delta_starts = o.fixed_delta > 0 ? std::vector<double>{o.fixed_delta} : std::vector<double>{2.0, 1.0};
  const Eigen::Index n = v.size();
  // A few chunks per thread: Ceres evaluates residual blocks in parallel.
  const Eigen::Index chunks = std::max<Eigen::Index>(1, std::min<Eigen::Index>(n / 2000, 4 * std::max(1, o.num_threads)));
  const double vmax = d.a.maxCoeff();
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
    std::vector<StribeckGramChunk*> parts;  // owned by the problem
    for (Eigen::Index c = 0; c < chunks; ++c) {
      parts.push_back(new StribeckGramChunk(d, n * c / chunks, n * (c + 1) / chunks));
      problem.AddResidualBlock(parts.back(), nullptr, cur.p);
    }
    problem.SetParameterLowerBound(cur.p, kFc, 0.0);
    problem.SetParameterLowerBound(cur.p, kDF, 0.0);
    problem.SetParameterLowerBound(cur.p, kVs, 1e-6 * vmax);
    problem.SetParameterUpperBound(cur.p, kVs, 10 * vmax);
    problem.SetParameterLowerBound(cur.p, kFv, 0.0);
    if (o.fixed_delta > 0) {
      problem.SetManifold(cur.p, new ceres::SubsetManifold(kNp, {kDelta}));
    } else {
      problem.SetParameterLowerBound(cur.p, kDelta, o.delta_min);
      problem.SetParameterUpperBound(cur.p, kDelta, o.delta_max);
    }
    detail::quiet_ceres_logging();
    ceres::Solver::Options sopts;
    sopts.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
    sopts.max_num_iterations = o.max_iterations;
    sopts.num_threads = std::max(1, o.num_threads);
    sopts.function_tolerance = 1e-12;
    sopts.gradient_tolerance = 1e-14;
    sopts.parameter_tolerance = 1e-12;
    sopts.logging_type = ceres::SILENT;
    detail::CancelCallback cancel;
    sopts.callbacks.push_back(&cancel);
    ceres::Solver::Summary summary;
    ceres::Solve(sopts, &problem, &summary);
    throw_if_cancelled();
    cur.ssr = 2 * summary.final_cost;
    cur.iterations = static_cast<int>(summary.iterations.size());
    cur.converged = summary.termination_type == ceres::CONVERGENCE;
    if (!(cur.ssr < best.ssr)) continue;
    // G at the solution: Ceres's last evaluation is usually there (the accepted final step), so
    // the chunks still hold it; otherwise one more pass.
    cur.G.setZero();
    for (const auto* part : parts) {
      if (const auto* g = part->gram_at(cur.p)) {
        cur.G += *g;
      } else {
        stribeck_pass(cur.p, d, 0, n, &cur.G);
        break;
      }
    }
    best = cur;
  }
  // Covariance s^2 (J'J)^-1 at the solution; a held exponent has zero variance. J'J is the
  // Jacobian's Gram matrix over all points, accumulated without storing J.
  best.point_ssr = best.G(kNp, kNp);
  const Eigen::Matrix<double, kNp, kNp> JtJ = best.G.topLeftCorner<kNp, kNp>();
  std::vector<int> free_idx;
  for (int k = 0; k < kNp; ++k)
    if (!(k == kDelta && o.fixed_delta > 0)) free_idx.push_back(k);
  const int nf = static_cast<int>(free_idx.size());
  Eigen::MatrixXd A(nf, nf);
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b) A(a, b) = JtJ(free_idx[a], free_idx[b]);
  const double s2 = best.ssr / std::max<double>(1, static_cast<double>(n - nf));
  const Eigen::MatrixXd Ainv = A.completeOrthogonalDecomposition().pseudoInverse();
  best.cov.setZero();
  for (int a = 0; a < nf; ++a)
    for (int b = 0; b < nf; ++b) best.cov(free_idx[a], free_idx[b]) = s2 * Ainv(a, b);
  best.s2 = s2;
  best.vmax = vmax;
  best.slowest = d.a.minCoeff();
  best.force_scale = d.g.abs().maxCoeff();
  best.below_vs = static_cast<int>((d.a < best.p[kVs]).count());
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

// Fit figures from the law's residuals, or from `known_ssr` (the sum of squared residuals at
// the solution, when the fit already has it) to save a pass over the points.
void finish(StaticFit& fit, const Eigen::VectorXd& v, const Eigen::VectorXd& f, double known_ssr = -1) {
  double ssr = known_ssr;
  if (ssr < 0) {
    ssr = 0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const double r = fit.law.sliding(v[i]) - f[i];
      ssr += r * r;
    }
  }
  fit.samples = static_cast<std::size_t>(v.size());
  fit.rmse = std::sqrt(ssr / static_cast<double>(v.size()));
  fit.relative_error_percent = 100.0 * std::sqrt(ssr) / f.norm();
}

// Stribeck parameters of one side in the law's order (Fc, Fs, vs, delta, Fv) with std.
std::vector<Parameter> stribeck_parameters(const OneSided& s, const std::string& suffix) {
  auto sd = [&](int k) { return std::sqrt(std::max(0.0, s.cov(k, k))); };
  const double var_fs = s.cov(kFc, kFc) + s.cov(kDF, kDF) + 2 * s.cov(kFc, kDF);
  return {{"Fc" + suffix, s.p[kFc], sd(kFc), Quantity::force, ""},
          {"Fs" + suffix, s.p[kFc] + s.p[kDF], std::sqrt(std::max(0.0, var_fs)), Quantity::force, ""},
          {"vs" + suffix, s.p[kVs], sd(kVs), Quantity::velocity, ""},
          {"delta" + suffix, s.p[kDelta], sd(kDelta), Quantity::dimensionless, ""},
          {"Fv" + suffix, s.p[kFv], sd(kFv), Quantity::viscous, ""}};
}

// Information (J'J / s^2) of one side's reported parameters (Fc, Fs, vs, delta, Fv; delta left
// out when held), their names and states (bounds; the Stribeck part undetermined without slow
// enough points), appended to the whole fit's.
struct Information {
  std::vector<std::string> names;
  std::vector<ParameterState> states;
  Eigen::MatrixXd A = Eigen::MatrixXd(0, 0);
};

void add_side_information(const OneSided& s, const std::string& suffix, const StaticFitOptions& o, Information& info) {
  // Reported = T internal with Fs = Fc + dF; J_reported = J_internal T^-1.
  Eigen::Matrix<double, kNp, kNp> Tinv = Eigen::Matrix<double, kNp, kNp>::Identity();
  Tinv(kDF, kFc) = -1.0;
  const Eigen::Matrix<double, kNp, kNp> JtJ = s.G.topLeftCorner<kNp, kNp>();
  const double s2 = s.s2 > 0 ? s.s2 : std::numeric_limits<double>::min();
  const Eigen::Matrix<double, kNp, kNp> A = Tinv.transpose() * JtJ * Tinv / s2;
  const bool held = o.fixed_delta > 0;
  const double inf = std::numeric_limits<double>::infinity();
  const double fscale = std::max(s.force_scale, std::numeric_limits<double>::min());
  std::vector<int> idx;
  for (int k = 0; k < kNp; ++k) {
    if (k == kDelta && held) continue;
    idx.push_back(k);
    ParameterState st;
    switch (k) {
      case kFc: st.at_bound = is_at_bound(s.p[kFc], 0.0, inf, fscale); break;
      case kDF:
        st.at_bound = is_at_bound(s.p[kDF], 0.0, inf, fscale);
        if (st.at_bound) st.reason = "Fs = Fc: the points show no Stribeck peak";
        break;
      case kVs: st.at_bound = is_at_bound(s.p[kVs], 1e-6 * s.vmax, 10 * s.vmax, s.vmax); break;
      case kDelta: st.at_bound = is_at_bound(s.p[kDelta], o.delta_min, o.delta_max, 1.0); break;
      case kFv: st.at_bound = is_at_bound(s.p[kFv], 0.0, inf, fscale / std::max(s.vmax, 1e-300)); break;
    }
    // The Stribeck curve is the slow points' business: without them vs and delta are guesses.
    if ((k == kVs || k == kDelta) && !st.at_bound &&
        (s.slowest > 2 * s.p[kVs] || s.below_vs < o.min_points_below_vs)) {
      st.undetermined = true;
      st.reason = "the slowest point is at " + detail::format_value(s.slowest, 3) + ", " +
                  std::to_string(s.below_vs) + " point(s) lie below vs; the Stribeck part needs points below vs";
    }
    info.states.push_back(st);
  }
  static const char* kNames[kNp] = {"Fc", "Fs", "vs", "delta", "Fv"};
  const auto base = info.A.rows();
  const auto m = static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixXd grown = Eigen::MatrixXd::Zero(base + m, base + m);
  grown.topLeftCorner(base, base) = info.A;
  for (Eigen::Index a = 0; a < m; ++a) {
    info.names.push_back(kNames[idx[static_cast<std::size_t>(a)]] + suffix);
    for (Eigen::Index b = 0; b < m; ++b) grown(base + a, base + b) = A(idx[static_cast<std::size_t>(a)], idx[static_cast<std::size_t>(b)]);
  }
  info.A = grown;
}

// Applies the honest-uncertainty rules to the fit's parameters (identify/uncertainty.hpp).
void apply_uncertainty(StaticFit& fit, const Information& info, Axis axis = Axis::linear) {
  Result r;
  for (const auto& q : fit.parameters) r.parameters.push_back({q.name, q.value, q.std, std::string(unit(q.quantity, axis)), ""});
  set_uncertainty_from_information(r, info.names, info.A, 1.0, info.states);
  for (std::size_t i = 0; i < fit.parameters.size(); ++i) {
    fit.parameters[i].std = r.parameters[i].std;
    fit.parameters[i].flag = r.parameters[i].flag;
  }
  for (auto& w : r.diagnostics.warnings) fit.warnings.push_back(std::move(w));
  fit.undetermined = r.diagnostics.undetermined;
  fit.at_bound = r.diagnostics.at_bound;
  fit.correlation = r.diagnostics.correlation;
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
  double known_ssr = -1;  // set by fits that end with the residuals' sum of squares
  switch (o.model) {
    case StaticFitModel::coulomb_viscous: {
      check_input(velocity, force, 3);
      double Fc, Fv, ssr;
      Eigen::Matrix2d cov;
      linear_coulomb_viscous(velocity, force, Fc, Fv, &cov, &ssr);
      fit.law = CoulombViscous{std::max(Fc, 0.0), std::max(Fv, 0.0)};
      fit.parameters = {{"Fc", Fc, std::sqrt(cov(0, 0)), Quantity::force, ""}, {"Fv", Fv, std::sqrt(cov(1, 1)), Quantity::viscous, ""}};
      fit.iterations = 1;
      fit.converged = true;
      if (cov.allFinite() && cov.determinant() > 0) {
        Information info{{"Fc", "Fv"}, {}, cov.inverse()};
        apply_uncertainty(fit, info);
      }
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
      fit.parameters = {{"Fc_pos", law.pos.Fc, std::sqrt(cp(0, 0)), Quantity::force, ""},
                        {"Fv_pos", law.pos.Fv, std::sqrt(cp(1, 1)), Quantity::viscous, ""},
                        {"Fc_neg", law.neg.Fc, std::sqrt(cn(0, 0)), Quantity::force, ""},
                        {"Fv_neg", law.neg.Fv, std::sqrt(cn(1, 1)), Quantity::viscous, ""}};
      if (cp.allFinite() && cn.allFinite() && cp.determinant() > 0 && cn.determinant() > 0) {
        Information info{{"Fc_pos", "Fv_pos", "Fc_neg", "Fv_neg"}, {}, Eigen::MatrixXd::Zero(4, 4)};
        info.A.topLeftCorner(2, 2) = cp.inverse();
        info.A.bottomRightCorner(2, 2) = cn.inverse();
        apply_uncertainty(fit, info);
      }
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
      Information info;
      add_side_information(s, "", o, info);
      apply_uncertainty(fit, info);
      known_ssr = s.point_ssr;
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
      Information info;
      add_side_information(p, "_pos", o, info);
      add_side_information(n, "_neg", o, info);
      apply_uncertainty(fit, info);
      known_ssr = p.point_ssr + n.point_ssr;
      break;
    }
  }
  finish(fit, velocity, force, known_ssr);
  return fit;
}

}  // namespace frictionlab
