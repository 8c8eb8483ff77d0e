// libFuzzer target: the part files of sharded runs (read_part) and their merge (merge_parts), as
// `frictionlab merge` uses them. An input is one to four part files separated by "\n|||\n"; each is
// read, the parts that read are merged, and the merge is written back (table_csv, part_to_json).
// Bad input must end in std::invalid_argument; anything else (a crash, a sanitizer report, another
// exception, an allocation sized by an edited total) is a finding.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "fleet/shard.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  constexpr std::string_view kSeparator = "\n|||\n";
  std::vector<frictionlab::Part> parts;
  std::vector<std::string> names;
  std::size_t begin = 0;
  for (int k = 0; k < 4 && begin <= all.size(); ++k) {
    std::size_t end = all.find(kSeparator, begin);
    if (k == 3 || end == std::string_view::npos) end = all.size();
    const std::string_view text = all.substr(begin, end - begin);
    const std::string name = "part" + std::to_string(k + 1) + ".json";
    const std::string path =
        frictionlab::fuzz::write_input(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    try {
      parts.push_back(frictionlab::read_part(path));
      names.push_back(path);
    } catch (const std::invalid_argument&) {
    }
    begin = end + kSeparator.size();
  }
  if (parts.empty()) return 0;
  try {
    const frictionlab::Part whole = frictionlab::merge_parts(parts, names);
    (void)frictionlab::table_csv(whole.table);
    (void)frictionlab::part_to_json(whole);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
