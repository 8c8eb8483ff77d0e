// libFuzzer target: the scenario parser (load_scenario on a .yaml file). The scratch directory
// also holds a small data.csv (columns time, u, q, p) and data.mat (the EMPS slice of the MAT
// corpus: t, qm, qg, vir and the scalars gtau, kp, kv), so that scenarios naming either reach the
// data inputs, named constants, pulses and an initial position read from a column. Bad input
// must end in std::invalid_argument; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "frictionlab/io/scenario.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  static const char kData[] =
      "time,u,q,p\n"
      "0,0.0,0.000,0\n"
      "0.001,0.5,0.001,5\n"
      "0.002,1.0,0.003,0\n"
      "0.003,1.5,0.006,0\n";
  (void)frictionlab::fuzz::write_input("data.csv", reinterpret_cast<const std::uint8_t*>(kData), std::strlen(kData));
  std::filesystem::copy_file(FRICTIONLAB_FUZZ_DIR "/corpus/fuzz_mat/emps_slice_v5.mat",
                             frictionlab::fuzz::scratch_dir() / "data.mat");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = frictionlab::fuzz::write_input("scenario.yaml", data, size);
  try {
    (void)frictionlab::load_scenario(path);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
