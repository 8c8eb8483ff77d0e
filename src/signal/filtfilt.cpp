#include "frictionlab/signal/filtfilt.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

// Direct form II transposed on normalised coefficients, in scipy's order of operations, in place
// over `count` samples from x with the given step (+1 forward, -1 backward). z: the k states.
// K > 0 fixes k at compile time: the states and coefficients are then local variables. Through
// the pointers they would be stored and reloaded every sample (z, x and the coefficients are all
// double*, which the compiler cannot prove apart), and that store-to-load round trip would sit on
// the recursion's critical path; the arithmetic, and so the result, is the same either way.
template <int K = 0>
void lfilter_in_place(const TransferFunction& tf, double* z, double* x, Eigen::Index count, int step) {
  const Eigen::Index k = K > 0 ? K : tf.a.size() - 1;
  if constexpr (K > 0) {
    std::array<double, K + 1> b, a;
    std::array<double, K> zl;
    std::copy(tf.b.data(), tf.b.data() + K + 1, b.begin());
    std::copy(tf.a.data(), tf.a.data() + K + 1, a.begin());
    std::copy(z, z + K, zl.begin());
    for (Eigen::Index n = 0; n < count; ++n) {
      double* const at = x + n * step;  // never formed one past either end
      const double xn = *at;
      const double yn = zl[0] + b[0] * xn;
      for (int i = 0; i + 1 < K; ++i) zl[i] = zl[i + 1] + xn * b[i + 1] - yn * a[i + 1];
      zl[K - 1] = xn * b[K] - yn * a[K];
      *at = yn;
    }
    std::copy(zl.begin(), zl.end(), z);
    return;
  }
  const double* b = tf.b.data();
  const double* a = tf.a.data();
  for (Eigen::Index n = 0; n < count; ++n) {
    double* const at = x + n * step;  // never formed one past either end
    const double xn = *at;
    const double yn = (k > 0 ? z[0] : 0.0) + b[0] * xn;
    for (Eigen::Index i = 0; i + 1 < k; ++i) z[i] = z[i + 1] + xn * b[i + 1] - yn * a[i + 1];
    if (k > 0) z[k - 1] = xn * b[k] - yn * a[k];
    *at = yn;
  }
}

// lfilter_in_place with the common orders' states in registers (see above).
void lfilter_dispatch(const TransferFunction& tf, double* z, double* x, Eigen::Index count, int step) {
  switch (tf.a.size() - 1) {
    case 2: return lfilter_in_place<2>(tf, z, x, count, step);
    case 4: return lfilter_in_place<4>(tf, z, x, count, step);
    default: return lfilter_in_place(tf, z, x, count, step);
  }
}

Eigen::VectorXd lfilter_normalized(const TransferFunction& tf, const Eigen::VectorXd& x, Eigen::VectorXd z) {
  Eigen::VectorXd y = x;
  lfilter_dispatch(tf, z.data(), y.data(), y.size(), 1);
  return y;
}

// Second-order sections divided by a0, row-major (b0 b1 b2 a0 a1 a2 per section).
using SectionCoefficients = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

SectionCoefficients normalized_sections(const SecondOrderSections& sos, const char* who) {
  SectionCoefficients s = sos;
  for (Eigen::Index r = 0; r < s.rows(); ++r) {
    if (s(r, 3) == 0.0) throw std::invalid_argument(std::string(who) + ": section " + std::to_string(r) + " has a0 = 0");
    s.row(r) /= s(r, 3);
  }
  return s;
}

// Columns filtered side by side: the recursion of one channel is a chain of dependent
// multiply-adds, so W independent channels in lock-step fill the pipeline (and SIMD lanes)
// that one channel leaves idle. Four lanes are two SSE2 registers (the x86-64 baseline the
// library is built for) and suit IDIM's few regressors.
constexpr Eigen::Index kLanes = 4;
constexpr int kDecimationSections = 4;  // scipy's order-8 decimation filter

// The section cascade over `count` samples of W interleaved channels (x[n * W + c]), in place,
// in scipy's sosfilt order of operations per channel. z holds 2 states per section and lane
// (z[(2 r + j) * W + c]); step is +1 forward or -1 backward (x then points at the last sample).
// NS > 0 fixes the number of sections at compile time (decimate's filter has 4), so the loop
// over sections unrolls and the states can stay in registers.
template <int W, int NS = 0>
void cascade(const SectionCoefficients& s, double* z, double* x, Eigen::Index count, int step) {
  using Lanes = Eigen::Array<double, W, 1>;  // one SIMD-friendly value per channel
  if constexpr (NS > 0) {
    // States and coefficients in local variables, for the reason lfilter_in_place<K> gives.
    std::array<Lanes, NS> z0, z1;
    std::array<std::array<double, 6>, NS> c;
    for (int r = 0; r < NS; ++r) {
      z0[r] = Eigen::Map<Lanes>(z + 2 * r * W);
      z1[r] = Eigen::Map<Lanes>(z + (2 * r + 1) * W);
      for (int j = 0; j < 6; ++j) c[r][j] = s(r, j);
    }
    for (Eigen::Index n = 0; n < count; ++n) {
      Eigen::Map<Lanes> sample(x + n * step * W);  // never formed one past either end
      Lanes cur = sample;
      for (int r = 0; r < NS; ++r) {
        const Lanes out = c[r][0] * cur + z0[r];
        z0[r] = c[r][1] * cur - c[r][4] * out + z1[r];
        z1[r] = c[r][2] * cur - c[r][5] * out;
        cur = out;
      }
      sample = cur;
    }
    for (int r = 0; r < NS; ++r) {
      Eigen::Map<Lanes>(z + 2 * r * W) = z0[r];
      Eigen::Map<Lanes>(z + (2 * r + 1) * W) = z1[r];
    }
    return;
  }
  const Eigen::Index ns = s.rows();
  for (Eigen::Index n = 0; n < count; ++n) {
    Eigen::Map<Lanes> sample(x + n * step * W);  // never formed one past either end
    Lanes cur = sample;
    for (Eigen::Index r = 0; r < ns; ++r) {
      Eigen::Map<Lanes> z0(z + 2 * r * W), z1(z + (2 * r + 1) * W);
      const Lanes out = s(r, 0) * cur + z0;
      z0 = s(r, 1) * cur - s(r, 4) * out + z1;
      z1 = s(r, 2) * cur - s(r, 5) * out;
      cur = out;
    }
    sample = cur;
  }
}

// sosfiltfilt of columns c0 .. c0 + W - 1 of x (fewer at the right edge) into the same columns
// of out, keeping samples 0, q, 2q, ...: odd extension, forward pass from the steady state of
// the first sample, backward pass from the steady state of the last output.
// `data` holds (n + 2 padlen) W doubles of work space.
template <int W>
void filtfilt_block(const SectionCoefficients& s, const Eigen::MatrixX2d& zi, const ColumnViews& x,
                    Eigen::Index c0, Eigen::Index padlen, Eigen::Index q, Eigen::MatrixXd& out, double* const data) {
  const Eigen::Index n = x.front().size(), m = n + 2 * padlen, ns = s.rows();
  const int used = static_cast<int>(std::min<Eigen::Index>(W, static_cast<Eigen::Index>(x.size()) - c0));
  for (int c = used; c < W; ++c) {
    for (Eigen::Index i = 0; i < m; ++i) data[i * W + c] = 0.0;  // an idle lane
  }
  for (int c = 0; c < used; ++c) {
    const auto& col = x[static_cast<std::size_t>(c0 + c)];
    double* b = data + c;
    for (Eigen::Index i = 0; i < padlen; ++i) {
      b[i * W] = 2.0 * col(0) - col(padlen - i);
      b[(padlen + n + i) * W] = 2.0 * col(n - 1) - col(n - 2 - i);
    }
    for (Eigen::Index i = 0; i < n; ++i) b[(padlen + i) * W] = col(i);
  }
  std::vector<double> z(static_cast<std::size_t>(2 * ns * W));
  const auto start = [&](const double* sample) {
    for (Eigen::Index r = 0; r < ns; ++r) {
      for (int c = 0; c < W; ++c) {
        z[static_cast<std::size_t>((2 * r) * W + c)] = zi(r, 0) * sample[c];
        z[static_cast<std::size_t>((2 * r + 1) * W + c)] = zi(r, 1) * sample[c];
      }
    }
  };
  // One pass over count samples from `from` (in place, interleaved).
  const auto pass = [&](double* from, Eigen::Index count, int step) {
    if (ns == kDecimationSections) cascade<W, kDecimationSections>(s, z.data(), from, count, step);
    else cascade<W>(s, z.data(), from, count, step);
  };
  start(data);
  pass(data, m, 1);
  start(data + (m - 1) * W);
  pass(data + (m - 1) * W, m, -1);
  for (int c = 0; c < used; ++c) {
    for (Eigen::Index i = 0; i < out.rows(); ++i) out(i, c0 + c) = data[(padlen + i * q) * W + c];
  }
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

Eigen::Index filtfilt_padlen(const TransferFunction& tf, const FiltfiltOptions& options, Eigen::Index n) {
  return checked_padlen(options.padlen, 3 * std::max(tf.a.size(), tf.b.size()), n, "filtfilt");
}

void filtfilt_in_place(const TransferFunction& tf, Eigen::Ref<Eigen::VectorXd> x, Eigen::Index padlen) {
  const TransferFunction n = normalized(tf);
  const Eigen::Index len = x.size() - 2 * padlen;
  checked_padlen(padlen, padlen, len, "filtfilt");
  for (Eigen::Index i = 0; i < padlen; ++i) {  // odd reflection about the first and last samples
    x(i) = 2.0 * x(padlen) - x(2 * padlen - i);
    x(padlen + len + i) = 2.0 * x(padlen + len - 1) - x(padlen + len - 2 - i);
  }
  const Eigen::VectorXd zi = lfilter_zi(n);
  Eigen::VectorXd z = zi * x(0);
  lfilter_dispatch(n, z.data(), x.data(), x.size(), 1);
  z = zi * x(x.size() - 1);
  lfilter_dispatch(n, z.data(), x.data() + x.size() - 1, x.size(), -1);
}

Eigen::VectorXd filtfilt(const TransferFunction& tf, const Eigen::VectorXd& x, const FiltfiltOptions& options) {
  const Eigen::Index padlen = filtfilt_padlen(tf, options, x.size());
  Eigen::VectorXd y(x.size() + 2 * padlen);
  y.segment(padlen, x.size()) = x;
  filtfilt_in_place(tf, y, padlen);
  return y.segment(padlen, x.size());
}

Eigen::VectorXd sosfilt(const SecondOrderSections& sos, const Eigen::VectorXd& x, const Eigen::MatrixX2d& zi) {
  const Eigen::Index ns = sos.rows();
  if (zi.size() != 0 && zi.rows() != ns) {
    throw std::invalid_argument("sosfilt: initial state zi has " + std::to_string(zi.rows()) +
                                " rows; expected one per section (" + std::to_string(ns) + ")");
  }
  const Eigen::MatrixX2d z0 = zi.size() == 0 ? Eigen::MatrixX2d::Zero(ns, 2) : zi;
  const SectionCoefficients s = normalized_sections(sos, "sosfilt");
  std::vector<double> z(static_cast<std::size_t>(2 * ns));
  for (Eigen::Index r = 0; r < ns; ++r) {
    z[static_cast<std::size_t>(2 * r)] = z0(r, 0);
    z[static_cast<std::size_t>(2 * r + 1)] = z0(r, 1);
  }
  Eigen::VectorXd y = x;
  cascade<1>(s, z.data(), y.data(), y.size(), 1);
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
  return sosfiltfilt_columns(sos, ColumnViews{{x.data(), x.size()}}, options).col(0);
}

Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const Eigen::MatrixXd& x,
                                    const FiltfiltOptions& options, Eigen::Index keep_every) {
  if (x.cols() == 0 && keep_every >= 1) return Eigen::MatrixXd((x.rows() + keep_every - 1) / keep_every, 0);
  ColumnViews views;
  for (Eigen::Index c = 0; c < x.cols(); ++c) views.emplace_back(x.col(c).data(), x.rows());
  return sosfiltfilt_columns(sos, views, options, keep_every);
}

Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const ColumnViews& x, const FiltfiltOptions& options,
                                    Eigen::Index keep_every) {
  FilterWorkspace workspace;
  return sosfiltfilt_columns(sos, x, options, keep_every, workspace);
}

Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const ColumnViews& x, const FiltfiltOptions& options,
                                    Eigen::Index keep_every, FilterWorkspace& workspace) {
  if (keep_every < 1) {
    throw std::invalid_argument("sosfiltfilt: keep_every = " + std::to_string(keep_every) + " must be >= 1");
  }
  const Eigen::Index n = x.empty() ? 0 : x.front().size();
  for (std::size_t c = 0; c < x.size(); ++c) {
    if (x[c].size() != n) {
      throw std::invalid_argument("sosfiltfilt: column " + std::to_string(c) + " has " + std::to_string(x[c].size()) +
                                  " samples; expected " + std::to_string(n) + " like column 0");
    }
  }
  // scipy's default: 3 * (2 * sections + 1 - min(#(b2 == 0), #(a2 == 0))).
  const Eigen::Index zeros_b = (sos.col(2).array() == 0.0).count();
  const Eigen::Index zeros_a = (sos.col(5).array() == 0.0).count();
  const Eigen::Index ntaps = 2 * sos.rows() + 1 - std::min(zeros_b, zeros_a);
  const Eigen::Index padlen = checked_padlen(options.padlen, 3 * ntaps, n, "sosfiltfilt");
  const SectionCoefficients s = normalized_sections(sos, "sosfiltfilt");
  const Eigen::MatrixX2d zi = sosfilt_zi(sos);
  const Eigen::Index cols = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd out((n + keep_every - 1) / keep_every, cols);
  // A constant column (IDIM's offset) starts and stays in the steady state of both passes: it
  // comes out times the squared DC gain, so it needs no filtering.
  double dc_gain = 1.0;
  for (Eigen::Index r = 0; r < s.rows(); ++r) dc_gain *= (s(r, 0) + s(r, 1) + s(r, 2)) / (1.0 + s(r, 4) + s(r, 5));
  ColumnViews varying;
  std::vector<Eigen::Index> where;
  for (Eigen::Index c = 0; c < cols; ++c) {
    const auto& col = x[static_cast<std::size_t>(c)];
    // Constant? A varying column shows it within its first samples; a constant one is checked
    // to its end in vector instructions (the summed differences from the first sample: a NaN
    // makes the sum NaN, so the column is filtered).
    constexpr Eigen::Index kHead = 64;
    const Eigen::Index head = std::min(kHead, n);
    if ((col.head(head).array() == col(0)).all() && (n == head || (col.tail(n - head).array() - col(0)).abs().sum() == 0.0)) {
      out.col(c).setConstant(col(0) * dc_gain * dc_gain);
    } else {
      varying.push_back(col);
      where.push_back(c);
    }
  }
  Eigen::MatrixXd filtered(out.rows(), static_cast<Eigen::Index>(varying.size()));
  // The widest block's work space (three columns run four lanes, one idle).
  const Eigen::Index widest = filtered.cols() > 2 ? kLanes : filtered.cols();
  double* const block = widest == 0 ? nullptr : workspace.block(static_cast<std::size_t>((n + 2 * padlen) * widest)).data();
  for (Eigen::Index c = 0; c < filtered.cols(); c += kLanes) {
    const Eigen::Index lanes = std::min<Eigen::Index>(kLanes, filtered.cols() - c);
    if (lanes == 1) filtfilt_block<1>(s, zi, varying, c, padlen, keep_every, filtered, block);
    else if (lanes == 2) filtfilt_block<2>(s, zi, varying, c, padlen, keep_every, filtered, block);
    else filtfilt_block<kLanes>(s, zi, varying, c, padlen, keep_every, filtered, block);  // 3 columns: one idle lane
  }
  for (std::size_t j = 0; j < where.size(); ++j) out.col(where[j]) = filtered.col(static_cast<Eigen::Index>(j));
  return out;
}

}  // namespace frictionlab
