// libFuzzer target: the MAT reader (load_dataset on a .mat file: the v5 structure walk, then
// matio). Bad input must end in std::invalid_argument; anything else is a finding. matio itself
// is not instrumented: ASan sees its heap and its memcpy calls, not each of its reads.

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "frictionlab/io/load.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = frictionlab::fuzz::write_input("data.mat", data, size);
  try {
    (void)frictionlab::load_dataset(path);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
