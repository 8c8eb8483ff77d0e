#include "frictionlab/identify/uncertainty.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "frictionlab/models/parameter.hpp"

namespace frictionlab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Parameter& find_parameter(Result& r, const std::string& name) {
  for (auto& p : r.parameters)
    if (p.name == name) return p;
  std::string have;
  for (const auto& p : r.parameters) have += (have.empty() ? "" : ", ") + p.name;
  throw std::invalid_argument("uncertainty: no parameter '" + name + "' in the result; parameters: " +
                              (have.empty() ? "(none)" : have));
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return s;
}

void add_unique(std::vector<std::string>& list, const std::string& name) {
  if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
}

}  // namespace

bool is_at_bound(double value, double lower, double upper, double scale) {
  const auto near = [&](double bound) {
    return std::isfinite(bound) && std::abs(value - bound) <= 1e-6 * std::max(std::abs(bound), std::abs(scale));
  };
  return near(lower) || near(upper);
}

namespace {

// The one assessment behind both public forms: with `meat` null the covariance over the
// determined set is s2 (A_SS)^-1; with it, (A_SS)^-1 meat_SS (A_SS)^-1 and std_ols from s2.
// With `iv` (cross = Z'W, instruments = Z'Z) the bread is (Z'W)_SS^-1 instead: the instrumental-
// variable sandwich (Z'W)^-1 meat (W'Z)^-1, and std_ols from s2 (Z'W)^-1 Z'Z (W'Z)^-1.
struct IvBread {
  const Eigen::MatrixXd* cross = nullptr;
  const Eigen::MatrixXd* instruments = nullptr;
};

Eigen::MatrixXd assess(Result& r, const std::vector<std::string>& names, const Eigen::MatrixXd& A, double s2,
                       const Eigen::MatrixXd* meat, const std::vector<ParameterState>& states_in,
                       const UncertaintyOptions& o, const IvBread& iv = {}) {
  const auto p = static_cast<Eigen::Index>(names.size());
  if (meat != nullptr && (meat->rows() != p || meat->cols() != p))
    throw std::invalid_argument("uncertainty: the sandwich's meat is " + std::to_string(meat->rows()) + " x " +
                                std::to_string(meat->cols()) + " for " + std::to_string(p) + " parameters");
  if (A.rows() != p || A.cols() != p)
    throw std::invalid_argument("uncertainty: information matrix is " + std::to_string(A.rows()) + " x " +
                                std::to_string(A.cols()) + " for " + std::to_string(p) + " parameters");
  if (!states_in.empty() && static_cast<Eigen::Index>(states_in.size()) != p)
    throw std::invalid_argument("uncertainty: " + std::to_string(states_in.size()) + " parameter states for " +
                                std::to_string(p) + " parameters");
  std::vector<ParameterState> st = states_in.empty() ? std::vector<ParameterState>(static_cast<std::size_t>(p)) : states_in;
  std::vector<Parameter*> est;
  for (const auto& n : names) est.push_back(&find_parameter(r, n));

  // 1. Columns without information, and the method's own verdicts.
  std::vector<bool> excluded(static_cast<std::size_t>(p), false);
  std::vector<std::string> why(static_cast<std::size_t>(p));
  for (Eigen::Index i = 0; i < p; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (st[u].at_bound || st[u].undetermined) {
      excluded[u] = true;
      why[u] = st[u].reason;
    } else if (!(A(i, i) > 0) || !std::isfinite(A(i, i))) {
      st[u].undetermined = excluded[u] = true;
      why[u] = "the data carry no information on it";
    }
  }
  // 2. Variance inflation over the remaining parameters, on the unit-diagonal scaled matrix.
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < p; ++i)
    if (!excluded[static_cast<std::size_t>(i)]) free.push_back(i);
  const auto nf = static_cast<Eigen::Index>(free.size());
  if (nf > 1) {
    Eigen::MatrixXd C(nf, nf);
    for (Eigen::Index a = 0; a < nf; ++a)
      for (Eigen::Index b = 0; b < nf; ++b)
        // sqrt times sqrt: the product of two diagonal entries beyond 1e154 overflows (a stiffness or
        // a force scale of 1e100 squared), which made every entry 0 and the inflation NaN.
        C(a, b) = A(free[a], free[b]) / (std::sqrt(A(free[a], free[a])) * std::sqrt(A(free[b], free[b])));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
    const Eigen::VectorXd lambda = eig.eigenvalues().cwiseMax(std::numeric_limits<double>::min());
    const Eigen::MatrixXd& V = eig.eigenvectors();
    for (Eigen::Index a = 0; a < nf; ++a) {
      const double vif = (V.row(a).array().square() / lambda.transpose().array()).sum();
      if (!(vif <= o.max_variance_inflation)) {
        const auto u = static_cast<std::size_t>(free[a]);
        st[u].undetermined = excluded[u] = true;
        // A figure only when it is one: an information matrix beyond double precision gives none.
        why[u] = std::isfinite(vif) ? "near-singular information: variance inflation " + detail::format_value(vif, 3) + " > " +
                                          detail::format_value(o.max_variance_inflation, 3) +
                                          "; it cannot be told apart from the other parameters"
                                    : "near-singular information: its variance inflation is beyond double precision; it "
                                      "cannot be told apart from the other parameters";
      }
    }
  }
  // 3. Covariance over the determined set.
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < p; ++i)
    if (!excluded[static_cast<std::size_t>(i)]) keep.push_back(i);
  const auto nk = static_cast<Eigen::Index>(keep.size());
  Eigen::MatrixXd cov = Eigen::MatrixXd::Constant(p, p, kNaN);
  Eigen::VectorXd var_ols = Eigen::VectorXd::Constant(p, kNaN);
  if (nk > 0) {
    Eigen::MatrixXd As(nk, nk);
    Eigen::VectorXd d(nk);
    for (Eigen::Index a = 0; a < nk; ++a) d(a) = 1.0 / std::sqrt(A(keep[a], keep[a]));
    for (Eigen::Index a = 0; a < nk; ++a)
      for (Eigen::Index b = 0; b < nk; ++b) As(a, b) = d(a) * A(keep[a], keep[b]) * d(b);
    // Scaled, so the pseudo-inverse's threshold is relative to unit-diagonal entries.
    const Eigen::MatrixXd inv = As.completeOrthogonalDecomposition().pseudoInverse();
    // (A_SS)^-1 = D inv D, symmetrised.
    Eigen::MatrixXd Ainv(nk, nk);
    for (Eigen::Index a = 0; a < nk; ++a)
      for (Eigen::Index b = 0; b < nk; ++b) Ainv(a, b) = d(a) * 0.5 * (inv(a, b) + inv(b, a)) * d(b);
    for (Eigen::Index a = 0; a < nk; ++a) var_ols(keep[a]) = s2 * Ainv(a, a);
    Eigen::MatrixXd ck = s2 * Ainv;
    if (iv.cross != nullptr) {
      // B = (Z'W)_SS scaled by the instruments' and the regressors' column norms, inverted by a
      // rank-revealing decomposition (a weak instrument leaves it near-singular, not an error).
      Eigen::VectorXd dz(nk);
      for (Eigen::Index a = 0; a < nk; ++a) {
        const double zz = (*iv.instruments)(keep[a], keep[a]);
        dz(a) = zz > 0 ? 1.0 / std::sqrt(zz) : 1.0;
      }
      Eigen::MatrixXd Bs(nk, nk), Ms(nk, nk), Zs(nk, nk);
      for (Eigen::Index a = 0; a < nk; ++a)
        for (Eigen::Index b = 0; b < nk; ++b) {
          Bs(a, b) = dz(a) * (*iv.cross)(keep[a], keep[b]) * d(b);
          Ms(a, b) = (*meat)(keep[a], keep[b]);
          Zs(a, b) = (*iv.instruments)(keep[a], keep[b]);
        }
      // (Z'W)^-1 = D_w Bs^-1 D_z.
      const Eigen::MatrixXd Binv = d.asDiagonal() * Bs.completeOrthogonalDecomposition().pseudoInverse() * dz.asDiagonal();
      Eigen::MatrixXd ols = s2 * Binv * Zs * Binv.transpose();
      for (Eigen::Index a = 0; a < nk; ++a) var_ols(keep[a]) = ols(a, a);
      ck = Binv * Ms * Binv.transpose();
      ck = 0.5 * (ck + ck.transpose()).eval();
    } else if (meat != nullptr) {
      Eigen::MatrixXd Bs(nk, nk);
      for (Eigen::Index a = 0; a < nk; ++a)
        for (Eigen::Index b = 0; b < nk; ++b) Bs(a, b) = (*meat)(keep[a], keep[b]);
      ck = Ainv * Bs * Ainv;
      ck = 0.5 * (ck + ck.transpose()).eval();
    }
    for (Eigen::Index a = 0; a < nk; ++a)
      for (Eigen::Index b = 0; b < nk; ++b) cov(keep[a], keep[b]) = ck(a, b);
  }
  // 4. Results: std, flags, warnings, lists, correlation.
  auto& diag = r.diagnostics;
  diag.correlation.names = names;
  diag.correlation.matrix.assign(static_cast<std::size_t>(p), std::vector<double>(static_cast<std::size_t>(p), kNaN));
  for (Eigen::Index i = 0; i < p; ++i) {
    const auto u = static_cast<std::size_t>(i);
    Parameter& e = *est[u];
    diag.correlation.matrix[u][u] = 1.0;
    if (meat != nullptr) e.std_ols = excluded[u] ? kNaN : std::sqrt(std::max(0.0, var_ols(i)));
    else e.std_ols.reset();
    if (excluded[u]) {
      e.std = kNaN;
      e.flag = st[u].at_bound ? "at bound" : "undetermined";
      add_unique(st[u].at_bound ? diag.at_bound : diag.undetermined, e.name);
      std::string w = e.name + " = " + detail::format_value(e.value, 6) + (e.unit.empty() ? "" : " " + e.unit) +
                      (st[u].at_bound ? " ended at a bound of the fit" : " is not determined by the data");
      if (!why[u].empty()) w += " (" + why[u] + ")";
      w += "; its std is not given";
      diag.warnings.push_back(w);
      continue;
    }
    e.std = std::sqrt(std::max(0.0, cov(i, i)));
    e.flag.clear();
    for (Eigen::Index j = i + 1; j < p; ++j) {  // upper triangle, mirrored: exactly symmetric
      if (excluded[static_cast<std::size_t>(j)]) continue;
      const double c = cov(i, j) / (std::sqrt(cov(i, i)) * std::sqrt(cov(j, j)));  // no overflow of the product
      diag.correlation.matrix[u][static_cast<std::size_t>(j)] = diag.correlation.matrix[static_cast<std::size_t>(j)][u] =
          std::isfinite(c) ? std::clamp(c, -1.0, 1.0) : kNaN;
    }
  }
  std::vector<std::string> correlated;
  for (Eigen::Index i = 0; i < p; ++i)
    if (excluded[static_cast<std::size_t>(i)] && !st[static_cast<std::size_t>(i)].at_bound &&
        why[static_cast<std::size_t>(i)].rfind("near-singular", 0) == 0)
      correlated.push_back(names[static_cast<std::size_t>(i)]);
  if (!correlated.empty() && nk > 0)
    diag.warnings.push_back("the std of the other parameters assumes " + joined(correlated) +
                            " known; they are larger in truth");
  return cov;
}

}  // namespace

Eigen::MatrixXd set_uncertainty_from_information(Result& r, const std::vector<std::string>& names,
                                                 const Eigen::MatrixXd& information, double residual_variance,
                                                 const std::vector<ParameterState>& states,
                                                 const UncertaintyOptions& options) {
  return assess(r, names, information, residual_variance, nullptr, states, options);
}

Eigen::MatrixXd set_uncertainty_from_sandwich(Result& r, const std::vector<std::string>& names,
                                              const Eigen::MatrixXd& information, const Eigen::MatrixXd& meat,
                                              double residual_variance, const std::vector<ParameterState>& states,
                                              const UncertaintyOptions& options) {
  return assess(r, names, information, residual_variance, &meat, states, options);
}

Eigen::MatrixXd set_uncertainty_from_iv(Result& r, const std::vector<std::string>& names,
                                        const Eigen::MatrixXd& information, const Eigen::MatrixXd& cross,
                                        const Eigen::MatrixXd& instruments, const Eigen::MatrixXd& meat,
                                        double residual_variance, const std::vector<ParameterState>& states,
                                        const UncertaintyOptions& options) {
  const auto p = static_cast<Eigen::Index>(names.size());
  if (cross.rows() != p || cross.cols() != p || instruments.rows() != p || instruments.cols() != p)
    throw std::invalid_argument("uncertainty: the instruments' matrices are " + std::to_string(cross.rows()) + " x " +
                                std::to_string(cross.cols()) + " and " + std::to_string(instruments.rows()) + " x " +
                                std::to_string(instruments.cols()) + " for " + std::to_string(p) + " parameters");
  return assess(r, names, information, residual_variance, &meat, states, options, IvBread{&cross, &instruments});
}

Eigen::MatrixXd set_uncertainty_from_covariance(Result& r, const std::vector<std::string>& names,
                                                const Eigen::MatrixXd& covariance,
                                                const std::vector<ParameterState>& states,
                                                const UncertaintyOptions& options) {
  const auto p = static_cast<Eigen::Index>(names.size());
  if (covariance.rows() != p || covariance.cols() != p)
    throw std::invalid_argument("uncertainty: covariance matrix is " + std::to_string(covariance.rows()) + " x " +
                                std::to_string(covariance.cols()) + " for " + std::to_string(p) + " parameters");
  std::vector<ParameterState> st = states.empty() ? std::vector<ParameterState>(static_cast<std::size_t>(p)) : states;
  if (static_cast<Eigen::Index>(st.size()) != p)
    throw std::invalid_argument("uncertainty: " + std::to_string(st.size()) + " parameter states for " + std::to_string(p) +
                                " parameters");
  // Parameters with a zero or unknown variance leave the inversion (their information is
  // infinite or unknown, not a figure to report).
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < p; ++i) {
    auto& s = st[static_cast<std::size_t>(i)];
    if (!(covariance(i, i) > 0) || !std::isfinite(covariance(i, i))) {
      if (!s.at_bound && !s.undetermined) {
        s.undetermined = true;
        s.reason = std::isfinite(covariance(i, i)) ? "its variance is " + detail::format_value(covariance(i, i), 3)
                                                   : std::string("its variance is not a finite number");
      }
    }
    if (!s.at_bound && !s.undetermined) keep.push_back(i);
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
  const auto nk = static_cast<Eigen::Index>(keep.size());
  if (nk > 0) {
    Eigen::MatrixXd Ck(nk, nk);
    Eigen::VectorXd d(nk);
    for (Eigen::Index a = 0; a < nk; ++a) d(a) = std::sqrt(covariance(keep[a], keep[a]));
    for (Eigen::Index a = 0; a < nk; ++a)
      for (Eigen::Index b = 0; b < nk; ++b) Ck(a, b) = covariance(keep[a], keep[b]) / (d(a) * d(b));
    const Eigen::MatrixXd inv = Ck.completeOrthogonalDecomposition().pseudoInverse();
    for (Eigen::Index a = 0; a < nk; ++a)
      for (Eigen::Index b = 0; b < nk; ++b) A(keep[a], keep[b]) = inv(a, b) / (d(a) * d(b));
  }
  return set_uncertainty_from_information(r, names, A, 1.0, st, options);
}

}  // namespace frictionlab
