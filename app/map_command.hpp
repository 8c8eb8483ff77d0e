#pragma once
// frictionlab analyze map SCENARIO.yaml --vary KEY=START:STOP:N ... [--jobs N] [--shard K/N]
//   [--contact NAME|INDEX] [-o OUT.csv|OUT.json|PART] [--json FILE|-] [--plot FILE] [--transient S]
//   [--tolerance F]
// The map part of `analyze` (app/cmd_analyze.cpp owns the subcommand): a grid of simulations of a
// scenario file, each point classified (analysis/map.hpp), with theory where it applies; written
// as a table (fleet/shard.hpp) or, with --shard, as a part that `frictionlab merge` joins; the map's
// figure (draw_map), drawn alike for an unsharded run and for merged parts.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "report/figure.hpp"
#include "fleet/shard.hpp"
#include "output.hpp"

namespace frictionlab::cli {

struct MapArgs {
  std::vector<std::string> vary;  ///< KEY=START:STOP:N, repeatable
  int jobs = 0;                   ///< threads, 0 = all cores
  std::string shard;              ///< K/N, empty = the whole grid
  std::string contact;            ///< the contact classified: a name or an index from 0; empty = the first
  std::string out;                ///< -o: table (.csv/.json) or, with --shard, the part file
  double transient = -1;          ///< s; < 0: half of each record
  double tolerance = 0.01;        ///< MotionOptions::tolerance
};

/// Adds the map's options to the analyze subcommand.
void add_map_options(CLI::App* cmd, MapArgs& a);

/// Runs the map on `scenario`, writing through `output` (--json, --plot, --overwrite). Returns the
/// exit status. \throws std::invalid_argument for bad input (exit 2).
int run_map_command(const std::string& scenario, const MapArgs& a, const OutputOptions& output);

/// Draws the map of a whole run (`run`: an unsharded map_scenario's part, or merge_parts of its
/// parts) to `plot` (.svg, .png, .pdf; data and gnuplot script next to it): 2-D, the classes as
/// coloured markers over the two keys; 1-D, the amplitude against the key; log axes as log10; the
/// theory's boundary or prediction on it. The grid, the theory and the scenario's name come from
/// the run's envelope; the boundary is computed from the scenario file the envelope names, or
/// `scenario` when given (a cluster's path that does not resolve here). One function for
/// `analyze map --plot` and `merge --plot`, so the two figures are equal.
/// \returns the files written. \throws std::invalid_argument (exit 2) for a map of more than two
///         keys, a scenario file that is missing or whose SHA-256 is not the run's (naming it), a
///         figure that cannot be written; std::logic_error for a part that is not a whole map run.
FigureFiles draw_map(const Part& run, const std::string& plot, bool overwrite, const std::string& scenario = "");

}  // namespace frictionlab::cli
