// Filter design and zero-phase filtering against scipy 1.10 (values recorded with
// tests/peers/emps_idim_reference.py --signal-csv tests/signal).

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "frictionlab/io/csv.hpp"
#include "frictionlab/signal/butterworth.hpp"
#include "frictionlab/signal/chebyshev.hpp"
#include "frictionlab/signal/decimate.hpp"
#include "frictionlab/signal/differentiate.hpp"
#include "frictionlab/signal/filtfilt.hpp"

namespace fl = frictionlab;

namespace {

// Coefficients are printed by scipy to 17 digits; the design differs from scipy's only by
// rounding in a few complex products, so agreement is ~1e-14; 1e-10 leaves room for a
// different libm while still catching any wrong formula.
constexpr double kCoefRelTol = 1e-10;
// Filtered series: same algorithm and order of operations as scipy, rounding differences
// only; 1e-10 relative to the signal's scale (about 1 to 4).
constexpr double kSeriesRelTol = 1e-10;

void expect_close(const Eigen::VectorXd& got, const Eigen::VectorXd& want, double rel_tol, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  const double scale = want.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got(i), want(i), rel_tol * scale) << what << " [" << i << "]";
  }
}

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out(i++) = x;
  return out;
}

std::string ref_path(const std::string& name) { return std::string(FRICTIONLAB_SOURCE_DIR) + "/tests/signal/" + name; }

// The textbook direct form II transposed (scipy's lfilter loop: one sample at a time, a multiply
// and an add per term), what the library's kernels must equal up to rounding.
Eigen::VectorXd textbook_lfilter(const fl::TransferFunction& tf, const Eigen::VectorXd& x, Eigen::VectorXd z) {
  const Eigen::VectorXd b = tf.b / tf.a(0), a = tf.a / tf.a(0);
  const Eigen::Index k = a.size() - 1;
  Eigen::VectorXd y(x.size());
  for (Eigen::Index n = 0; n < x.size(); ++n) {
    y(n) = z(0) + b(0) * x(n);
    for (Eigen::Index i = 0; i + 1 < k; ++i) z(i) = z(i + 1) + x(n) * b(i + 1) - y(n) * a(i + 1);
    z(k - 1) = x(n) * b(k) - y(n) * a(k);
  }
  return y;
}

// scipy's filtfilt from the textbook loop: odd padding, forward from lfilter_zi times the first
// sample, backward from lfilter_zi times the last output.
// x with `pad` samples of odd reflection at each end (scipy's padtype 'odd').
Eigen::VectorXd odd_padded(const Eigen::VectorXd& x, Eigen::Index pad) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd e(n + 2 * pad);
  for (Eigen::Index i = 0; i < pad; ++i) {
    e(i) = 2 * x(0) - x(pad - i);
    e(pad + n + i) = 2 * x(n - 1) - x(n - 2 - i);
  }
  e.segment(pad, n) = x;
  return e;
}

Eigen::VectorXd textbook_filtfilt(const fl::TransferFunction& tf, const Eigen::VectorXd& x) {
  const Eigen::Index pad = 3 * tf.a.size(), n = x.size();
  const Eigen::VectorXd e = odd_padded(x, pad);
  const Eigen::VectorXd zi = fl::lfilter_zi(tf);
  const Eigen::VectorXd f = textbook_lfilter(tf, e, zi * e(0));
  const Eigen::VectorXd r = f.reverse();
  return textbook_lfilter(tf, r, zi * r(0)).reverse().segment(pad, n);
}

// A record like a position log: a slow sine, a seeded random walk and noise.
Eigen::VectorXd wandering(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> step(0.0, 0.01), noise(0.0, 0.002);
  Eigen::VectorXd x(n);
  double walk = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    walk += step(rng);
    x(i) = std::sin(0.002 * static_cast<double>(i)) + walk + noise(rng);
  }
  return x;
}

}  // namespace

TEST(Butterworth, MatchesScipyButter) {
  struct Case {
    int order;
    double wn;
    Eigen::VectorXd b, a;
  };
  const Case cases[] = {
      {4, 0.2,
       vec({0.00482434335771623, 0.01929737343086492, 0.02894606014629739, 0.01929737343086492, 0.00482434335771623}),
       vec({1., -2.3695130071820376, 2.31398841441588, -1.0546654058785676, 0.18737949236818488})},
      {2, 0.5, vec({0.2928932188134525, 0.585786437626905, 0.2928932188134525}), vec({1., 0., 0.1715728752538099})},
      {5, 0.05,
       vec({2.3409914930614002e-06, 1.1704957465307002e-05, 2.3409914930614004e-05, 2.3409914930614004e-05,
            1.1704957465307002e-05, 2.3409914930614002e-06}),
       vec({1., -4.491830965077046, 8.094055417826647, -7.312081280150383, 3.3110475619883983, -0.6011158228598384})},
      {8, 0.9,
       vec({0.44508427467139355, 3.5606741973711484, 12.462359690799019, 24.924719381598038, 31.155899226997548,
            24.924719381598038, 12.462359690799019, 3.5606741973711484, 0.44508427467139355}),
       vec({1., 6.390364563108543, 18.000338335739908, 29.171099374882864, 29.731375438327472, 19.505631768126655,
            8.040995932998943, 1.903668891132587, 0.19810001155979165})},
  };
  for (const auto& c : cases) {
    const auto tf = fl::butter(c.order, c.wn);
    const std::string what = "butter(" + std::to_string(c.order) + ", " + std::to_string(c.wn) + ")";
    expect_close(tf.b, c.b, kCoefRelTol, what + ".b");
    expect_close(tf.a, c.a, kCoefRelTol, what + ".a");
  }
}

TEST(Butterworth, RejectsBadArguments) {
  EXPECT_THROW(fl::butter(0, 0.2), std::invalid_argument);
  EXPECT_THROW(fl::butter(4, 1.0), std::invalid_argument);
  EXPECT_THROW(fl::butter(4, 0.0), std::invalid_argument);
  try {
    fl::normalized_cutoff(600.0, 1e-3);
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("600 Hz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("500 Hz"), std::string::npos) << e.what();
  }
  EXPECT_DOUBLE_EQ(fl::normalized_cutoff(100.0, 1e-3), 0.2);
}

TEST(Chebyshev, MatchesScipyCheby1) {
  struct Case {
    int order;
    double rp, wn;
    Eigen::VectorXd b, a;
  };
  const Case cases[] = {
      {8, 0.05, 0.08,
       vec({3.5863243209995207e-09, 2.8690594567996165e-08, 1.0041708098798658e-07, 2.0083416197597316e-07,
            2.5104270246996645e-07, 2.0083416197597316e-07, 1.0041708098798658e-07, 2.8690594567996165e-08,
            3.5863243209995207e-09}),
       vec({1., -7.397720470943626, 24.072727760966973, -44.998914665983264, 52.84346676692242, -39.915914352468405,
            18.93766580976049, -5.159179426375671, 0.6178695015203624})},
      {5, 1.0, 0.3,
       vec({0.00202016939761766, 0.01010084698808828, 0.02020169397617656, 0.02020169397617656, 0.01010084698808828,
            0.00202016939761766}),
       vec({1., -3.162364647736195, 4.760700364549024, -4.052794082948058, 1.9343905258872025, -0.41528673902820834})},
      {3, 0.5, 0.6, vec({0.24887256626278964, 0.7466176987883689, 0.7466176987883689, 0.24887256626278964}),
       vec({1., 0.5043332968678547, 0.5289392467403876, -0.04229201350592467})},
  };
  for (const auto& c : cases) {
    const auto tf = fl::cheby1(c.order, c.rp, c.wn);
    const std::string what = "cheby1(" + std::to_string(c.order) + ")";
    expect_close(tf.b, c.b, kCoefRelTol, what + ".b");
    expect_close(tf.a, c.a, kCoefRelTol, what + ".a");
  }
}

TEST(Chebyshev, SecondOrderSectionsMatchScipy) {
  // scipy.signal.cheby1(8, 0.05, 0.08, output='sos'), the filter of decimate(x, 10).
  fl::SecondOrderSections want(4, 6);
  want << 3.5863243209995207e-09, 7.1726486419990414e-09, 3.5863243209995207e-09, 1.0, -1.8204968644767618,
      8.3085974037961374e-01,  //
      1.0, 2.0, 1.0, 1.0, -1.8289505620176847, 8.5531737103877414e-01,  //
      1.0, 2.0, 1.0, 1.0, -1.8517334482627625, 9.0151610557138129e-01,  //
      1.0, 2.0, 1.0, 1.0, -1.8965395961864169, 9.6442455846429320e-01;
  const auto sos = fl::cheby1_sos(8, 0.05, 0.08);
  ASSERT_EQ(sos.rows(), 4);
  for (Eigen::Index r = 0; r < 4; ++r) {
    expect_close(sos.row(r).transpose(), want.row(r).transpose(), kCoefRelTol, "sos row " + std::to_string(r));
  }
}

TEST(Filtfilt, MatchesScipyFiltfilt) {
  const fl::Dataset ref = fl::read_csv(ref_path("ref_filtfilt.csv"));
  const Eigen::VectorXd& x = ref.column("x");
  const auto b4 = fl::butter(4, 0.2);
  expect_close(fl::filtfilt(b4, x, {12}), ref.column("filtfilt_butter4_0p2_pad12"), kSeriesRelTol, "padlen 12");
  expect_close(fl::filtfilt(b4, x), ref.column("filtfilt_butter4_0p2_default"), kSeriesRelTol, "default padlen");
  expect_close(fl::filtfilt(fl::cheby1(5, 1.0, 0.3), x), ref.column("filtfilt_cheby1_5_1_0p3_default"), kSeriesRelTol,
               "cheby1");
}

TEST(Filtfilt, LfilterZiIsTheStepSteadyState) {
  // A constant input starting from zi * x0 stays at the DC gain (1 for Butterworth).
  const auto tf = fl::butter(4, 0.2);
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(50, 2.5);
  const Eigen::VectorXd y = fl::lfilter(tf, x, fl::lfilter_zi(tf) * 2.5);
  constexpr double kTol = 1e-12;  // exact steady state up to rounding
  for (Eigen::Index i = 0; i < y.size(); ++i) EXPECT_NEAR(y(i), 2.5, kTol);
}

TEST(Filtfilt, TooShortSignalNamesTheLengths) {
  const Eigen::VectorXd x = Eigen::VectorXd::Ones(10);
  try {
    fl::filtfilt(fl::butter(4, 0.2), x);
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("10 samples"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("padlen = 15"), std::string::npos) << e.what();
  }
}

TEST(Decimate, MatchesScipyDecimate) {
  const fl::Dataset ref = fl::read_csv(ref_path("ref_filtfilt.csv"));
  const Eigen::VectorXd& x = ref.column("x");
  expect_close(fl::decimate(x, 10), fl::read_csv(ref_path("ref_decimate10.csv")).column("y"), kSeriesRelTol, "q = 10");
  expect_close(fl::decimate(x, 3), fl::read_csv(ref_path("ref_decimate3.csv")).column("y"), kSeriesRelTol, "q = 3");
  EXPECT_THROW(fl::decimate(x, 0), std::invalid_argument);
}

// The multi-column forms run the same operations per column in SIMD lanes, so they must equal
// the one-column forms exactly, for every block width (1, 2, 3 with an idle lane, 4, 4 + 1).
TEST(Decimate, ColumnsEqualOneColumnAtATime) {
  const fl::Dataset ref = fl::read_csv(ref_path("ref_filtfilt.csv"));
  const Eigen::VectorXd& x = ref.column("x");
  for (Eigen::Index cols = 1; cols <= 5; ++cols) {
    Eigen::MatrixXd m(x.size(), cols);
    for (Eigen::Index c = 0; c < cols; ++c) m.col(c) = x * (1.0 + static_cast<double>(c)) + x.reverse() * static_cast<double>(c);
    const Eigen::MatrixXd d = fl::decimate_columns(m, 10);
    const Eigen::MatrixXd f = fl::sosfiltfilt_columns(fl::cheby1_sos(8, 0.05, 0.08), m);
    for (Eigen::Index c = 0; c < cols; ++c) {
      EXPECT_EQ(d.col(c), fl::decimate(m.col(c), 10)) << cols << " columns, column " << c;
      EXPECT_EQ(f.col(c), fl::sosfiltfilt(fl::cheby1_sos(8, 0.05, 0.08), m.col(c))) << cols << " columns, column " << c;
    }
  }
}

TEST(Decimate, ColumnViewsMustHaveEqualLengths) {
  const Eigen::VectorXd a = Eigen::VectorXd::Ones(100), b = Eigen::VectorXd::Ones(90);
  const fl::ColumnViews views{{a.data(), a.size()}, {b.data(), b.size()}};
  try {
    fl::decimate_columns(views, 10);
    FAIL() << "expected invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "sosfiltfilt: column 1 has 90 samples; expected 100 like column 0");
  }
}

TEST(Filtfilt, InPlaceEqualsFiltfilt) {
  const fl::Dataset ref = fl::read_csv(ref_path("ref_filtfilt.csv"));
  const Eigen::VectorXd& x = ref.column("x");
  const auto b4 = fl::butter(4, 0.2);
  const Eigen::Index pad = fl::filtfilt_padlen(b4, {12}, x.size());
  EXPECT_EQ(pad, 12);
  Eigen::VectorXd buffer = Eigen::VectorXd::Constant(x.size() + 2 * pad, 1e300);  // padding overwritten
  buffer.segment(pad, x.size()) = x;
  fl::filtfilt_in_place(b4, buffer, pad);
  EXPECT_EQ(Eigen::VectorXd(buffer.segment(pad, x.size())), fl::filtfilt(b4, x, {12}));
}

TEST(Gradient, MatchesNumpyGradient) {
  const fl::Dataset ref = fl::read_csv(ref_path("ref_filtfilt.csv"));
  expect_close(fl::gradient(ref.column("x"), 0.001), ref.column("gradient_dt0p001"), kSeriesRelTol, "gradient");
  EXPECT_THROW(fl::gradient(Eigen::VectorXd::Ones(1), 0.001), std::invalid_argument);
  EXPECT_THROW(fl::gradient(Eigen::VectorXd::Ones(5), 0.0), std::invalid_argument);
  Eigen::VectorXd out(ref.column("x").size());
  fl::gradient(ref.column("x"), 0.001, out);
  EXPECT_EQ(out, fl::gradient(ref.column("x"), 0.001));
  Eigen::VectorXd short_out(3);
  EXPECT_THROW(fl::gradient(ref.column("x"), 0.001, short_out), std::invalid_argument);
}

TEST(Gradient, ExactOnAQuadraticInside) {
  // Central differences are exact for a parabola away from the ends.
  const double dt = 0.01;
  Eigen::VectorXd x(20);
  for (Eigen::Index i = 0; i < 20; ++i) x(i) = 3.0 * (i * dt) * (i * dt);
  const Eigen::VectorXd d = fl::gradient(x, dt);
  constexpr double kTol = 1e-12;  // rounding of differences of values <= 1
  for (Eigen::Index i = 1; i < 19; ++i) EXPECT_NEAR(d(i), 6.0 * i * dt, kTol);
}

// Long records: the recursion's loops (states held in local variables for the common orders)
// must give the textbook recursion's result up to rounding, at even and odd lengths, forward and
// backward, and for a filter with a long memory (order 2 at 0.002). The filters are ones a transfer function holds well: at higher orders and lower cut-offs the
// direct form amplifies any change of rounding (order 6 at 0.05, or order 4 at 0.0005, differ by
// 1e-10 between two correct loops), which is why the pipelines use order 4 at 0.2.
TEST(Filtfilt, LongRecordsEqualTheTextbookRecursion) {
  struct Case {
    int order;
    double wn;
  };
  for (const Case c : {Case{2, 0.3}, Case{4, 0.2}, Case{4, 0.05}, Case{3, 0.1}, Case{2, 0.002}}) {
    const fl::TransferFunction tf = fl::butter(c.order, c.wn);
    for (const Eigen::Index n : {Eigen::Index{4095}, Eigen::Index{4096}, Eigen::Index{4099}, Eigen::Index{30001}}) {
      const Eigen::VectorXd x = wandering(n, static_cast<unsigned>(c.order * 100000 + n));
      const Eigen::VectorXd zi = fl::lfilter_zi(tf) * x(0);
      const std::string what = "order " + std::to_string(c.order) + ", wn " + std::to_string(c.wn) + ", n " + std::to_string(n);
      expect_close(fl::lfilter(tf, x, zi), textbook_lfilter(tf, x, zi), kSeriesRelTol, "lfilter, " + what);
      expect_close(fl::filtfilt(tf, x), textbook_filtfilt(tf, x), kSeriesRelTol, "filtfilt, " + what);
    }
  }
}

namespace {

// scipy's sosfiltfilt from textbook loops: each section a direct form II transposed, a multiply
// and an add per term; odd padding; sosfilt_zi states times the first (last) sample.
Eigen::VectorXd textbook_sosfiltfilt(const fl::SecondOrderSections& sos, const Eigen::VectorXd& x) {
  const Eigen::Index ns = sos.rows(), n = x.size();
  const Eigen::Index pad = 3 * (2 * ns + 1 - std::min((sos.col(2).array() == 0.0).count(), (sos.col(5).array() == 0.0).count()));
  const Eigen::VectorXd e = odd_padded(x, pad);
  const Eigen::MatrixX2d zi = fl::sosfilt_zi(sos);
  const auto run = [&](Eigen::VectorXd v) {  // section after section, each from its zi state
    const Eigen::MatrixX2d z0 = zi * v(0);
    for (Eigen::Index r = 0; r < ns; ++r) {
      const fl::TransferFunction section{sos.row(r).head<3>().transpose(), sos.row(r).tail<3>().transpose()};
      v = textbook_lfilter(section, v, z0.row(r).transpose());
    }
    return v;
  };
  const Eigen::VectorXd forward = run(e);
  return run(forward.reverse()).reverse().segment(pad, n);
}

}  // namespace

// Long records: the decimation filter runs four columns side by side (one lane each).
// Columns must equal the textbook cascade up to rounding, with an even and an odd length, and
// decimate must keep every q-th of them.
TEST(Decimate, LongRecordsEqualTheTextbookCascade) {
  const fl::SecondOrderSections sos = fl::cheby1_sos(8, 0.05, 0.08);
  for (const Eigen::Index n : {Eigen::Index{20000}, Eigen::Index{20001}}) {
    Eigen::MatrixXd m(n, 4);
    for (Eigen::Index c = 0; c < 4; ++c) m.col(c) = wandering(n, static_cast<unsigned>(10 * n + c));
    const Eigen::MatrixXd f = fl::sosfiltfilt_columns(sos, m);
    const Eigen::MatrixXd d = fl::decimate_columns(m, 10);
    for (Eigen::Index c = 0; c < 4; ++c) {
      const Eigen::VectorXd want = textbook_sosfiltfilt(sos, m.col(c));
      const std::string what = std::to_string(n) + " samples, column " + std::to_string(c);
      expect_close(f.col(c), want, kSeriesRelTol, "sosfiltfilt, " + what);
      Eigen::VectorXd kept(d.rows());
      for (Eigen::Index i = 0; i < d.rows(); ++i) kept(i) = want(10 * i);
      expect_close(d.col(c), kept, kSeriesRelTol, "decimate, " + what);
    }
  }
}

// A NaN reaches every later sample of a recursion, and filtfilt's backward pass carries it to all
// of them, as scipy's does; the columns filtered beside it in the same lanes stay finite.
TEST(Filtfilt, ANaNInALongRecordReachesEveryLaterOutput) {
  Eigen::VectorXd x = wandering(30001, 3);
  x(10000) = std::numeric_limits<double>::quiet_NaN();
  const fl::TransferFunction tf = fl::butter(4, 0.2);
  const Eigen::VectorXd y = fl::lfilter(tf, x);
  EXPECT_TRUE(y.head(10000).allFinite());
  EXPECT_TRUE(y.tail(20001).array().isNaN().all());
  EXPECT_TRUE(fl::filtfilt(tf, x).array().isNaN().all());
  Eigen::MatrixXd m(x.size(), 4);
  for (Eigen::Index c = 0; c < 4; ++c) m.col(c) = wandering(x.size(), static_cast<unsigned>(20 + c));
  m.col(2) = x;
  const Eigen::MatrixXd f = fl::sosfiltfilt_columns(fl::cheby1_sos(8, 0.05, 0.08), m);
  EXPECT_TRUE(f.col(2).array().isNaN().all());
  EXPECT_TRUE(f.col(0).allFinite());
}

// No sections at all: the identity, with every block width.
TEST(Filtfilt, NoSectionsIsTheIdentity) {
  Eigen::MatrixXd m(20001, 5);
  for (Eigen::Index c = 0; c < m.cols(); ++c) m.col(c) = wandering(m.rows(), static_cast<unsigned>(40 + c));
  EXPECT_EQ(fl::sosfiltfilt_columns(fl::SecondOrderSections(0, 6), m), m);
}

// A workspace reused across calls (signal/filter_workspace.hpp) gives the numbers of fresh calls
// to the bit, whichever size it was last grown to; a released one too.
TEST(Filtfilt, AReusedWorkspaceGivesTheNumbersOfFreshCalls) {
  const fl::SecondOrderSections sos = fl::cheby1_sos(8, 0.05, 0.08);
  fl::FilterWorkspace workspace;
  for (const Eigen::Index n : {Eigen::Index{30001}, Eigen::Index{500}, Eigen::Index{20000}}) {
    Eigen::MatrixXd m(n, 5);
    for (Eigen::Index c = 0; c < m.cols(); ++c) m.col(c) = wandering(n, static_cast<unsigned>(60 + c));
    fl::ColumnViews views;
    for (Eigen::Index c = 0; c < m.cols(); ++c) views.emplace_back(m.col(c).data(), n);
    EXPECT_EQ(fl::sosfiltfilt_columns(sos, views, {}, 1, workspace), fl::sosfiltfilt_columns(sos, m)) << n << " samples";
    EXPECT_EQ(fl::decimate_columns(views, 10, workspace), fl::decimate_columns(m, 10)) << n << " samples";
  }
  // It holds what the largest call needed (30001 samples and 2 x 27 of padding, four lanes) until released.
  EXPECT_GE(workspace.capacity(), std::size_t{(30001 + 54) * 4});
  workspace.release();
  EXPECT_EQ(workspace.capacity(), 0u);
}
