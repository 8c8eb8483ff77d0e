#include "frictionlab/analysis/envelope.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "frictionlab/format.hpp"

namespace frictionlab {

const char* decay_kind_name(DecayKind kind) {
  switch (kind) {
    case DecayKind::none: return "none";
    case DecayKind::linear: return "linear";
    case DecayKind::exponential: return "exponential";
    case DecayKind::mixed: return "mixed";
  }
  return "?";
}

namespace {

struct Extreme {
  double t, x;
};

// Vertex of the parabola through three samples (ta < tb < tc), clamped to [ta, tc].
Extreme refine(double ta, double xa, double tb, double xb, double tc, double xc) {
  const double d1 = (xb - xa) / (tb - ta), d2 = (xc - xb) / (tc - tb);
  const double curv = (d2 - d1) / (tc - ta);  // half the second derivative
  if (curv == 0.0) return {tb, xb};
  const double tm = 0.5 * (ta + tb) - d1 / (2.0 * curv);
  const double tv = std::clamp(tm, ta, tc);
  // value of the interpolating parabola at tv (Newton form)
  const double xv = xa + d1 * (tv - ta) + curv * (tv - ta) * (tv - tb);
  return {tv, xv};
}

// Fits A = p exp(-lambda t) + q for fixed lambda by linear least squares (q fixed at 0 when
// !with_q); returns the rms residual.
double fit_fixed_lambda(const std::vector<double>& t, const std::vector<double>& a, double lambda, bool with_q,
                        double& p, double& q) {
  const std::size_t n = t.size();
  double see = 0, se = 0, s1 = static_cast<double>(n), sea = 0, sa = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = std::exp(-lambda * (t[i] - t[0]));
    see += e * e;
    se += e;
    sea += e * a[i];
    sa += a[i];
  }
  if (with_q) {
    const double det = see * s1 - se * se;
    if (std::abs(det) < 1e-300) {
      p = 0;
      q = sa / s1;
    } else {
      p = (sea * s1 - se * sa) / det;
      q = (see * sa - se * sea) / det;
    }
  } else {
    p = sea / see;
    q = 0;
  }
  double ss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = a[i] - (p * std::exp(-lambda * (t[i] - t[0])) + q);
    ss += r * r;
  }
  return std::sqrt(ss / static_cast<double>(n));
}

// Separable least squares (variable projection): the model is linear in p, q, so only lambda is
// searched, by golden section on a log scale over [1e-4, 1e2] / T. Written by hand because it is
// a 1-D bounded search of a smooth profile; a general solver would need start values for p and q.
EnvelopeFit fit_exponential(const std::vector<double>& t, const std::vector<double>& a, bool with_q, double mean) {
  const double span = std::max(t.back() - t.front(), 1e-12);
  double lo = std::log(1e-4 / span), hi = std::log(1e2 / span);
  auto cost = [&](double loglam) {
    double p, q;
    return fit_fixed_lambda(t, a, std::exp(loglam), with_q, p, q);
  };
  // coarse scan first (the profile can have a shallow second minimum at large lambda)
  double best = lo, best_cost = cost(lo);
  for (int i = 1; i <= 60; ++i) {
    const double x = lo + (hi - lo) * i / 60.0;
    const double c = cost(x);
    if (c < best_cost) {
      best_cost = c;
      best = x;
    }
  }
  const double step = (hi - lo) / 60.0;
  double a0 = best - step, b0 = best + step;
  const double gr = (std::sqrt(5.0) - 1.0) / 2.0;
  double c0 = b0 - gr * (b0 - a0), d0 = a0 + gr * (b0 - a0);
  for (int it = 0; it < 100; ++it) {
    if (cost(c0) < cost(d0)) {
      b0 = d0;
    } else {
      a0 = c0;
    }
    c0 = b0 - gr * (b0 - a0);
    d0 = a0 + gr * (b0 - a0);
  }
  EnvelopeFit f;
  f.lambda = std::exp(0.5 * (a0 + b0));
  const double rms = fit_fixed_lambda(t, a, f.lambda, with_q, f.p, f.q);
  f.relative_rms = rms / mean;
  return f;
}

EnvelopeFit fit_linear(const std::vector<double>& t, const std::vector<double>& a, double mean) {
  const std::size_t n = t.size();
  const double tm = std::accumulate(t.begin(), t.end(), 0.0) / static_cast<double>(n);
  double stt = 0, sta = 0;
  for (std::size_t i = 0; i < n; ++i) {
    stt += (t[i] - tm) * (t[i] - tm);
    sta += (t[i] - tm) * (a[i] - mean);
  }
  EnvelopeFit f;
  f.slope = stt > 0 ? sta / stt : 0.0;
  f.q = mean - f.slope * tm;
  double ss = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = a[i] - (f.q + f.slope * t[i]);
    ss += r * r;
  }
  f.relative_rms = std::sqrt(ss / static_cast<double>(n)) / mean;
  return f;
}

}  // namespace

EnvelopeResult decay_envelope(std::span<const double> t, std::span<const double> x, const EnvelopeOptions& options) {
  if (t.size() != x.size())
    throw std::invalid_argument("decay envelope: time has " + std::to_string(t.size()) + " samples but position has " +
                                std::to_string(x.size()) + "; expected equal lengths");
  if (t.size() < 3) throw std::invalid_argument("decay envelope: need at least 3 samples, got " + std::to_string(t.size()));
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw std::invalid_argument("decay envelope: time must increase strictly; sample " + std::to_string(i + 1) +
                                  " has t = " + format_number(t[i]) + " after " + format_number(t[i - 1]));

  // Extremes: sign changes of the slope, skipping flat stretches.
  // The start of the record counts as an extreme when it starts at rest (a release from an
  // initial deflection); otherwise the first half swing would be a partial one.
  std::vector<Extreme> ext;
  double dmax = 0;
  for (std::size_t i = 1; i < x.size(); ++i) dmax = std::max(dmax, std::abs(x[i] - x[i - 1]));
  const bool starts_at_rest = std::abs(x[1] - x[0]) <= 0.05 * dmax;
  if (starts_at_rest) ext.push_back({t[0], x[0]});
  int last_sign = 0;
  std::size_t last_nonflat = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double d = x[i] - x[i - 1];
    const int s = d > 0 ? 1 : (d < 0 ? -1 : 0);
    if (s == 0) continue;
    if (last_sign != 0 && s != last_sign) {
      const std::size_t k = i - 1;  // the turning sample
      if (k >= 1 && last_nonflat == k)
        ext.push_back(refine(t[k - 1], x[k - 1], t[k], x[k], t[k + 1], x[k + 1]));
      else
        ext.push_back({t[k], x[k]});
    }
    last_sign = s;
    last_nonflat = i;
  }
  // A final rest (the body stuck): its start is the last extreme.
  if (last_nonflat + 1 < x.size() && last_nonflat > 0 && (ext.empty() || ext.back().t < t[last_nonflat]))
    ext.push_back({t[last_nonflat], x[last_nonflat]});

  EnvelopeResult r;
  double amax = 0;
  for (std::size_t k = 1; k < ext.size(); ++k) amax = std::max(amax, 0.5 * std::abs(ext[k].x - ext[k - 1].x));
  for (std::size_t k = 1; k < ext.size(); ++k) {
    const double a = 0.5 * std::abs(ext[k].x - ext[k - 1].x);
    if (a < options.min_relative_amplitude * amax) break;  // the oscillation has died out
    r.peak_times.push_back(ext[k].t);
    r.amplitudes.push_back(a);
  }
  if (r.amplitudes.size() < 4)
    throw std::invalid_argument("decay envelope: found " + std::to_string(r.amplitudes.size()) +
                                " half cycles; need at least 4 to fit an envelope (is this a free oscillation?)");
  const std::size_t n = r.amplitudes.size();
  r.half_period = (r.peak_times.back() - r.peak_times.front()) / static_cast<double>(n - 1);
  const double mean = std::accumulate(r.amplitudes.begin(), r.amplitudes.end(), 0.0) / static_cast<double>(n);
  r.decay_fraction = 1.0 - r.amplitudes.back() / r.amplitudes.front();
  r.linear = fit_linear(r.peak_times, r.amplitudes, mean);
  r.exponential = fit_exponential(r.peak_times, r.amplitudes, false, mean);
  r.mixed = fit_exponential(r.peak_times, r.amplitudes, true, mean);
  r.decrement_per_half_cycle = -r.linear.slope * r.half_period;
  r.log_decrement = r.exponential.lambda * 2.0 * r.half_period;
  const double best2 = std::min(r.linear.relative_rms, r.exponential.relative_rms);
  if (std::abs(r.decay_fraction) < options.none_tolerance) {
    r.kind = DecayKind::none;
  } else if (best2 > options.fit_tolerance && r.mixed.relative_rms < options.mixed_gain * best2 && r.mixed.q < 0) {
    r.kind = DecayKind::mixed;  // q = -c < 0: an exponential that reaches zero in finite time
  } else {
    r.kind = r.linear.relative_rms <= r.exponential.relative_rms ? DecayKind::linear : DecayKind::exponential;
  }
  return r;
}

}  // namespace frictionlab
