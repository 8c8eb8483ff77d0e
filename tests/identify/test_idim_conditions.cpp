// IDIM's terms of the conditions (load, temperature, position ripple) on noiseless data made from
// the model itself, and their error paths: a missing column, a ripple without a position or a
// period, the reference temperature reported.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "error_message.hpp"
#include "frictionlab/identify/idim.hpp"

namespace fl = frictionlab;

namespace {

using frictionlab::testing::error_of;

// As in test_idim_synthetic.cpp the recipe differentiates a filtered position; here the ripple
// column is a sine of that filtered position (its 16 Hz at most pass the 100 Hz low-pass with a
// gain within 1e-6 of 1) and the load and temperature columns go through the same decimation as
// the force, so the parameters come back to well within 1e-3 of the truth.
constexpr double kRecoveryRelTol = 1e-3;

struct Truth {
  double M = 2.0, Fv = 20.0, Fc = 3.0, offset = 0.5;
  double load_gain = 1.0, mu_load = 0.05;
  double Fv_per_K = -0.25, T_ref = 30.0;
  double period = 0.02, ripple_sin = 0.6, ripple_cos = -0.4;  // m, N, N
};

// q = A1 sin(w1 t) + A2 sin(w2 t + phi) over five ripple periods, 30 s at 1 kHz; a load of
// 10 to 50 N and a temperature rising from 20 to 44 degC; force from the exact derivatives.
fl::IdimData simulate(const Truth& p = {}) {
  constexpr double kDt = 1e-3;
  constexpr int kSamples = 30001;
  const double w1 = 2 * std::numbers::pi * 0.5, w2 = 2 * std::numbers::pi * 1.3, a1 = 0.05, a2 = 0.01, phi = 0.4;
  fl::IdimData d;
  for (auto* v : {&d.time, &d.position, &d.force, &d.load, &d.temperature}) v->resize(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    const double t = i * kDt;
    const double q = a1 * std::sin(w1 * t) + a2 * std::sin(w2 * t + phi);
    const double qd = a1 * w1 * std::cos(w1 * t) + a2 * w2 * std::cos(w2 * t + phi);
    const double qdd = -a1 * w1 * w1 * std::sin(w1 * t) - a2 * w2 * w2 * std::sin(w2 * t + phi);
    const double s = (qd > 0) - (qd < 0);
    const double load = 30.0 + 20.0 * std::sin(0.3 * t);
    const double temp = 20.0 + 0.8 * t;
    const double k = 2 * std::numbers::pi / p.period;
    d.time(i) = t;
    d.position(i) = q;
    d.load(i) = load;
    d.temperature(i) = temp;
    d.force(i) = p.M * qdd + (p.Fv + p.Fv_per_K * (temp - p.T_ref)) * qd + (p.Fc + p.mu_load * std::abs(load)) * s +
                 p.offset + p.load_gain * load + p.ripple_sin * std::sin(k * q) + p.ripple_cos * std::cos(k * q);
  }
  d.file = "conditions";
  return d;
}

fl::IdimOptions with_conditions(const Truth& p = {}) {
  fl::IdimOptions o;
  o.terms = {"inertia", "viscous", "coulomb", "offset", "load", "temperature", "ripple"};
  o.ripple_period = p.period;
  o.temperature_ref = p.T_ref;
  o.skip_end = 49;  // the record ends in motion
  return o;
}

void expect_rel(double got, double want, const std::string& what) {
  EXPECT_NEAR(got, want, kRecoveryRelTol * std::abs(want)) << what;
}

}  // namespace

TEST(IdimConditions, RecoversLoadTemperatureAndRipple) {
  const Truth p;
  const fl::Result r = fl::identify_idim(simulate(), with_conditions());
  ASSERT_TRUE(r.ok()) << r.message;
  expect_rel(r.value("M"), p.M, "M");
  expect_rel(r.value("Fv"), p.Fv, "Fv");
  expect_rel(r.value("Fc"), p.Fc, "Fc");
  expect_rel(r.value("load_gain"), p.load_gain, "load_gain");
  expect_rel(r.value("mu_load"), p.mu_load, "mu_load");
  expect_rel(r.value("Fv_per_K"), p.Fv_per_K, "Fv_per_K");
  expect_rel(r.value("ripple_sin_1"), p.ripple_sin, "ripple_sin_1");
  expect_rel(r.value("ripple_cos_1"), p.ripple_cos, "ripple_cos_1");
  // Units follow the quantities; a negative Fv_per_K is physical (grease thins as it warms).
  EXPECT_EQ(r.find("Fv_per_K")->unit, "N s/m/K");
  EXPECT_EQ(r.find("mu_load")->unit, "");
  EXPECT_EQ(r.find("ripple_sin_1")->unit, "N");
  for (const auto& w : r.diagnostics.warnings) EXPECT_EQ(w.find("Fv_per_K"), std::string::npos) << w;
  EXPECT_EQ(r.diagnostics.numbers.at("temperature_ref"), p.T_ref);
  EXPECT_EQ(r.diagnostics.numbers.at("ripple_period"), p.period);
  // The attached law carries the conditions as its effects, ready to simulate (docs/laws.md).
  ASSERT_TRUE(r.law.has_value());
  EXPECT_EQ(r.law->scalars.at("mu_load"), r.value("mu_load"));
  EXPECT_EQ(r.law->scalars.at("Fv_per_K"), r.value("Fv_per_K"));
  EXPECT_EQ(r.law->scalars.at("T_ref"), p.T_ref);
  EXPECT_EQ(r.law->scalars.at("ripple_period"), p.period);
  EXPECT_EQ(r.law->arrays.at("ripple_a"), std::vector<double>{r.value("ripple_sin_1")});
  EXPECT_EQ(r.law->arrays.at("ripple_b"), std::vector<double>{r.value("ripple_cos_1")});
  EXPECT_EQ(r.law->scalars.count("load_gain"), 0u);  // the load acting on the axis is not friction
  EXPECT_NE(r.diagnostics.texts.at("law_conditions").find("the law carries the conditions"), std::string::npos);
}

TEST(IdimConditions, ReferenceTemperatureDefaultsToTheMeanAndMovesFvOnly) {
  // T_ref not given: the mean temperature of the used samples. Fv is then the viscous coefficient
  // at that temperature, Fv_per_K unchanged.
  const Truth p;
  fl::IdimOptions o = with_conditions();
  o.temperature_ref = std::numeric_limits<double>::quiet_NaN();
  const fl::IdimData d = simulate();
  const fl::Result r = fl::identify_idim(d, o);
  ASSERT_TRUE(r.ok()) << r.message;
  const double mean = d.temperature.segment(o.skip, d.temperature.size() - o.skip - o.skip_end).mean();
  EXPECT_DOUBLE_EQ(r.diagnostics.numbers.at("temperature_ref"), mean);
  expect_rel(r.value("Fv"), p.Fv + p.Fv_per_K * (mean - p.T_ref), "Fv at the mean temperature");
  expect_rel(r.value("Fv_per_K"), p.Fv_per_K, "Fv_per_K");
}

TEST(IdimConditions, TwoRippleHarmonicsGiveFourParameters) {
  fl::IdimOptions o = with_conditions();
  o.ripple_harmonics = 2;
  const fl::Result r = fl::identify_idim(simulate(), o);
  ASSERT_TRUE(r.ok()) << r.message;
  // The data have no second harmonic: it comes back near zero, on the scale of the first's 0.6 N.
  EXPECT_NEAR(r.value("ripple_sin_2"), 0.0, kRecoveryRelTol * 0.6);
  EXPECT_NEAR(r.value("ripple_cos_2"), 0.0, kRecoveryRelTol * 0.6);
}

TEST(IdimConditions, BadInputNamesWhatIsMissing) {
  fl::IdimData no_load = simulate();
  no_load.load.resize(0);
  EXPECT_NE(error_of([&] { fl::identify_idim(no_load, with_conditions()); }).find("conditions: the 'load' term needs the load column"),
            std::string::npos);
  fl::IdimData no_temperature = simulate();
  no_temperature.temperature.resize(0);
  EXPECT_NE(error_of([&] { fl::identify_idim(no_temperature, with_conditions()); }).find("'temperature' term needs the temperature column"),
            std::string::npos);
  fl::IdimData short_load = simulate();
  short_load.load.conservativeResize(100);
  EXPECT_NE(error_of([&] { fl::identify_idim(short_load, with_conditions()); }).find("load has 100 samples; expected 30001"),
            std::string::npos);
  fl::IdimOptions no_period = with_conditions();
  no_period.ripple_period = 0;
  EXPECT_NE(error_of([&] { fl::identify_idim(simulate(), no_period); }).find("ripple period = 0 must be > 0"), std::string::npos);
  // Regressors from a velocity have no position for the ripple.
  fl::IdimData by_velocity = simulate();
  by_velocity.velocity = by_velocity.position;  // any velocity-like signal: the check comes first
  fl::IdimOptions from_velocity = with_conditions();
  from_velocity.source = fl::IdimSource::velocity;
  EXPECT_NE(error_of([&] { fl::identify_idim(by_velocity, from_velocity); }).find("'ripple' term needs the position"),
            std::string::npos);
  fl::IdimOptions unknown = with_conditions();
  unknown.terms.push_back("humidity");
  EXPECT_NE(error_of([&] { fl::identify_idim(simulate(), unknown); }).find("unknown term 'humidity'; known terms:"),
            std::string::npos);
}

TEST(IdimConditions, ColumnGivenWithoutItsTermIsReported) {
  fl::IdimOptions o;
  o.skip_end = 49;
  const fl::Result r = fl::identify_idim(simulate(), o);  // the data carry load and temperature
  ASSERT_TRUE(r.ok()) << r.message;
  int reported = 0;
  for (const auto& w : r.diagnostics.warnings) reported += w.find("the terms do not include") != std::string::npos;
  EXPECT_EQ(reported, 2);
}
