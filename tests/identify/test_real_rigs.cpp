// The identification methods on records generated to look like real rigs' logs: a robot
// controller's multi-joint log at a jittered 100 Hz (resampled), current instead of torque,
// noise, quantisation and an offset; Virgala-style constant-speed sweeps with velocity noise;
// idim's rate-dependent defaults; honest uncertainty (NaN std, warnings, correlation).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/sweep.hpp"

namespace fl = frictionlab;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Linear interpolation of samples (t, x) at the times tq (t increasing, tq inside).
Eigen::VectorXd interpolate(const std::vector<double>& t, const std::vector<double>& x, const Eigen::VectorXd& tq) {
  Eigen::VectorXd out(tq.size());
  std::size_t k = 0;
  for (Eigen::Index i = 0; i < tq.size(); ++i) {
    while (k + 2 < t.size() && t[k + 1] < tq[i]) ++k;
    const double w = (tq[i] - t[k]) / (t[k + 1] - t[k]);
    out[i] = (1 - w) * x[k] + w * x[k + 1];
  }
  return out;
}

bool has_warning_about(const fl::Result& r, const std::string& name) {
  for (const auto& w : r.diagnostics.warnings)
    if (w.rfind(name + " = ", 0) == 0) return true;
  return false;
}

// Every parameter either has a finite, non-negligible std, or a NaN std with a flag, a warning
// and a place in diagnostics: never a tiny number standing for "held by a bound".
void expect_honest(const fl::Result& r) {
  for (const auto& p : r.parameters) {
    if (std::isnan(p.std)) {  // NOLINT(bugprone-branch-clone)
      EXPECT_FALSE(p.flag.empty()) << p.name;
      EXPECT_TRUE(has_warning_about(r, p.name)) << p.name;
      const auto& u = r.diagnostics.undetermined;
      const auto& b = r.diagnostics.at_bound;
      EXPECT_TRUE(std::find(u.begin(), u.end(), p.name) != u.end() || std::find(b.begin(), b.end(), p.name) != b.end())
          << p.name;
    } else if (p.name.rfind("delta", 0) != 0 || p.std != 0.0) {  // a held exponent has std 0
      constexpr double kTinyRelStd = 1e-9;  // below this a std is rounding, not a measurement
      EXPECT_GT(p.std, kTinyRelStd * std::abs(p.value)) << p.name;
    }
  }
  // The correlation matrix: symmetric, unit diagonal, entries within [-1, 1].
  const auto& c = r.diagnostics.correlation;
  ASSERT_FALSE(c.names.empty());
  ASSERT_EQ(c.matrix.size(), c.names.size());
  for (std::size_t i = 0; i < c.matrix.size(); ++i) {
    EXPECT_EQ(c.matrix[i][i], 1.0);
    for (std::size_t j = 0; j < c.matrix.size(); ++j) {
      const double a = c.matrix[i][j], b = c.matrix[j][i];
      EXPECT_TRUE((std::isnan(a) && std::isnan(b)) || a == b) << i << "," << j;
      if (!std::isnan(a)) {
        EXPECT_LE(std::abs(a), 1.0);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// A six-joint robot log: time jittering between 10 and 12 ms, per joint position (17-bit encoder
// quantisation), velocity and motor current (torque / kt + noise + offset). Only joint 3 moves.
struct RobotLog {
  Eigen::MatrixXd columns;  // N x 19: time, q1..q6, qd1..qd6, i1..i6, on a uniform 10 ms grid
};

constexpr double kM = 0.35, kFv = 2.0, kFc = 3.0, kOffset = 0.4;  // joint 3: kg m^2, N m s/rad, N m, N m
constexpr double kKt = 0.12;                                         // N m/A

RobotLog robot_log(unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> step(0.010, 0.012);
  std::normal_distribution<double> n01;
  const double quantum = 2 * kPi / 131072.0;  // 17-bit encoder, rad
  std::vector<double> t;
  for (double s = 0; s < 90.0; s += step(gen)) t.push_back(s);
  std::vector<std::vector<double>> raw(18, std::vector<double>(t.size()));
  for (std::size_t k = 0; k < t.size(); ++k) {
    for (int j = 0; j < 6; ++j) {
      double q = 0.1 * j, qd = 0, qdd = 0;
      if (j == 2) {  // joint 3: two sines, both directions, speeds up to ~2.5 rad/s
        const double w1 = 2 * kPi * 0.15, w2 = 2 * kPi * 0.55;
        q = 1.2 * std::sin(w1 * t[k]) + 0.25 * std::sin(w2 * t[k] + 1.0);
        qd = 1.2 * w1 * std::cos(w1 * t[k]) + 0.25 * w2 * std::cos(w2 * t[k] + 1.0);
        qdd = -1.2 * w1 * w1 * std::sin(w1 * t[k]) - 0.25 * w2 * w2 * std::sin(w2 * t[k] + 1.0);
      }
      const double tau = j == 2 ? kM * qdd + kFv * qd + kFc * (qd > 0 ? 1.0 : qd < 0 ? -1.0 : 0.0) + kOffset : 0.05 * j;
      raw[static_cast<std::size_t>(j)][k] = std::round(q / quantum) * quantum;
      raw[static_cast<std::size_t>(6 + j)][k] = qd + 0.01 * n01(gen);
      raw[static_cast<std::size_t>(12 + j)][k] = tau / kKt + 0.15 * n01(gen);  // A; noise ~0.02 N m
    }
  }
  // Resampled onto 10 ms, as `--resample 0.01` does.
  const auto n = static_cast<Eigen::Index>(std::floor((t.back() - 0.1) / 0.01));
  RobotLog log;
  log.columns.resize(n, 19);
  for (Eigen::Index i = 0; i < n; ++i) log.columns(i, 0) = 0.01 * static_cast<double>(i);
  for (int c = 0; c < 18; ++c) log.columns.col(c + 1) = interpolate(t, raw[static_cast<std::size_t>(c)], log.columns.col(0));
  return log;
}

fl::IdimOptions rate_defaults() {
  fl::IdimOptions o;
  o.auto_cutoff = o.auto_decimation = o.auto_skip = true;
  o.skip_end = 60;  // the record ends in motion
  o.axis = fl::Axis::rotary;
  return o;
}

TEST(RealRigs, RobotJointFromJitteredHeaderlessLogAt100Hz) {
  const RobotLog log = robot_log(20261125);
  fl::IdimData d;
  d.time = log.columns.col(0);
  d.position = log.columns.col(3);             // q3
  d.force = kKt * log.columns.col(15);         // kt * i3
  const fl::Result r = fl::identify_idim(d, rate_defaults());
  ASSERT_TRUE(r.ok()) << r.message;
  constexpr double kRelTol = 0.05;  // the issue's bound; noise, quantisation and resampling use part of it
  EXPECT_NEAR(r.value("Fc"), kFc, kRelTol * kFc);
  EXPECT_NEAR(r.value("Fv"), kFv, kRelTol * kFv);
  // The 100 Hz defaults, said to be defaults.
  const auto& defaults = r.diagnostics.groups.at("defaults");
  EXPECT_EQ(defaults.at("cutoff_hz"), 10.0);
  EXPECT_EQ(defaults.at("decimation"), 1.0);
  EXPECT_EQ(defaults.at("skip"), 49.0);
  EXPECT_EQ(r.diagnostics.texts.at("regressors_from"), "position");
  expect_honest(r);

  // The same from the measured velocity (filtered, not differentiated): close to the truth too.
  d.velocity = log.columns.col(9);  // qd3
  fl::IdimOptions o = rate_defaults();
  o.source = fl::IdimSource::velocity;
  const fl::Result rv = fl::identify_idim(d, o);
  ASSERT_TRUE(rv.ok()) << rv.message;
  EXPECT_EQ(rv.diagnostics.texts.at("regressors_from"), "velocity");
  EXPECT_NEAR(rv.value("Fc"), kFc, kRelTol * kFc);
  EXPECT_NEAR(rv.value("Fv"), kFv, kRelTol * kFv);
}

TEST(RealRigs, StillJointIsNoExcitation) {
  const RobotLog log = robot_log(7);
  fl::IdimData d;
  d.time = log.columns.col(0);
  d.position = log.columns.col(1);  // q1 never moves
  d.force = kKt * log.columns.col(13);
  const fl::Result r = fl::identify_idim(d, rate_defaults());
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.parameters.empty());
}

TEST(RealRigs, ZeroDriveForceIsAnError) {
  const RobotLog log = robot_log(3);
  fl::IdimData d;
  d.time = log.columns.col(0);
  d.position = log.columns.col(3);
  d.force = Eigen::VectorXd::Zero(log.columns.rows());  // --gain 0
  const fl::Result r = fl::identify_idim(d, rate_defaults());
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.message.find("force is zero throughout"), std::string::npos) << r.message;
}

// ---------------------------------------------------------------------------------------------
// idim's defaults at several sample rates: the EMPS recipe at 1 kHz, valid elsewhere, and a
// record at each rate identified with them.
TEST(RealRigs, IdimDefaultsFollowTheSampleRate) {
  const auto at = [](double fs) { return fl::idim_rate_defaults(fs); };
  EXPECT_EQ(at(1000).cutoff_hz, 100.0);
  EXPECT_EQ(at(1000).decimation, 10);
  EXPECT_EQ(at(1000).skip, 49);
  EXPECT_EQ(at(1000 * (1 + 1e-12)).cutoff_hz, 100.0);  // a mean step with rounding
  EXPECT_EQ(at(999.9999999).decimation, 10);
  // A jittered log resampled at its median step (1.0001 ms) is a 1 kHz record.
  EXPECT_EQ(at(1.0 / 1.0001e-3).cutoff_hz, 100.0);
  EXPECT_EQ(at(1.0 / 1.0001e-3).decimation, 10);
  EXPECT_EQ(at(1.0 / 1.0001e-3).skip, 49);
  EXPECT_EQ(at(990.0).decimation, 9);  // 1 % off is another rate
  for (double fs : {100.0, 500.0, 1000.0, 8000.0}) {
    const auto d = at(fs);
    EXPECT_LT(d.cutoff_hz, 0.5 * fs / 4) << fs;  // well below the raw Nyquist frequency
    EXPECT_GE(d.decimation, 1) << fs;
    EXPECT_LE(d.decimation, 10) << fs;
    EXPECT_GE(d.skip, 1) << fs;
    // The skipped start lasts about five cut-off periods at every rate.
    EXPECT_NEAR((static_cast<double>(d.skip) + 1) / fs, 5 / d.cutoff_hz, 1.0 / fs) << fs;
  }
  EXPECT_THROW(at(0.0), std::invalid_argument);
  EXPECT_THROW(at(std::nan("")), std::invalid_argument);

  for (double fs : {100.0, 500.0, 1000.0, 8000.0}) {
    const double dt = 1.0 / fs;
    const auto n = static_cast<Eigen::Index>(40.0 / dt);
    std::mt19937 gen(static_cast<unsigned>(fs));
    std::normal_distribution<double> n01;
    fl::IdimData d;
    d.time.resize(n);
    d.position.resize(n);
    d.force.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const double t = dt * static_cast<double>(k), w = 2 * kPi * 0.3;
      const double q = 0.8 * std::sin(w * t), qd = 0.8 * w * std::cos(w * t), qdd = -0.8 * w * w * std::sin(w * t);
      d.time[k] = t;
      d.position[k] = q + 1e-6 * n01(gen);
      d.force[k] = kM * qdd + kFv * qd + kFc * (qd > 0 ? 1 : qd < 0 ? -1 : 0) + kOffset + 0.02 * n01(gen);
    }
    fl::IdimOptions o = rate_defaults();
    o.skip_end = static_cast<Eigen::Index>(0.5 / dt);
    const fl::Result r = fl::identify_idim(d, o);
    ASSERT_TRUE(r.ok()) << fs << ": " << r.message;
    constexpr double kRelTol = 0.05;  // as the robot joint
    EXPECT_NEAR(r.value("Fc"), kFc, kRelTol * kFc) << fs;
    EXPECT_NEAR(r.value("Fv"), kFv, kRelTol * kFv) << fs;
    EXPECT_EQ(r.diagnostics.groups.at("defaults").at("cutoff_hz"), at(fs).cutoff_hz) << fs;
  }
}

// ---------------------------------------------------------------------------------------------
// Constant-velocity sweeps in the Virgala procedure: levels held 3 s each, positive then
// negative, a first-order speed loop between them, white velocity noise, force noise.
struct Stribeck {
  double Fc = 0.02, Fs = 0.035, vs = 0.8, delta = 2.0, Fv = 1.5e-4;  // N m, N m, rad/s, -, N m s/rad
  double operator()(double v) const {
    const double s = v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0;
    return s * (Fc + (Fs - Fc) * std::exp(-std::pow(std::abs(v) / vs, delta))) + Fv * v;
  }
};

// The commanded velocity of the last record made with `with_reference` (SweepOptions::reference).
Eigen::VectorXd g_reference;

// `with_reference`: keep the commanded velocity in g_reference.
fl::SweepData sweep_record(const std::vector<double>& speeds, double noise_std, unsigned seed, const Stribeck& law = {},
                           bool with_reference = false) {
  constexpr double kDt = 1e-3, kHold = 3.0, kTau = 0.05, kInertia = 1e-4;  // s, s, s, kg m^2
  std::mt19937 gen(seed);
  std::normal_distribution<double> n01;
  std::vector<double> levels;
  for (double s : speeds) levels.push_back(s);
  for (double s : speeds) levels.push_back(-s);
  const auto per = static_cast<Eigen::Index>(kHold / kDt);
  const Eigen::Index n = per * static_cast<Eigen::Index>(levels.size() + 1);
  fl::SweepData d;
  d.time.resize(n);
  d.velocity.resize(n);
  d.force.resize(n);
  g_reference.resize(n);
  double v = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto level = static_cast<std::size_t>(k / per);
    const double ref = level == 0 ? 0.0 : levels[level - 1];  // at rest for the first hold
    const double a = (ref - v) / kTau;
    v += kDt * a;
    d.time[k] = kDt * static_cast<double>(k);
    g_reference[k] = ref;
    d.velocity[k] = v + noise_std * n01(gen);
    d.force[k] = (v == 0 ? 0.0 : law(v)) + kInertia * a + 2e-4 * n01(gen);
  }
  if (!with_reference) g_reference.resize(0);
  return d;
}

std::vector<double> log_speeds(double lo, double hi, int count) {
  std::vector<double> s;
  for (int i = 0; i < count; ++i) s.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (count - 1)));
  return s;
}

// Every commanded level appears once among the points, within 2 % (the noise of a 2.4 s mean is far below).
void expect_all_levels(const fl::Result& r, const std::vector<double>& speeds) {
  const auto& pts = r.diagnostics.lists.at("points");
  std::string found;
  for (const auto& p : pts)
    found += " " + std::to_string(p.at("velocity")) + "@" + std::to_string(p.at("t_begin")) + "-" + std::to_string(p.at("t_end"));
  ASSERT_EQ(pts.size(), 2 * speeds.size()) << "levels found:" << found;
  for (double sign : {1.0, -1.0}) {
    for (double s : speeds) {
      const auto hits = std::count_if(pts.begin(), pts.end(), [&](const auto& p) {
        constexpr double kLevelRelTol = 0.02;
        return std::abs(p.at("velocity") - sign * s) <= kLevelRelTol * s;
      });
      EXPECT_EQ(hits, 1) << sign * s;
    }
  }
  const auto& levels = r.diagnostics.lists.at("levels");
  ASSERT_EQ(levels.size(), pts.size());
  for (const auto& l : levels) {
    EXPECT_GT(l.at("duration"), 1.0);
    EXPECT_GT(l.at("samples"), 1000.0);
  }
}

TEST(RealRigs, NoisySweepFindsEveryLevelDownToTheSlowest) {
  const Stribeck truth;
  const auto speeds = log_speeds(0.1 * truth.vs, 250 * truth.vs, 15);  // 0.08 to 200 rad/s
  const double noise = 0.04 * speeds.front();                              // 4 % of the slowest speed
  fl::SweepOptions o;
  o.fit.model = fl::StaticFitModel::stribeck;
  const fl::Result r = fl::identify_sweep(sweep_record(speeds, noise, 42), o);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_all_levels(r, speeds);
  // Stribeck parameters within tolerance, or honestly undetermined.
  constexpr double kForceRelTol = 0.05;  // Fc, Fs: levels averaged over 2.4 s each
  constexpr double kVsRelTol = 0.25;     // vs rests on the few levels near it
  EXPECT_NEAR(r.value("Fc"), truth.Fc, kForceRelTol * truth.Fc);
  EXPECT_NEAR(r.value("Fs"), truth.Fs, kForceRelTol * truth.Fs);
  const auto* vs = r.find("vs");
  ASSERT_NE(vs, nullptr);
  if (!std::isnan(vs->std)) {
    EXPECT_NEAR(vs->value, truth.vs, kVsRelTol * truth.vs);
  }
  expect_honest(r);
}

TEST(RealRigs, SweepDownToHalfAPercentOfFullSpeed) {
  const auto speeds = log_speeds(0.5, 100.0, 12);  // 0.5 % of full speed
  const fl::Result r = fl::identify_sweep(sweep_record(speeds, 0.03 * 0.5, 5), {});
  ASSERT_TRUE(r.ok()) << r.message;
  expect_all_levels(r, speeds);
}

TEST(RealRigs, SweepSegmentsOnTheReferenceWhenGiven) {
  const auto speeds = log_speeds(0.08, 200.0, 15);
  fl::SweepData d = sweep_record(speeds, 0.1 * 0.08, 9, Stribeck{}, true);  // noise 10 % of the slowest
  fl::SweepOptions o;
  o.reference = g_reference;
  const fl::Result r = fl::identify_sweep(d, o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.diagnostics.texts.at("segmented_on"), "reference");
  expect_all_levels(r, speeds);
}

TEST(RealRigs, SweepAboveTheStribeckRegionSaysSo) {
  const Stribeck truth;
  const auto speeds = log_speeds(3 * truth.vs, 250 * truth.vs, 10);  // the slowest is 3 vs
  fl::SweepData d = sweep_record(speeds, 0.0, 11);
  const fl::Result r = fl::identify_sweep(d, {});
  ASSERT_TRUE(r.ok()) << r.message;
  for (const char* name : {"vs", "delta"}) {
    const auto* p = r.find(name);
    ASSERT_NE(p, nullptr);
    EXPECT_TRUE(std::isnan(p->std)) << name << " std " << p->std;
  }
  bool warned = false;
  for (const auto& w : r.diagnostics.warnings) warned |= w.find("Stribeck part is not determined by the data") != std::string::npos;
  EXPECT_TRUE(warned);
  expect_honest(r);
}

// A law without a Stribeck peak fitted with one: Fs ends at its bound Fs = Fc; vs and delta then
// carry no information. None gets a tiny std.
TEST(RealRigs, SweepWithoutStribeckPeakReportsBoundNotTinyStd) {
  Stribeck flat;
  flat.Fs = flat.Fc;
  const auto speeds = log_speeds(0.1, 200.0, 15);
  fl::SweepData d = sweep_record(speeds, 0.002, 13, flat);
  const fl::Result r = fl::identify_sweep(d, {});
  ASSERT_TRUE(r.ok()) << r.message;
  expect_honest(r);
  constexpr double kForceRelTol = 0.05;
  EXPECT_NEAR(r.value("Fc"), flat.Fc, kForceRelTol * flat.Fc);
}

}  // namespace
