#include "map_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "frictionlab/analysis/map.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/models/parameter.hpp"
#include "io/atomic_write.hpp"
#include "report/figure.hpp"
#include "fleet/map_run.hpp"
#include "frictionlab/scenario/scenario_grid.hpp"
#include "io/sha256.hpp"
#include "fleet/shard.hpp"

namespace frictionlab::cli {
namespace {

const char* const kClassColours[][2] = {{"converged", "#009e73"},  {"steady-sliding", "#0072b2"},
                                        {"stick-slip", "#d55e00"}, {"hunting", "#cc79a7"},
                                        {"oscillating", "#e69f00"}, {"failed", "#000000"}};

// Plot coordinate of a value on an axis: the value itself; a log-spaced axis is drawn on a
// logarithmic scale (FigurePanel::log_x, log_y), so its tick labels are values, not log10 values.
double coord(const MapAxis&, double v) { return v; }

// The quantity of a scenario key by its last part (the parameters scenario.hpp lists), for the
// axis label's unit; nullopt for a key the table does not know.
std::optional<Quantity> key_quantity(const std::string& key) {
  const std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  static const std::map<std::string, Quantity> table = {
      {"Fc", Quantity::force},        {"Fs", Quantity::force},        {"offset", Quantity::force},
      {"Fc_pos", Quantity::force},    {"Fc_neg", Quantity::force},    {"Fs_pos", Quantity::force},
      {"Fs_neg", Quantity::force},    {"Fv", Quantity::viscous},
      {"c", Quantity::viscous},       {"B", Quantity::viscous},       {"sigma1", Quantity::viscous},
      {"sigma2", Quantity::viscous},  {"Kd", Quantity::viscous},      {"vs", Quantity::velocity},
      {"vd", Quantity::velocity},     {"V0", Quantity::velocity},     {"velocity", Quantity::velocity},
      {"sigma0", Quantity::stiffness}, {"k", Quantity::stiffness},    {"Kp", Quantity::stiffness},
      {"M", Quantity::inertia},       {"m", Quantity::inertia},       {"mass", Quantity::inertia},
      {"inertia", Quantity::inertia}, {"duration", Quantity::time},   {"delta", Quantity::dimensionless}};
  const auto it = table.find(last);
  if (it == table.end()) return std::nullopt;
  return it->second;
}

// "KEY (UNIT)": the unit by the key's quantity on the scenario's axis (rotary for a DC motor or a
// pendulum), "(-)" for a dimensionless key, "(scenario units)" for a key the table does not know
// (the scenario file's own unit, SI).
std::string axis_label(const MapAxis& a, Axis axis) {
  const std::string last = a.key.substr(a.key.rfind('.') == std::string::npos ? 0 : a.key.rfind('.') + 1);
  std::string u;
  if (last == "Ki") u = axis == Axis::rotary ? "N m/(rad s)" : "N/(m s)";
  else if (const auto q = key_quantity(a.key)) u = *q == Quantity::dimensionless ? "-" : std::string(unit(*q, axis));
  else u = "scenario units, SI";
  return a.key + " (" + u + ")";
}

// The axis of the scenario's plant: rotary for a DC motor or a pendulum, else linear.
Axis scenario_axis(const std::string& file) {
  try {
    const YAML::Node root = YAML::LoadFile(file);
    const std::string type = root["plant"] && root["plant"]["type"] ? root["plant"]["type"].as<std::string>() : "";
    return type == "dc-motor" || type == "pendulum" ? Axis::rotary : Axis::linear;
  } catch (const YAML::Exception&) {
    return Axis::linear;  // read again (and its errors reported) by ScenarioGrid
  }
}

// The theory's indicator at a point: the sliding margin (spring-block), +1 / -1 for a predicted
// hunting / none (pid-hunting); NaN where the scenario is refused or no theory applies.
double indicator(const ScenarioGrid& g, const std::vector<double>& p) {
  try {
    const MapTheory th = map_theory(g.at(p));
    if (th.kind == "spring-block") return th.margin;
    if (th.kind == "pid-hunting") return th.predicted == "hunting" ? 1.0 : th.predicted.empty() ? NAN : -1.0;
  } catch (const std::invalid_argument&) {
  }
  return NAN;
}

// The theory's boundary on the map: where the indicator changes sign, by marching squares on a
// fine grid (2-D; segments as one series with gaps), or the sign changes along the axis (1-D:
// vertical lines from 0 to y_top).
FigureSeries boundary(const ScenarioGrid& g, const MapGrid& grid, double y_top) {
  FigureSeries s;
  s.name = "theory boundary";
  s.color = "#333333";
  const auto sample = [](const MapAxis& a, int n) {
    MapAxis fine = a;
    fine.count = static_cast<std::size_t>(n);
    return fine.count > 1 && a.start != a.stop ? fine.values() : std::vector<double>{a.start};
  };
  const auto push = [&](double x, double y) {
    s.x.push_back(x);
    s.y.push_back(y);
  };
  const auto gap = [&] { push(NAN, NAN); };
  if (grid.axes.size() == 1) {
    const MapAxis& a = grid.axes[0];
    const std::vector<double> xs = sample(a, 400);
    double prev = NAN;
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double m = indicator(g, {xs[i]});
      if (i > 0 && std::isfinite(prev) && std::isfinite(m) && (prev < 0) != (m < 0)) {
        const double f = prev / (prev - m);
        const double x = coord(a, xs[i - 1]) + f * (coord(a, xs[i]) - coord(a, xs[i - 1]));
        push(x, 0.0);
        push(x, y_top);
        gap();
      }
      prev = m;
    }
    return s;
  }
  if (grid.axes.size() != 2) return s;
  constexpr int kFine = 48;  // cells per axis: a smooth line for 2 300 scenario reads
  const MapAxis &ax = grid.axes[0], &ay = grid.axes[1];
  const std::vector<double> xs = sample(ax, kFine + 1), ys = sample(ay, kFine + 1);
  std::vector<std::vector<double>> m(xs.size(), std::vector<double>(ys.size()));
  for (std::size_t i = 0; i < xs.size(); ++i)
    for (std::size_t j = 0; j < ys.size(); ++j) m[i][j] = indicator(g, {xs[i], ys[j]});
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
      // Crossings on the cell's four edges, joined in pairs.
      const double cx[4][2] = {{coord(ax, xs[i]), coord(ay, ys[j])},
                               {coord(ax, xs[i + 1]), coord(ay, ys[j])},
                               {coord(ax, xs[i + 1]), coord(ay, ys[j + 1])},
                               {coord(ax, xs[i]), coord(ay, ys[j + 1])}};
      const double v[4] = {m[i][j], m[i + 1][j], m[i + 1][j + 1], m[i][j + 1]};
      std::vector<std::pair<double, double>> hits;
      for (int e = 0; e < 4; ++e) {
        const double a = v[e], b = v[(e + 1) % 4];
        if (!std::isfinite(a) || !std::isfinite(b) || (a < 0) == (b < 0)) continue;
        const double f = a / (a - b);
        hits.emplace_back(cx[e][0] + f * (cx[(e + 1) % 4][0] - cx[e][0]), cx[e][1] + f * (cx[(e + 1) % 4][1] - cx[e][1]));
      }
      for (std::size_t h = 0; h + 1 < hits.size(); h += 2) {
        push(hits[h].first, hits[h].second);
        push(hits[h + 1].first, hits[h + 1].second);
        gap();
      }
    }
  return s;
}

Figure map_figure(const ScenarioGrid& g, const MapGrid& grid, const RowTable& t, const std::string& theory_kind,
                  const std::string& title, Axis axis) {
  Figure f;
  f.title = "Map - " + title;
  f.panel_height = 520;  // a grid of markers under a legend of several lines
  FigurePanel p;
  const std::size_t nk = grid.axes.size();
  const bool two_d = nk == 2;
  p.x_label = axis_label(grid.axes[0], axis);
  p.y_label = two_d ? axis_label(grid.axes[1], axis) : std::string("amplitude (") + (axis == Axis::rotary ? "rad" : "m") + ")";
  p.log_x = grid.axes[0].log;
  p.log_y = two_d && grid.axes[1].log;
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin());
  };
  const std::size_t c_class = col("class"), c_amp = col("amplitude"), c_tamp = col("theory_amplitude");
  double y_top = 0;
  for (const auto& [name, colour] : kClassColours) {
    FigureSeries s;
    s.name = name;
    s.color = colour;
    s.style = SeriesStyle::points;
    s.point_size = 1.2;
    for (const auto& row : t.rows) {
      if (std::get<std::string>(row[c_class]) != name) continue;
      const double x = coord(grid.axes[0], std::get<double>(row[0]));
      const double y = two_d ? coord(grid.axes[1], std::get<double>(row[1])) : std::get<double>(row[c_amp]);
      s.x.push_back(x);
      s.y.push_back(std::isfinite(y) ? y : 0.0);
      if (!two_d && std::isfinite(y)) y_top = std::max(y_top, y);
    }
    if (!s.x.empty()) p.series.push_back(std::move(s));
  }
  if (!two_d && theory_kind == "pid-hunting") {
    FigureSeries s;
    s.name = "describing function amplitude";
    s.color = "#cc79a7";
    for (const auto& row : t.rows) {
      s.x.push_back(coord(grid.axes[0], std::get<double>(row[0])));
      s.y.push_back(std::get<double>(row[c_tamp]));
      if (std::isfinite(s.y.back())) y_top = std::max(y_top, s.y.back());
    }
    p.series.push_back(std::move(s));
  }
  if (nk <= 2 && !theory_kind.empty()) {
    FigureSeries b = boundary(g, grid, y_top > 0 ? y_top : 1.0);
    if (!b.x.empty()) {
      if (theory_kind == "spring-block") b.name = "linear stability boundary c + dF/dv(V0) = 0";
      p.series.push_back(std::move(b));
    }
  }
  f.panels.push_back(std::move(p));
  return f;
}

}  // namespace

FigureFiles draw_map(const Part& run, const std::string& plot, bool overwrite, const std::string& scenario) {
  if (run.command != "analyze map" || !run.shard.whole())
    throw std::logic_error("draw_map: expects a whole analyze map run, got " + run.command + " shard " + run.shard.text());
  // What the figure needs besides the rows, from the run's envelope (map_run.hpp): the scenario
  // file (its theory boundary is drawn from it), the grid and the theory's kind.
  std::string recorded, theory_kind, digest, contact;
  MapGrid grid;
  try {
    const nlohmann::json env = nlohmann::json::parse(run.envelope);
    const nlohmann::json& result = env.at("result");
    recorded = result.at("scenario").get<std::string>();
    for (const auto& text : result.at("grid")) grid.axes.push_back(parse_map_axis(text.get<std::string>()));
    theory_kind = result.at("theory").at("kind").get<std::string>();
    digest = env.at("data").at("sha256").get<std::string>();
    if (result.contains("contact")) contact = result.at("contact").at("name").get<std::string>();
  } catch (const std::exception& e) {  // a hand-edited part: its envelope is not a map run's
    throw std::invalid_argument(std::string("--plot: the parts' envelope is not a map run's (result.scenario, "
                                            "result.grid, result.theory.kind, data.sha256): ") + e.what());
  }
  if (grid.axes.size() > 2)
    throw std::invalid_argument("--plot draws 1-D and 2-D maps; this one varies " + std::to_string(grid.axes.size()) +
                                " keys (write the table with -o and plot two of them yourself)");
  // The scenario is read again for the boundary: it must be the file the map ran on.
  const std::string file = scenario.empty() ? recorded : scenario;
  const std::string given = scenario.empty() ? "" : " (--scenario)";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw std::invalid_argument("--plot: the map's scenario " + file + given +
                                " is not a file here; the map's theory boundary is drawn from it (give it with "
                                "--scenario FILE where the parts' path does not resolve)");
  if (sha256_file(file) != digest)
    throw std::invalid_argument("--plot: the scenario " + file + given + " is not the file the map ran on (" + recorded +
                                "): its SHA-256 differs from the run's");
  std::vector<std::string> keys;
  for (const auto& ax : grid.axes) keys.push_back(ax.key);
  const ScenarioGrid g(file, keys);
  progress_stage("drawing " + plot);
  const FigureFiles files = write_figure(
      map_figure(g, grid, run.table, theory_kind,
                 std::filesystem::path(recorded).filename().string() + (contact.empty() ? "" : ", contact " + contact),
                 scenario_axis(file)),
      plot, overwrite);
  return files;
}

void add_map_options(CLI::App* cmd, MapArgs& a) {
  cmd->add_option("--vary", a.vary,
                  "map: KEY=START:STOP:N (or KEY=log:START:STOP:N): N values of a scenario key, a dotted path into "
                  "the scenario file (plant.k, plant.V0, controller.Kp, friction.Fs, ...); repeat for a 2-D map")
      ->group("Map (analyze map SCENARIO.yaml)");
  cmd->add_option("--jobs", a.jobs, "map: threads (default 0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->group("Map (analyze map SCENARIO.yaml)");
  cmd->add_option("--shard", a.shard,
                  "map: run only shard K of N (grid points i with i % N == K - 1) and write a part file to -o; "
                  "`frictionlab merge` joins the parts")
      ->check(shard_text_check())
      ->group("Map (analyze map SCENARIO.yaml)");
  cmd->add_option("--contact", a.contact,
                  "map: the contact whose motion is classified, by name (x, y of an xy-table) or index from 0; "
                  "default: the first (the one contact of a 1-DOF plant). Its name is the table's contact column "
                  "and the JSON's result.contact")
      ->group("Map (analyze map SCENARIO.yaml)");
  output_option(cmd->add_option("-o,--output", a.out,
                                "map: the table, one row per grid point (.csv or .json), or with --shard the part file")
                    ->group("Map (analyze map SCENARIO.yaml)"));
  cmd->add_option("--transient", a.transient,
                  "map: time discarded from the start of each run before classifying (s; default: half of the run)")
      ->check(CLI::NonNegativeNumber)
      ->group("Map (analyze map SCENARIO.yaml)");
  cmd->add_option("--tolerance", a.tolerance,
                  "map: a velocity oscillation below this fraction of the run's largest |v| counts as none")
      ->capture_default_str()
      ->group("Map (analyze map SCENARIO.yaml)");
}

int run_map_command(const std::string& scenario, const MapArgs& a, const OutputOptions& output) {
  MapGrid grid;
  for (const auto& v : a.vary) grid.axes.push_back(parse_map_axis(v));
  grid.validate();
  MapRunOptions ro;
  ro.shard = a.shard.empty() ? ShardSpec{} : parse_shard(a.shard);
  if (a.transient >= 0) ro.motion.transient = a.transient;
  ro.motion.tolerance = a.tolerance;
  ro.motion.validate();
  ro.threads = a.jobs;
  ro.contact = a.contact;
  const bool sharded = !a.shard.empty();
  if (sharded) {
    if (a.out.empty()) throw std::invalid_argument("--shard " + a.shard + " needs -o PART (the part file to write)");
    if (std::filesystem::path(a.out).extension() != ".json")
      throw InputError(errc::option_invalid,
                       "-o " + a.out + ": --shard " + a.shard + " writes a part file, which is JSON: expected -o PART.json",
                       {.option = "-o", .value = a.out});
    if (!output.json.empty() || !output.plot.empty())
      throw std::invalid_argument("--shard writes a part file only (-o); merge the parts (frictionlab merge PART... -o "
                                  "OUT.csv|OUT.json) and draw the unsharded map for --plot");
  } else if (!a.out.empty()) {
    const std::string ext = std::filesystem::path(a.out).extension().string();
    if (ext != ".csv" && ext != ".json")
      throw std::invalid_argument("-o " + a.out + ": expected a .csv or .json file (the table)");
  }
  if (!output.plot.empty() && grid.axes.size() > 2)
    throw std::invalid_argument("--plot draws 1-D and 2-D maps; this one varies " + std::to_string(grid.axes.size()) +
                                " keys (write the table with -o and plot two of them yourself)");
  std::vector<RunFile> inputs = output.command ? command_inputs(output.command) : std::vector<RunFile>{};
  inputs.push_back({"SCENARIO", scenario, RunFile::Kind::file});
  for (RunFile& f : scenario_inputs(scenario)) inputs.push_back(std::move(f));
  check_outputs(output, inputs, {{"-o", a.out, RunFile::Kind::file}});

  std::mutex m;
  ro.progress = [&](std::size_t done, std::size_t n) {
    std::lock_guard lock(m);
    progress_stage("simulated " + std::to_string(done) + " of " + std::to_string(n) + " points");
  };
  const MapRun run = map_scenario(scenario, grid, ro);
  const Part& part = run.part;

  // The text: what ran, the transient discarded, the classes found, theory against simulation.
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(part.table.columns.begin(), part.table.columns.end(), name) -
                                    part.table.columns.begin());
  };
  const std::size_t c_class = col("class"), c_theory = col("theory"), c_transient = col("transient");
  std::map<std::string, std::size_t> counts;
  std::size_t agree = 0, predicted = 0;
  double shown_transient = NAN;
  for (const auto& row : part.table.rows) {
    const std::string& kind = std::get<std::string>(row[c_class]);
    ++counts[kind];
    const std::string& th = std::get<std::string>(row[c_theory]);
    if (!th.empty()) {
      ++predicted;
      agree += th == kind;
    }
    if (std::isnan(shown_transient)) shown_transient = std::get<double>(row[c_transient]);
  }
  std::ostringstream text;
  text << "map " << scenario << ": "
       << (sharded ? "shard " + ro.shard.text() + ", " + std::to_string(part.table.rows.size()) + " of " : "")
       << part.total << " points";
  for (const auto& ax : grid.axes) text << " " << ax.text();
  if (!run.contact_name.empty()) text << ", contact " << run.contact_name << " (index " << run.contact << ")";
  text << "\ntransient: "
       << (a.transient >= 0 ? "the first " + format_number(a.transient) + " s"
                            : "the first half of each run (" + format_number(shown_transient) + " s here)")
       << " discarded before classifying (--transient S)\n";
  for (const auto& [kind, n] : counts) text << "  " << kind << " " << n << "\n";
  if (!run.theory_kind.empty()) {
    text << "theory (" << run.theory_kind << "): " << run.theory_note << "\n";
    if (predicted > 0) text << "  agrees with the simulation at " << agree << " of " << predicted << " points\n";
  }

  std::ostream& note = output.json == "-" ? std::cerr : std::cout;
  if (sharded) {
    AtomicWriteOptions w;
    w.overwrite = output.overwrite;
    write_file_atomic(a.out, part_to_json(part), w);
    note << text.str() << "part " << a.out << " (join the parts: frictionlab merge PART... -o OUT.csv)\n";
    progress_stop();
    return 0;
  }
  note << text.str();
  if (!output.plot.empty()) {
    const FigureFiles files = draw_map(part, output.plot, output.overwrite);
    note << "figure " << files.figure << " (data " << files.data << ", gnuplot script " << files.script << ")\n";
  }
  if (!a.out.empty()) {
    write_table(a.out, part, output.overwrite);
    note << "table " << a.out << "\n";
  }
  if (output.json == "-") {
    std::cout << table_json(part, -1);
  } else if (!output.json.empty()) {
    std::cout.flush();
    AtomicWriteOptions w;
    w.overwrite = output.overwrite;
    write_file_atomic(output.json, table_json(part), w);
  }
  progress_stop();
  return 0;
}

}  // namespace frictionlab::cli
