#pragma once
// frictionlab analyze map SCENARIO.yaml --vary KEY=START:STOP:N ... [--jobs N] [--shard K/N]
//   [-o OUT.csv|OUT.json|PART] [--json FILE|-] [--plot FILE] [--transient S] [--tolerance F]
// The map part of `analyze` (app/cmd_analyze.cpp owns the subcommand): a grid of simulations of a
// scenario file, each point classified (analysis/map.hpp), with theory where it applies; written
// as a table (io/shard.hpp) or, with --shard, as a part that `frictionlab merge` joins.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "output.hpp"

namespace frictionlab::cli {

struct MapArgs {
  std::vector<std::string> vary;  ///< KEY=START:STOP:N, repeatable
  int jobs = 0;                   ///< threads, 0 = all cores
  std::string shard;              ///< K/N, empty = the whole grid
  std::string out;                ///< -o: table (.csv/.json) or, with --shard, the part file
  double transient = -1;          ///< s; < 0: half of each record
  double tolerance = 0.01;        ///< MotionOptions::tolerance
};

/// Adds the map's options to the analyze subcommand.
void add_map_options(CLI::App* cmd, MapArgs& a);

/// Runs the map on `scenario`, writing through `output` (--json, --plot, --overwrite). Returns the
/// exit status. \throws std::invalid_argument for bad input (exit 2).
int run_map_command(const std::string& scenario, const MapArgs& a, const OutputOptions& output);

}  // namespace frictionlab::cli
