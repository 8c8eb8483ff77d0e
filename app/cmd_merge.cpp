// frictionlab merge PART... -o OUT [--overwrite]: joins the part files that `--shard K/N` runs
// wrote (io/shard.hpp checks that they belong together and are complete) into the output the
// unsharded run writes: CSV for OUT.csv, JSON for OUT.json, equal byte for byte.
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "frictionlab/io/shard.hpp"
#include "output.hpp"

namespace frictionlab::cli {

Handler register_merge(CLI::App& app) {
  struct Args {
    std::vector<std::string> parts;
    std::string out;
    bool overwrite = false;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the part files of a --shard K/N run (analyze map, identify METHOD) into its whole output, as the unsharded run "
               "writes it; checks that the parts come from one run and that every shard is there once.");
  cmd->add_option("parts", a->parts, "part files (any order), one per shard 1..N")->required();
  cmd->add_option("-o,--output", a->out, "the whole output: OUT.csv (the table) or OUT.json (the JSON result or table)")
      ->required();
  cmd->add_flag("--overwrite", a->overwrite, "replace an existing OUT");
  return [a]() -> int {
    const std::string ext = std::filesystem::path(a->out).extension().string();
    if (ext != ".csv" && ext != ".json")
      throw std::invalid_argument("-o " + a->out + ": expected a .csv or .json file");
    check_output_file(a->out, a->overwrite, "-o");
    std::vector<Part> parts;
    for (const auto& p : a->parts) parts.push_back(read_part(p));
    const Part whole = merge_parts(parts, a->parts);
    write_table(a->out, whole, a->overwrite);
    std::cout << "merged " << parts.size() << " parts, " << whole.table.rows.size() << " rows (" << whole.command
              << ") -> " << a->out << "\n";
    return 0;
  };
}

}  // namespace frictionlab::cli
