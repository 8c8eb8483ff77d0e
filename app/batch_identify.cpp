#include "batch_identify.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>

#include "frictionlab/io/json_text.hpp"
#include "frictionlab/format.hpp"
#include "finite_output.hpp"
#include "io/atomic_write.hpp"
#include "report/figure.hpp"
#include "io/sha256.hpp"
#include "fleet/shard.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

namespace fs = std::filesystem;

bool ends_with_json(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".json";
}

Cell integer_cell(std::size_t n) { return static_cast<std::int64_t>(n); }

// The fixed columns before the parameters and after them.
std::vector<std::string> head_columns(bool with_date) {
  std::vector<std::string> c = {"index", "file"};
  if (with_date) c.push_back("date");
  for (const char* s : {"status", "message", "method", "model", "axis"}) c.push_back(s);
  return c;
}
const std::vector<std::string> kTailColumns = {"relative_error_percent", "rmse", "rmse_unit", "samples", "sha256"};

// A table as a whole run's Part (command "identify") whose JSON is {"schema": 1, "kind": KIND,
// "columns": [...], "rows": [{...}]} (python frictionlab.batch.Table's form).
Part table_part(const std::string& kind, RowTable table) {
  Part p;
  p.command = "identify";
  p.envelope = json_text(nlohmann::ordered_json{{"schema", 1},
                                                {"kind", kind},
                                                {"columns", nlohmann::ordered_json::array()},
                                                {"rows", nlohmann::ordered_json::array()}});
  p.rows_at = "/rows";
  p.columns_at = "/columns";
  p.total = table.rows.size();
  p.table = std::move(table);
  return p;
}

// The table's text for FILE: JSON for .json, else CSV (also for '-' and no file).
std::string table_text(const Part& p, const std::string& file) {
  return !file.empty() && file != "-" && ends_with_json(file) ? table_json(p) : table_csv(p.table);
}

const std::vector<std::string> kDriftColumns = {"file", "date", "parameter", "value", "std", "unit",
                                                "change", "combined_std", "flagged"};

Part drift_part(const std::vector<DriftRow>& rows) {
  RowTable t;
  t.columns = kDriftColumns;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const DriftRow& r = rows[i];
    t.index.push_back(i);
    t.rows.push_back({r.sample.file, r.sample.date.iso, r.sample.parameter, r.sample.value, r.sample.std, r.sample.unit,
                      r.change, r.combined_std, r.flagged});
  }
  return table_part("drift", std::move(t));
}

// What decides the rows besides the files: the subcommand's options given on the command line
// (name and values, in CLI11's order), without the output and batch options (where the rows go,
// threads, the shard, the drift) and DATA.
nlohmann::ordered_json row_options(const CLI::App* cmd, const std::string& batch_group) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  if (!cmd) return out;
  for (const CLI::Option* opt : cmd->get_options()) {
    if (opt == cmd->get_help_ptr() || !opt->nonpositional() || opt->count() == 0) continue;
    if (opt->get_group() == "Output" || opt->get_group() == batch_group) continue;
    out.push_back({opt->get_name(), opt->results()});
  }
  return out;
}

const std::string kBatchGroup = "Batch (several files or a folder)";

// The drift figure: one panel per parameter, value +- std against days since the first log,
// flagged logs marked. Dates on the x axis as days keep the figure kit's numeric axes.
Figure drift_figure(const std::vector<DriftRow>& rows, double threshold) {
  Figure f;
  double t0 = INFINITY;
  for (const auto& r : rows) t0 = std::min(t0, r.sample.date.posix_seconds);
  std::string first;
  for (const auto& r : rows)
    if (r.sample.date.posix_seconds == t0) first = r.sample.date.iso;
  std::set<std::string> logs;  // rows are per parameter and log: the count is of distinct logs
  for (const auto& r : rows) logs.insert(r.sample.file);
  f.title = "Drift of the identified parameters over " + std::to_string(logs.size()) + " logs";
  std::vector<std::string> names;
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), r.sample.parameter) == names.end()) names.push_back(r.sample.parameter);
  for (const auto& name : names) {
    FigurePanel p;
    FigureSeries s, flagged;
    s.name = "value +- std";
    s.style = SeriesStyle::errorbars;
    flagged.name = "change > " + format_exact(threshold) + " combined std";
    flagged.style = SeriesStyle::points;
    flagged.color = "#d55e00";
    flagged.point_size = 1.8;
    std::string unit;
    for (const auto& r : rows) {
      if (r.sample.parameter != name) continue;
      const double day = (r.sample.date.posix_seconds - t0) / 86400.0;
      s.x.push_back(day);
      s.y.push_back(r.sample.value);
      s.y_error.push_back(std::isfinite(r.sample.std) ? r.sample.std : 0.0);
      if (r.flagged) {
        flagged.x.push_back(day);
        flagged.y.push_back(r.sample.value);
      }
      unit = r.sample.unit;
    }
    p.x_label = "time since " + first + " (days)";
    p.y_label = name + (unit.empty() ? "" : " (" + unit + ")");
    p.series.push_back(s);
    if (!flagged.x.empty()) p.series.push_back(flagged);
    f.panels.push_back(p);
  }
  f.panel_height = 260;
  return f;
}

}  // namespace

void add_batch_options(CLI::App* cmd, BatchOptions& o) {
  const std::string& g = kBatchGroup;
  o.command = cmd;
  o.table_opt = cmd->add_option("--table", o.table,
                                "Write one row per file (index, file, status, message, parameters with std and unit, "
                                "fit figures): CSV, or JSON when FILE ends in .json; '-' for stdout (CSV). "
                                "Several files or a folder write the table to stdout without it. A file that fails is "
                                "its row's status and message; exit status 2 only when every file failed. With "
                                "--shard: the part file, PART.json")
                    ->group(g);
  output_option(o.table_opt);
  cmd->add_option("--jobs", o.jobs, "Files identified at once (threads)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str()
      ->group(g);
  cmd->add_option("--shard", o.shard,
                  "Identify only shard K of N of the files (file i, from 0 in the expanded DATA list, with "
                  "i % N == K - 1) and write a part file to --table PART.json; `frictionlab merge PART... -o "
                  "OUT.csv|OUT.json` joins the parts into the table the unsharded run writes. Give every shard the "
                  "same DATA and options; --drift and --plot are refused (they need every file: give them to "
                  "`frictionlab merge`, which writes the same drift table and figure)")
      ->check(shard_text_check())
      ->group(g);
  cmd->add_option("--date-from", o.date_from,
                  "The log's date per row: 'name' (from the file name, e.g. axis3_2026-11-02.csv or "
                  "axis3_20261102T0815.mat) or 'column:NAME' (POSIX time in s in the first sample of column NAME, or "
                  "scalar NAME of a MAT file)")
      ->group(g);
  output_option(cmd->add_option("--drift", o.drift,
                  "With --date-from: write the drift table (each parameter by date, its change from the previous "
                  "log and whether it exceeds --drift-threshold combined std): CSV, or JSON by .json. With several "
                  "files, --plot FIG draws the drift figure (each parameter with its std against the date)")
      ->group(g));
  cmd->add_option("--drift-threshold", o.drift_threshold,
                  "Flag a change larger than this many combined std (1: about 32 % of pairs flag from noise "
                  "alone; 2 or 3 for a fleet)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str()
      ->group(g);
}

std::vector<BatchJob> batch_jobs(const std::vector<std::string>& data) {
  if (data.empty()) throw std::invalid_argument("DATA: no data file given");
  std::vector<BatchJob> jobs;
  for (const auto& d : data) {
    std::error_code ec;
    if (fs::is_directory(d, ec)) {
      std::vector<std::string> found;
      for (const auto& e : fs::directory_iterator(d, ec)) {
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        if ((ext == ".csv" || ext == ".mat") && e.is_regular_file(ec)) found.push_back(e.path().string());
      }
      if (ec) throw std::invalid_argument(d + ": cannot read the folder: " + ec.message());
      if (found.empty()) throw std::invalid_argument(d + ": folder has no .csv or .mat file");
      std::sort(found.begin(), found.end());
      for (auto& f : found) jobs.push_back({jobs.size(), std::move(f)});
    } else {
      jobs.push_back({jobs.size(), d});
    }
  }
  return jobs;
}

bool is_batch(const std::vector<std::string>& data, const BatchOptions& o) {
  std::error_code ec;
  // --drift too: a drift table is a batch's output (of one log, one row), never ignored.
  return data.size() != 1 || fs::is_directory(data.front(), ec) || !o.table.empty() || !o.shard.empty() ||
         !o.drift.empty();
}

std::vector<BatchRow> run_batch(const std::vector<BatchJob>& jobs, int threads,
                                const std::function<Result(const std::string& file)>& identify,
                                const std::string& date_from,
                                const std::function<double(const std::string&, const std::string&)>& date_of_column) {
  std::vector<BatchRow> rows(jobs.size());
  std::atomic<std::size_t> next{0}, finished{0};
  const auto one = [&](const BatchJob& job, BatchRow& row) {
    row.job = job;
    try {
      if (date_from == "name") {
        const auto d = log_date_from_name(job.file);
        if (!d)
          throw std::invalid_argument(job.file + ": no date in the file's name; expected e.g. name_2026-11-02.csv "
                                      "(YYYY-MM-DD, YYYYMMDD, optionally with a time)");
        row.date = *d;
      } else if (date_from.rfind("column:", 0) == 0) {
        row.date = log_date_from_posix(date_of_column(job.file, date_from.substr(7)));
      }
      row.result = identify(job.file);
    } catch (const std::exception& e) {
      row.result = Result{};
      row.result.status = ResultStatus::error;
      row.result.message = e.what();
      row.result.data_file = job.file;
    }
    if (row.result.data_file.empty()) row.result.data_file = job.file;
    const std::size_t k = ++finished;
    progress_stage("file " + std::to_string(k) + " of " + std::to_string(jobs.size()));
  };
  const auto worker = [&] {
    for (std::size_t i; (i = next++) < jobs.size();) one(jobs[i], rows[i]);
  };
  // Files are handed out one at a time from a shared counter, so uneven files balance out; each
  // row is written by one thread only. (simulate/batch.hpp does the same for scenarios; its
  // pool is tied to simulate().)
  const std::size_t n = std::min<std::size_t>(std::max(threads, 1), jobs.size());
  std::vector<std::jthread> pool;
  for (std::size_t t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  pool.clear();  // joins
  return rows;
}

RowTable batch_table(const std::vector<BatchRow>& rows, bool with_date) {
  RowTable t;
  t.columns = head_columns(with_date);
  t.grown = GrownColumns{t.columns.size(), t.columns.size(), {}};
  t.columns.insert(t.columns.end(), kTailColumns.begin(), kTailColumns.end());
  const double none = std::nan("");
  for (const BatchRow& row : rows) {
    const Result& r = row.result;
    t.index.push_back(row.job.index);
    std::vector<Cell> head = {integer_cell(row.job.index), row.job.file};
    if (with_date) head.emplace_back(row.date.iso);
    const std::string axis = r.method.empty() && r.parameters.empty() ? "" : (r.axis == Axis::rotary ? "rotary" : "linear");
    for (const std::string& s : {std::string(r.ok() ? "ok" : "error"), r.message, r.method, r.model, axis})
      head.emplace_back(s);
    t.rows.emplace_back(t.columns.size(), Cell{none});
    std::copy(head.begin(), head.end(), t.rows.back().begin());
    for (const Parameter& p : r.parameters) {
      // Each grow_column may insert a column (NaN in the rows before): look the row up afterwards.
      const std::size_t v = grow_column(t, p.name, row.job.index);
      const std::size_t sd = grow_column(t, p.name + "_std", row.job.index);
      const std::size_t u = grow_column(t, p.name + "_unit", row.job.index);
      auto& cells = t.rows.back();
      cells[v] = p.value;
      cells[sd] = p.std;
      cells[u] = p.unit;
    }
    auto tail = t.rows.back().end() - static_cast<std::ptrdiff_t>(kTailColumns.size());
    if (r.ok() || !r.parameters.empty()) {
      tail[0] = r.fit.relative_error_percent;
      tail[1] = r.fit.rmse;
      tail[2] = r.fit.unit;
      tail[3] = integer_cell(r.fit.samples);
    }
    tail[4] = r.data_sha256;
  }
  return t;
}

std::string batch_key(const std::vector<BatchJob>& jobs, const BatchOptions& o) {
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const BatchJob& j : jobs) {
    std::error_code ec;
    const auto size = fs::file_size(j.file, ec);
    files.push_back({j.file, ec ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(size)});
  }
  const nlohmann::ordered_json id = {{"command", "identify"},
                                     {"method", o.method},
                                     {"options", row_options(o.command, kBatchGroup)},
                                     {"date_from", o.date_from},
                                     {"files", files}};
  return sha256_hex(json_text(id));
}

std::vector<DriftRow> table_drift(const RowTable& table, double threshold) {
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(table.columns.begin(), table.columns.end(), name) - table.columns.begin());
  };
  const std::size_t c_date = col("date"), c_file = col("file"), c_status = col("status");
  if (c_date == table.columns.size())
    throw std::invalid_argument("the rows carry no dates (identify ran without --date-from): a batch's drift table "
                                "and figure compare the logs by date, so these rows have no figure and no drift");
  // The parameters: grown columns P followed by P_std and P_unit (batch_table).
  std::vector<std::size_t> params;
  const GrownColumns g = table.grown.value_or(GrownColumns{});
  for (std::size_t c = g.begin; c + 2 < g.end; ++c)
    if (table.columns[c + 1] == table.columns[c] + "_std" && table.columns[c + 2] == table.columns[c] + "_unit")
      params.push_back(c);
  const auto text = [](const Cell& c) { return std::holds_alternative<std::string>(c) ? std::get<std::string>(c) : ""; };
  const auto number = [](const Cell& c) { return std::holds_alternative<double>(c) ? std::get<double>(c) : std::nan(""); };
  std::vector<DriftSample> samples;
  for (const auto& row : table.rows) {
    if (text(row[c_status]) != "ok") continue;
    const std::string file = text(row[c_file]), iso = text(row[c_date]);
    // The table's ISO date (to the second), read back by the file-name parser ("HH-MM-SS" is
    // one of its time forms).
    std::string name = iso;
    std::replace(name.begin(), name.end(), ':', '-');
    const std::optional<LogDate> date = log_date_from_name(name);
    if (!date) throw std::invalid_argument(file + ": date '" + iso + "': expected YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS");
    for (std::size_t c : params) {
      const double value = number(row[c]);
      if (std::isnan(value)) continue;  // a parameter this row does not have
      samples.push_back({file, *date, table.columns[c], value, number(row[c + 1]), text(row[c + 2])});
    }
  }
  return drift_table(samples, threshold);
}

void write_drift(const std::vector<DriftRow>& drift, const std::string& drift_file, const std::string& plot,
                 double threshold, bool overwrite) {
  if (!drift_file.empty()) write_file_atomic(drift_file, table_text(drift_part(drift), drift_file), {overwrite});
  if (!plot.empty() && !drift.empty()) {
    progress_stage("drawing " + plot);
    write_figure(drift_figure(drift, threshold), plot, overwrite);
  }
}

int run_identify_batch(const std::vector<std::string>& data, const BatchOptions& o, const std::string& json,
                       const std::string& report, const std::string& plot, bool overwrite,
                       const std::function<Result(const std::string& file)>& identify,
                       const std::function<double(const std::string&, const std::string&)>& date_of_column,
                       const std::vector<RunFile>& inputs) {
  const std::vector<BatchJob> all = batch_jobs(data);  // first: a folder without data names itself
  // The one rule for outputs, before the batch's own usage checks: an output at one of its logs
  // is named as that, whichever option it is.
  std::vector<RunFile> run_inputs = inputs;
  for (const BatchJob& job : all) run_inputs.push_back({"DATA", job.file, RunFile::Kind::file});
  check_run_files(run_inputs,
                  {{"--table", o.table, RunFile::Kind::file},
                   {"--drift", o.drift, RunFile::Kind::file},
                   {"--plot", plot, RunFile::Kind::figure},
                   {"--json", json, RunFile::Kind::file},
                   {"--report", report, RunFile::Kind::report}},
                  overwrite);
  if (!json.empty())
    throw std::invalid_argument("--json writes one file's result; with several files or a folder use --table OUT.json");
  if (!report.empty())
    throw std::invalid_argument("--report is for one file; with several files or a folder use --table");
  if (!o.date_from.empty() && o.date_from != "name" && !(o.date_from.rfind("column:", 0) == 0 && o.date_from.size() > 7))
    throw std::invalid_argument("--date-from '" + o.date_from + "': expected name or column:NAME");
  const bool sharded = !o.shard.empty();
  const ShardSpec shard = sharded ? parse_shard(o.shard) : ShardSpec{};
  if (sharded) {
    if (o.table.empty() || o.table == "-" || !ends_with_json(o.table))
      throw std::invalid_argument("--shard " + o.shard + " writes a part file: give --table PART.json (then "
                                  "frictionlab merge PART... -o OUT.csv|OUT.json)");
    if (!o.drift.empty() || !plot.empty())
      throw std::invalid_argument(std::string(o.drift.empty() ? "--plot" : "--drift") + " with --shard " + o.shard +
                                  ": the drift compares consecutive logs, so it needs every file's row; merge the "
                                  "parts with --drift and --plot (frictionlab merge PART... -o OUT --drift FILE --plot "
                                  "FIG)");
  }
  const bool dated = !o.date_from.empty();
  if (!dated && !o.drift.empty()) throw std::invalid_argument("--drift needs --date-from (the logs' dates)");
  if (!dated && !plot.empty())
    throw std::invalid_argument("--plot with several files draws the drift figure: it needs --date-from");

  std::vector<BatchJob> jobs;
  for (std::size_t i : shard_jobs(all.size(), shard)) jobs.push_back(all[i]);
  const std::string what = sharded ? "shard " + shard.text() + ": " + std::to_string(jobs.size()) + " of " +
                                         std::to_string(all.size()) + " files"
                                   : std::to_string(jobs.size()) + " files";
  progress_start("frictionlab identify (" + what + ")");
  std::vector<BatchRow> rows = run_batch(jobs, o.jobs, identify, o.date_from, date_of_column);
  std::size_t ok = 0;
  for (auto& r : rows) {
    // Numbers or an error, never both (finite_output.hpp): a file whose figures are not finite is
    // an error row, not an ok row with empty cells.
    r.result = finite_or_error(std::move(r.result), "");
    ok += r.result.ok();
    if (r.result.method.empty()) r.result.method = o.method;
  }

  // Outputs: the drift table and figure first, the table last (the main output; a failure of
  // the others leaves none of them half-written, and no table that claims a finished run).
  Part part = table_part("identify", batch_table(rows, dated));
  std::vector<DriftRow> drift;
  if (dated && ok > 0) drift = table_drift(part.table, o.drift_threshold);
  write_drift(drift, o.drift, plot, o.drift_threshold, overwrite);
  if (sharded) {
    part.key = batch_key(all, o);
    part.shard = shard;
    part.total = all.size();
    write_file_atomic(o.table, part_to_json(part), {overwrite});
  } else if (o.table.empty() || o.table == "-") {
    progress_stop();
    std::cout << table_text(part, o.table) << std::flush;
  } else {
    write_file_atomic(o.table, table_text(part, o.table), {overwrite});
  }
  progress_stop();
  const std::string written = o.table.empty() || o.table == "-" ? "" : (sharded ? "; part " : "; table ") + o.table;
  if (ok == 0 && !rows.empty()) {
    const std::string& first = rows.front().result.message;
    // Exit 2 with the one error line of every failed run; the table holds each file's reason.
    print_error("every file failed (" + what + written + "); the first: " +
                (first.find(rows.front().job.file) == std::string::npos ? rows.front().job.file + ": " + first : first));
    return 2;
  }
  std::cerr << "frictionlab identify: " << what << ": " << ok << " ok, " << rows.size() - ok << " failed" << written;
  if (!o.drift.empty()) std::cerr << "; drift " << o.drift;
  if (!plot.empty() && !drift.empty()) std::cerr << "; figure " << plot;
  std::cerr << "\n";
  if (sharded) std::cerr << "join the parts: frictionlab merge PART... -o OUT.csv|OUT.json\n";
  std::size_t flagged = 0;
  for (const auto& d : drift) flagged += d.flagged;
  if (dated && !sharded)
    std::cerr << "drift: " << flagged << " flagged (a change beyond " << o.drift_threshold << " combined std)\n";
  for (const auto& r : rows) {
    if (r.result.ok()) continue;
    const std::string& m = r.result.message;
    std::cerr << "  failed: " << (m.find(r.job.file) == std::string::npos ? r.job.file + ": " + m : m) << "\n";
  }
  return 0;
}

}  // namespace frictionlab::cli
