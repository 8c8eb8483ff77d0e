// libFuzzer target: the simulation numerics at whatever values a scenario holds. Each input is
// read as a scenario (as fuzz_scenario does, with the same scratch data files) and, when it is
// valid, simulated within a step budget: the library's work budget lowered to 1e6 units (output
// rows, fixed steps, controller samples) and at most 20000 CVODE steps. The run must end in
// columns that are all finite (Numbers or an error, never both: docs/guarantees.md), a refusal
// (std::invalid_argument), or the integrator giving up ("simulation failed at t = ..."); anything
// else is a finding: another exception, a crash, a sanitizer report, an inf or NaN in a column.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "frictionlab/budget.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/simulate.hpp"
#include "fuzz_input_file.hpp"
#include "scenario_data.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  using namespace frictionlab::fuzz;
  for (const auto& [name, text] : kScenarioTextFiles)
    (void)write_input(name, reinterpret_cast<const std::uint8_t*>(text), std::strlen(text));
  std::filesystem::copy_file(std::string(FRICTIONLAB_FUZZ_DIR) + "/" + kScenarioMat, scratch_dir() / "data.mat");
  frictionlab::set_budget_factor(1e-3);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = frictionlab::fuzz::write_input("scenario.yaml", data, size);
  frictionlab::Scenario sc;
  try {
    sc = frictionlab::load_scenario(path);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  if (sc.options.max_steps > 20000) sc.options.max_steps = 20000;
  frictionlab::Trajectory tr;
  try {
    tr = frictionlab::simulate(sc);
  } catch (const std::invalid_argument&) {
    return 0;
  } catch (const std::runtime_error& e) {
    if (std::strncmp(e.what(), "simulation failed at t = ", 25) == 0) return 0;
    throw;
  }
  for (const std::string& name : tr.names()) {
    // The temperature column is NaN by definition for a contact without a temperature effect.
    if (name == "temperature" || (name.size() > 12 && name.compare(name.size() - 12, 12, ".temperature") == 0)) continue;
    for (double x : tr.column(name))
      if (!std::isfinite(x)) std::abort();  // a non-finite number returned as a result
  }
  return 0;
}
