#include "output.hpp"

#include "data_options.hpp"

#include <algorithm>
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
#include <cerrno>
#include <cstring>
#include <optional>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

#include "figures.hpp"
#include "frictionlab/format.hpp"
#include "frictionlab/identify/diagnostic_units.hpp"
#include "frictionlab/identify/method.hpp"
#include "frictionlab/error.hpp"
#include "frictionlab/io/json_text.hpp"
#include "frictionlab/scenario/scenario.hpp"
#include "finite_output.hpp"
#include "io/atomic_write.hpp"
#include "report/figure.hpp"
#include "report/report.hpp"
#include "frictionlab/version.hpp"

#include <nlohmann/json.hpp>

namespace frictionlab::cli {

// ---------------------------------------------------------------------------------------------
// Progress line. On a terminal, a thread redraws "\r<task>: <stage> ... 3.2 s" on stderr every
// 0.25 s once the run has taken a second; std::cout and std::cerr are routed through a buffer that
// erases the line before any other text, so messages never land in the middle of it. When stderr
// is not a terminal (a log, a pipe, a batch job), a run prints one whole line "<task>: <stage> ...
// 2.0 s" once it has taken 2 s, and another every 3 s after, so a slow run is never silent.
// FRICTIONLAB_NO_PROGRESS (any value) turns both off.
namespace {

class Progress {
 public:
  static Progress& instance() {
    static Progress p;
    return p;
  }

  void start(const std::string& task) {
    if (std::getenv("FRICTIONLAB_NO_PROGRESS")) return;
    std::lock_guard lock(mutex_);
    if (thread_.joinable()) return;
    tty_ = ::isatty(STDERR_FILENO) != 0;
    task_ = task;
    stage_ = "working";
    begin_ = last_output_ = last_line_ = Clock::now();
    lines_ = 0;
    if (tty_) install();
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
      if (!tty_) {
        // The first line at 2 s, the next ones 3 s apart.
        if (lines_ == 0 ? now - begin_ < std::chrono::seconds(2) : now - last_line_ < std::chrono::seconds(3)) continue;
        ++lines_;
        std::ostringstream line;
        line << task_ << ": " << stage_ << " ... " << std::fixed << std::setprecision(1)
             << std::chrono::duration<double>(now - begin_).count() << " s\n";
        const std::string s = line.str();
        [[maybe_unused]] const auto n = ::write(STDERR_FILENO, s.data(), s.size());
        last_line_ = now;
        continue;
      }
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
  Clock::time_point begin_, last_output_, last_line_;
  bool shown_ = false;
  bool tty_ = false;
  int lines_ = 0;  // whole lines printed (stderr not a terminal)
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

// The method's table entry of a command-line option ("--kp"), or null for the command line's
// own options (data columns, outputs, batch).
const OptionSpec* table_option(const OutputOptions& o, const std::string& name) {
  if (!o.values) return nullptr;
  for (const OptionSpec& s : o.values->table())
    if ("--" + s.name == name) return &s;
  return nullptr;
}

// The unit of an option's value in the run, on its axis: a method option's from its table, as
// the run's choices decide it (OptionValues::unit: --kp's 1/s with --controller emps-pd, also when
// the scenario gave the controller), a data option's from data_option_unit ("" for others and for
// a flag).
std::string option_unit(const OptionValues* values, const OptionSpec* spec, const std::string& name, const Result& r) {
  const bool rotary = r.axis == Axis::rotary;
  if (spec) return spec->type == OptionType::flag ? "" : values->unit(spec->name, rotary, r.diagnostics.texts);
  return data_option_unit(name, rotary ? Axis::rotary : Axis::linear);
}

// The command line (as given, options in their declared order) and the options that applied to
// the run, each with its unit: every option given, with its value; a method option not given,
// with its default when it has one and applies (OptionSpec::applies_if: --iv-iterations only with
// --iv); a data column option not given, with the column the run took by default (--velocity
// 'velocity' when the run read velocity, none when it read the position; DataOptions::columns_read),
// as a column option of the method's table not given (validate's --x); a command-line option not
// given, with its default unless that is empty or "none" (an output not asked for). The batch
// options are left out unless given: a report is of one file's run.
ReportInfo report_info(const Result& r, const OutputOptions& o) {
  ReportInfo info;
  info.version = kVersion;
  if (!o.command) {
    info.title = "frictionlab " + r.method;
    return info;
  }
  info.title = command_path(o.command);
  const auto given = [&o](const char* name) {
    const CLI::Option* opt = o.command->get_option_no_throw(name);
    return opt && opt->count() > 0;
  };
  // Without the record of the columns read: the force comes from one of --force, --input (with
  // --gain) or --current (with --kt) (force_column, data_options.cpp); once one is given, the
  // others' defaults are not used.
  const bool force_source_given = given("--force") || given("--input") || given("--gain") || given("--current") ||
                                  given("--kt");
  const auto read = [&o](const std::string& name) -> const std::string* {
    if (!o.data) return nullptr;
    const auto it = o.data->columns_read.find(name);
    return it == o.data->columns_read.end() ? nullptr : &it->second;
  };
  static const std::set<std::string> kColumns = {"--time", "--position", "--velocity", "--current", "--force", "--input"};
  std::string line = info.title;
  for (const CLI::Option* opt : o.command->get_options()) {
    const std::string name = opt->get_name(false, true);
    if (name == "--help" || name == "-h" || name.empty()) continue;
    const bool flag = opt->get_expected_min() == 0 && opt->get_type_size_max() == 0;
    const OptionSpec* spec = table_option(o, name);
    const std::string unit = flag ? "" : option_unit(o.values, spec, name, r);
    if (opt->count() > 0) {
      std::string joined;
      for (const auto& v : opt->results()) {
        if (!flag) line += " " + (opt->get_positional() ? "" : name + " ") + shell_word(v);
        joined += (joined.empty() ? "" : ", ") + v;
      }
      if (flag) line += " " + name;
      // --resample without DT: the step the run took, the median step (an empty cell said nothing).
      if (!flag && joined.empty() && name == "--resample") {
        const auto g = r.diagnostics.groups.find("resampling");
        joined = g != r.diagnostics.groups.end() && g->second.count("dt")
                     ? format_number(g->second.at("dt"), 6) + " (the median step)"
                     : "the median step";
      }
      info.options.push_back({name, flag ? "yes" : joined, unit});
    } else if (spec && spec->type == OptionType::column && o.data) {
      if (const std::string* column = read(name)) info.options.push_back({name, *column + " (default)", unit});
    } else if (spec) {
      if (spec->default_value && o.values->applies(spec->name))
        info.options.push_back({name, option_text(*spec->default_value) + " (default)", unit});
    } else if (o.data && kColumns.count(name)) {
      if (const std::string* column = read(name)) info.options.push_back({name, *column + " (default)", unit});
    } else if (const std::string d = opt->get_default_str();
               !d.empty() && d != "none" && opt->get_group().rfind("Batch", 0) != 0 &&  // kBatchGroup
               !(force_source_given && (name == "--force" || name == "--input" || name == "--current"))) {
      info.options.push_back({name, d + " (default)", unit});
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
  CLI::Option* json = output_option(
      cmd->add_option("--json", o.json, "Write the result as JSON to FILE, or to stdout with '-'")->group("Output"));
  output_option(cmd->add_option("--plot", o.plot,
                                "Draw the result's figure to FILE (.svg, .png or .pdf, by gnuplot); FILE.dat (data) and "
                                "FILE.gp (script) are written next to it for restyling")
                    ->group("Output"),
                RunFile::Kind::figure);
  output_option(cmd->add_option("--report", o.report,
                                "Write a self-contained DIR/report.html (data, options, parameters with std and units, "
                                "fit, diagnostics, warnings, figures)")
                    ->group("Output"),
                RunFile::Kind::report);
  cmd->add_flag("--overwrite", o.overwrite, "Replace existing output files and report files")->group("Output");
  const std::string name = cmd->get_name();
  register_json_output(cmd, json, [name] { return name; });
}

void add_plot_option(CLI::App* cmd, std::string& plot) {
  output_option(cmd->add_option("--plot", plot,
                                "Draw the figure to FILE (.svg, .png or .pdf, by gnuplot); FILE.dat (data) and FILE.gp "
                                "(script) are written next to it for restyling"),
                RunFile::Kind::figure);
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
    const nlohmann::json j = {{"schema", 2},
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
    rethrow_with_option(e, option + " ", option);
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

void check_outputs(const OutputOptions& o, const std::vector<RunFile>& inputs, const std::vector<RunFile>& extra) {
  std::vector<RunFile> outputs{{"--json", o.json, RunFile::Kind::file},
                               {"--plot", o.plot, RunFile::Kind::figure},
                               {"--report", o.report, RunFile::Kind::report}};
  outputs.insert(outputs.end(), extra.begin(), extra.end());
  check_run_files(inputs, outputs, o.overwrite);
  progress_start(o.command ? command_path(o.command) : "frictionlab");
}

// ---------------------------------------------------------------------------------------------
// The one rule for outputs (check_run_files).
namespace {

namespace fs = std::filesystem;

// What a path is on disk: a file's device and inode (links resolved), or for a file that does
// not exist yet its directory's device and inode and its name.
struct FileId {
  dev_t dev = 0;
  ino_t ino = 0;
  std::string name;  // empty for an existing file
  bool regular = false;
  bool operator==(const FileId& o) const { return dev == o.dev && ino == o.ino && name == o.name; }
};

std::optional<FileId> existing_id(const std::string& path) {
  struct stat st{};
  if (::stat(path.c_str(), &st) != 0 || S_ISDIR(st.st_mode)) return std::nullopt;
  return FileId{st.st_dev, st.st_ino, "", S_ISREG(st.st_mode)};
}

std::string parent_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

std::optional<FileId> output_id(const std::string& path) {
  if (auto id = existing_id(path)) return id;
  struct stat st{};
  if (::stat(parent_of(path).c_str(), &st) != 0) return std::nullopt;
  return FileId{st.st_dev, st.st_ino, fs::path(path).filename().string(), true};
}

bool is_link(const std::string& path) {
  struct stat st{};
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

// One file an output writes.
struct OutFile {
  std::string option;
  std::string path;
  std::optional<FileId> id;
  bool in_place = false;  // a device or FIFO (or a path under /dev, /proc): written through, never replaced
};

[[noreturn]] void refuse(const char* code, const std::string& message, const std::string& option, const std::string& path,
                         const std::string& other_option = "", const std::string& other_file = "") {
  throw InputError(code, message,
                   {.file = path, .option = option, .other_file = other_file, .other_option = other_option});
}

// The kind check of one output (what it is), its exists check apart (overwrite true).
void check_kind(const RunFile& out) {
  try {
    switch (out.kind) {
      case RunFile::Kind::file:
        check_output_path(out.path, true);
        break;
      case RunFile::Kind::figure:
        check_plot(out.path, true);
        break;
      case RunFile::Kind::report:
        check_report_dir(out.path, true);
        find_gnuplot();
        break;
    }
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    // check_plot names its option itself.
    const std::string message = what.rfind(out.option + " ", 0) == 0 ? what : out.option + " " + what;
    const char* code = dynamic_cast<const InputError*>(&e) ? static_cast<const InputError&>(e).code().c_str()
                                                            : errc::output_not_writable;
    refuse(code, message, out.option, out.path);
  }
}

}  // namespace

void check_run_files(const std::vector<RunFile>& inputs, const std::vector<RunFile>& outputs, bool overwrite) {
  std::vector<RunFile> given;
  for (const RunFile& o : outputs)
    if (!o.path.empty() && o.path != "-") given.push_back(o);

  // The files the outputs write.
  std::vector<OutFile> files;
  for (const RunFile& o : given) {
    std::vector<std::pair<std::string, std::string>> names;
    if (o.kind == RunFile::Kind::figure) {
      const FigureFiles ff = figure_files(o.path);
      names = {{o.option, ff.figure}, {o.option + " data", ff.data}, {o.option + " script", ff.script}};
    } else if (o.kind == RunFile::Kind::report) {
      names = {{o.option, (fs::path(o.path) / "report.html").string()}};
    } else {
      names = {{o.option, o.path}};
    }
    for (auto& [option, path] : names) {
      OutFile f{option, path, output_id(path), false};
      if (o.kind == RunFile::Kind::file) {
        try {
          f.in_place = check_output_path(path, true) == OutputKind::write_through;
        } catch (const std::invalid_argument&) {
        }
      }
      files.push_back(std::move(f));
    }
  }

  // 1. No output is one of the run's inputs (with or without overwrite), checked first: whatever
  //    else is wrong with such an output (a --plot at DATA.csv, a --report at a file), this is
  //    what the user needs to hear. A report directory that is an input file is refused too.
  for (const RunFile& o : given) {
    if (o.kind != RunFile::Kind::report) continue;
    const std::optional<FileId> dir = existing_id(o.path);
    for (const RunFile& in : inputs) {
      const std::optional<FileId> id = existing_id(in.path);
      if (!dir || !id || !(*id == *dir)) continue;
      refuse(errc::output_is_input,
             o.option + " " + o.path + " is the input " + in.path + " (" + in.option +
                 "): an output never replaces an input of its run, with or without --overwrite; write it to "
                 "another directory",
             o.option, o.path, in.option, in.path);
    }
  }
  for (const OutFile& f : files) {
    if (!f.id || (f.in_place && !f.id->regular)) continue;
    for (const RunFile& in : inputs) {
      const std::optional<FileId> id = existing_id(in.path);
      if (!id || !(*id == *f.id)) continue;
      refuse(errc::output_is_input,
             f.option + " " + f.path + " is the input " + in.path + " (" + in.option +
                 "): an output never replaces an input of its run, with or without --overwrite; write it to "
                 "another file",
             f.option, f.path, in.option, in.path);
    }
  }

  // 2. Each output can take an output at all (not a directory, its directory exists, ...).
  for (const RunFile& o : given) check_kind(o);

  // 3. No two outputs are one file (devices and FIFOs are written through: several may share one).
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!files[i].id || files[i].in_place) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (!files[j].id || files[j].in_place || !(*files[i].id == *files[j].id)) continue;
      refuse(errc::output_duplicate,
             files[i].option + " " + files[i].path + " is also the " + files[j].option +
                 " output; give each output its own file",
             files[i].option, files[i].path, files[j].option, files[j].path);
    }
  }

  // 4. What is there is replaced only with overwrite: a regular file, a symbolic link (also a
  //    dangling one), a report directory that is not empty.
  if (!overwrite) {
    for (const OutFile& f : files) {
      if (f.in_place) continue;
      std::error_code ec;
      if (is_link(f.path) && !fs::exists(f.path, ec))
        refuse(errc::output_exists,
               f.option + " " + f.path + " is a symbolic link to a missing file; pass --overwrite to replace the link",
               f.option, f.path);
      if (fs::exists(f.path, ec))
        refuse(errc::output_exists, f.option + " " + f.path + " exists; pass --overwrite to replace it", f.option, f.path);
    }
    for (const RunFile& o : given) {
      if (o.kind != RunFile::Kind::report) continue;
      try {
        check_report_dir(o.path, false);
      } catch (const std::invalid_argument& e) {
        refuse(errc::output_exists, o.option + " " + e.what(), o.option, o.path);
      }
    }
  }

  // 5. The directory that receives each new or replaced file is writable (found now, not after
  //    the computation).
  for (const OutFile& f : files) {
    if (f.in_place) continue;
    std::error_code ec;
    std::string target = f.path;
    if (is_link(f.path) && fs::exists(f.path, ec)) target = fs::canonical(f.path, ec).string();  // the link's file is replaced
    std::string dir = parent_of(target);
    // A new report directory is made in its parent.
    for (const RunFile& o : given)
      if (o.kind == RunFile::Kind::report && f.option == o.option && !fs::exists(o.path, ec)) dir = parent_of(o.path);
    if (::access(dir.c_str(), W_OK | X_OK) != 0) {
      const int err = errno;
      refuse(errc::output_not_writable,
             f.option + " " + f.path + ": directory " + dir + " is not writable (" + std::strerror(err) +
                 "); expected a directory where frictionlab can create files",
             f.option, f.path);
    }
  }
}

std::vector<RunFile> scenario_inputs(const std::string& scenario) {
  std::vector<std::string> named;
  try {
    ScenarioOptions options;
    options.files_read = &named;
    (void)load_scenario(scenario, options);
  } catch (const std::exception&) {
    // Reported by the command when it reads the scenario.
  }
  std::vector<RunFile> out;
  for (auto& f : named) out.push_back({"named by " + scenario, std::move(f), RunFile::Kind::file});
  return out;
}

namespace {

std::vector<std::pair<const CLI::Option*, RunFile::Kind>>& output_options() {
  static std::vector<std::pair<const CLI::Option*, RunFile::Kind>> options;
  return options;
}

const char* kind_name(RunFile::Kind k) {
  switch (k) {
    case RunFile::Kind::figure: return "figure";
    case RunFile::Kind::report: return "report";
    case RunFile::Kind::file: break;
  }
  return "file";
}

void list_commands(const CLI::App& app, const std::string& path, nlohmann::json& out) {
  const auto subs = app.get_subcommands([](const CLI::App*) { return true; });
  if (!subs.empty()) {
    for (const CLI::App* sub : subs) list_commands(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
    return;
  }
  nlohmann::json positionals = nlohmann::json::array(), options = nlohmann::json::array();
  for (const CLI::App* a = &app; a; a = a->get_parent()) {
    for (const CLI::Option* opt : a->get_options()) {
      if (opt->get_positional()) {
        if (a == &app) positionals.push_back(opt->get_name(true, false));
        continue;
      }
      if (opt->get_lnames().empty() && opt->get_snames().empty()) continue;
      nlohmann::json o = {{"name", opt->get_lnames().empty() ? "-" + opt->get_snames().front()
                                                              : "--" + opt->get_lnames().front()}};
      if (!opt->get_snames().empty()) o["short"] = "-" + opt->get_snames().front();
      if (const RunFile::Kind* k = output_kind(opt)) o["output"] = kind_name(*k);
      if (opt->get_type_size() == 0) o["flag"] = true;
      options.push_back(std::move(o));
    }
  }
  out.push_back({{"command", path}, {"positionals", positionals}, {"options", options}});
}

}  // namespace

CLI::Option* output_option(CLI::Option* opt, RunFile::Kind kind) {
  output_options().emplace_back(opt, kind);
  return opt;
}

const RunFile::Kind* output_kind(const CLI::Option* opt) {
  for (const auto& [o, k] : output_options())
    if (o == opt) return &k;
  return nullptr;
}

std::string commands_json(const CLI::App& app) {
  nlohmann::json commands = nlohmann::json::array();
  list_commands(app, "", commands);
  return json_text(nlohmann::json{{"schema", 1}, {"commands", commands}});
}

std::vector<RunFile> command_inputs(const CLI::App* cmd) {
  std::vector<RunFile> out;
  for (const CLI::App* app = cmd; app; app = app->get_parent()) {
    for (const CLI::Option* opt : app->get_options()) {
      if (output_kind(opt) || opt->count() == 0) continue;
      const std::string role = opt->get_positional() ? opt->get_name(true, false) : opt->get_name(false, true);
      for (const std::string& v : opt->results()) {
        if (v.empty() || v == "-") continue;
        std::error_code ec;
        const fs::file_status st = fs::status(v, ec);
        if (fs::is_regular_file(st)) {
          out.push_back({role, v, RunFile::Kind::file});
        }
      }
    }
  }
  return out;
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
  s << "model " << r.model << ", " << (r.axis == Axis::rotary ? "rotary" : "linear") << " axis, " << r.fit.samples
    << " samples\n";
  std::size_t w = 6;
  for (const auto& p : r.parameters) w = std::max(w, p.name.size());
  for (const auto& p : r.parameters) {
    s << "  " << std::left << std::setw(static_cast<int>(w)) << p.name << " = " << std::right << std::setw(12)
      << format_number(p.value, 6) << "  +- " << std::left << std::setw(10)
      << (std::isfinite(p.std) ? format_number(p.std, 3) : std::string("n/a")) << " " << p.unit
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
    for (const auto& [k, v] : group) {
      const std::string u = std::isnan(v) ? "" : diagnostic_unit(r, name, k);
      s << " " << k << " = " << (std::isnan(v) ? std::string("n/a") : format_number(v, 6)) << (u.empty() ? "" : " " + u);
    }
    s << "\n";
  }
  for (const auto& [name, word] : r.diagnostics.texts) s << name << ": " << word << "\n";
  for (const auto& w2 : r.diagnostics.warnings) s << "warning: " << w2 << "\n";
  return s.str();
}

int emit(const Result& result, const OutputOptions& o, const std::string& text_override,
         const std::vector<ReportFigure>* figures) {
  progress_stage("writing results");
  // Numbers or an error, never both: a figure or a word of the text that is not finite makes the
  // result an error before anything is written (finite_output.hpp).
  const std::string text = text_override.empty() ? result_text(result) : text_override;
  const Result r = finite_or_error(result, text);
  std::ostream& note = o.json == "-" ? std::cerr : std::cout;
  if (!r.ok()) {
    // The data gave no answer: one error line (naming the data file), then the JSON and the
    // report that say why. No figure.
    const bool named = r.data_file.empty() || r.message.find(r.data_file) != std::string::npos;
    print_error(named ? r.message : r.data_file + ": " + r.message);
    if (!o.report.empty()) write_report(r, {}, report_info(r, o), o.report, o.overwrite);
  } else {
    // Text goes to stderr when stdout carries the JSON.
    (o.json == "-" ? std::cerr : std::cout) << text;
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
