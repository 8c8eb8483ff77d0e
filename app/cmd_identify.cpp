// frictionlab identify METHOD DATA...: friction parameters from measured data. One subcommand per
// registered method (app/methods/): DATA, the column, output and batch options, then the
// method's own. One file: its result (text, --json, --plot, --report). Several files or a
// folder: one row per file in a table (batch_identify.hpp).
#include <memory>
#include <vector>

#include "batch_identify.hpp"
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
    GivenOptions options;
  };
  auto chosen = std::make_shared<std::vector<Chosen>>();
  for (const CliMethod& m : cli_methods()) {
    if (!m.run) continue;  // a command of its own (validate)
    auto io = std::make_unique<MethodIO>();
    auto* cmd = identify->add_subcommand(m.name, m.help);
    cmd->add_option("DATA", io->inputs,
                    "Measured data: a CSV file (with a header row, or without one: see --names), or a MATLAB .mat "
                    "file. Several files or a folder (its .csv and .mat files): each identified alone, one row per "
                    "file (see --table)")
        ->required();
    add_data_options(cmd, io->columns);  // every method: linear unless --axis rotary
    add_output_options(cmd, io->output);
    add_batch_options(cmd, io->batch);
    io->batch.method = m.name;
    GivenOptions options = add_table_options(cmd, *m.info);
    chosen->push_back({cmd, std::move(io), m.run, std::move(options)});
  }
  return [chosen]() -> int {
    for (const auto& c : *chosen) {
      if (!c.cmd->parsed()) continue;
      MethodIO& io = *c.io;
      const OptionValues options = c.options();  // checked once, before any file is read
      const auto run = [&c, &options](const MethodIO& one) {
        Result r = c.run(one, options);
        record_options(r, options);
        return r;
      };
      if (!is_batch(io.inputs, io.batch)) {
        io.data = io.inputs.front();
        io.output.values = &options;  // the report lists the defaults that applied
        io.output.data = &io.columns;  // and the columns the run took by default
        check_outputs(io.output, command_inputs(c.cmd));
        return emit(run(io), io.output);
      }
      // Each file on its own copy of the options (the runs may be on several threads).
      const auto identify_file = [&run, &io](const std::string& file) {
        MethodIO one = io;
        one.data = file;
        return run(one);
      };
      const auto date_of_column = [&io](const std::string& file, const std::string& name) {
        const Dataset d = load_data(file, io.columns.read, io.columns.time);
        if (d.has_column(name) && d.rows() > 0) return d.column(name)(0);
        if (d.has_scalar(name)) return d.scalars.at(name);
        throw std::invalid_argument(d.where() + "--date-from column:" + name + ": no column or scalar '" + name +
                                    "'; the file has: " + d.describe_contents());
      };
      return run_identify_batch(io.inputs, io.batch, io.output.json, io.output.report, io.output.plot,
                                io.output.overwrite, identify_file, date_of_column, command_inputs(c.cmd));
    }
    return 2;
  };
}

}  // namespace frictionlab::cli
