// libFuzzer target: the friction-law file parser (load_law), each input read both as a .json
// and as a .yaml file. Bad input must end in std::invalid_argument; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "frictionlab/scenario/law_file.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const char* name : {"law.json", "law.yaml"}) {
    const std::string path = frictionlab::fuzz::write_input(name, data, size);
    try {
      (void)frictionlab::load_law(path);
    } catch (const std::invalid_argument&) {
    }
  }
  return 0;
}
