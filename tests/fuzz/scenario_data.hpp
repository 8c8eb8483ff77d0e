#pragma once
// The data files beside a fuzzed scenario (fuzz_scenario, and test_io's replay of its kept
// regression inputs): data.csv below and data.mat, a copy of the EMPS slice of the MAT corpus
// (t, qm, qg, vir and the scalars gtau, kp, kv).

namespace frictionlab::fuzz {

inline constexpr const char* kScenarioCsv =
    "time,u,q,p\n"
    "0,0.0,0.000,0\n"
    "0.001,0.5,0.001,5\n"
    "0.002,1.0,0.003,0\n"
    "0.003,1.5,0.006,0\n";
inline constexpr const char* kScenarioMat = "corpus/fuzz_mat/emps_slice_v5.mat";  // from tests/fuzz

}  // namespace frictionlab::fuzz
