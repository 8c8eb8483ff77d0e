#pragma once
// The data files beside a fuzzed scenario (fuzz_scenario, and test_io's replay of its kept
// regression inputs): data.csv below and data.mat, a copy of the EMPS slice of the MAT corpus
// (t, qm, qg, vir and the scalars gtau, kp, kv); and the models a `compensation:` block's
// `model:` may name, model.json (identify's MODEL.json with M, a LuGre law) and law.yaml (a
// Stribeck law file).

#include <utility>

namespace frictionlab::fuzz {

inline constexpr const char* kScenarioCsv =
    "time,u,q,p\n"
    "0,0.0,0.000,0\n"
    "0.001,0.5,0.001,5\n"
    "0.002,1.0,0.003,0\n"
    "0.003,1.5,0.006,0\n";
inline constexpr const char* kScenarioModelJson =
    R"({"schema": 1, "status": "ok", "message": "", "method": "lugre", "model": "lugre", "parameters": {)"
    R"("M": {"value": 26.8, "std": 0.1, "unit": "kg"}, "sigma0": {"value": 1e6, "std": null, "unit": "N/m"}, )"
    R"("sigma1": {"value": 1e4, "std": null, "unit": "N s/m"}, "sigma2": {"value": 150, "std": 2, "unit": "N s/m"}, )"
    R"("Fc": {"value": 25, "std": 0.3, "unit": "N"}, "Fs": {"value": 40, "std": 0.5, "unit": "N"}, )"
    R"("vs": {"value": 0.002, "std": 1e-4, "unit": "m/s"}}})";

inline constexpr const char* kScenarioLawYaml = "law: stribeck\nFc: 15\nFs: 25\nvs: 0.002\ndelta: 2\nFv: 100\n";

/// Every text file above, by the name a scenario gives it.
inline constexpr std::pair<const char*, const char*> kScenarioTextFiles[] = {
    {"data.csv", kScenarioCsv}, {"model.json", kScenarioModelJson}, {"law.yaml", kScenarioLawYaml}};

inline constexpr const char* kScenarioMat = "corpus/fuzz_mat/emps_slice_v5.mat";  // from tests/fuzz

}  // namespace frictionlab::fuzz
