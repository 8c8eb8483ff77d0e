// frictionlab merge PART... -o OUT [--plot FIG] [--drift FILE] [--drift-threshold K] [--scenario FILE]
//                   [--overwrite]: joins the part files that `--shard K/N` runs wrote (fleet/shard.hpp
// checks that they belong together and are complete) into the output the unsharded run writes:
// CSV for OUT.csv, JSON for OUT.json, equal byte for byte. --plot draws the whole run's figure
// with the unsharded run's own code: a map's (draw_map), or a dated batch's drift figure
// (write_drift); so the figures are equal too.
#include <filesystem>
#include <iostream>
#include <memory>

#include "batch_identify.hpp"
#include "commands.hpp"
#include "report/figure.hpp"
#include "fleet/shard.hpp"
#include "map_command.hpp"
#include "output.hpp"

namespace frictionlab::cli {

Handler register_merge(CLI::App& app) {
  struct Args {
    std::vector<std::string> parts;
    std::string out;
    std::string plot;
    std::string drift;
    double drift_threshold = 1.0;
    CLI::Option* threshold_opt = nullptr;
    std::string scenario;
    bool overwrite = false;
  };
  auto a = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Join the part files of a --shard K/N run (analyze map, identify METHOD) into its whole output, as the unsharded run "
               "writes it; checks that the parts come from one run and that every shard is there once. --plot draws "
               "the whole run's figure as the unsharded run draws it.");
  cmd->add_option("parts", a->parts, "part files (any order), one per shard 1..N")->required();
  output_option(
      cmd->add_option("-o,--output", a->out, "the whole output: OUT.csv (the table) or OUT.json (the JSON result or table)")
          ->required());
  output_option(cmd->add_option("--plot", a->plot,
                  "also draw the whole run's figure (.svg, .png or .pdf; data and gnuplot script next to it), as the "
                  "unsharded run's --plot draws it: a map's parts, the map (1-D or 2-D, with the theory's boundary: "
                  "the scenario file is read again, see --scenario); identify parts with dates (--date-from), the drift "
                  "figure. Other parts have no figure (exit 2)"),
                RunFile::Kind::figure);
  cmd->add_option("--scenario", a->scenario,
                  "map parts with --plot: the map's scenario file, when it is not at the path the parts recorded (a "
                  "cluster's /data/map.yaml); it must be the same file (its SHA-256 is checked)");
  output_option(cmd->add_option("--drift", a->drift,
                                "identify parts with dates: also write the drift table (CSV, or JSON by .json), as "
                                "identify --drift does"));
  a->threshold_opt = cmd->add_option("--drift-threshold", a->drift_threshold,
                                     "identify parts: flag a drift change larger than this many combined std (as "
                                     "identify --drift-threshold)")
                         ->check(CLI::PositiveNumber)
                         ->capture_default_str();
  cmd->add_flag("--overwrite", a->overwrite, "replace existing outputs");
  return [a]() -> int {
    std::vector<RunFile> inputs;
    for (const auto& part : a->parts) inputs.push_back({"PART", part, RunFile::Kind::file});
    if (!a->scenario.empty()) inputs.push_back({"--scenario", a->scenario, RunFile::Kind::file});
    check_run_files(inputs,
                    {{"-o", a->out, RunFile::Kind::file},
                     {"--drift", a->drift, RunFile::Kind::file},
                     {"--plot", a->plot, RunFile::Kind::figure}},
                    a->overwrite);
    // After the rule for outputs: an -o at one of the parts is named as that, whatever its name.
    const std::string ext = std::filesystem::path(a->out).extension().string();
    if (ext != ".csv" && ext != ".json")
      throw std::invalid_argument("-o " + a->out + ": expected a .csv or .json file");

    std::vector<Part> parts;
    for (const auto& p : a->parts) parts.push_back(read_part(p));
    const Part whole = merge_parts(parts, a->parts);
    // What the parts' kind draws and writes besides the table, refused before anything is written.
    const bool map = whole.command == "analyze map", batch = whole.command == "identify";
    const auto refuse = [&](const std::string& option, const std::string& why) {
      throw std::invalid_argument(option + ": the parts are of `frictionlab " + whole.command + "`, " + why);
    };
    if (!batch && !a->drift.empty()) refuse("--drift", "not of a batch identification: there is no drift to write");
    if (!batch && a->threshold_opt->count() > 0)
      refuse("--drift-threshold", "not of a batch identification: there is no drift");
    if (!map && !a->scenario.empty()) refuse("--scenario", "not of a map: there is no scenario");
    if (!map && !batch && !a->plot.empty()) refuse("--plot", "which has no figure");
    std::string written;
    if (map && !a->plot.empty()) {
      progress_start("frictionlab merge");
      draw_map(whole, a->plot, a->overwrite, a->scenario);
      written += "; figure " + a->plot;
    }
    std::size_t flagged = 0;
    if (batch && (!a->plot.empty() || !a->drift.empty())) {
      std::vector<DriftRow> drift;
      try {
        drift = table_drift(whole.table, a->drift_threshold);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string(a->plot.empty() ? "--drift" : "--plot") + ": " + e.what());
      }
      if (drift.empty())
        throw std::invalid_argument(std::string(a->plot.empty() ? "--drift" : "--plot") +
                                    ": no ok row with parameters in the parts: nothing to draw");
      progress_start("frictionlab merge");
      write_drift(drift, a->drift, a->plot, a->drift_threshold, a->overwrite);
      for (const auto& d : drift) flagged += d.flagged;
      if (!a->drift.empty()) written += "; drift " + a->drift;
      if (!a->plot.empty()) written += "; figure " + a->plot;
    }
    write_table(a->out, whole, a->overwrite);
    progress_stop();
    std::cout << "merged " << parts.size() << " parts, " << whole.table.rows.size() << " rows (" << whole.command
              << ") -> " << a->out << written << "\n";
    if (batch && (!a->plot.empty() || !a->drift.empty()))
      std::cout << "drift: " << flagged << " flagged (a change beyond " << a->drift_threshold << " combined std)\n";
    return 0;
  };
}

}  // namespace frictionlab::cli
