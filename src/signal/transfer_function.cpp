#include "frictionlab/signal/transfer_function.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace frictionlab {
namespace {

using cd = std::complex<double>;

// numpy.poly: convolve [1] with [1, -r] root by root, in the given order.
std::vector<cd> poly(const Eigen::VectorXcd& roots) {
  std::vector<cd> c{cd(1.0, 0.0)};
  for (Eigen::Index k = 0; k < roots.size(); ++k) {
    std::vector<cd> next(c.size() + 1, cd(0.0, 0.0));
    for (std::size_t i = 0; i < c.size(); ++i) {
      next[i] += c[i];
      next[i + 1] -= c[i] * roots(k);
    }
    c = std::move(next);
  }
  return c;
}

}  // namespace

TransferFunction zpk_to_tf(const ZerosPolesGain& zpk) {
  const auto b = poly(zpk.zeros);
  const auto a = poly(zpk.poles);
  TransferFunction tf;
  tf.b.resize(static_cast<Eigen::Index>(b.size()));
  tf.a.resize(static_cast<Eigen::Index>(a.size()));
  for (std::size_t i = 0; i < b.size(); ++i) tf.b(static_cast<Eigen::Index>(i)) = zpk.gain * b[i].real();
  for (std::size_t i = 0; i < a.size(); ++i) tf.a(static_cast<Eigen::Index>(i)) = a[i].real();
  return tf;
}

SecondOrderSections zpk_to_sos(const ZerosPolesGain& zpk) {
  if (zpk.zeros.size() != zpk.poles.size()) {
    std::ostringstream msg;
    msg << "zpk_to_sos: expected as many zeros as poles (a low-pass with its zeros at z = -1), got "
        << zpk.zeros.size() << " zeros and " << zpk.poles.size() << " poles";
    throw std::invalid_argument(msg.str());
  }
  // Groups of poles: a conjugate pair (the member with positive imaginary part) or a real pole.
  struct Group {
    cd pole;
    bool pair;
  };
  std::vector<Group> groups;
  constexpr double kRealTol = 1e-12;  // imaginary parts below this (relative) count as real poles
  for (Eigen::Index i = 0; i < zpk.poles.size(); ++i) {
    const cd p = zpk.poles(i);
    const bool real = std::abs(p.imag()) <= kRealTol * std::max(1.0, std::abs(p));
    if (real) groups.push_back({cd(p.real(), 0.0), false});
    else if (p.imag() > 0) groups.push_back({p, true});
  }
  // scipy's 'nearest' pairing fills sections from the last one with the poles closest to the
  // unit circle: order the groups by decreasing distance from it. Two real poles share a section.
  std::stable_sort(groups.begin(), groups.end(), [](const Group& x, const Group& y) {
    return std::abs(1.0 - std::abs(x.pole)) > std::abs(1.0 - std::abs(y.pole));
  });
  std::vector<std::array<double, 6>> rows;
  std::vector<double> pending_real;
  for (const auto& g : groups) {
    if (g.pair) {
      rows.push_back({1.0, 2.0, 1.0, 1.0, -2.0 * g.pole.real(), std::norm(g.pole)});
    } else {
      pending_real.push_back(g.pole.real());
    }
  }
  // Real poles: pairs of them make a section [1 2 1 | 1 -(p1+p2) p1 p2]; a lone one [1 1 0 | 1 -p 0].
  for (std::size_t i = 0; i + 1 < pending_real.size(); i += 2) {
    const double p1 = pending_real[i], p2 = pending_real[i + 1];
    rows.insert(rows.begin(), {1.0, 2.0, 1.0, 1.0, -(p1 + p2), p1 * p2});
  }
  if (pending_real.size() % 2 == 1) {
    rows.insert(rows.begin(), {1.0, 1.0, 0.0, 1.0, -pending_real.back(), 0.0});
  }
  SecondOrderSections sos(static_cast<Eigen::Index>(rows.size()), 6);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (int c = 0; c < 6; ++c) sos(static_cast<Eigen::Index>(r), c) = rows[r][static_cast<std::size_t>(c)];
  if (sos.rows() > 0) sos.row(0).head<3>() *= zpk.gain;
  return sos;
}

ZerosPolesGain analog_prototype_to_digital_lowpass(const Eigen::VectorXcd& analog_poles, double analog_gain,
                                                   double wn) {
  if (!(wn > 0.0 && wn < 1.0)) {
    std::ostringstream msg;
    msg.precision(10);
    msg << "filter design: normalised cut-off wn = " << wn
        << " must be in (0, 1) (1 is the Nyquist frequency, half the sampling rate)";
    throw std::invalid_argument(msg.str());
  }
  // scipy.signal.iirfilter: fs = 2, warped = 2 fs tan(pi wn / fs); lp2lp_zpk; bilinear_zpk.
  constexpr double fs = 2.0;
  const double warped = 2.0 * fs * std::tan(std::numbers::pi * wn / fs);
  const Eigen::Index degree = analog_poles.size();  // no finite analog zeros
  const Eigen::VectorXcd p = warped * analog_poles;
  const double k = analog_gain * std::pow(warped, static_cast<double>(degree));
  constexpr double fs2 = 2.0 * fs;
  ZerosPolesGain out;
  out.poles.resize(degree);
  cd denominator(1.0, 0.0);
  for (Eigen::Index i = 0; i < degree; ++i) {
    out.poles(i) = (fs2 + p(i)) / (fs2 - p(i));
    denominator *= (fs2 - p(i));
  }
  out.zeros = Eigen::VectorXcd::Constant(degree, cd(-1.0, 0.0));
  out.gain = k * (cd(1.0, 0.0) / denominator).real();
  return out;
}

}  // namespace frictionlab
