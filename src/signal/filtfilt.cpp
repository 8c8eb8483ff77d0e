#include "frictionlab/signal/filtfilt.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

namespace frictionlab {
namespace {

// b and a divided by a(0) and zero-padded to a common length (scipy's lfilter / lfilter_zi).
TransferFunction normalized(const TransferFunction& tf) {
  if (tf.a.size() == 0 || tf.a(0) == 0.0) {
    throw std::invalid_argument("filter: the first denominator coefficient a(0) must be non-zero");
  }
  if (tf.b.size() == 0) throw std::invalid_argument("filter: the numerator b must have at least one coefficient");
  const Eigen::Index n = std::max(tf.a.size(), tf.b.size());
  TransferFunction out;
  out.b = Eigen::VectorXd::Zero(n);
  out.a = Eigen::VectorXd::Zero(n);
  out.b.head(tf.b.size()) = tf.b / tf.a(0);
  out.a.head(tf.a.size()) = tf.a / tf.a(0);
  return out;
}

// Direct form II transposed on normalised coefficients, in scipy's order of operations.
Eigen::VectorXd lfilter_normalized(const TransferFunction& tf, const Eigen::VectorXd& x, Eigen::VectorXd z) {
  const Eigen::Index k = tf.a.size() - 1;
  Eigen::VectorXd y(x.size());
  for (Eigen::Index n = 0; n < x.size(); ++n) {
    const double xn = x(n);
    const double yn = (k > 0 ? z(0) : 0.0) + tf.b(0) * xn;
    for (Eigen::Index i = 0; i + 1 < k; ++i) z(i) = z(i + 1) + xn * tf.b(i + 1) - yn * tf.a(i + 1);
    if (k > 0) z(k - 1) = xn * tf.b(k) - yn * tf.a(k);
    y(n) = yn;
  }
  return y;
}

// scipy.signal._arraytools.odd_ext: 2 x(0) - x(padlen..1) before, 2 x(N-1) - x(N-2..N-1-padlen) after.
Eigen::VectorXd odd_extend(const Eigen::VectorXd& x, Eigen::Index padlen) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd ext(n + 2 * padlen);
  for (Eigen::Index i = 0; i < padlen; ++i) {
    ext(i) = 2.0 * x(0) - x(padlen - i);
    ext(padlen + n + i) = 2.0 * x(n - 1) - x(n - 2 - i);
  }
  ext.segment(padlen, n) = x;
  return ext;
}

Eigen::Index checked_padlen(std::optional<Eigen::Index> requested, Eigen::Index fallback, Eigen::Index n,
                            const char* who) {
  const Eigen::Index padlen = requested.value_or(fallback);
  if (padlen < 0) {
    throw std::invalid_argument(std::string(who) + ": padlen = " + std::to_string(padlen) + " must be >= 0");
  }
  if (n <= padlen) {
    std::ostringstream msg;
    msg << who << ": the signal has " << n << " samples; it must be longer than padlen = " << padlen;
    throw std::invalid_argument(msg.str());
  }
  if (padlen > 0 && n < 2) throw std::invalid_argument(std::string(who) + ": odd padding needs at least 2 samples");
  return padlen;
}

}  // namespace

Eigen::VectorXd lfilter(const TransferFunction& tf, const Eigen::VectorXd& x, const Eigen::VectorXd& zi) {
  const TransferFunction n = normalized(tf);
  const Eigen::Index k = n.a.size() - 1;
  if (zi.size() != 0 && zi.size() != k) {
    throw std::invalid_argument("lfilter: initial state zi has " + std::to_string(zi.size()) +
                                " entries; expected max(len(a), len(b)) - 1 = " + std::to_string(k));
  }
  return lfilter_normalized(n, x, zi.size() == 0 ? Eigen::VectorXd::Zero(k) : zi);
}

Eigen::VectorXd lfilter_zi(const TransferFunction& tf) {
  const TransferFunction n = normalized(tf);
  const Eigen::Index k = n.a.size() - 1;
  if (k == 0) return Eigen::VectorXd();
  // scipy: (I - companion(a)^T) zi = b[1:] - a[1:] b[0]; companion(a)^T has -a[1:] in its
  // first column and ones above the diagonal.
  Eigen::MatrixXd i_minus_a = Eigen::MatrixXd::Identity(k, k);
  for (Eigen::Index r = 0; r < k; ++r) {
    i_minus_a(r, 0) += n.a(r + 1);
    if (r + 1 < k) i_minus_a(r, r + 1) -= 1.0;
  }
  const Eigen::VectorXd rhs = n.b.tail(k) - n.a.tail(k) * n.b(0);
  return i_minus_a.partialPivLu().solve(rhs);
}

Eigen::VectorXd filtfilt(const TransferFunction& tf, const Eigen::VectorXd& x, const FiltfiltOptions& options) {
  const TransferFunction n = normalized(tf);
  const Eigen::Index padlen =
      checked_padlen(options.padlen, 3 * std::max(tf.a.size(), tf.b.size()), x.size(), "filtfilt");
  const Eigen::VectorXd ext = odd_extend(x, padlen);
  const Eigen::VectorXd zi = lfilter_zi(n);
  Eigen::VectorXd y = lfilter_normalized(n, ext, zi * ext(0));
  const double y0 = y(y.size() - 1);
  y = lfilter_normalized(n, y.reverse().eval(), zi * y0).reverse();
  return y.segment(padlen, x.size());
}

Eigen::VectorXd sosfilt(const SecondOrderSections& sos, const Eigen::VectorXd& x, const Eigen::MatrixX2d& zi) {
  const Eigen::Index ns = sos.rows();
  if (zi.size() != 0 && zi.rows() != ns) {
    throw std::invalid_argument("sosfilt: initial state zi has " + std::to_string(zi.rows()) +
                                " rows; expected one per section (" + std::to_string(ns) + ")");
  }
  Eigen::MatrixX2d z = zi.size() == 0 ? Eigen::MatrixX2d::Zero(ns, 2) : zi;
  SecondOrderSections s = sos;
  for (Eigen::Index r = 0; r < ns; ++r) {
    if (s(r, 3) == 0.0) throw std::invalid_argument("sosfilt: section " + std::to_string(r) + " has a0 = 0");
    s.row(r) /= s(r, 3);
  }
  Eigen::VectorXd y(x.size());
  for (Eigen::Index n = 0; n < x.size(); ++n) {
    double cur = x(n);
    for (Eigen::Index r = 0; r < ns; ++r) {
      const double out = s(r, 0) * cur + z(r, 0);
      z(r, 0) = s(r, 1) * cur - s(r, 4) * out + z(r, 1);
      z(r, 1) = s(r, 2) * cur - s(r, 5) * out;
      cur = out;
    }
    y(n) = cur;
  }
  return y;
}

Eigen::MatrixX2d sosfilt_zi(const SecondOrderSections& sos) {
  Eigen::MatrixX2d zi(sos.rows(), 2);
  double scale = 1.0;
  for (Eigen::Index r = 0; r < sos.rows(); ++r) {
    const TransferFunction section{sos.row(r).head<3>().transpose(), sos.row(r).tail<3>().transpose()};
    zi.row(r) = scale * lfilter_zi(section).transpose();
    scale *= section.b.sum() / section.a.sum();
  }
  return zi;
}

Eigen::VectorXd sosfiltfilt(const SecondOrderSections& sos, const Eigen::VectorXd& x, const FiltfiltOptions& options) {
  // scipy's default: 3 * (2 * sections + 1 - min(#(b2 == 0), #(a2 == 0))).
  const Eigen::Index zeros_b = (sos.col(2).array() == 0.0).count();
  const Eigen::Index zeros_a = (sos.col(5).array() == 0.0).count();
  const Eigen::Index ntaps = 2 * sos.rows() + 1 - std::min(zeros_b, zeros_a);
  const Eigen::Index padlen = checked_padlen(options.padlen, 3 * ntaps, x.size(), "sosfiltfilt");
  const Eigen::VectorXd ext = odd_extend(x, padlen);
  const Eigen::MatrixX2d zi = sosfilt_zi(sos);
  Eigen::VectorXd y = sosfilt(sos, ext, zi * ext(0));
  const double y0 = y(y.size() - 1);
  y = sosfilt(sos, y.reverse().eval(), zi * y0).reverse();
  return y.segment(padlen, x.size());
}

}  // namespace frictionlab
