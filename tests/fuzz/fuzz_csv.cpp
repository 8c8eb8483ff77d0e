// libFuzzer target: the CSV reader (load_dataset on a .csv file, and read_csv dropping invalid
// rows). Bad input must end in std::invalid_argument; anything else (another exception, a crash,
// a sanitizer report) is a finding.

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "frictionlab/io/csv.hpp"
#include "frictionlab/io/load.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = frictionlab::fuzz::write_input("data.csv", data, size);
  try {
    (void)frictionlab::load_dataset(path);
  } catch (const std::invalid_argument&) {
  }
  frictionlab::CsvOptions lenient;
  lenient.drop_invalid = true;
  try {
    (void)frictionlab::read_csv(path, lenient);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
