// The MJCF text of export/mjcf_export.hpp without MuJoCo: what each law maps to, what is listed as
// left out, and the checks of the options. (tests/export/mujoco/ loads the files in MuJoCo.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "error_message.hpp"
#include "frictionlab/export/mjcf_export.hpp"
#include "frictionlab/scenario/law_file.hpp"

namespace frictionlab {
namespace {

using testing::error_of;

FrictionLaw law_of(const nlohmann::json& j) { return law_from_json(j, "law"); }

std::vector<std::string> names(const MjcfModel& m) {
  std::vector<std::string> n;
  for (const auto& l : m.left_out) n.push_back(l.name);
  return n;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

MjcfOptions with_inertia(double M) {
  MjcfOptions o;
  o.inertia = M;
  return o;
}

TEST(MjcfExport, CoulombViscousMapsFullyOnASlideJoint) {
  const MjcfModel m = mjcf_model(CoulombViscous{.Fc = 1.25, .Fv = 0.1}, with_inertia(2.5));
  EXPECT_EQ(m.joint_type, "slide");
  EXPECT_EQ(m.frictionloss, 1.25);
  EXPECT_EQ(m.damping, 0.1);
  EXPECT_EQ(m.body_inertia, 2.5);
  EXPECT_TRUE(m.left_out.empty());
  // Numbers at full precision (shortest round trip), MuJoCo's defaults written out.
  EXPECT_TRUE(has(m.xml, "type=\"slide\" axis=\"1 0 0\" frictionloss=\"1.25\" damping=\"0.1\" armature=\"0\""));
  EXPECT_TRUE(has(m.xml, "mass=\"2.5\""));
  EXPECT_TRUE(has(m.xml, "<option timestep=\"0.002\" integrator=\"Euler\" gravity=\"0 0 0\"/>"));
  EXPECT_TRUE(has(m.xml, "solreffriction=\"0.02 1\" solimpfriction=\"0.9 0.95 0.001 0.5 2\""));
  EXPECT_TRUE(has(m.xml, "<motor name=\"drive\" joint=\"axis\" gear=\"1\"/>"));
  EXPECT_FALSE(has(m.xml, "Left out"));
}

TEST(MjcfExport, RotaryAxisIsAHingeWithItsInertiaAboutTheAxisAndArmature) {
  MjcfOptions o = with_inertia(0.8);
  o.axis = Axis::rotary;
  o.armature = 0.2;
  o.timestep = 0.001;
  const MjcfModel m = mjcf_model(Coulomb{.Fc = 0.3}, o);
  EXPECT_EQ(m.joint_type, "hinge");
  EXPECT_EQ(m.damping, 0.0);
  EXPECT_NEAR(m.body_inertia, 0.6, 1e-15);  // 0.8 - 0.2, one rounding
  EXPECT_EQ(m.armature, 0.2);
  EXPECT_TRUE(has(m.xml, "type=\"hinge\" axis=\"0 0 1\""));
  EXPECT_TRUE(has(m.xml, "armature=\"0.2\""));
  EXPECT_TRUE(has(m.xml, "timestep=\"0.001\""));
  EXPECT_TRUE(has(m.xml, "N m"));
}

TEST(MjcfExport, StribeckListsWhatMujocoCannotExpressWithUnits) {
  const MjcfModel m = mjcf_model(law_of({{"law", "stribeck"}, {"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.001}, {"Fv", 0.4}}),
                                 with_inertia(1.0));
  EXPECT_EQ(m.frictionloss, 1.0);
  EXPECT_EQ(m.damping, 0.4);
  EXPECT_EQ(names(m), (std::vector<std::string>{"Fs", "vs", "delta"}));
  EXPECT_EQ(m.left_out[0].unit, "N");
  EXPECT_EQ(m.left_out[1].unit, "m/s");
  EXPECT_TRUE(has(m.xml, "<!-- Left out (MuJoCo cannot express them):"));
  EXPECT_TRUE(has(m.xml, "Fs = 1.5 N: static (breakaway) level above Fc"));
  EXPECT_TRUE(has(mjcf_left_out_text(m.left_out), "vs = 0.001 m/s: Stribeck curve"));
}

TEST(MjcfExport, LugreMapsSigma2AndListsBristlesAndState) {
  MjcfOptions o = with_inertia(1.0);
  o.axis = Axis::rotary;
  const MjcfModel m = mjcf_model(law_of({{"law", "lugre"}, {"sigma0", 1e5}, {"sigma1", 316.2}, {"sigma2", 0.4},
                                         {"Fc", 1.0}, {"Fs", 1.5}, {"vs", 0.001}}),
                                 o);
  EXPECT_EQ(m.damping, 0.4);
  const auto n = names(m);
  for (const char* want : {"sigma0", "sigma1", "Fs", "vs", "states"})
    EXPECT_NE(std::find(n.begin(), n.end(), want), n.end()) << want;
  EXPECT_EQ(std::find(n.begin(), n.end(), "sigma2"), n.end());
  EXPECT_EQ(m.left_out[0].unit, "N m/rad");  // sigma0 on a rotary axis
  EXPECT_EQ(m.left_out.back().value, 1.0);   // one state
}

TEST(MjcfExport, AsymmetricLevelsAreWrittenAsTheirMeanAndListed) {
  const FrictionLaw law = law_of({{"law", "coulomb-viscous-asymmetric"}, {"Fc_pos", 0.7}, {"Fv_pos", 0.2},
                                  {"Fc_neg", 0.9}, {"Fv_neg", 0.2}});
  const MjcfModel m = mjcf_model(law, with_inertia(1.0));
  EXPECT_NEAR(m.frictionloss, 0.8, 1e-15);
  EXPECT_EQ(m.damping, 0.2);
  // Fv is the same both ways: nothing lost; Fc differs: both listed.
  EXPECT_EQ(names(m), (std::vector<std::string>{"Fc_pos", "Fc_neg"}));
  EXPECT_TRUE(has(m.left_out[0].reason, "mean"));
  EXPECT_EQ(mjcf_coulomb_level(law), m.frictionloss);
}

TEST(MjcfExport, OffsetIsListedLast) {
  MjcfOptions o = with_inertia(1.0);
  o.offset = -0.25;
  const MjcfModel m = mjcf_model(Coulomb{.Fc = 1.0}, o);
  ASSERT_EQ(names(m), std::vector<std::string>{"offset"});
  EXPECT_EQ(m.left_out[0].value, -0.25);
  EXPECT_EQ(m.left_out[0].unit, "N");
}

TEST(MjcfExport, SourceNameCannotBreakTheComment) {
  MjcfOptions o = with_inertia(1.0);
  o.source = "a--b-->.json";
  const MjcfModel m = mjcf_model(Coulomb{.Fc = 1.0}, o);
  // The only "--" in the text are the comments' own delimiters.
  std::size_t count = 0;
  for (std::size_t at = m.xml.find("--"); at != std::string::npos; at = m.xml.find("--", at + 2)) ++count;
  EXPECT_EQ(count, 2u);  // one comment: "<!--" and "-->"
  EXPECT_TRUE(has(m.xml, "a- -b- ->.json"));
}

TEST(MjcfExport, RefusesLawsWithoutFcAndBadOptions) {
  EXPECT_EQ(mjcf_coulomb_level(Viscous{.Fv = 1.0}), std::nullopt);
  EXPECT_EQ(error_of([] { mjcf_model(Viscous{.Fv = 1.0}, with_inertia(1.0)); }),
            "law viscous has no Coulomb level Fc (nor Fc_pos and Fc_neg): MuJoCo's frictionloss needs one");
  const FrictionLaw c = Coulomb{.Fc = 1.0};
  EXPECT_EQ(error_of([&] { mjcf_model(c, MjcfOptions{}); }), "mjcf: inertia = 0 must be > 0 (kg or kg m^2)");
  EXPECT_EQ(error_of([&] { mjcf_model(c, with_inertia(-2)); }), "mjcf: inertia = -2 must be > 0 (kg or kg m^2)");
  EXPECT_EQ(error_of([&] { mjcf_model(c, with_inertia(std::numeric_limits<double>::quiet_NaN())); }),
            "mjcf: inertia = nan must be > 0 (kg or kg m^2)");
  MjcfOptions o = with_inertia(1.0);
  o.armature = 1.0;
  EXPECT_EQ(error_of([&] { mjcf_model(c, o); }), "mjcf: armature = 1 must be >= 0 and < the inertia 1 (kg or kg m^2)");
  o.armature = -0.1;
  EXPECT_EQ(error_of([&] { mjcf_model(c, o); }), "mjcf: armature = -0.1 must be >= 0 and < the inertia 1 (kg or kg m^2)");
  o = with_inertia(1.0);
  o.timestep = 0;
  EXPECT_EQ(error_of([&] { mjcf_model(c, o); }), "mjcf: timestep = 0 must be > 0 (s)");
  o = with_inertia(1.0);
  o.offset = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of([&] { mjcf_model(c, o); }), "mjcf: offset = inf must be finite (N or N m)");
}

}  // namespace
}  // namespace frictionlab
