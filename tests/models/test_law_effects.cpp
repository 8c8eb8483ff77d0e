// Load, temperature and position effects composed with the velocity laws (models/law_effects.hpp):
// the levels they move, the file form, and the typed errors of bad parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "frictionlab/error.hpp"
#include "frictionlab/models/friction_law.hpp"

using namespace frictionlab;

namespace {

// The law of `spec` must be refused with an InputError of code law.parameter whose key is `key`
// and whose message names `key` and (when given) `also`.
void expect_refused(const LawSpec& spec, const std::string& key, const std::string& also = "") {
  try {
    (void)FrictionLaw::from_spec(spec);
    FAIL() << "accepted a law that breaks " << key;
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "law.parameter") << e.what();
    EXPECT_EQ(e.fields().key, key) << e.what();
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    if (!also.empty()) EXPECT_NE(std::string(e.what()).find(also), std::string::npos) << e.what();
  }
}

LawSpec stribeck_spec() {
  LawSpec s;
  s.name = "stribeck";
  s.scalars = {{"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.01}, {"Fv", 0.4}};
  return s;
}

// Every value here is a sum or product of a few doubles: a few roundings at most.
constexpr double kRel = 1e-14;

}  // namespace

TEST(LoadEffect, OneCoefficientRaisesStaticAndCoulombLevelsTogether) {
  LawSpec s = stribeck_spec();
  s.scalars["mu_load"] = 0.05;
  const FrictionLaw law = FrictionLaw::from_spec(s);
  Conditions c;
  c.load = -20.0;  // the magnitude counts
  EXPECT_NEAR(law.breakaway_positive(c), 1.5 + 0.05 * 20, kRel * 2.5);
  EXPECT_NEAR(law.breakaway_negative(c), 1.5 + 0.05 * 20, kRel * 2.5);
  // Far past vs the Stribeck curve is Fc' + Fv v.
  EXPECT_NEAR(law.sliding(1.0, c), 1.0 + 0.05 * 20 + 0.4, kRel * 2.4);
  EXPECT_NEAR(law.sliding(-1.0, c), -(1.0 + 0.05 * 20 + 0.4), kRel * 2.4);
  // Without load the law is its plain self.
  EXPECT_EQ(law.sliding(0.3, Conditions{}), law.sliding(0.3));
  EXPECT_EQ(law.breakaway_positive(Conditions{}), 1.5);
}

TEST(LoadEffect, TwoCoefficientsRaiseTheLevelsApart) {
  LawSpec s = stribeck_spec();
  s.scalars["mu_load_static"] = 0.08;
  s.scalars["mu_load_coulomb"] = 0.02;
  const FrictionLaw law = FrictionLaw::from_spec(s);
  Conditions c;
  c.load = 50.0;
  EXPECT_NEAR(law.breakaway_positive(c), 1.5 + 4.0, kRel * 5.5);
  EXPECT_NEAR(law.sliding(1.0, c), 1.0 + 1.0 + 0.4, kRel * 2.4);
  // The file form keeps both.
  const LawSpec back = law.to_spec();
  EXPECT_EQ(back.scalars.at("mu_load_static"), 0.08);
  EXPECT_EQ(back.scalars.at("mu_load_coulomb"), 0.02);
  EXPECT_EQ(FrictionLaw::from_spec(back).to_spec().scalars, back.scalars);
}

TEST(LoadEffect, ComposesWithEveryLawThatHasACoulombLevel) {
  // One law of each family: static with one level, with two, asymmetric, and the bristle laws.
  const std::vector<LawSpec> specs = {
      {"coulomb", {{"Fc", 1.0}}, {}, {}},
      {"karnopp", {{"Fc", 1.0}, {"Fs", 1.5}, {"Fv", 0.1}, {"dv", 1e-4}}, {}, {}},
      {"stribeck-asymmetric",
       {{"Fc_pos", 1.0}, {"Fs_pos", 1.5}, {"vs_pos", 0.01}, {"Fv_pos", 0.4}, {"Fc_neg", 0.8}, {"Fs_neg", 1.2}, {"vs_neg", 0.01}, {"Fv_neg", 0.3}},
       {}, {}},
      {"lugre", {{"sigma0", 1e5}, {"sigma1", 300}, {"sigma2", 0.4}, {"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.001}}, {}, {}},
  };
  for (LawSpec s : specs) {
    const FrictionLaw plain = FrictionLaw::from_spec(s);
    s.scalars["mu_load"] = 0.1;
    const FrictionLaw law = FrictionLaw::from_spec(s);
    Conditions c;
    c.load = 10.0;  // raises every level by 1
    // A difference of two forces of a few N, each a few roundings: well below 1e-12 N.
    constexpr double kAbs = 1e-12;
    // Far past the Stribeck velocity the force rises by exactly the Coulomb rise.
    EXPECT_NEAR(law.sliding(2.0, c) - plain.sliding(2.0), 1.0, kAbs) << s.name;
    EXPECT_NEAR(law.sliding(-2.0, c) - plain.sliding(-2.0), -1.0, kAbs) << s.name;
    if (!law.is_dynamic()) {
      EXPECT_NEAR(law.breakaway_positive(c) - plain.breakaway_positive(), 1.0, kAbs) << s.name;
      EXPECT_NEAR(law.breakaway_negative(c) - plain.breakaway_negative(), 1.0, kAbs) << s.name;
    }
  }
}

TEST(TemperatureEffect, ViscousAndCoulombCoefficientsAreLinearInTheTemperature) {
  LawSpec s = stribeck_spec();
  s.scalars["T_ref"] = 20.0;
  s.scalars["Fv_per_K"] = -0.004;
  s.scalars["Fc_per_K"] = -0.002;
  const FrictionLaw law = FrictionLaw::from_spec(s);
  Conditions c;
  c.temperature = 70.0;  // 50 K above T_ref: Fv 0.4 -> 0.2, Fc 1 -> 0.9, Fs 1.5 -> 1.4
  EXPECT_NEAR(law.sliding(1.0, c), 0.9 + 0.2, kRel * 1.1 * 8);
  EXPECT_NEAR(law.breakaway_positive(c), 1.4, kRel * 1.4 * 8);
  // No temperature given: the law at T_ref.
  EXPECT_EQ(law.sliding(1.0, Conditions{}), law.sliding(1.0));
}

TEST(TemperatureEffect, ARangeThatMakesACoefficientNegativeIsRefusedNamingItAndTheTemperature) {
  LawSpec s = stribeck_spec();
  s.scalars["T_ref"] = 20.0;
  s.scalars["Fv_per_K"] = -0.004;  // Fv = 0 at 120 degC
  s.scalars["T_max"] = 130.0;
  expect_refused(s, "Fv_per_K", "130");
  s.scalars["T_max"] = 110.0;
  EXPECT_NO_THROW((void)FrictionLaw::from_spec(s));
  s.scalars["Fc_per_K"] = 0.02;  // Fc = 0 at -30 degC
  s.scalars["T_min"] = -40.0;
  expect_refused(s, "Fc_per_K", "-40");
  // Outside a given range, at a run's temperature: refused naming the bound.
  s.scalars["T_min"] = -20.0;
  const FrictionLaw law = FrictionLaw::from_spec(s);
  Conditions c;
  c.temperature = 111.0;
  try {
    (void)law.sliding(1.0, c);
    FAIL() << "a temperature above T_max was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "law.parameter");
    EXPECT_EQ(e.fields().key, "T_max");
    EXPECT_NE(std::string(e.what()).find("111"), std::string::npos) << e.what();
  }
  // Without a range, a temperature that makes a coefficient negative is refused when it occurs.
  LawSpec open = stribeck_spec();
  open.scalars["T_ref"] = 20.0;
  open.scalars["Fv_per_K"] = -0.004;
  c.temperature = 125.0;
  try {
    (void)FrictionLaw::from_spec(open).sliding(1.0, c);
    FAIL() << "a negative viscous coefficient was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.fields().key, "Fv_per_K");
    EXPECT_NE(std::string(e.what()).find("125"), std::string::npos) << e.what();
  }
}

TEST(RippleEffect, AddsTheHarmonicsAndHoldsWhileTheRestWithinTheLevels) {
  LawSpec s = stribeck_spec();
  s.scalars["ripple_period"] = 0.004;  // a 4 mm screw pitch
  s.arrays["ripple_a"] = {0.2, 0.05};
  s.arrays["ripple_b"] = {0.1, 0.0};
  const FrictionLaw law = FrictionLaw::from_spec(s);
  const double q = 0.0013, w = 2 * std::numbers::pi * q / 0.004;
  const double r = 0.2 * std::sin(w) + 0.05 * std::sin(2 * w) + 0.1 * std::cos(w);
  constexpr double kAbs = 1e-15;        // N: the same sum of three terms, in another order at most
  constexpr double kPeriodAbs = 1e-13;  // N: q + P rounds the phase by ~1e-16 of 2 pi, times the amplitudes
  EXPECT_NEAR(law.ripple(q), r, kAbs);
  EXPECT_NEAR(law.ripple(q + 0.004), r, kPeriodAbs);  // periodic
  Conditions c;
  c.position = q;
  // At rest: holds applied within r +- Fs, and is r + Fs beyond.
  EXPECT_EQ(law.force(0.0, r + 1.4, c), r + 1.4);
  EXPECT_NEAR(law.force(0.0, r + 1.6, c), r + 1.5, kAbs);
  EXPECT_NEAR(law.force(0.0, r - 1.6, c), r - 1.5, kAbs);
  EXPECT_NEAR(law.force(0.5, 0.0, c), law.sliding(0.5) + r, kAbs);
  // Round trip of the file form.
  EXPECT_EQ(FrictionLaw::from_spec(law.to_spec()).ripple(q), law.ripple(q));
}

TEST(RippleEffect, PotentialIsTheIntegralOfTheRipple) {
  PositionRipple r{0.01, {0.3, -0.1}, {0.2, 0.05}, {}, {}};
  // Simpson's rule over a third of a period, 2000 panels: error ~ (h^4) r'''' ~ 1e-16 relative.
  const double q1 = 0.0033;
  const int n = 2000;
  const double h = q1 / n;
  double sum = r.force(0) + r.force(q1);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * r.force(i * h);
  constexpr double kQuadratureAbs = 1e-12;  // J: the quadrature's error and roundoff on a 1e-3 J potential
  EXPECT_NEAR(r.potential(q1), sum * h / 3, kQuadratureAbs);
  // The slope is its derivative (central difference, h = 1e-7 of a 1e-2 period: truncation ~ 1e-9
  // N/m, roundoff ~ 1e-16 / 1e-7 ~ 1e-9 N/m, against slopes of ~ 200 N/m).
  constexpr double kDifferenceAbs = 1e-6;
  EXPECT_NEAR(r.slope(q1), (r.force(q1 + 1e-7) - r.force(q1 - 1e-7)) / 2e-7, kDifferenceAbs);
}

TEST(EffectErrors, BadParametersAreRefusedWithTheirName) {
  LawSpec s = stribeck_spec();
  s.scalars["mu_load"] = -0.1;
  expect_refused(s, "mu_load");
  s.scalars.erase("mu_load");
  s.scalars["mu_load_static"] = 0.01;
  s.scalars["mu_load_coulomb"] = 0.02;
  expect_refused(s, "mu_load_static", "mu_load_coulomb");
  s.scalars.erase("mu_load_coulomb");
  expect_refused(s, "mu_load_coulomb");
  s.scalars.erase("mu_load_static");
  s.scalars["ripple_period"] = 0.0;
  s.arrays["ripple_a"] = {0.1};
  expect_refused(s, "ripple_period");
  s.scalars["ripple_period"] = -1.0;
  expect_refused(s, "ripple_period");
  s.scalars["ripple_period"] = 1.0;
  s.arrays["ripple_b"] = {0.1, 0.2};
  expect_refused(s, "ripple_b");
  s.arrays.erase("ripple_b");
  s.scalars.erase("ripple_period");
  expect_refused(s, "ripple_period");  // amplitudes without a period
  s.arrays.clear();
  s.scalars["Fv_per_K"] = -0.001;
  expect_refused(s, "T_ref");  // a slope without its reference temperature
  // Effects a law has nothing for.
  LawSpec viscous{"viscous", {{"Fv", 0.5}, {"mu_load", 0.1}}, {}, {}};
  expect_refused(viscous, "mu_load", "viscous");
  LawSpec coulomb{"coulomb", {{"Fc", 1.0}, {"mu_load_static", 0.2}, {"mu_load_coulomb", 0.1}}, {}, {}};
  expect_refused(coulomb, "mu_load_static", "one level");
  LawSpec dry{"coulomb", {{"Fc", 1.0}, {"T_ref", 20.0}, {"Fv_per_K", -0.01}}, {}, {}};
  expect_refused(dry, "Fv_per_K", "viscous");
}

// A ripple given as a table over one period (ripple_position, ripple_force): periodic, linear
// between the rows, its slope the segment's, its potential the integral (a table's mean included),
// and the file form's round trip.
TEST(RippleTable, InterpolatesPeriodicallyBetweenItsRows) {
  LawSpec s = stribeck_spec();
  s.scalars["ripple_period"] = 0.004;                        // m
  s.arrays["ripple_position"] = {0.001, 0.002, 0.0035, 0.005};  // m: spans one period from 1 mm
  s.arrays["ripple_force"] = {0.2, -0.3, 0.1, 0.2};             // N: the last row is the first a period on
  const FrictionLaw law = FrictionLaw::from_spec(s);
  ASSERT_TRUE(law.effects().ripple && law.effects().ripple->is_table());
  const PositionRipple& r = *law.effects().ripple;
  constexpr double kAbs = 1e-12;  // N: a wrap by fmod and one linear interpolation
  EXPECT_NEAR(law.ripple(0.001), 0.2, kAbs);
  EXPECT_NEAR(law.ripple(0.0015), -0.05, kAbs);   // halfway along the first segment
  EXPECT_NEAR(law.ripple(0.0030), -0.3 + 0.4 * (1.0 / 1.5), kAbs);
  EXPECT_NEAR(law.ripple(0.0005), 0.1 + 0.1 * (0.001 / 0.0015), kAbs);  // 0.0045 - P: the last segment
  EXPECT_NEAR(law.ripple(-0.0025), law.ripple(0.0015), kAbs);  // periodic on the negative side
  EXPECT_NEAR(law.ripple(0.0415), law.ripple(0.0015), kAbs);   // and ten periods on
  EXPECT_NEAR(r.slope(0.0015), -0.5 / 0.001, 1e-9);            // N/m: the segment's slope
  // The potential against Simpson's rule over each linear piece (exact for a linear integrand).
  auto integral = [&](double a, double b) {
    const int n = 4000;
    const double h = (b - a) / n;
    double sum = r.force(a) + r.force(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * r.force(a + i * h);
    return sum * h / 3;
  };
  constexpr double kQuadratureAbs = 1e-9;  // J: Simpson across the kinks of a piecewise-linear r
  for (double q : {0.0013, 0.0047, -0.0061, 0.0123})
    EXPECT_NEAR(r.potential(q), q >= 0 ? integral(0.0, q) : -integral(q, 0.0), kQuadratureAbs) << "q = " << q;
  // At rest the contact holds while |applied - r(q)| <= Fs.
  Conditions c;
  c.position = 0.0015;
  EXPECT_EQ(law.force(0.0, -0.05 + 1.4, c), -0.05 + 1.4);
  EXPECT_NEAR(law.force(0.0, -0.05 + 1.6, c), -0.05 + 1.5, kAbs);
  // The file form keeps the table; harmonics are none.
  const LawSpec back = law.to_spec();
  EXPECT_EQ(back.arrays.at("ripple_position"), s.arrays.at("ripple_position"));
  EXPECT_EQ(back.arrays.at("ripple_force"), s.arrays.at("ripple_force"));
  EXPECT_EQ(back.arrays.count("ripple_a"), 0u);
  EXPECT_EQ(FrictionLaw::from_spec(back).ripple(0.0027), law.ripple(0.0027));
}

TEST(RippleTable, BadTablesAreRefusedNamingTheKey) {
  LawSpec s = stribeck_spec();
  s.scalars["ripple_period"] = 0.004;
  auto with = [&](std::vector<double> q, std::vector<double> f) {
    LawSpec t = s;
    t.arrays["ripple_position"] = std::move(q);
    t.arrays["ripple_force"] = std::move(f);
    return t;
  };
  expect_refused(with({0.0, 0.002, 0.002, 0.004}, {0.1, 0.2, 0.3, 0.1}), "ripple_position[2]", "strictly increasing");
  expect_refused(with({0.0, 0.003, 0.002, 0.004}, {0.1, 0.2, 0.3, 0.1}), "ripple_position[2]", "strictly increasing");
  expect_refused(with({0.0, 0.002, 0.003}, {0.1, 0.2, 0.1}), "ripple_position", "not one period");
  expect_refused(with({0.0, 0.002, 0.005}, {0.1, 0.2, 0.1}), "ripple_position", "not one period");
  expect_refused(with({0.0, NAN, 0.004}, {0.1, 0.2, 0.1}), "ripple_position[1]", "finite");
  expect_refused(with({0.0, 0.002, 0.004}, {0.1, INFINITY, 0.1}), "ripple_force[1]", "finite");
  expect_refused(with({0.0, 0.002, 0.004}, {0.1, 0.2, 0.15}), "ripple_force[2]", "ripple_force[0]");
  expect_refused(with({0.0, 0.002, 0.004}, {0.1, 0.1}), "ripple_position", "one force");
  expect_refused(with({0.004}, {0.1}), "ripple_position", "at least 2 rows");
  LawSpec both = with({0.0, 0.002, 0.004}, {0.1, 0.2, 0.1});
  both.arrays["ripple_a"] = {0.1};
  expect_refused(both, "ripple_position", "not both");
  LawSpec alone = s;
  alone.arrays["ripple_position"] = {0.0, 0.004};
  expect_refused(alone, "ripple_force", "both");
  LawSpec no_period = with({0.0, 0.002, 0.004}, {0.1, 0.2, 0.1});
  no_period.scalars.erase("ripple_period");
  expect_refused(no_period, "ripple_period");
}
