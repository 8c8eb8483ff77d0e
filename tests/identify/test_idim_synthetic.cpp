// IDIM on noiseless data simulated from the model itself, and its error paths.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>
#include <string>

#include "error_message.hpp"
#include "frictionlab/identify/idim.hpp"

namespace fl = frictionlab;

namespace {

using frictionlab::testing::error_of;

// The recipe differentiates a filtered position numerically; on a 0.5-1.3 Hz trajectory at
// 1 kHz the central-difference error is (w dt)^2 / 6 ~ 1e-5 and the 100 Hz Butterworth passes
// it untouched, so the parameters come back to well within 1e-4. The record ends in motion, so
// the last samples (one-sided differences) are dropped as the first are.
constexpr double kRecoveryRelTol = 1e-4;

fl::IdimOptions trimmed() {
  fl::IdimOptions o;
  o.skip_end = 49;
  return o;
}

struct Truth {
  double M = 95.0, Fv = 200.0, Fc = 20.0, offset = -3.0;
  double Fv_pos = 170.0, Fc_pos = 19.0, Fv_neg = 240.0, Fc_neg = 21.0;
};

// q = A1 sin(w1 t) + A2 sin(w2 t + phi), 20 s at 1 kHz; force from the exact derivatives.
fl::IdimData simulate(bool asymmetric, const Truth& p = {}) {
  constexpr double kDt = 1e-3;
  constexpr int kSamples = 20001;
  const double w1 = 2 * std::numbers::pi * 0.5, w2 = 2 * std::numbers::pi * 1.3, a1 = 0.1, a2 = 0.03, phi = 0.4;
  fl::IdimData d;
  d.time.resize(kSamples);
  d.position.resize(kSamples);
  d.force.resize(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double t = i * kDt;
    const double q = a1 * std::sin(w1 * t) + a2 * std::sin(w2 * t + phi);
    const double qd = a1 * w1 * std::cos(w1 * t) + a2 * w2 * std::cos(w2 * t + phi);
    const double qdd = -a1 * w1 * w1 * std::sin(w1 * t) - a2 * w2 * w2 * std::sin(w2 * t + phi);
    const double s = (qd > 0) - (qd < 0);
    double f = p.M * qdd;
    if (asymmetric) f += qd > 0 ? p.Fv_pos * qd + p.Fc_pos : (qd < 0 ? p.Fv_neg * qd - p.Fc_neg : 0.0);
    else f += p.Fv * qd + p.Fc * s + p.offset;
    d.time(i) = t;
    d.position(i) = q;
    d.force(i) = f;
  }
  d.file = "synthetic";
  return d;
}

void expect_rel(double got, double want, const std::string& what) {
  EXPECT_NEAR(got, want, kRecoveryRelTol * std::abs(want)) << what;
}


}  // namespace

TEST(IdimSynthetic, RecoversSymmetricParameters) {
  const Truth p;
  const fl::Result r = fl::identify_idim(simulate(false), trimmed());
  ASSERT_TRUE(r.ok()) << r.message;
  expect_rel(r.value("M"), p.M, "M");
  expect_rel(r.value("Fv"), p.Fv, "Fv");
  expect_rel(r.value("Fc"), p.Fc, "Fc");
  expect_rel(r.value("offset"), p.offset, "offset");
  EXPECT_TRUE(r.diagnostics.warnings.empty()) << r.diagnostics.warnings.front();
}

TEST(IdimSynthetic, RecoversAsymmetricParameters) {
  const Truth p;
  fl::IdimOptions o = trimmed();
  o.terms = {"inertia", "asymmetric"};
  const fl::Result r = fl::identify_idim(simulate(true), o);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_rel(r.value("M"), p.M, "M");
  expect_rel(r.value("Fv_pos"), p.Fv_pos, "Fv_pos");
  expect_rel(r.value("Fc_pos"), p.Fc_pos, "Fc_pos");
  expect_rel(r.value("Fv_neg"), p.Fv_neg, "Fv_neg");
  expect_rel(r.value("Fc_neg"), p.Fc_neg, "Fc_neg");
}

TEST(IdimSynthetic, CrossTestOnItsOwnModelIsNearZero) {
  const fl::Result r = fl::identify_idim(simulate(false), trimmed());
  const fl::ValidationFigures v = fl::cross_test(r, simulate(false), trimmed());
  constexpr double kResidualPercent = 0.05;  // differentiation error only, far below EMPS's 6 %
  EXPECT_LT(v.relative_error_percent, kResidualPercent);
}

TEST(IdimSynthetic, CustomTermExtendsTheRegression) {
  // A position-dependent term (e.g. a spring or cable force k q) added without touching the library.
  constexpr double kStiffness = 150.0;  // N/m
  fl::IdimData d = simulate(false);
  d.force += kStiffness * d.position;
  fl::IdimOptions o = trimmed();
  o.extra_terms.push_back({"k", fl::Quantity::stiffness, [](const fl::IdimKinematics& k) { return k.q; }});
  const fl::Result r = fl::identify_idim(d, o);
  ASSERT_TRUE(r.ok()) << r.message;
  // q and qdd are nearly collinear on a sum of two sines (qdd = -w^2 q for each), which
  // amplifies the differentiation error in k and M by about 10.
  constexpr double kCollinearRelTol = 1e-3;
  EXPECT_NEAR(r.value("k"), kStiffness, kCollinearRelTol * kStiffness);
  EXPECT_NEAR(r.value("M"), Truth{}.M, kCollinearRelTol * Truth{}.M);
  EXPECT_EQ(r.find("k")->unit, "N/m");
}

TEST(IdimErrors, NoMotionIsAStatusErrorNotNumbers) {
  fl::IdimData d = simulate(false);
  d.position.setConstant(0.25);
  d.force.setConstant(1.0);
  const fl::Result r = fl::identify_idim(d);
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.parameters.empty());
  EXPECT_NE(r.message.find("no excitation"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("synthetic"), std::string::npos) << r.message;
  const auto j = nlohmann::json::parse(fl::to_json(r));
  EXPECT_EQ(j["status"], "error");
  EXPECT_EQ(j["message"], r.message);
  EXPECT_TRUE(j["parameters"].empty());
}

TEST(IdimErrors, MotionInOneDirectionOnlyCannotGiveAsymmetricTerms) {
  fl::IdimData d = simulate(false);
  for (Eigen::Index i = 0; i < d.time.size(); ++i) d.position(i) = 0.01 * d.time(i) + 0.001 * std::sin(d.time(i));
  fl::IdimOptions o;
  o.terms = {"inertia", "asymmetric"};
  const fl::Result r = fl::identify_idim(d, o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("_neg"), std::string::npos) << r.message;
}

TEST(IdimErrors, BarelyMovingIsNoExcitation) {
  fl::IdimData d = simulate(false);
  d.position *= 1e-9;
  fl::IdimOptions o;
  o.min_velocity = 1e-3;  // m/s
  const fl::Result r = fl::identify_idim(d, o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("no excitation"), std::string::npos) << r.message;
}

TEST(IdimErrors, NonIncreasingTimeNamesTheSample) {
  fl::IdimData d = simulate(false);
  d.time(100) = d.time(99);
  const std::string msg = error_of([&] { fl::identify_idim(d); });
  EXPECT_NE(msg.find("sample 101"), std::string::npos) << msg;
  EXPECT_NE(msg.find("strictly increasing"), std::string::npos) << msg;
}

TEST(IdimErrors, NanAndLengthAndTermErrors) {
  fl::IdimData d = simulate(false);
  d.force(7) = std::nan("");
  EXPECT_NE(error_of([&] { fl::identify_idim(d); }).find("sample 8: force"), std::string::npos);
  d = simulate(false);
  d.force.conservativeResize(10);
  EXPECT_NE(error_of([&] { fl::identify_idim(d); }).find("force has 10 samples"), std::string::npos);
  fl::IdimOptions o;
  o.terms = {"inertia", "friction"};
  const std::string msg = error_of([&] { fl::identify_idim(simulate(false), o); });
  EXPECT_NE(msg.find("unknown term 'friction'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("coulomb"), std::string::npos) << msg;
  o.terms = {"viscous", "viscous"};
  EXPECT_NE(error_of([&] { fl::identify_idim(simulate(false), o); }).find("twice"), std::string::npos);
  o = {};
  o.cutoff_hz = 800;  // above the 500 Hz Nyquist frequency
  EXPECT_NE(error_of([&] { fl::identify_idim(simulate(false), o); }).find("Nyquist"), std::string::npos);
}

TEST(IdimErrors, CollinearTermsAreRankDeficient) {
  fl::IdimOptions o = trimmed();
  o.extra_terms.push_back({"Fv2", fl::Quantity::viscous, [](const fl::IdimKinematics& k) { return (2.0 * k.qd).eval(); }});
  const fl::Result r = fl::identify_idim(simulate(false), o);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("rank-deficient"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("condition number"), std::string::npos) << r.message;
}
