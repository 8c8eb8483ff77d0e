// frictionlab identify METHOD DATA: friction parameters from measured data. One subcommand per
// registered method (app/methods/): DATA, the column and output options, then the method's own.
#include <memory>
#include <vector>

#include "commands.hpp"
#include "methods/method.hpp"

namespace frictionlab::cli {

Handler register_identify(CLI::App& app) {
  auto* identify = app.add_subcommand("identify", "Identify friction parameters from measured data");
  identify->require_subcommand(1);
  struct Chosen {
    CLI::App* cmd;
    std::unique_ptr<MethodIO> io;
    MethodRun run;
  };
  auto chosen = std::make_shared<std::vector<Chosen>>();
  for (const CliMethod& m : cli_methods()) {
    if (!m.add_options) continue;  // a command of its own (validate)
    auto io = std::make_unique<MethodIO>();
    auto* cmd = identify->add_subcommand(m.name, m.help);
    cmd->add_option("DATA", io->data,
                    "Measured data: a CSV file (with a header row, or without one: see --names), or a MATLAB .mat file")
        ->required();
    add_data_options(cmd, io->columns, m.default_axis);
    add_output_options(cmd, io->output);
    MethodRun run = m.add_options(cmd);
    chosen->push_back({cmd, std::move(io), std::move(run)});
  }
  return [chosen]() -> int {
    for (const auto& c : *chosen)
      if (c.cmd->parsed()) return c.run(*c.io, *c.cmd);
    return 2;
  };
}

}  // namespace frictionlab::cli
