#include "frictionlab/identify/selection.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "frictionlab/error.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/io/json_text.hpp"

namespace frictionlab {

std::vector<SampleBlock> contiguous_blocks(Eigen::Index samples, int folds) {
  if (folds < 2) throw std::invalid_argument("contiguous_blocks: folds = " + std::to_string(folds) + " must be >= 2");
  if (samples < 2 * static_cast<Eigen::Index>(folds))
    throw std::invalid_argument("contiguous_blocks: " + std::to_string(samples) + " samples are too few for " +
                                std::to_string(folds) + " blocks of at least 2 samples");
  std::vector<SampleBlock> blocks;
  for (int k = 0; k < folds; ++k)
    blocks.emplace_back(samples * k / folds, samples * (k + 1) / folds);
  return blocks;
}

double HeldOutErrors::relative_error_percent() const {
  if (error_squares.empty()) return std::numeric_limits<double>::quiet_NaN();
  double e = 0, s = 0;
  for (std::size_t k = 0; k < error_squares.size(); ++k) {
    if (!std::isfinite(error_squares[k])) return std::numeric_limits<double>::quiet_NaN();
    e += error_squares[k];
    s += signal_squares[k];
  }
  return 100.0 * std::sqrt(e / s);
}

std::vector<double> HeldOutErrors::block_errors_percent() const {
  std::vector<double> out;
  for (std::size_t k = 0; k < error_squares.size(); ++k) out.push_back(100.0 * std::sqrt(error_squares[k] / signal_squares[k]));
  return out;
}

HeldOutErrors linear_heldout_errors(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                                    const std::vector<SampleBlock>& blocks) {
  const Eigen::Index n = X.rows(), p = X.cols();
  if (y.size() != n)
    throw std::invalid_argument("linear_heldout_errors: X has " + std::to_string(n) + " rows, y " +
                                std::to_string(y.size()));
  HeldOutErrors out;
  for (const auto& [b, e] : blocks) {
    if (b < 0 || e > n || b >= e)
      throw std::invalid_argument("linear_heldout_errors: block [" + std::to_string(b) + ", " + std::to_string(e) +
                                  ") is not within [0, " + std::to_string(n) + ")");
    const Eigen::Index m = e - b, train = n - m;
    const Eigen::VectorXd yk = y.segment(b, m);
    out.signal_squares.push_back(yk.squaredNorm());
    out.samples += static_cast<std::size_t>(m);
    if (train < p) {
      out.error_squares.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    Eigen::MatrixXd Xt(train, p);
    Eigen::VectorXd yt(train);
    Xt << X.topRows(b), X.bottomRows(n - e);
    yt << y.head(b), y.tail(n - e);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Xt);
    if (qr.rank() < p) {
      out.error_squares.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const Eigen::VectorXd theta = qr.solve(yt);
    out.error_squares.push_back((yk - X.middleRows(b, m) * theta).squaredNorm());
  }
  return out;
}

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The parameter's name without a direction suffix (_pos, _neg).
std::string base_name(const std::string& n) {
  for (const char* tail : {"_pos", "_neg"})
    if (ends_with(n, tail)) return n.substr(0, n.size() - 4);
  return n;
}

std::string said(const Parameter& p) { return p.name + " = " + format_number(p.value, 4) + (p.unit.empty() ? "" : " " + p.unit); }

}  // namespace

std::string physical_refusal(const Result& r) {
  // A candidate refused because a figure of it is not finite, in words: its message names the
  // figure as "std(M) = inf", which would put an inf into the chosen result's texts.
  if (!r.ok() && r.code == errc::output_not_finite)
    return "the fit failed: a figure of it is beyond what double precision holds";
  if (!r.ok()) return "the fit failed: " + r.message;
  for (const auto& p : r.parameters) {
    if (!std::isfinite(p.value)) return p.name + " is not finite";
    const std::string b = base_name(p.name);
    if ((b == "Fc" || b == "Fs" || b == "Fv" || b == "M" || b == "sigma0" || b == "sigma1" || b == "sigma2") &&
        p.value < 0)
      return said(p) + " < 0: a friction level, damping or mass cannot be negative";
    if (b == "vs" && p.value <= 0) return said(p) + " <= 0: the Stribeck velocity must be positive";
    if (b == "Fs_minus_Fc" && p.value < 0)
      return said(p) + " < 0: the static level would be below the Coulomb level";
  }
  for (const char* tail : {"", "_pos", "_neg"}) {
    const Parameter *fs = r.find(std::string("Fs") + tail), *fc = r.find(std::string("Fc") + tail);
    if (fs && fc && fs->value < fc->value)
      return said(*fs) + " < " + said(*fc) + ": the static level would be below the Coulomb level";
  }
  return "";
}

double heldout_standard_error(const SelectionCandidate& c) {
  const auto& e = c.block_errors_percent;
  if (e.size() < 2) return 0.0;
  double mean = 0;
  for (double x : e) mean += x;
  mean /= static_cast<double>(e.size());
  double ss = 0;
  for (double x : e) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / static_cast<double>(e.size() - 1)) / std::sqrt(static_cast<double>(e.size()));
}

std::optional<std::size_t> select_candidate(const std::vector<SelectionCandidate>& candidates,
                                            double min_relative_margin) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (c.refused() || !std::isfinite(c.heldout_error_percent)) continue;
    if (!best || c.heldout_error_percent < candidates[*best].heldout_error_percent) best = i;
  }
  if (!best) return best;
  const double e = candidates[*best].heldout_error_percent;
  const double limit = e + std::max(heldout_standard_error(candidates[*best]), min_relative_margin * e);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (!c.refused() && std::isfinite(c.heldout_error_percent) && c.heldout_error_percent <= limit) return i;
  }
  return best;
}

std::string selection_json(const std::vector<SelectionCandidate>& candidates, std::optional<std::size_t> chosen) {
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json arr = nlohmann::json::array();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    nlohmann::json o;
    o["name"] = c.name;
    o["method"] = c.method;
    o["structure"] = c.structure;
    o["status"] = chosen && *chosen == i ? "chosen" : c.refused() ? "refused" : "runner-up";
    o["heldout_error_percent"] = number(c.heldout_error_percent);
    o["training_error_percent"] = number(c.training_error_percent);
    nlohmann::json blocks = nlohmann::json::array();
    for (double e : c.block_errors_percent) blocks.push_back(number(e));
    o["block_errors_percent"] = blocks;
    o["reason"] = c.refusal;
    nlohmann::json params = nlohmann::json::object();
    for (const auto& p : c.result.parameters) params[p.name] = number(p.value);
    o["parameters"] = params;
    arr.push_back(o);
  }
  return json_text(arr);
}

}  // namespace frictionlab
