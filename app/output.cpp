#include "output.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <streambuf>
#include <thread>
#include <unistd.h>

#include "figures.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/io/atomic_write.hpp"
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/report/figure.hpp"
#include "frictionlab/report/report.hpp"
#include "frictionlab/version.hpp"

#include <nlohmann/json.hpp>

namespace frictionlab::cli {

// ---------------------------------------------------------------------------------------------
// Progress line. A thread redraws "\r<task>: <stage> ... 3.2 s" on stderr every 0.25 s once the
// run has taken a second; std::cout and std::cerr are routed through a buffer that erases the
// line before any other text, so messages never land in the middle of it.
namespace {

class Progress {
 public:
  static Progress& instance() {
    static Progress p;
    return p;
  }

  void start(const std::string& task) {
    if (!::isatty(STDERR_FILENO) || std::getenv("FRICTIONLAB_NO_PROGRESS")) return;
    std::lock_guard lock(mutex_);
    if (thread_.joinable()) return;
    task_ = task;
    stage_ = "working";
    begin_ = last_output_ = Clock::now();
    install();
    thread_ = std::jthread([this](std::stop_token stop) { loop(stop); });
  }

  void stage(const std::string& s) {
    std::lock_guard lock(mutex_);
    stage_ = s;
  }

  void stop() {
    if (!thread_.joinable()) return;
    thread_.request_stop();
    wake_.notify_all();
    thread_.join();
    std::lock_guard lock(mutex_);
    erase_locked();
  }

  // Called by the routing buffer before any text goes out.
  void before_output() {
    std::lock_guard lock(mutex_);
    erase_locked();
    last_output_ = Clock::now();
  }

  ~Progress() {
    stop();
    if (cout_) std::cout.rdbuf(cout_->inner);
    if (cerr_) std::cerr.rdbuf(cerr_->inner);
  }

 private:
  using Clock = std::chrono::steady_clock;

  struct Routing : std::streambuf {
    explicit Routing(std::streambuf* in) : inner(in) {}
    std::streambuf* inner;

   protected:
    int_type overflow(int_type c) override {
      if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
      Progress::instance().before_output();
      return inner->sputc(traits_type::to_char_type(c));
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
      Progress::instance().before_output();
      return inner->sputn(s, n);
    }
    int sync() override { return inner->pubsync(); }
  };

  void install() {
    if (cout_) return;
    cout_ = std::make_unique<Routing>(std::cout.rdbuf());
    cerr_ = std::make_unique<Routing>(std::cerr.rdbuf());
    std::cout.rdbuf(cout_.get());
    std::cerr.rdbuf(cerr_.get());
  }

  void erase_locked() {
    if (!shown_) return;
    const char clear[] = "\r\033[K";
    [[maybe_unused]] const auto n = ::write(STDERR_FILENO, clear, sizeof clear - 1);
    shown_ = false;
  }

  void loop(const std::stop_token& stop) {
    std::mutex m;
    std::unique_lock wait_lock(m);
    while (!stop.stop_requested()) {
      wake_.wait_for(wait_lock, stop, std::chrono::milliseconds(250), [] { return false; });
      if (stop.stop_requested()) break;
      std::lock_guard lock(mutex_);
      const auto now = Clock::now();
      if (now - begin_ < std::chrono::seconds(1) || now - last_output_ < std::chrono::milliseconds(500)) continue;
      std::ostringstream line;
      line << "\r\033[K" << task_ << ": " << stage_ << " ... " << std::fixed << std::setprecision(1)
           << std::chrono::duration<double>(now - begin_).count() << " s";
      const std::string s = line.str();
      [[maybe_unused]] const auto n = ::write(STDERR_FILENO, s.data(), s.size());
      shown_ = true;
    }
  }

  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::jthread thread_;
  std::string task_, stage_;
  Clock::time_point begin_, last_output_;
  bool shown_ = false;
  std::unique_ptr<Routing> cout_, cerr_;
};

std::string command_path(const CLI::App* cmd) {
  std::string s;
  // The root's name is argv[0] (a build path): the tool's own name reads better.
  for (const CLI::App* a = cmd; a; a = a->get_parent())
    s = (a->get_parent() ? a->get_name() : std::string("frictionlab")) + (s.empty() ? "" : " " + s);
  return s;
}

std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_of(" \t\n'\"\\$`*?[]{}();&|<>!#~") == std::string::npos) return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The command line (as given, options in their declared order) and every option with its value
// or default, for the report.
ReportInfo report_info(const Result& r, const OutputOptions& o) {
  ReportInfo info;
  info.version = kVersion;
  if (!o.command) {
    info.title = "frictionlab " + r.method;
    return info;
  }
  info.title = command_path(o.command);
  std::string line = info.title;
  for (const CLI::Option* opt : o.command->get_options()) {
    const std::string name = opt->get_name(false, true);
    if (name == "--help" || name == "-h" || name.empty()) continue;
    const bool flag = opt->get_expected_min() == 0 && opt->get_type_size_max() == 0;
    if (opt->count() > 0) {
      std::string joined;
      for (const auto& v : opt->results()) {
        if (!flag) line += " " + (opt->get_positional() ? "" : name + " ") + shell_word(v);
        joined += (joined.empty() ? "" : ", ") + v;
      }
      if (flag) line += " " + name;
      info.options.emplace_back(name, flag ? "yes" : joined);
    } else if (!opt->get_default_str().empty()) {
      info.options.emplace_back(name, opt->get_default_str() + " (default)");
    }
  }
  info.command_line = line;
  return info;
}

}  // namespace

void progress_start(const std::string& task) { Progress::instance().start(task); }
void progress_stage(const std::string& stage) { Progress::instance().stage(stage); }
void progress_stop() { Progress::instance().stop(); }

// ---------------------------------------------------------------------------------------------

void add_output_options(CLI::App* cmd, OutputOptions& o) {
  o.command = cmd;
  CLI::Option* json =
      cmd->add_option("--json", o.json, "Write the result as JSON to FILE, or to stdout with '-'")->group("Output");
  cmd->add_option("--plot", o.plot,
                  "Draw the result's figure to FILE (.svg, .png or .pdf, by gnuplot); FILE.dat (data) and FILE.gp "
                  "(script) are written next to it for restyling")
      ->group("Output");
  cmd->add_option("--report", o.report,
                  "Write a self-contained DIR/report.html (data, options, parameters with std and units, fit, "
                  "diagnostics, warnings, figures)")
      ->group("Output");
  cmd->add_flag("--overwrite", o.overwrite, "Replace existing output files and report files")->group("Output");
  const std::string name = cmd->get_name();
  register_json_output(cmd, json, [name] { return name; });
}

void add_plot_option(CLI::App* cmd, std::string& plot) {
  cmd->add_option("--plot", plot,
                  "Draw the figure to FILE (.svg, .png or .pdf, by gnuplot); FILE.dat (data) and FILE.gp (script) are "
                  "written next to it for restyling");
}

// ---------------------------------------------------------------------------------------------
// Errors: one line on stderr, and the error JSON where --json asks for it.
namespace {

struct JsonOutput {
  CLI::App* command;
  CLI::Option* json;
  std::function<std::string()> method;
};

std::vector<JsonOutput>& json_outputs() {
  static std::vector<JsonOutput> outputs;
  return outputs;
}

// The registered subcommand that was chosen (parsed() is set as soon as CLI11 enters it, so this
// also works after a parse error).
const JsonOutput* chosen_output() {
  for (const auto& o : json_outputs())
    if (o.command->parsed()) return &o;
  return nullptr;
}

// Messages are one line: a stray newline from a library message must not split it.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

void register_json_output(CLI::App* cmd, CLI::Option* json, std::function<std::string()> method) {
  json_outputs().push_back({cmd, json, std::move(method)});
}

void print_error(const std::string& message, bool internal) {
  progress_stop();
  std::cerr << "frictionlab: " << (internal ? "internal error: " : "error: ") << one_line(message) << std::endl;
}

int fail(const std::string& message, int status, bool internal, const std::string& code, const ErrorFields& fields) {
  try {
    print_error(valid_utf8(message), internal);
    const JsonOutput* out = chosen_output();
    if (!out || !out->json || out->json->count() == 0 || out->json->results().empty()) return status;
    const std::string path = out->json->results().back();
    if (path.empty()) return status;
    const std::string text = one_line(message);
    nlohmann::json error = {{"code", code.empty() ? (status == 2 ? errc::input_invalid : errc::internal) : code},
                            {"message", text}};
    for (const auto& [name, value] : fields.items()) {
      if (name == "row") error[name] = *fields.row;
      else error[name] = value;
    }
    const nlohmann::json j = {{"schema", 1},
                              {"status", "error"},
                              {"message", text},
                              {"method", out->method ? out->method() : std::string()},
                              {"error", error}};
    if (path == "-") std::cout << json_text(j) << std::endl;
  } catch (...) {
    // Reporting an error must not raise another one; the line on stderr is out already.
  }
  return status;
}

int fail(const std::exception& e, int status, bool internal) {
  return fail(e.what(), status, internal, error_code(e), error_fields(e));
}

// ---------------------------------------------------------------------------------------------
// Output paths, checked before any work.

void check_output_file(const std::string& path, bool overwrite, const std::string& option) {
  if (path.empty() || path == "-") return;
  try {
    check_output_path(path, overwrite);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(option + " " + e.what());
  }
}

void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& paths) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, fs::path>> seen;
  for (const auto& [option, path] : paths) {
    if (path.empty() || path == "-") continue;
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    if (ec) p = fs::absolute(path, ec).lexically_normal();
    for (const auto& [other, q] : seen)
      if (p == q)
        throw std::invalid_argument(option + " " + path + " is also the " + other +
                                    " output; give each output its own file");
    seen.emplace_back(option, p);
  }
}

void check_plot(const std::string& plot, bool overwrite) {
  if (plot.empty()) return;
  try {
    check_figure_path(plot, overwrite);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--plot ") + e.what());
  }
  // The figure, its data and its script are renamed into place: what is there must be a
  // regular file (never a directory, device or FIFO, which a rename would replace).
  const FigureFiles files = figure_files(plot);
  for (const auto& f : {files.figure, files.data, files.script}) {
    std::error_code ec;
    const auto st = std::filesystem::status(f, ec);
    if (st.type() == std::filesystem::file_type::not_found || st.type() == std::filesystem::file_type::none) continue;
    if (std::filesystem::is_directory(st))
      throw std::invalid_argument("--plot " + f + " is a directory; expected a file name");
    if (!std::filesystem::is_regular_file(st))
      throw std::invalid_argument("--plot " + f +
                                  " is not a regular file; a figure is written with its .dat and .gp files by "
                                  "renaming them into place, so give the name of a regular file");
  }
  find_gnuplot();
}

void check_outputs(const OutputOptions& o) {
  check_output_file(o.json, o.overwrite, "--json");
  check_plot(o.plot, o.overwrite);
  if (!o.report.empty()) {
    try {
      check_report_dir(o.report, o.overwrite);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--report ") + e.what());
    }
    find_gnuplot();
  }
  std::vector<std::pair<std::string, std::string>> paths{{"--json", o.json}, {"--report", o.report}};
  if (!o.plot.empty()) {
    const FigureFiles files = figure_files(o.plot);
    paths.insert(paths.end(), {{"--plot", files.figure}, {"--plot data", files.data}, {"--plot script", files.script}});
  }
  check_distinct_outputs(paths);
  progress_start(o.command ? command_path(o.command) : "frictionlab");
}

std::string result_text(const Result& r) {
  std::ostringstream s;
  s << "frictionlab identify " << r.method;
  if (!r.data_file.empty()) s << ": " << r.data_file;
  s << "\n";
  if (!r.ok()) {
    s << "error: " << r.message << "\n";
    return s.str();
  }
  s << "model " << r.model << ", " << r.fit.samples << " samples\n";
  std::size_t w = 6;
  for (const auto& p : r.parameters) w = std::max(w, p.name.size());
  for (const auto& p : r.parameters) {
    s << "  " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::right << std::setw(12)
      << format_number(p.value, 6) << "  +- " << std::left << std::setw(10) << format_number(p.std, 3) << " " << p.unit
      << (p.flag.empty() ? "" : "  (" + p.flag + ")") << "\n";
  }
  // The fitted signal's unit comes with the result (set by its method: identify/method.hpp).
  const std::string fit_unit = fit_signal_and_unit(r).second;
  s << "fit: relative error " << format_number(r.fit.relative_error_percent, 4) << " %, rmse "
    << format_number(r.fit.rmse, 4) << " " << fit_unit << "\n";
  if (r.validation)
    s << "cross-test " << r.validation->file << ": relative error "
      << format_number(r.validation->relative_error_percent, 4) << " %, rmse " << format_number(r.validation->rmse, 4)
      << " " << fit_unit << "\n";
  if (std::isfinite(r.diagnostics.condition_number))
    s << "condition number " << format_number(r.diagnostics.condition_number, 4) << "\n";
  for (const auto& [name, group] : r.diagnostics.groups) {
    s << name << ":";
    for (const auto& [k, v] : group) s << " " << k << " = " << format_number(v, 6);
    s << "\n";
  }
  for (const auto& [name, word] : r.diagnostics.texts) s << name << ": " << word << "\n";
  for (const auto& w2 : r.diagnostics.warnings) s << "warning: " << w2 << "\n";
  return s.str();
}

int emit(const Result& r, const OutputOptions& o, const std::string& text_override,
         const std::vector<ReportFigure>* figures) {
  progress_stage("writing results");
  std::ostream& note = o.json == "-" ? std::cerr : std::cout;
  if (!r.ok()) {
    // The data gave no answer: one error line (naming the data file), then the JSON and the
    // report that say why. No figure.
    const bool named = r.data_file.empty() || r.message.find(r.data_file) != std::string::npos;
    print_error(named ? r.message : r.data_file + ": " + r.message);
    if (!o.report.empty()) write_report(r, {}, report_info(r, o), o.report, o.overwrite);
  } else {
    // Text goes to stderr when stdout carries the JSON.
    (o.json == "-" ? std::cerr : std::cout) << (text_override.empty() ? result_text(r) : text_override);
    // The figure and the report first: they run gnuplot and may fail; the JSON, written last,
    // then never says ok for a run that failed (the error JSON replaces it, see fail()).
    // The method's figures (app/methods/), or the ones the command drew itself.
    const std::vector<ReportFigure> figs = figures ? *figures : result_figures(r);
    // --plot draws the method's "fit" figure, or the first of the command's own.
    const bool has_fit = !figs.empty() && (figures != nullptr || figs.front().name == "fit");
    if (!o.plot.empty()) {
      if (!has_fit) throw std::runtime_error("--plot: the " + r.method + " result carries no signals to draw");
      progress_stage("drawing " + o.plot);
      const FigureFiles files = write_figure(figs.front().figure, o.plot, o.overwrite);
      note << "figure " << files.figure << " (data " << files.data << ", gnuplot script " << files.script << ")\n";
    }
    if (!o.report.empty()) {
      progress_stage("writing report " + o.report);
      const std::string page = write_report(r, figs, report_info(r, o), o.report, o.overwrite);
      note << "report " << page << "\n";
    }
  }
  if (o.json == "-") {
    std::cout << to_json(r, -1) << std::endl;
  } else if (!o.json.empty()) {
    std::cout.flush();  // the table first when --json is this process's stdout (/dev/stdout)
    AtomicWriteOptions w;
    w.overwrite = o.overwrite;
    write_file_atomic(o.json, to_json(r) + "\n", w);
  }
  progress_stop();
  return r.ok() ? 0 : 2;
}

}  // namespace frictionlab::cli
