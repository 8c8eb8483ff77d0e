// libFuzzer target: the scenario parser (load_scenario on a .yaml file). The scratch directory
// also holds data.csv, data.mat, model.json and law.yaml (scenario_data.hpp), so that scenarios
// naming them reach the data inputs, named constants, pulses, an initial position read from a
// column, an xy-table's path and a compensation's model file. Bad input
// must end in std::invalid_argument; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "frictionlab/scenario/scenario.hpp"
#include "fuzz_input_file.hpp"
#include "scenario_data.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  using namespace frictionlab::fuzz;
  for (const auto& [name, text] : kScenarioTextFiles)
    (void)write_input(name, reinterpret_cast<const std::uint8_t*>(text), std::strlen(text));
  std::filesystem::copy_file(std::string(FRICTIONLAB_FUZZ_DIR) + "/" + kScenarioMat, scratch_dir() / "data.mat");
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
