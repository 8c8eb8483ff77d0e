#include "frictionlab/identify/adequacy.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "frictionlab/format.hpp"

namespace frictionlab {
namespace {

double mean_of(const std::vector<double>& x, const std::vector<std::size_t>& idx) {
  double s = 0;
  for (std::size_t i : idx) s += x[i];
  return idx.empty() ? 0.0 : s / static_cast<double>(idx.size());
}

double std_of(const std::vector<double>& x, const std::vector<std::size_t>& idx, double mean) {
  if (idx.size() < 2) return 0.0;
  double s = 0;
  for (std::size_t i : idx) s += (x[i] - mean) * (x[i] - mean);
  return std::sqrt(s / static_cast<double>(idx.size() - 1));
}

// Splits `idx` (sorted by `key`) into `bins` runs of equal count and summarises the residual in each.
// `inflation` = samples / effective samples widens each bin's standard error.
// When `bin_mean` is given, each sample's entry is set to its bin's mean.
std::vector<ResidualBin> bin_by(const std::vector<double>& key, const std::vector<double>& residual,
                                std::vector<std::size_t> idx, std::size_t bins, double inflation,
                                std::vector<double>* bin_mean = nullptr) {
  std::vector<ResidualBin> out;
  if (idx.empty() || bins == 0) return out;
  std::sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  bins = std::min(bins, idx.size() / 5);  // at least five samples a bin
  if (bins == 0) return out;
  for (std::size_t b = 0; b < bins; ++b) {
    const std::size_t lo = b * idx.size() / bins, hi = (b + 1) * idx.size() / bins;
    std::vector<std::size_t> part(idx.begin() + static_cast<std::ptrdiff_t>(lo), idx.begin() + static_cast<std::ptrdiff_t>(hi));
    ResidualBin r;
    r.samples = part.size();
    r.centre = key[part[part.size() / 2]];
    r.mean = mean_of(residual, part);
    r.standard_error = std_of(residual, part, r.mean) * std::sqrt(inflation / static_cast<double>(part.size()));
    if (bin_mean != nullptr)
      for (std::size_t i : part) (*bin_mean)[i] = r.mean;
    out.push_back(r);
  }
  return out;
}

// The bin farthest from zero in standard errors, among those that are both significant and relevant.
const ResidualBin* worst(const std::vector<ResidualBin>& bins, double significance, double threshold) {
  const ResidualBin* w = nullptr;
  for (const auto& b : bins) {
    if (!(std::abs(b.mean) > significance * b.standard_error && std::abs(b.mean) > threshold)) continue;
    if (w == nullptr || std::abs(b.mean) / b.standard_error > std::abs(w->mean) / w->standard_error) w = &b;
  }
  return w;
}

std::string num(double x) { return detail::format_value(x, 3); }

}  // namespace

Adequacy assess_residuals(const std::vector<double>& velocity, const std::vector<double>& position,
                          const std::vector<double>& time, const std::vector<double>& residual,
                          const std::string& force_unit, const std::string& velocity_unit,
                          const AdequacyOptions& options) {
  const std::size_t n = residual.size();
  if (velocity.size() != n || (!position.empty() && position.size() != n) || (!time.empty() && time.size() != n)) {
    throw std::invalid_argument("assess_residuals: velocity, position and time must have the residual's " +
                                std::to_string(n) + " samples (velocity " + std::to_string(velocity.size()) +
                                ", position " + std::to_string(position.size()) + ", time " +
                                std::to_string(time.size()) + ")");
  }
  if (n < kAdequacyMinSamples) {
    throw std::invalid_argument("assess_residuals: " + std::to_string(n) + " samples; expected at least " +
                                std::to_string(kAdequacyMinSamples));
  }
  Adequacy a;
  a.samples = n;
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t{0});
  const double mean = mean_of(residual, all);
  a.residual_std = std_of(residual, all, mean);
  if (!(a.residual_std > 0)) {  // an exact fit: nothing to check
    a.effective_samples = static_cast<double>(n);
    return a;
  }

  // Autocorrelation, and the effective sample size from its initial positive run (longer lags
  // than reported, so that a slowly decaying correlation is counted).
  // Around the mean, or around each segment's own mean and within segments only (a segment's
  // offset is the structure under test, not the noise's memory).
  std::vector<double> centred(n);
  std::vector<std::size_t> segment(n, 0);
  if (options.segment_ends.empty()) {
    for (std::size_t i = 0; i < n; ++i) centred[i] = residual[i] - mean;
  } else {
    std::size_t begin = 0, id = 0;
    for (std::size_t end : options.segment_ends) {
      end = std::min(end, n);
      if (end <= begin) continue;
      double m = 0;
      for (std::size_t i = begin; i < end; ++i) m += residual[i];
      m /= static_cast<double>(end - begin);
      for (std::size_t i = begin; i < end; ++i) centred[i] = residual[i] - m, segment[i] = id;
      begin = end;
      ++id;
    }
    if (begin != n)
      throw std::invalid_argument("assess_residuals: segment_ends end at sample " + std::to_string(begin) +
                                  "; expected them to end at the residual's " + std::to_string(n) + " samples");
  }
  double var = a.residual_std * a.residual_std * static_cast<double>(n - 1);
  if (!options.segment_ends.empty()) {
    double within = 0;
    for (double c : centred) within += c * c;
    if (within > 0) var = within;
  }
  const std::size_t long_lag = std::min<std::size_t>(n / 4, 500);
  double positive_sum = 0;
  bool positive_run = true;
  for (std::size_t k = 1; k <= std::max(long_lag, options.max_lag) && k < n; ++k) {
    double s = 0;
    for (std::size_t i = k; i < n; ++i)
      if (segment[i] == segment[i - k]) s += centred[i] * centred[i - k];
    const double rho = s / var;
    if (k <= options.max_lag) a.autocorrelation.push_back(rho);
    if (positive_run && k <= long_lag) {
      if (rho > 0) positive_sum += rho;
      else positive_run = false;
    }
  }
  a.effective_samples = std::max(1.0, static_cast<double>(n) / (1.0 + 2.0 * positive_sum));
  const double inflation = static_cast<double>(n) / a.effective_samples;

  // Velocity: the two directions apart, standstill apart.
  double vmax = 0;
  for (double v : velocity) vmax = std::max(vmax, std::abs(v));
  a.standstill_speed = options.standstill_fraction * vmax;
  std::vector<std::size_t> pos, neg;
  std::size_t still = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (velocity[i] > a.standstill_speed) pos.push_back(i);
    else if (velocity[i] < -a.standstill_speed) neg.push_back(i);
    else ++still;
  }
  a.standstill_share = static_cast<double>(still) / static_cast<double>(n);
  std::vector<double> speed(n);
  for (std::size_t i = 0; i < n; ++i) speed[i] = std::abs(velocity[i]);
  std::vector<double> velocity_pattern(n, 0.0);  // each moving sample's velocity-bin mean
  auto by_neg = bin_by(speed, residual, neg, options.velocity_bins, inflation, &velocity_pattern);
  auto by_pos = bin_by(speed, residual, pos, options.velocity_bins, inflation, &velocity_pattern);
  for (auto it = by_neg.rbegin(); it != by_neg.rend(); ++it) {
    ResidualBin b = *it;
    b.centre = -b.centre;
    a.by_velocity.push_back(b);
  }
  a.by_velocity.insert(a.by_velocity.end(), by_pos.begin(), by_pos.end());
  // Position and time are judged on the residual less its velocity pattern: moves at different
  // speeds happen at different times and places, and a velocity effect must not pass for a drift.
  std::vector<double> partial(n);
  for (std::size_t i = 0; i < n; ++i) partial[i] = residual[i] - velocity_pattern[i];
  if (!position.empty()) a.by_position = bin_by(position, partial, all, options.position_bins, inflation);
  if (!time.empty()) a.by_time = bin_by(time, partial, all, options.position_bins, inflation);

  // Relevance is judged against the residual of the moving samples: stuck samples, where the
  // Coulomb term's sign is noise, can dominate the whole residual's spread.
  std::vector<std::size_t> moving(pos);
  moving.insert(moving.end(), neg.begin(), neg.end());
  const double moving_std = moving.size() > 1 ? std_of(residual, moving, mean_of(residual, moving)) : a.residual_std;
  const double z = options.significance,
               threshold = std::max(options.relevance * moving_std, options.force_share * options.force_scale);
  auto significant = [&](const ResidualBin& b) {
    return std::abs(b.mean) > z * b.standard_error && std::abs(b.mean) > threshold;
  };
  // Friction acts against the motion, so a residual (measured less model) with the sign of the
  // velocity is friction the model lacks. The lowest-speed bin of each direction speaks of the
  // Stribeck region.
  const ResidualBin* low_pos = by_pos.empty() ? nullptr : &by_pos.front();
  const ResidualBin* low_neg = by_neg.empty() ? nullptr : &by_neg.front();
  auto excess = [](const ResidualBin* b, double sign) { return b == nullptr ? 0.0 : sign * b->mean; };
  const bool high_pos = low_pos && significant(*low_pos) && excess(low_pos, 1) > 0;
  const bool high_neg = low_neg && significant(*low_neg) && excess(low_neg, -1) > 0;
  const bool lower_pos = low_pos && significant(*low_pos) && excess(low_pos, 1) < 0;
  const bool lower_neg = low_neg && significant(*low_neg) && excess(low_neg, -1) < 0;
  bool explained = false;
  if (high_pos || high_neg) {
    const ResidualBin* b = high_pos && (!high_neg || excess(low_pos, 1) >= excess(low_neg, -1)) ? low_pos : low_neg;
    a.findings.push_back("friction at low speed is higher than the model: " + num(std::abs(b->mean)) + " " + force_unit +
                         " more at |v| about " + num(std::abs(b->centre)) + " " + velocity_unit + " (" +
                         num(std::abs(b->mean) / b->standard_error) +
                         " standard errors); " + options.advice.stribeck);
    explained = true;
  } else if (lower_pos && lower_neg) {
    a.findings.push_back("friction at low speed is lower than the model (" + num(std::abs(low_pos->mean)) + " " +
                         force_unit + " at |v| about " + num(low_pos->centre) + " " + velocity_unit +
                         "): the faster samples pull the Coulomb level up; " + options.advice.shape);
    explained = true;
  }
  if (!pos.empty() && !neg.empty()) {
    // Friction's magnitude in each direction, less the model's: positive direction residual
    // mean, negative direction residual mean with its sign turned.
    const double e_pos = mean_of(residual, pos), e_neg = -mean_of(residual, neg);
    const double se = a.residual_std * std::sqrt(inflation / static_cast<double>(pos.size()) +
                                                 inflation / static_cast<double>(neg.size()));
    const double d = e_pos - e_neg;
    if (std::abs(d) > z * se && std::abs(d) > threshold) {
      a.findings.push_back("friction differs by direction: " + num(std::abs(d)) + " " + force_unit + " more when moving " +
                           (d > 0 ? "positive" : "negative") + " than the model has (" + num(std::abs(d) / se) +
                           " standard errors); " + options.advice.asymmetry);
      explained = true;
    }
  }
  if (!explained) {
    if (const ResidualBin* b = worst(a.by_velocity, z, threshold)) {
      a.findings.push_back("the residual changes with velocity (" + num(b->mean) + " " + force_unit + " at v = " +
                           num(b->centre) + " " + velocity_unit +
                           "): the friction-velocity curve is not the model's shape; compare models on held-out data");
    }
  }
  if (const ResidualBin* b = worst(a.by_position, z, threshold)) {
    a.findings.push_back("the residual depends on position (" + num(b->mean) + " " + force_unit + " near " +
                         num(b->centre) + "): friction or load that changes along the travel (ripple, cogging,"
                         " gravity, a cable)");
  }
  if (const ResidualBin* b = worst(a.by_time, z, threshold)) {
    a.findings.push_back("the residual drifts over time (" + num(b->mean) + " " + force_unit + " near t = " +
                         num(b->centre) + " s): friction changes during the run (temperature, running-in) or the"
                         " force signal drifts");
  }
  constexpr double kCorrelated = 0.5;  // lag-1 autocorrelation above this: std from least squares mislead
  // A residual below 0.1 % of the force's scale is the filter's and the arithmetic's, not the
  // data's: its correlation says nothing about the std a user reads.
  constexpr double kNegligible = 1e-3;
  const bool negligible = a.residual_std < kNegligible * options.force_scale;
  if (!options.advice.correlated_std.empty() && !negligible && !a.autocorrelation.empty() && a.autocorrelation.front() > kCorrelated) {
    a.findings.push_back("the residual is correlated from sample to sample (lag-1 autocorrelation " +
                         num(a.autocorrelation.front()) + "; " + std::to_string(n) + " samples count as about " +
                         num(a.effective_samples) + " independent ones): " + options.advice.correlated_std +
                         " are too small by about " + num(std::sqrt(inflation)) + " times; " +
                         options.advice.correlated_remedy);
  }
  constexpr double kStandstillShare = 0.2;  // beyond this share, stuck samples weigh on the Coulomb level
  if (options.advice.standstill && a.standstill_share > kStandstillShare) {
    a.findings.push_back(num(100 * a.standstill_share) + " % of the samples are near standstill (|v| < " +
                         num(a.standstill_speed) + " " + velocity_unit +
                         "), where the Coulomb term's sign follows noise: they bias the Coulomb level; record"
                         " more motion or leave those samples out (idim: --exclude-below " +
                         num(a.standstill_speed) + ")");
  }
  return a;
}

void add_adequacy(Result& result, const Adequacy& a) {
  auto rows = [](const std::vector<ResidualBin>& bins) {
    std::vector<std::map<std::string, double>> out;
    for (const auto& b : bins) {
      out.push_back({{"centre", b.centre}, {"mean", b.mean}, {"standard_error", b.standard_error},
                     {"samples", static_cast<double>(b.samples)}});
    }
    return out;
  };
  auto& d = result.diagnostics;
  d.lists["residual_by_velocity"] = rows(a.by_velocity);
  if (!a.by_position.empty()) d.lists["residual_by_position"] = rows(a.by_position);
  if (!a.by_time.empty()) d.lists["residual_by_time"] = rows(a.by_time);
  std::vector<std::map<std::string, double>> acf;
  for (std::size_t k = 0; k < a.autocorrelation.size(); ++k) {
    acf.push_back({{"lag", static_cast<double>(k + 1)}, {"autocorrelation", a.autocorrelation[k]}});
  }
  d.lists["residual_autocorrelation"] = acf;
  d.groups["adequacy"] = {{"residual_std", a.residual_std},
                          {"samples", static_cast<double>(a.samples)},
                          {"effective_samples", a.effective_samples},
                          {"standstill_speed", a.standstill_speed},
                          {"standstill_share", a.standstill_share},
                          {"lag1_autocorrelation", a.autocorrelation.empty() ? 0.0 : a.autocorrelation.front()},
                          {"findings", static_cast<double>(a.findings.size())}};
  for (const auto& f : a.findings) d.warnings.push_back(f);
}

}  // namespace frictionlab
