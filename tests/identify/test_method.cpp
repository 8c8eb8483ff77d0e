// What a method tells a result's readers (identify/method.hpp): its axis and the fitted signal's
// quantity and unit come with the Result, set by the method from its options, so that the text
// table, the report and the figures need neither the method's name nor the units' spelling.
// Also the one parameter type (models/parameter.hpp) and the one number formatter (format.hpp).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <stdexcept>

#include "../error_message.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/decay.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/models/friction_law.hpp"

namespace frictionlab {
namespace {

// A pendulum-like free decay with Coulomb friction as a rig logs it: the amplitude falls by a
// fixed step per half cycle, an encoder quantises the angle, the sensor adds seeded noise.
DecayData coulomb_decay_record() {
  constexpr double kDt = 1e-3, kOmega = 2 * std::numbers::pi, kA0 = 0.2, kStep = 0.004;  // rad, rad/half cycle
  constexpr double kQuantum = 2 * std::numbers::pi / 40000;  // 10000-line encoder, x4
  std::mt19937 gen(15);
  std::normal_distribution<double> noise(0.0, 2e-5);
  const int n = 20000;
  DecayData d{Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const double t = i * kDt;
    const double a = std::max(0.0, kA0 - kStep * std::floor(t * kOmega / std::numbers::pi));
    d.time[i] = t;
    d.position[i] = std::round((a * std::cos(kOmega * t) + noise(gen)) / kQuantum) * kQuantum;
  }
  return d;
}

TEST(Method, DecayResultCarriesItsAxisAndFitUnit) {
  const DecayData d = coulomb_decay_record();
  for (const Axis axis : {Axis::linear, Axis::rotary}) {
    DecayOptions o;
    o.stiffness = 9.81;
    o.axis = axis;
    const Result r = identify_decay(d, o);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.axis, axis);
    EXPECT_EQ(r.fit.quantity, "energy lost per half cycle");
    EXPECT_EQ(r.fit.unit, "J");  // energy: J on either axis
    const Parameter* Fc = r.find("Fc");
    ASSERT_NE(Fc, nullptr);
    EXPECT_EQ(Fc->unit, axis == Axis::rotary ? "N m" : "N");
    const auto j = nlohmann::json::parse(to_json(r));
    EXPECT_EQ(j["axis"], axis == Axis::rotary ? "rotary" : "linear");
    EXPECT_EQ(j["fit"]["unit"], "J");
  }
}

TEST(Method, NewResultTakesTheUnitOfTheFittedSignalOnTheAxis) {
  const Result idim = new_result(method_info("idim"), "coulomb-viscous", Axis::rotary);
  EXPECT_EQ(idim.method, "idim");
  EXPECT_EQ(idim.axis, Axis::rotary);
  EXPECT_EQ(idim.fit.unit, "N m");
  EXPECT_EQ(new_result(method_info("lugre"), "lugre", Axis::linear).fit.unit, "m");
  // validate reports per-signal errors: no single fitted signal, no unit.
  const Result v = new_result(method_info("validate"), "", Axis::linear);
  EXPECT_TRUE(v.fit.quantity.empty());
  EXPECT_TRUE(v.fit.unit.empty());
  EXPECT_FALSE(nlohmann::json::parse(to_json(v))["fit"].contains("unit"));
}

TEST(Method, AHandMadeResultGetsItsMethodsFitUnitOnItsAxis) {
  Result r;  // as a program would make one without new_result: method and axis only
  r.method = "sweep";
  r.axis = Axis::rotary;
  EXPECT_EQ(fit_signal_and_unit(r), std::make_pair(std::string("friction force"), std::string("N m")));
  r.method = "not-a-method";
  EXPECT_EQ(fit_signal_and_unit(r), std::make_pair(std::string(), std::string()));
  r.fit.unit = "J";  // the result's own word wins
  EXPECT_EQ(fit_signal_and_unit(r).second, "J");
}

TEST(Method, EveryMethodHasASummaryAndUnknownNamesAreListed) {
  ASSERT_GE(identification_methods().size(), 6u);
  for (const auto& m : identification_methods()) {
    EXPECT_FALSE(m.summary.empty()) << m.name;
    EXPECT_EQ(m.fit_signal.empty(), !m.fit_quantity.has_value()) << m.name;
    EXPECT_EQ(&method_info(m.name), &m);
  }
  EXPECT_NE(testing::error_of([] { method_info("hammer"); }).find("'hammer' is not known; expected one of idim"),
            std::string::npos);
}

TEST(Method, JsonSectionsGoUnderTheirKeyAndBadOnesAreRefused) {
  Result r;
  r.method = "envelope";
  r.json_sections["result"] = R"({"kind": "linear", "half_cycles": 7})";
  const auto j = nlohmann::json::parse(to_json(r, -1));
  EXPECT_EQ(j["result"]["kind"], "linear");
  EXPECT_EQ(j["result"]["half_cycles"], 7);
  r.json_sections["result"] = "{kind";
  EXPECT_NE(testing::error_of([&] { to_json(r); }).find("section 'result' is not valid JSON"), std::string::npos);
}

TEST(Parameter, OneTypeForLawsFitsAndResults) {
  const FrictionLaw law = Stribeck{};
  const std::vector<Parameter> ps = law.parameters();
  ASSERT_FALSE(ps.empty());
  for (const auto& p : ps) {
    EXPECT_TRUE(p.unit.empty()) << p.name;  // a law's parameter: the axis comes later
    EXPECT_EQ(p.with_unit(Axis::rotary).unit, std::string(unit(p.quantity, Axis::rotary))) << p.name;
  }
  const Parameter fv("Fv", 0.4, 0.01, Quantity::viscous, Axis::rotary, "");
  EXPECT_EQ(fv.unit, "N m s/rad");
  const Parameter e{"Fc", 1.0, 0.1, "N", "at bound"};  // the estimate form tests and methods write
  EXPECT_EQ(e.unit, "N");
  EXPECT_EQ(e.flag, "at bound");
}

TEST(Format, SignificantDigitsAndTheStdsPrecision) {
  EXPECT_EQ(format_number(1e-5), "1e-05");
  EXPECT_EQ(format_number(95.10074896), "95.1007");
  EXPECT_EQ(format_number(95.10074896, 3), "95.1");
  EXPECT_EQ(format_number(1.0 / 3.0, 10), "0.3333333333");
  EXPECT_EQ(format_number(std::nan("")), "nan");
  EXPECT_EQ(format_with_std(95.10074896, 0.10997), std::make_pair(std::string("95.10"), std::string("0.11")));
  EXPECT_EQ(format_with_std(1.234e5, 2.1e3), std::make_pair(std::string("1.234e+05"), std::string("2.1e+03")));
  EXPECT_EQ(format_with_std(2.5, 0.0).second, "0");
  EXPECT_EQ(format_with_std(2.5, std::nan("")).second, "n/a");
}

}  // namespace
}  // namespace frictionlab
