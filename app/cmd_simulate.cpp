// frictionlab simulate SCENARIO.yaml [-o OUT.csv] [--plot FILE] [--overwrite]
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/models/parameter.hpp"
#include "contour_figure.hpp"
#include "figures.hpp"
#include "report/figure.hpp"
#include "output.hpp"
#include "finite_output.hpp"
#include "io/atomic_write.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "frictionlab/simulate/output_size.hpp"
#include "frictionlab/simulate/simulate.hpp"

namespace frictionlab::cli {
namespace {

struct SimulateArgs {
  std::string scenario;
  std::string output;
  std::string plot;
  bool overwrite = false;
};

// A contact's label in the summary: "" for a 1-DOF plant's one contact, "x: " for a named one.
std::string label_of(const Trajectory& tr, int k) {
  const std::string& name = tr.contact_names.empty() ? std::string() : tr.contact_names[static_cast<std::size_t>(k)];
  return name.empty() ? std::string() : name + ": ";
}

// A short human summary of a run: what ran, where it ended, the mode switches. A plant with
// several contacts gets one line per contact where the 1-DOF summary has one value.
std::string summary(const std::string& file, const Scenario& sc, const Trajectory& tr) {
  std::ostringstream out;
  const int nc = tr.num_contacts();
  std::string laws, finals, peaks;
  // Units of the plant's motion: m, m/s, N on a linear axis; rad, rad/s, N m on a rotary one.
  const Axis axis = sc.plant->motion_axis();
  const std::string pos = " " + std::string(unit(Quantity::displacement, axis));
  const std::string vel = " " + std::string(unit(Quantity::velocity, axis));
  const std::string force = " " + std::string(unit(Quantity::force, axis));
  for (int k = 0; k < nc; ++k) {
    const ContactColumns& c = tr.contact(k);
    double vmax = 0.0, fmax = 0.0;
    for (std::size_t i = 0; i < tr.rows(); ++i) {
      vmax = std::max(vmax, std::abs(c.velocity[i]));
      fmax = std::max(fmax, std::abs(c.friction[i]));
    }
    const std::string sep = k == 0 ? "" : "\n           ";
    const FrictionLaw* own = k < sc.plant->num_contacts() ? sc.plant->contact(k).law : nullptr;
    laws += sep + label_of(tr, k) + (own ? own->name() : sc.law.name());
    finals += sep + label_of(tr, k) + "position " + format_number(c.position.back()) + pos + ", velocity " +
              format_number(c.velocity.back()) + vel;
    peaks += sep + label_of(tr, k) + "|velocity| " + format_number(vmax) + vel + ", |friction| " + format_number(fmax) + force;
  }
  out << "scenario   " << file << "\n"
      << "plant      " << sc.plant->type() << "\n"
      << "friction   " << laws << "\n"
      << "solver     " << tr.stats.solver << " (" << tr.stats.steps << " steps, " << tr.stats.restarts
      << " restarts)\n"
      << "samples    " << tr.rows() << " rows, t = 0 .. " << format_number(tr.time.back()) << " s\n"
      << "final      " << finals << "\n"
      << "peak       " << peaks << "\n";
  if (!tr.switches.empty()) {
    out << "switches   " << tr.switches.size() << " (stick/slip mode changes)\n";
    const std::size_t shown = std::min<std::size_t>(tr.switches.size(), 6);
    for (std::size_t i = 0; i < shown; ++i) {
      const auto& s = tr.switches[i];
      out << "  t = " << format_number(s.time) << " s  " << label_of(tr, s.contact) << switch_kind_name(s.kind) << "  at position "
          << format_number(s.position) << pos << ", applied " << format_number(s.applied) << force << "\n";
    }
    if (shown < tr.switches.size()) out << "  ... (" << tr.switches.size() - shown << " more)\n";
  }
  if (!tr.plant_events.empty()) {
    // Impacts and separations of a backlash, a compensator's switches: first and last instants.
    out << "events     " << tr.plant_events.size() << " of the plant's own (impacts, separations, switches), t = "
        << format_number(tr.plant_events.front().time) << " .. " << format_number(tr.plant_events.back().time) << " s\n";
  }
  return out.str();
}

}  // namespace

Handler register_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate a scenario file (plant, friction law, input) to CSV.");
  cmd->add_option("scenario", args->scenario, "scenario YAML file (see examples/*.yaml)")->required();
  output_option(cmd->add_option("-o,--output", args->output,
                                "write the trajectory as CSV (columns time, position, velocity, friction, applied, "
                                "current, voltage, reference, stuck; a plant with several axes: time, then x.position, "
                                "x.velocity, ... x.drive for each axis); without it a summary is printed"));
  add_plot_option(cmd, args->plot);
  cmd->add_flag("--overwrite", args->overwrite, "replace an existing output file");
  return [args]() -> int {
    // Every output path is checked before the (possibly long) simulation; the figure, which
    // runs gnuplot and may fail, is written before the CSV.
    // What the output paths are is checked first (a bad path is named before a bad scenario);
    // the files the scenario names (data, compensation models) are inputs too, known once it is
    // read: then every rule, before the simulation.
    const std::vector<RunFile> outputs{{"-o", args->output, RunFile::Kind::file},
                                       {"--plot", args->plot, RunFile::Kind::figure}};
    std::vector<RunFile> inputs{{"scenario", args->scenario, RunFile::Kind::file}};
    try {
      check_run_files(inputs, outputs, true);
    } catch (const std::invalid_argument&) {
      // An output at a file the scenario names is said to be that, whatever else is wrong with it
      // (a --plot at the scenario's data file): the same check with those files throws it first.
      std::vector<RunFile> all = inputs;
      for (auto& f : scenario_inputs(args->scenario)) all.push_back(std::move(f));
      check_run_files(all, outputs, true);
      throw;
    }
    progress_start("frictionlab simulate");
    std::vector<std::string> named;
    ScenarioOptions options;
    options.files_read = &named;
    const Scenario sc = load_scenario(args->scenario, options);
    for (const auto& f : named) inputs.push_back({"named by the scenario", f, RunFile::Kind::file});
    check_run_files(inputs, outputs, args->overwrite);
    if (!args->output.empty()) {
      // The CSV text is made in memory beside the columns the run holds: up to 25 bytes a
      // number (%.17g and a separator) against 8, so the scenario's own check is not enough.
      double columns = 1;  // time
      for (int k = 0; k < sc.plant->num_contacts(); ++k) {
        const FrictionLaw* law = sc.plant->contact(k).law ? sc.plant->contact(k).law : &sc.law;
        columns += 11 + (law->is_dynamic() ? law->num_states() : 0);
      }
      const double rows = output_rows(sc.options);
      check_memory(rows * columns * (8.0 + 25.0),
                   args->scenario + ": duration " + format_number(sc.options.duration, 6) + " s at " +
                       format_number(sc.options.output_rate, 6) + " Hz gives " + format_number(rows, 3) +
                       " output rows, held with their CSV text for -o",
                   {.file = args->scenario, .key = "duration", .value = format_number(sc.options.duration, 6)});
    }
    progress_stage("simulating");
    const Trajectory tr = simulate(sc);
    if (!args->plot.empty()) {
      progress_stage("drawing " + args->plot);
      // Pendulums and motors turn (rad, N m); the other plants translate (m, N): the plant says.
      const Axis axis = sc.plant->motion_axis();
      const std::string title = std::filesystem::path(args->scenario).filename().string();
      // A two-axis table: its path in the plane (the circular test's polar error plot).
      const std::optional<Figure> xy = xy_figure(tr, title);
      const FigureFiles files = write_figure(xy ? *xy : trajectory_figure(tr, axis, title), args->plot, args->overwrite);
      progress_stop();
      std::cerr << "figure     " << files.figure << " (data " << files.data << ", script " << files.script << ")\n";
    }
    progress_stop();
    // Numbers or an error, never both: simulate() refuses non-finite columns itself; this is the
    // check every writer of numbers runs (finite_output.hpp).
    const std::string text = summary(args->scenario, sc, tr);
    require_finite_output(text, "");
    if (args->output.empty()) {
      std::cout << text;
    } else {
      const std::string csv = tr.to_csv();
      require_finite_output(csv, args->output);
      AtomicWriteOptions w;
      w.overwrite = args->overwrite;
      write_file_atomic(args->output, csv, w);
      std::cerr << text << "wrote      " << args->output << "\n";
    }
    return 0;
  };
}

}  // namespace frictionlab::cli
