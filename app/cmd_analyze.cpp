// frictionlab analyze envelope|stick-slip DATA [--time C] [--position C] [--velocity C] [--force C]
//                     [--json FILE|-] [--plot FILE] [--overwrite]
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "data_options.hpp"
#include "figures.hpp"
#include "frictionlab/io/figure.hpp"
#include "output.hpp"
#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "frictionlab/io/atomic_write.hpp"
#include "frictionlab/io/load.hpp"

namespace frictionlab::cli {
namespace {

struct AnalyzeArgs {
  std::string method;
  std::string data;
  std::string time = "time", position = "position", velocity = "velocity", force = "friction";
  std::string json;
  std::string plot;
  bool overwrite = false;
  double threshold = 0.0;
  ReadOptions read;  // --names, --resample, --max-gap, --drop-invalid
};

// NaN is not JSON: null instead.
nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

std::vector<double> column(const Dataset& d, const std::string& name, const std::string& option) {
  if (!d.has_column(name)) throw std::invalid_argument(d.missing_column_message(name, option));
  const Eigen::VectorXd& c = d.column(name);
  std::vector<double> out(c.data(), c.data() + c.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      throw std::invalid_argument(d.where() + d.row_label(static_cast<Eigen::Index>(i)) + ", column '" + name +
                                  "': expected a finite number");
  return out;
}

nlohmann::json envelope_json(const EnvelopeResult& r) {
  auto fit = [](const EnvelopeFit& f) {
    return nlohmann::json{{"lambda", num(f.lambda)}, {"p", num(f.p)}, {"q", num(f.q)}, {"slope", num(f.slope)},
                          {"relative_rms", num(f.relative_rms)}};
  };
  return {{"kind", decay_kind_name(r.kind)},
          {"half_cycles", r.amplitudes.size()},
          {"half_period", num(r.half_period)},
          {"decay_fraction", num(r.decay_fraction)},
          {"decrement_per_half_cycle", num(r.decrement_per_half_cycle)},
          {"log_decrement", num(r.log_decrement)},
          {"fits", {{"linear", fit(r.linear)}, {"exponential", fit(r.exponential)}, {"mixed", fit(r.mixed)}}},
          {"peak_times", r.peak_times},
          {"amplitudes", r.amplitudes}};
}

nlohmann::json stick_slip_json(const StickSlipResult& r) {
  auto intervals = [](const std::vector<TimeInterval>& v) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& i : v) a.push_back({i.start, i.end});
    return a;
  };
  return {{"slips", r.slip.size()},
          {"period", num(r.period)},
          {"peak_slip_velocity", num(r.peak_slip_velocity)},
          {"mean_slip_duration", num(r.mean_slip_duration)},
          {"velocity_threshold", num(r.velocity_threshold)},
          {"mean_breakaway_force", num(r.mean_breakaway_force)},
          {"mean_restick_force", num(r.mean_restick_force)},
          {"mean_force_drop", num(r.mean_force_drop)},
          {"breakaway_force", r.breakaway_force},
          {"restick_force", r.restick_force},
          {"stick", intervals(r.stick)},
          {"slip", intervals(r.slip)}};
}

std::string envelope_text(const EnvelopeResult& r) {
  std::ostringstream o;
  o.precision(6);
  o << "decay        " << decay_kind_name(r.kind) << " (" << r.amplitudes.size() << " half cycles, half period "
    << r.half_period << " s)\n"
    << "amplitude    " << r.amplitudes.front() << " -> " << r.amplitudes.back() << " (lost "
    << 100.0 * r.decay_fraction << " %)\n"
    << "linear       " << r.decrement_per_half_cycle << " per half cycle (rms " << 100 * r.linear.relative_rms
    << " %)\n"
    << "exponential  rate " << r.exponential.lambda << " 1/s, log decrement " << r.log_decrement << " (rms "
    << 100 * r.exponential.relative_rms << " %)\n"
    << "mixed        rate " << r.mixed.lambda << " 1/s, offset " << r.mixed.q << " (rms "
    << 100 * r.mixed.relative_rms << " %)\n";
  return o.str();
}

std::string stick_slip_text(const StickSlipResult& r, bool with_force) {
  std::ostringstream o;
  o.precision(6);
  o << "slips        " << r.slip.size() << " (velocity threshold " << r.velocity_threshold << ")\n"
    << "period       " << (std::isfinite(r.period) ? (std::ostringstream() << std::setprecision(6) << r.period << " s").str()
                                              : std::string("n/a (fewer than two slips)"))
    << "\n"
    << "peak slip    " << r.peak_slip_velocity << " (velocity unit)\n"
    << "slip length  " << r.mean_slip_duration << " s (mean)\n";
  if (with_force)
    o << "breakaway    " << r.mean_breakaway_force << " (force unit, mean)\n"
      << "re-stick     " << r.mean_restick_force << "\n"
      << "force drop   " << r.mean_force_drop << "\n";
  return o.str();
}

}  // namespace

Handler register_analyze(CLI::App& app) {
  auto a = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand("analyze", "Analyse a motion record: decay envelope or stick-slip.");
  cmd->add_option("method", a->method,
                  "envelope (free-oscillation decay) or stick-slip (exit 2 with a message when the record never "
                  "slips)")
      ->required()
      ->check(CLI::IsMember({"envelope", "stick-slip"}));
  cmd->add_option("data", a->data,
                  "CSV file, with a header row (the output of `frictionlab simulate` works) or without one (see "
                  "--names), or .mat")
      ->required();
  cmd->add_option("--time", a->time, "time column (s)")->capture_default_str();
  cmd->add_option("--position", a->position, "position column (envelope)")->capture_default_str();
  cmd->add_option("--velocity", a->velocity, "velocity column (stick-slip)")->capture_default_str();
  cmd->add_option("--force", a->force, "friction force column (stick-slip; optional: skipped if absent)")
      ->capture_default_str();
  cmd->add_option("--threshold", a->threshold,
                  "stick-slip: |v| at or below counts as stuck (0 = automatic: exact zeros or 1 % of max |v|)");
  CLI::Option* json = cmd->add_option("--json", a->json, "write the result as JSON to FILE, or '-' for stdout");
  add_plot_option(cmd, a->plot);
  cmd->add_flag("--overwrite", a->overwrite, "replace an existing --json or --plot file");
  add_read_options(cmd, a->read);
  register_json_output(cmd, json, [a] { return a->method.empty() ? std::string("analyze") : a->method; });
  return [a]() -> int {
    check_output_file(a->json, a->overwrite, "--json");
    check_plot(a->plot, a->overwrite);
    if (!a->plot.empty()) {
      const FigureFiles files = figure_files(a->plot);
      check_distinct_outputs(
          {{"--json", a->json}, {"--plot", files.figure}, {"--plot data", files.data}, {"--plot script", files.script}});
    }
    const Dataset d = load_data(a->data, a->read, a->time);
    // The result (or the reason there is none) to stdout with --json -, or atomically to FILE.
    const auto write_json = [&a](const nlohmann::json& j) {
      if (a->json == "-") {
        std::cout << j.dump(2) << "\n";
      } else if (!a->json.empty()) {
        AtomicWriteOptions w;
        w.overwrite = a->overwrite;
        write_file_atomic(a->json, j.dump(2) + "\n", w);
      }
    };
    std::optional<Figure> figure;
    const std::string name = std::filesystem::path(a->data).filename().string();
    const std::vector<double> t = column(d, a->time, "--time");
    nlohmann::json result;
    std::string text;
    if (a->method == "envelope") {
      const std::vector<double> x = column(d, a->position, "--position");
      EnvelopeResult r;
      try {
        r = decay_envelope(t, x);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(d.where() + e.what());
      }
      result = envelope_json(r);
      if (!a->plot.empty()) figure = envelope_figure(t, x, r, name);
      text = envelope_text(r);
    } else {
      const std::vector<double> v = column(d, a->velocity, "--velocity");
      std::vector<double> f;
      if (d.has_column(a->force)) f = column(d, a->force, "--force");
      StickSlipOptions o;
      o.velocity_threshold = a->threshold;
      StickSlipResult r;
      try {
        r = detect_stick_slip(t, v, f, o);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(d.where() + e.what());
      }
      if (!r.found()) {  // data that cannot give an answer: exit 2, with the JSON if asked for
        const std::string message = d.where() + r.message;
        const nlohmann::json j = {{"schema", 1},
                                  {"status", "error"},
                                  {"message", message},
                                  {"method", a->method},
                                  {"data", {{"file", d.file}, {"sha256", d.sha256}}}};
        print_error(message);
        write_json(j);
        return 2;
      }
      result = stick_slip_json(r);
      if (!a->plot.empty()) figure = stick_slip_figure(t, v, f, r, name);
      text = stick_slip_text(r, !f.empty());
    }
    text = data_note(d) + text;
    nlohmann::json j = {{"schema", 1},
                        {"status", "ok"},
                        {"message", ""},
                        {"method", a->method},
                        {"data", {{"file", d.file}, {"sha256", d.sha256}}},
                        {"result", result}};
    if (d.resampling || !d.warnings.empty()) {
      Result notes;  // the data's resampling record and warnings, as identify reports them
      note_data(notes, d);
      j["diagnostics"]["warnings"] = notes.diagnostics.warnings;
      if (d.resampling) j["diagnostics"]["resampling"] = notes.diagnostics.groups.at("resampling");
    }
    (a->json == "-" ? std::cerr : std::cout) << text;
    // The figure (gnuplot may fail) before the JSON, so that a failed run leaves no JSON saying ok.
    if (figure) {
      const FigureFiles files = write_figure(*figure, a->plot, a->overwrite);
      (a->json == "-" ? std::cerr : std::cout) << "figure " << files.figure << " (data " << files.data
                                               << ", gnuplot script " << files.script << ")\n";
    }
    write_json(j);
    return 0;
  };
}

}  // namespace frictionlab::cli
