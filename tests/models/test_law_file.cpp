// Friction laws in files: the YAML form, the plain JSON form and MODEL.json, with error
// messages that name the place and the key.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "error_message.hpp"
#include "temp_dir.hpp"
#include "frictionlab/scenario/law_file.hpp"

namespace frictionlab {
namespace {

using frictionlab::testing::error_of;

using ::testing::HasSubstr;


TEST(LawFromYaml, Stribeck) {
  const FrictionLaw law = law_from_yaml(YAML::Load("law: stribeck\nFc: 1.0\nFs: 1.5\nvs: 0.001\nFv: 0.4\n"), "test.yaml");
  EXPECT_EQ(law.name(), "stribeck");
  const auto& s = std::get<Stribeck>(law.variant());
  EXPECT_EQ(s.Fc, 1.0);
  EXPECT_EQ(s.Fs, 1.5);
  EXPECT_EQ(s.vs, 0.001);
  EXPECT_EQ(s.delta, 2.0);  // optional, default
  EXPECT_EQ(s.Fv, 0.4);
}

TEST(LawFromYaml, ListsAndShape) {
  const FrictionLaw gms = law_from_yaml(
      YAML::Load("law: gms\nk: [1.0e5, 2.0e4]\nalpha: [0.6, 0.4]\nFc: 1\nFs: 1.2\nvs: 0.01\nC: 10\nsigma2: 0.1\n"), "g.yaml");
  EXPECT_EQ(std::get<Gms>(gms.variant()).k, (std::vector<double>{1e5, 2e4}));
  const FrictionLaw table = law_from_yaml(YAML::Load("law: table\nvelocity: [0.1, 0.2]\nforce: [1.0, 1.1]\n"), "t.yaml");
  EXPECT_EQ(table.sliding(0.2), 1.1);
  const FrictionLaw smooth = law_from_yaml(YAML::Load("law: smooth\nFc: 1\nvt: 0.01\nshape: atan\n"), "s.yaml");
  EXPECT_EQ(std::get<Smooth>(smooth.variant()).shape, SmoothShape::atan);
}

TEST(LawFromYaml, ErrorsNameTheKey) {
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("Fc: 1.0\n"), "test.yaml"); }),
            "test.yaml: missing 'law' (one of the friction law names, e.g. stribeck)");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("law: coulomb\nFc: abc\n"), "test.yaml"); }),
            "test.yaml.Fc: expected a number, got 'abc'");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("law: table\nvelocity: [0.1, x]\nforce: [1, 1]\n"), "t.yaml"); }),
            "t.yaml.velocity[1]: expected a number, got 'x'");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("- 1\n- 2\n"), "test.yaml"); }),
            "test.yaml: expected a mapping with 'law' and its parameters");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("law: stribeck\nFc: 1\nFs: 1.5\nvs: -1\nFv: 0\n"), "test.yaml"); }),
            "test.yaml: stribeck: vs = -1 must be > 0 (m/s or rad/s)");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("law: coulomb\nFc: 1\nFv: 2\n"), "test.yaml"); }),
            "test.yaml: coulomb: unknown parameter 'Fv'; coulomb has Fc");
  EXPECT_EQ(error_of([] { law_from_yaml(YAML::Load("law: coulomb-viscous\nFc: 1\n"), "test.yaml"); }),
            "test.yaml: coulomb-viscous: missing parameter 'Fv' (coulomb-viscous needs Fc, Fv)");
  EXPECT_THAT(error_of([] { law_from_yaml(YAML::Load("law: friction\n"), "test.yaml"); }),
              HasSubstr("test.yaml: unknown friction law 'friction'; valid laws: coulomb"));
}

TEST(LawFromJson, PlainForm) {
  const FrictionLaw law = law_from_json(
      nlohmann::json::parse(R"({"law": "lugre", "sigma0": 1e5, "sigma1": 316.2, "sigma2": 0.4, "Fc": 1,
                                "Fs": 1.5, "vs": 0.001})"),
      "model.json");
  EXPECT_EQ(law.name(), "lugre");
  EXPECT_EQ(std::get<LuGre>(law.variant()).sigma1, 316.2);
  const FrictionLaw t = law_from_json(nlohmann::json::parse(R"({"law": "table", "velocity": [0.1, 0.2], "force": [1, 2]})"),
                                      "t.json");
  EXPECT_EQ(t.sliding(0.1), 1.0);
}

TEST(LawFromJson, ModelJsonForm) {
  const auto j = nlohmann::json::parse(R"({
    "schema": 1, "status": "ok", "message": "", "method": "sweep", "model": "stribeck",
    "data": {"file": "run.csv", "sha256": "abc"},
    "parameters": {
      "Fc": {"value": 1, "std": 0.1, "unit": "N"},
      "Fs": {"value": 1.5, "std": 0.2, "unit": "N"},
      "vs": {"value": 0.002, "std": 0.0001, "unit": "m/s"},
      "delta": {"value": 2, "std": 0, "unit": ""},
      "Fv": {"value": 0.4, "std": 0.01, "unit": "N s/m"},
      "M": {"value": 2.0, "std": 0.1, "unit": "kg"},
      "offset": {"value": 0.05, "std": 0.01, "unit": "N"}
    },
    "fit": {"relative_error_percent": 1.2, "rmse": 0.01, "samples": 100}
  })");
  const FrictionLaw law = law_from_json(j, "MODEL.json");
  ASSERT_EQ(law.name(), "stribeck");
  const auto& s = std::get<Stribeck>(law.variant());
  EXPECT_EQ(s.Fc, 1.0);
  EXPECT_EQ(s.Fs, 1.5);
  EXPECT_EQ(s.vs, 0.002);
  EXPECT_EQ(s.Fv, 0.4);  // M and offset belong to the plant and are skipped
}

TEST(LawFromJson, ErrorsNameTheKey) {
  EXPECT_EQ(error_of([] { law_from_json(nlohmann::json::parse(R"({"Fc": 1})"), "m.json"); }),
            "m.json: missing 'law' (or 'model' with 'parameters')");
  EXPECT_EQ(error_of([] { law_from_json(nlohmann::json::parse(R"([1, 2])"), "m.json"); }),
            "m.json: expected a JSON object describing a friction law");
  EXPECT_EQ(error_of([] { law_from_json(nlohmann::json::parse(R"({"law": "coulomb", "Fc": "one"})"), "m.json"); }),
            "m.json.Fc: expected a number (or {\"value\": number}), got \"one\"");
  EXPECT_EQ(error_of([] {
              law_from_json(nlohmann::json::parse(R"({"model": "coulomb", "parameters": {"Fc": {"std": 0.1}}})"), "M.json");
            }),
            "M.json.Fc: expected a number (or {\"value\": number}), got {\"std\":0.1}");
  EXPECT_EQ(error_of([] { law_from_json(nlohmann::json::parse(R"({"model": 3, "parameters": {}})"), "M.json"); }),
            "M.json: 'model' must be a law name");
  EXPECT_EQ(error_of([] {
              law_from_json(nlohmann::json::parse(R"({"law": "table", "velocity": [0.1, "a"], "force": [1, 1]})"), "t.json");
            }),
            "t.json.velocity[1]: expected a number, got \"a\"");
  EXPECT_EQ(error_of([] {
              law_from_json(nlohmann::json::parse(R"({"model": "stribeck", "parameters": {"Fc": {"value": 1},
                 "Fs": {"value": 0.5}, "vs": {"value": 0.001}, "Fv": {"value": 0}}})"),
                            "M.json");
            }),
            "M.json: stribeck: Fs = 0.5 must be >= Fc = 1 (N or N m)");
  EXPECT_EQ(error_of([] { law_from_json(nlohmann::json::parse(R"({"law": "coulomb"})"), "m.json"); }),
            "m.json: coulomb: missing parameter 'Fc' (coulomb needs Fc)");
}

TEST(LawToJson, RoundTripForEveryLaw) {
  for (const FrictionLaw& law : {FrictionLaw(Stribeck{}), FrictionLaw(Table({0.1, 0.3}, {1.0, 1.2})), FrictionLaw(Gms{}),
                                 FrictionLaw(Smooth{1.0, 1.0, 1e-3, 2.0, 0.0, 1e-3, SmoothShape::atan}),
                                 FrictionLaw(Asymmetric<Coulomb>{Coulomb{2.0}, Coulomb{1.0}}), FrictionLaw(LuGre{})}) {
    SCOPED_TRACE(law.name());
    const nlohmann::json j = law_to_json(law);
    EXPECT_EQ(j["law"], law.name());
    const FrictionLaw back = law_from_json(j, "round.json");
    EXPECT_EQ(back.to_spec().scalars, law.to_spec().scalars);
    EXPECT_EQ(back.to_spec().arrays, law.to_spec().arrays);
    EXPECT_EQ(back.to_spec().strings, law.to_spec().strings);
    // And through YAML text.
    YAML::Emitter out;
    out << YAML::BeginMap;
    for (const auto& [k, v] : j.items()) {
      out << YAML::Key << k;
      if (v.is_string()) out << YAML::Value << v.get<std::string>();
      else if (v.is_array()) out << YAML::Value << YAML::Flow << v.get<std::vector<double>>();
      else out << YAML::Value << YAML::Precision(17) << v.get<double>();
    }
    out << YAML::EndMap;
    const FrictionLaw from_yaml = law_from_yaml(YAML::Load(out.c_str()), "round.yaml");
    EXPECT_EQ(from_yaml.to_spec().scalars, law.to_spec().scalars) << out.c_str();
  }
}

TEST(LoadLaw, FilesAndScenarioFrictionBlock) {
  const frictionlab::testing::TempDir tmp;
  const auto& dir = tmp.path();
  {
    std::ofstream(dir / "law.yaml") << "friction:\n  law: coulomb\n  Fc: 2.5\n";
    std::ofstream(dir / "law.json") << R"({"law": "viscous", "Fv": 0.25})";
    std::ofstream(dir / "bad.json") << "{not json";
  }
  EXPECT_EQ(load_law((dir / "law.yaml").string()).sliding(1.0), 2.5);
  EXPECT_EQ(load_law((dir / "law.json").string()).sliding(2.0), 0.5);
  EXPECT_THAT(error_of([&] { load_law((dir / "bad.json").string()); }), HasSubstr("bad.json: not valid JSON"));
  EXPECT_THAT(error_of([&] { load_law((dir / "missing.yaml").string()); }),
              HasSubstr("missing.yaml: cannot open the friction law file"));
}

}  // namespace
}  // namespace frictionlab
