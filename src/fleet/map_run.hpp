#pragma once
// A whole map run from a scenario file: the grid's scenarios (scenario/scenario_grid.hpp), the points of
// one shard simulated and classified (analysis/map.hpp), the theory at each point, and the rows as
// the table that `frictionlab analyze map` writes, `frictionlab merge` joins (fleet/shard.hpp) and
// Python's fl.analyze_map returns. One function, so that all three give the same rows.
//
// Columns: the varied keys (their units), then
//   class               converged | steady-sliding | stick-slip | hunting | oscillating | failed
//   amplitude           half peak-to-peak of the drift-free position after the transient (m or rad)
//   period              of the cycle (s; empty without one)
//   mean_velocity       net displacement / time after the transient (m/s or rad/s)
//   velocity_amplitude  half peak-to-peak of the velocity after the transient (m/s or rad/s)
//   stuck_fraction      of the time after the transient spent stuck (0..1)
//   transient           time discarded from the start (s)
//   theory              the class theory predicts ("" where none applies)
//   theory_margin       spring-block: c + dF/dv(V0) (N s/m), < 0 predicts stick-slip
//   theory_amplitude    pid-hunting: describing-function amplitude (m)
//   theory_period       pid-hunting: describing-function period (s)
//   message             why a point failed, or why theory gives no prediction there
//   contact             the name of the contact classified ("" for a 1-DOF plant's one contact)

#include <functional>
#include <string>
#include <vector>

#include "frictionlab/analysis/map.hpp"
#include "fleet/shard.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of map_scenario.
struct MapRunOptions {
  MotionOptions motion;  ///< transient and tolerance
  int threads = 0;       ///< simulation threads (0: all cores)
  ShardSpec shard;       ///< the points to run (default: all)
  /// The contact classified: a name or an index from 0 (analysis map_contact); "" = the first.
  std::string contact;
  /// The option's name in messages about `contact` ("--contact" on the command line).
  std::string contact_option = "--contact";
  /// Called as points finish (thread-safe): finished, of the shard's points. Optional.
  std::function<void(std::size_t finished, std::size_t total)> progress;
};

/// The outcome of map_scenario.
struct MapRun {
  /// The rows (table.index: the points' global indices) with what identifies the run: key =
  /// SHA-256 of the scenario file's bytes, the grid, the motion options and the contact;
  /// envelope = the JSON result without rows ({"schema": 1, "status": "ok", "method": "map",
  /// "data": {file, sha256}, "result": {scenario, grid, points, transient, tolerance,
  /// contact: {index, name}, theory: {kind, note}, columns, rows}}).
  Part part;
  int contact = 0;           ///< the contact classified (index from 0)
  std::string contact_name;  ///< its name ("" for a 1-DOF plant's one contact)
  /// map_theory(point 0).kind: "spring-block", "pid-hunting" or ""; "" when a contact other than
  /// the first is classified (both theories are of a 1-DOF plant's one contact).
  std::string theory_kind;
  std::string theory_note;  ///< one line on what the theory says and how far to trust it
};

/// Runs the shard's points of the map of `scenario` over `grid`.
/// \throws std::invalid_argument for a bad grid or options, an unknown key (ScenarioGrid), a
///         contact the plant does not have (map_contact: listing its contacts), or values the
///         scenario reader refuses at some point (naming the point's values), before anything is
///         simulated. A simulation that fails is a row of class "failed" with its
///         message; the others go on.
MapRun map_scenario(const std::string& scenario, const MapGrid& grid, const MapRunOptions& options = {});

}  // namespace frictionlab
