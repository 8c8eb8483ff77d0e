#include "fleet/map_run.hpp"
#include "frictionlab/cancellation.hpp"
#include "frictionlab/io/json_text.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "frictionlab/budget.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "frictionlab/scenario/scenario_grid.hpp"
#include "io/sha256.hpp"

namespace frictionlab {
namespace {

const std::vector<std::string> kColumns = {"class",          "amplitude",        "period",        "mean_velocity",
                                           "velocity_amplitude", "stuck_fraction", "transient",     "theory",
                                           "theory_margin",  "theory_amplitude", "theory_period", "message",
                                           "contact"};

std::string note_of(const std::string& kind) {
  if (kind == "spring-block")
    return "linearised stability of steady sliding: c + dF/dv(V0) > 0 slides steadily, < 0 sticks and slips (a "
           "local criterion: near the line a start from rest may still stick-slip)";
  if (kind == "pid-hunting")
    return "describing function of the stuck mass as a relay with hysteresis against the integrator: amplitude "
           "(Fs - Fc)(1 + rho)/(2 Kp), period pi^2 (Fs - Kp A)/(2 Ki A); approximate (amplitude within about 30 %, period 40 %)";
  return "";
}

}  // namespace

MapRun map_scenario(const std::string& scenario, const MapGrid& grid, const MapRunOptions& options) {
  grid.validate();
  options.motion.validate();
  std::vector<std::string> keys;
  for (const auto& ax : grid.axes) keys.push_back(ax.key);
  const ScenarioGrid g(scenario, keys);
  const std::size_t total = grid.size();
  const std::vector<std::size_t> jobs = shard_jobs(total, options.shard);
  {
    // The work before any point runs: the points times the first point's output rows (each
    // point simulates its scenario); the exact sum is checked once the scenarios are made.
    const double rows0 = output_rows(g.at(grid.point(0)).options);
    check_work(static_cast<double>(jobs.size()) * (rows0 + kWorkPerRun), "work units",
               scenario + ": the map's " + std::to_string(jobs.size()) + " points (--vary) of about " +
                   format_number(rows0, 3) + " output rows each",
               {.file = scenario, .option = "--vary"});
  }
  std::vector<Scenario> scenarios;
  scenarios.reserve(jobs.size());
  double rows = 0;
  for (std::size_t i : jobs) {
    throw_if_cancelled();  // making 1e5 scenarios takes seconds
    scenarios.push_back(g.at(grid.point(i)));
    rows += output_rows(scenarios.back().options) + kWorkPerRun;
  }
  check_work(rows, "work units", scenario + ": the map's " + std::to_string(jobs.size()) + " points (--vary)",
             {.file = scenario, .option = "--vary"});

  MapRun run;
  const Scenario first = !jobs.empty() && jobs.front() == 0 ? scenarios.front() : g.at(grid.point(0));
  run.contact = map_contact(first, options.contact, options.contact_option);
  run.contact_name = first.plant->contact(run.contact).name;
  // Both theories are of a 1-DOF plant's one contact (map_theory).
  const bool theory = run.contact == 0;
  run.theory_kind = theory ? map_theory(first).kind : "";
  run.theory_note = note_of(run.theory_kind);

  MapOptions mo;
  mo.motion = options.motion;
  mo.contact = run.contact;
  mo.threads = options.threads;
  mo.progress = options.progress;
  const std::vector<MotionSummary> summaries = run_map(scenarios, mo);

  Part& part = run.part;
  part.command = "analyze map";
  part.shard = options.shard;
  part.total = total;
  part.rows_at = "/result/rows";
  part.table.columns = keys;
  part.table.columns.insert(part.table.columns.end(), kColumns.begin(), kColumns.end());
  for (std::size_t r = 0; r < jobs.size(); ++r) {
    const MotionSummary& s = summaries[r];
    const MapTheory th = theory ? map_theory(scenarios[r]) : MapTheory{};
    std::vector<Cell> row;
    for (double v : grid.point(jobs[r])) row.emplace_back(v);
    row.emplace_back(std::string(motion_class_name(s.kind)));
    for (double v : {s.amplitude, s.period, s.mean_velocity, s.velocity_amplitude, s.stuck_fraction, s.transient})
      row.emplace_back(v);
    row.emplace_back(th.predicted);
    for (double v : {th.margin, th.amplitude, th.period}) row.emplace_back(v);
    row.emplace_back(s.message.empty() ? th.message : s.message);
    row.emplace_back(run.contact_name);
    part.table.index.push_back(jobs[r]);
    part.table.rows.push_back(std::move(row));
  }

  const std::string digest = sha256_file(scenario);
  const bool given = !std::isnan(options.motion.transient);
  nlohmann::ordered_json grid_text = nlohmann::ordered_json::array();
  for (const auto& ax : grid.axes) grid_text.push_back(ax.text());
  const nlohmann::ordered_json transient =
      given ? nlohmann::ordered_json(options.motion.transient) : nlohmann::ordered_json("half of each run");
  const nlohmann::ordered_json contact = {{"index", run.contact}, {"name", run.contact_name}};
  const nlohmann::ordered_json id = {{"command", part.command}, {"scenario_sha256", digest},
                                     {"grid", grid_text},       {"transient", transient},
                                     {"tolerance", options.motion.tolerance}, {"contact", contact},
                                     {"columns", part.table.columns}};
  part.key = sha256_hex(json_text(id));

  Result env;
  env.method = "map";
  env.data_file = scenario;
  env.data_sha256 = digest;
  const nlohmann::ordered_json result = {{"scenario", scenario},
                                         {"grid", grid_text},
                                         {"points", total},
                                         {"transient", transient},
                                         {"tolerance", options.motion.tolerance},
                                         {"contact", contact},
                                         {"theory", {{"kind", run.theory_kind}, {"note", run.theory_note}}},
                                         {"columns", part.table.columns},
                                         {"rows", nlohmann::ordered_json::array()}};
  env.json_sections["result"] = json_text(result);
  part.envelope = to_json(env, -1);
  return run;
}

}  // namespace frictionlab
