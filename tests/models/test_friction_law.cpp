// FrictionLaw: a law chosen by name. from_spec for every name, the error messages for unknown
// names, unknown and missing parameters, the to_spec round trip, and wrong-kind calls.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {
namespace {

using ::testing::HasSubstr;

// Dispatch through the variant calls the same code: results agree to rounding.
constexpr double kRelTol = 1e-14;

// A complete, valid file form for every law name, with values unlike the defaults.
std::map<std::string, LawSpec> all_specs() {
  std::map<std::string, LawSpec> m;
  auto add = [&](LawSpec s) { m[s.name] = s; };
  add({"coulomb", {{"Fc", 2.0}}, {}, {}});
  add({"viscous", {{"Fv", 0.3}}, {}, {}});
  add({"coulomb-viscous", {{"Fc", 2.0}, {"Fv", 0.3}}, {}, {}});
  add({"static-coulomb-viscous", {{"Fs", 2.5}, {"Fc", 2.0}, {"Fv", 0.3}}, {}, {}});
  add({"stribeck", {{"Fc", 2.0}, {"Fs", 2.5}, {"vs", 0.01}, {"delta", 1.5}, {"Fv", 0.3}}, {}, {}});
  add({"karnopp", {{"Fs", 2.5}, {"Fc", 2.0}, {"Fv", 0.3}, {"dv", 1e-3}}, {}, {}});
  add({"table", {}, {{"velocity", {-0.2, -0.1, 0.1, 0.2}}, {"force", {-1.4, -1.2, 1.1, 1.3}}}, {}});
  add({"smooth", {{"Fc", 2.0}, {"Fs", 2.5}, {"vs", 0.01}, {"delta", 1.5}, {"Fv", 0.3}, {"vt", 1e-4}}, {}, {{"shape", "atan"}}});
  add({"coulomb-asymmetric", {{"Fc_pos", 2.0}, {"Fc_neg", 1.5}}, {}, {}});
  add({"viscous-asymmetric", {{"Fv_pos", 0.3}, {"Fv_neg", 0.2}}, {}, {}});
  add({"coulomb-viscous-asymmetric", {{"Fc_pos", 2.0}, {"Fv_pos", 0.3}, {"Fc_neg", 1.5}, {"Fv_neg", 0.2}}, {}, {}});
  add({"static-coulomb-viscous-asymmetric",
       {{"Fs_pos", 2.5}, {"Fc_pos", 2.0}, {"Fv_pos", 0.3}, {"Fs_neg", 2.0}, {"Fc_neg", 1.5}, {"Fv_neg", 0.2}},
       {},
       {}});
  add({"stribeck-asymmetric",
       {{"Fc_pos", 2.0}, {"Fs_pos", 2.5}, {"vs_pos", 0.01}, {"delta_pos", 1.5}, {"Fv_pos", 0.3},
        {"Fc_neg", 1.5}, {"Fs_neg", 2.0}, {"vs_neg", 0.02}, {"delta_neg", 2.0}, {"Fv_neg", 0.2}},
       {},
       {}});
  add({"dahl", {{"sigma0", 2e5}, {"Fc", 2.0}, {"alpha", 1.5}}, {}, {}});
  add({"lugre",
       {{"sigma0", 2e5}, {"sigma1", 300.0}, {"sigma2", 0.3}, {"Fc", 2.0}, {"Fs", 2.5}, {"vs", 0.01}, {"delta", 1.5},
        {"vd", 0.02}},
       {},
       {}});
  add({"elastoplastic",
       {{"sigma0", 2e5}, {"sigma1", 300.0}, {"sigma2", 0.3}, {"Fc", 2.0}, {"Fs", 2.5}, {"vs", 0.01}, {"delta", 1.5},
        {"zba", 5e-6}},
       {},
       {}});
  add({"gms",
       {{"Fc", 2.0}, {"Fs", 2.5}, {"vs", 0.01}, {"delta", 1.5}, {"C", 30.0}, {"sigma2", 0.3}},
       {{"k", {1e5, 2e4}}, {"alpha", {0.6, 0.4}}},
       {}});
  return m;
}

const std::vector<std::string> kDynamic = {"dahl", "lugre", "elastoplastic", "gms"};
bool is_dynamic_name(const std::string& n) { return std::find(kDynamic.begin(), kDynamic.end(), n) != kDynamic.end(); }

std::string error_of(const LawSpec& spec) {
  try {
    FrictionLaw::from_spec(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no std::invalid_argument>";
}

TEST(FrictionLaw, NamesAreTheSeventeenLaws) {
  const auto& names = FrictionLaw::names();
  EXPECT_THAT(names, ::testing::ElementsAre("coulomb", "viscous", "coulomb-viscous", "static-coulomb-viscous", "stribeck",
                                            "karnopp", "table", "smooth", "coulomb-asymmetric", "viscous-asymmetric",
                                            "coulomb-viscous-asymmetric", "static-coulomb-viscous-asymmetric",
                                            "stribeck-asymmetric", "dahl", "lugre", "elastoplastic", "gms"));
}

TEST(FrictionLaw, FromSpecForEveryName) {
  const auto specs = all_specs();
  for (const auto& name : FrictionLaw::names()) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(specs.count(name)) << "the test has no spec for law " << name;
    const LawSpec& spec = specs.at(name);
    const FrictionLaw law = FrictionLaw::from_spec(spec);
    EXPECT_EQ(law.name(), name);
    EXPECT_EQ(law.is_dynamic(), is_dynamic_name(name));
    // Every scalar given is a parameter with that value, and there are no others.
    const auto params = law.parameters();
    EXPECT_EQ(params.size(), spec.scalars.size());
    for (const auto& p : params) {
      ASSERT_TRUE(spec.scalars.count(p.name)) << p.name;
      EXPECT_EQ(p.value, spec.scalars.at(p.name)) << p.name;
    }
    if (law.is_dynamic()) {
      EXPECT_GT(law.num_states(), 0);
      EXPECT_EQ(law.breakaway_positive(), 0.0);
    } else {
      EXPECT_EQ(law.num_states(), 0);
    }
  }
}

TEST(FrictionLaw, FromSpecBuildsTheRightValues) {
  const FrictionLaw s = FrictionLaw::from_spec(all_specs().at("stribeck"));
  // 2 + 0.5 exp(-(0.01/0.01)^1.5) + 0.3 * 0.01
  EXPECT_NEAR(s.sliding(0.01), 2.0 + 0.5 * std::exp(-1.0) + 0.003, kRelTol * 2.0);
  EXPECT_EQ(s.breakaway_positive(), 2.5);
  const FrictionLaw g = FrictionLaw::from_spec(all_specs().at("gms"));
  EXPECT_EQ(g.num_states(), 2);
  const FrictionLaw sm = FrictionLaw::from_spec(all_specs().at("smooth"));
  EXPECT_EQ(std::get<Smooth>(sm.variant()).shape, SmoothShape::atan);
}

TEST(FrictionLaw, UnknownLawListsValidNames) {
  const std::string msg = error_of({"stribek", {{"Fc", 1.0}}, {}, {}});
  EXPECT_THAT(msg, HasSubstr("unknown friction law 'stribek'; valid laws: coulomb, viscous, "));
  for (const auto& name : FrictionLaw::names()) EXPECT_THAT(msg, HasSubstr(name));
}

TEST(FrictionLaw, UnknownParameterListsTheLawsParameters) {
  LawSpec spec = all_specs().at("stribeck");
  spec.scalars["Fk"] = 1.0;
  EXPECT_EQ(error_of(spec), "stribeck: unknown parameter 'Fk'; stribeck has Fc, Fs, vs, delta, Fv");
  LawSpec g = all_specs().at("gms");
  g.scalars["sigma0"] = 1.0;
  EXPECT_EQ(error_of(g), "gms: unknown parameter 'sigma0'; gms has Fc, Fs, vs, delta, C, sigma2, k, alpha");
  LawSpec a = all_specs().at("coulomb-asymmetric");
  a.scalars["Fc"] = 1.0;
  EXPECT_EQ(error_of(a), "coulomb-asymmetric: unknown parameter 'Fc'; coulomb-asymmetric has Fc_pos, Fc_neg");
  LawSpec t = all_specs().at("table");
  t.scalars["Fc"] = 1.0;
  EXPECT_EQ(error_of(t), "table: unknown parameter 'Fc'; table has velocity, force (lists of numbers)");
}

TEST(FrictionLaw, MissingParameterIsNamed) {
  LawSpec spec = all_specs().at("stribeck");
  spec.scalars.erase("vs");
  EXPECT_EQ(error_of(spec), "stribeck: missing parameter 'vs' (stribeck needs Fc, Fs, vs, delta, Fv)");
  LawSpec l = all_specs().at("lugre");
  l.scalars.erase("sigma0");
  EXPECT_THAT(error_of(l), HasSubstr("lugre: missing parameter 'sigma0'"));
  LawSpec g = all_specs().at("gms");
  g.arrays.erase("alpha");
  EXPECT_EQ(error_of(g), "gms: missing parameter 'alpha' (a list of numbers)");
  LawSpec t = all_specs().at("table");
  t.arrays.erase("force");
  EXPECT_EQ(error_of(t), "table: missing parameter 'force' (a list of numbers, N or N m)");
}

TEST(FrictionLaw, OptionalParametersTakeTheirDefaults) {
  LawSpec spec = all_specs().at("stribeck");
  spec.scalars.erase("delta");
  EXPECT_EQ(std::get<Stribeck>(FrictionLaw::from_spec(spec).variant()).delta, 2.0);
  LawSpec l = all_specs().at("lugre");
  l.scalars.erase("vd");
  EXPECT_EQ(std::get<LuGre>(FrictionLaw::from_spec(l).variant()).vd, 0.0);
  LawSpec d = all_specs().at("dahl");
  d.scalars.erase("alpha");
  EXPECT_EQ(std::get<Dahl>(FrictionLaw::from_spec(d).variant()).alpha, 1.0);
  // smooth: Fs defaults to Fc (no Stribeck dip), Fv to 0.
  const FrictionLaw sm = FrictionLaw::from_spec({"smooth", {{"Fc", 2.0}, {"vt", 1e-3}}, {}, {}});
  EXPECT_EQ(std::get<Smooth>(sm.variant()).Fs, 2.0);
  EXPECT_EQ(std::get<Smooth>(sm.variant()).Fv, 0.0);
  EXPECT_EQ(std::get<Smooth>(sm.variant()).shape, SmoothShape::tanh);
}

TEST(FrictionLaw, InvalidValueGivesTheLawsMessage) {
  LawSpec spec = all_specs().at("stribeck");
  spec.scalars["vs"] = -1;
  EXPECT_EQ(error_of(spec), "stribeck: vs = -1 must be > 0 (m/s or rad/s)");
  LawSpec sm = all_specs().at("smooth");
  sm.strings["shape"] = "sigmoid";
  EXPECT_EQ(error_of(sm), "smooth: shape 'sigmoid' is not valid; expected tanh or atan");
  EXPECT_THROW(FrictionLaw(Stribeck{1.0, 0.5, 1e-3, 2.0, 0.0}), std::invalid_argument);  // the constructor validates
}

TEST(FrictionLaw, ToSpecRoundTrip) {
  for (const auto& [name, spec] : all_specs()) {
    SCOPED_TRACE(name);
    const FrictionLaw law = FrictionLaw::from_spec(spec);
    const LawSpec out = law.to_spec();
    EXPECT_EQ(out.name, spec.name);
    EXPECT_EQ(out.scalars, spec.scalars);
    EXPECT_EQ(out.arrays, spec.arrays);
    if (name == "smooth") {
      EXPECT_EQ(out.strings, spec.strings);
    }
    const LawSpec again = FrictionLaw::from_spec(out).to_spec();
    EXPECT_EQ(again.scalars, out.scalars);
    EXPECT_EQ(again.arrays, out.arrays);
    EXPECT_EQ(again.strings, out.strings);
  }
}

TEST(FrictionLaw, WrongKindCallsThrowLogicError) {
  double z[3] = {0, 0, 0}, dz[3];
  const FrictionLaw stat = Stribeck{};
  EXPECT_THROW(stat.derivative(std::span<const double>(z, 1), 1.0, std::span<double>(dz, 1)), std::logic_error);
  EXPECT_THROW(stat.force(std::span<const double>(z, 1), 1.0), std::logic_error);
  EXPECT_THROW(stat.step(std::span<double>(z, 1), 1.0, 1e-3), std::logic_error);
  EXPECT_THROW(stat.steady_state(1.0, std::span<double>(z, 1)), std::logic_error);
  try {
    stat.step(std::span<double>(z, 1), 1.0, 1e-3);
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "friction law 'stribeck' is static; step(z, v, dt) is for dynamic laws");
  }
  const FrictionLaw dyn = LuGre{};
  EXPECT_THROW(dyn.force(1.0, 0.0), std::logic_error);
  try {
    dyn.force(1.0, 0.0);
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "friction law 'lugre' is dynamic; force(v, applied) is for static laws");
  }
  // std::invalid_argument is also a std::logic_error: make sure it is not that.
  try {
    dyn.force(1.0, 0.0);
  } catch (const std::invalid_argument&) {
    ADD_FAILURE() << "wrong-kind call threw std::invalid_argument";
  } catch (const std::logic_error&) {
  }
}

TEST(FrictionLaw, DispatchMatchesTheConcreteLaw) {
  const Stribeck s{1.0, 1.5, 0.01, 2.0, 0.4};
  const FrictionLaw fs = s;
  for (double v : {-0.3, -1e-3, 2e-3, 0.7}) {
    EXPECT_EQ(fs.sliding(v), s.sliding(v));
    EXPECT_EQ(fs.force(v, 0.0), s.sliding(v));
  }
  EXPECT_EQ(fs.force(0.0, 1.0), 1.0);
  EXPECT_EQ(fs.force(0.0, -2.0), -1.5);
  const Karnopp k{1.5, 1.0, 0.1, 1e-3};
  EXPECT_EQ(FrictionLaw(k).force(5e-4, 0.7), 0.7);  // Karnopp's band through the variant

  const LuGre l;
  const FrictionLaw fl = l;
  double z1[1] = {1e-6}, z2[1] = {1e-6}, d1[1], d2[1];
  fl.derivative(std::span<const double>(z1, 1), 2e-3, std::span<double>(d1, 1));
  l.derivative(std::span<const double>(z2, 1), 2e-3, std::span<double>(d2, 1));
  EXPECT_EQ(d1[0], d2[0]);
  EXPECT_EQ(fl.step(std::span<double>(z1, 1), 2e-3, 1e-3), l.step(std::span<double>(z2, 1), 2e-3, 1e-3));
  EXPECT_EQ(z1[0], z2[0]);
  // For a dynamic law, sliding(v) is the steady-state (Stribeck) force.
  const double want = Stribeck{1.0, 1.5, 1e-3, 2.0, 0.4}.sliding(2e-3);
  EXPECT_NEAR(fl.sliding(2e-3), want, kRelTol * std::abs(want));
  const FrictionLaw fg = Gms{};
  EXPECT_NEAR(fg.sliding(2e-3), want, kRelTol * std::abs(want));
}

TEST(FrictionLaw, DefaultIsCoulomb) {
  const FrictionLaw law;
  EXPECT_EQ(law.name(), "coulomb");
  EXPECT_EQ(law.sliding(-2.0), -1.0);
}

}  // namespace
}  // namespace frictionlab
