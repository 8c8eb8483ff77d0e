#include "batch_identify.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>
#include <thread>

#include "frictionlab/format.hpp"
#include "frictionlab/io/atomic_write.hpp"
#include "frictionlab/io/figure.hpp"
#include "output.hpp"

namespace frictionlab::cli {
namespace {

namespace fs = std::filesystem;

bool ends_with_json(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".json";
}

// A number as the shortest text that reads back to the same double; "" for NaN (CSV's "none").
std::string number_text(double v) {
  return std::isfinite(v) ? format_exact(v) : "";
}

std::string csv_cell(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// One row's cells by column name: numbers as json numbers (null when none), text as strings.
std::map<std::string, nlohmann::json> row_cells(const BatchRow& row, bool with_date) {
  std::map<std::string, nlohmann::json> c;
  const Result& r = row.result;
  c["index"] = row.job.index;
  c["file"] = row.job.file;
  if (with_date) c["date"] = row.date.iso;
  c["status"] = r.ok() ? "ok" : "error";
  c["message"] = r.message;
  c["method"] = r.method;
  c["model"] = r.model;
  c["axis"] = r.method.empty() && r.parameters.empty() ? "" : (r.axis == Axis::rotary ? "rotary" : "linear");
  for (const Parameter& p : r.parameters) {
    c[p.name] = json_number(p.value);
    c[p.name + "_std"] = json_number(p.std);
    c[p.name + "_unit"] = p.unit;
  }
  if (r.ok() || !r.parameters.empty()) {
    c["relative_error_percent"] = json_number(r.fit.relative_error_percent);
    c["rmse"] = json_number(r.fit.rmse);
    c["rmse_unit"] = r.fit.unit;
    c["samples"] = r.fit.samples;
  }
  c["sha256"] = r.data_sha256;
  return c;
}

std::string cell_text(const nlohmann::json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return csv_cell(v.get<std::string>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_unsigned()) return std::to_string(v.get<std::size_t>());
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  return number_text(v.get<double>());
}

std::string table_csv(const std::vector<std::string>& columns, const std::vector<std::map<std::string, nlohmann::json>>& rows) {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) out += ',';
    out += csv_cell(columns[i]);
  }
  out += '\n';
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out += ',';
      if (const auto it = row.find(columns[i]); it != row.end()) out += cell_text(it->second);
    }
    out += '\n';
  }
  return out;
}

std::string table_json(const std::string& kind, const std::vector<std::string>& columns,
                       const std::vector<std::map<std::string, nlohmann::json>>& rows) {
  nlohmann::ordered_json j;
  j["schema"] = 1;
  j["kind"] = kind;
  j["columns"] = columns;
  j["rows"] = nlohmann::ordered_json::array();
  for (const auto& row : rows) {
    nlohmann::ordered_json o;
    for (const auto& c : columns) {
      const auto it = row.find(c);
      o[c] = it == row.end() ? nlohmann::json(nullptr) : it->second;
    }
    j["rows"].push_back(o);
  }
  return j.dump(1) + "\n";
}

const std::vector<std::string> kDriftColumns = {"file", "date", "parameter", "value", "std", "unit",
                                                "change", "combined_std", "flagged"};

std::vector<std::map<std::string, nlohmann::json>> drift_cells(const std::vector<DriftRow>& rows) {
  std::vector<std::map<std::string, nlohmann::json>> out;
  for (const DriftRow& r : rows)
    out.push_back({{"file", r.sample.file},
                   {"date", r.sample.date.iso},
                   {"parameter", r.sample.parameter},
                   {"value", json_number(r.sample.value)},
                   {"std", json_number(r.sample.std)},
                   {"unit", r.sample.unit},
                   {"change", json_number(r.change)},
                   {"combined_std", json_number(r.combined_std)},
                   {"flagged", r.flagged}});
  return out;
}

// The drift figure: one panel per parameter, value +- std against days since the first log,
// flagged logs marked. Dates on the x axis as days keep the figure kit's numeric axes.
Figure drift_figure(const std::vector<DriftRow>& rows, double threshold) {
  Figure f;
  double t0 = INFINITY;
  for (const auto& r : rows) t0 = std::min(t0, r.sample.date.posix_seconds);
  std::string first;
  for (const auto& r : rows)
    if (r.sample.date.posix_seconds == t0) first = r.sample.date.iso;
  f.title = "Drift of the identified parameters over " + std::to_string(rows.size()) + " values";
  std::vector<std::string> names;
  for (const auto& r : rows)
    if (std::find(names.begin(), names.end(), r.sample.parameter) == names.end()) names.push_back(r.sample.parameter);
  for (const auto& name : names) {
    FigurePanel p;
    FigureSeries s, flagged;
    s.name = "value +- std";
    s.style = SeriesStyle::errorbars;
    flagged.name = "change > " + number_text(threshold) + " combined std";
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
    p.x_label = "days since " + first;
    p.y_label = name + (unit.empty() ? "" : " (" + unit + ")");
    p.key = "top left";
    p.series.push_back(s);
    if (!flagged.x.empty()) p.series.push_back(flagged);
    f.panels.push_back(p);
  }
  f.panel_height = 260;
  return f;
}

}  // namespace

void add_batch_options(CLI::App* cmd, BatchOptions& o) {
  const std::string g = "Batch (several files or a folder)";
  o.table_opt = cmd->add_option("--table", o.table,
                                "Write one row per file (index, file, status, message, parameters with std and unit, "
                                "fit figures): CSV, or JSON when FILE ends in .json; '-' for stdout (CSV). "
                                "Several files or a folder write the table to stdout without it. A file that fails is "
                                "its row's status and message; exit status 2 only when every file failed")
                    ->group(g);
  cmd->add_option("--jobs", o.jobs, "Files identified at once (threads)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str()
      ->group(g);
  cmd->add_option("--date-from", o.date_from,
                  "The log's date per row: 'name' (from the file name, e.g. axis3_2026-11-02.csv or "
                  "axis3_20261102T0815.mat) or 'column:NAME' (POSIX time in s in the first sample of column NAME, or "
                  "scalar NAME of a MAT file)")
      ->group(g);
  cmd->add_option("--drift", o.drift,
                  "With --date-from: write the drift table (each parameter by date, its change from the previous "
                  "log and whether it exceeds --drift-threshold combined std): CSV, or JSON by .json. With several "
                  "files, --plot FIG draws the drift figure (each parameter with its std against the date)")
      ->group(g);
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
  return data.size() != 1 || fs::is_directory(data.front(), ec) || !o.table.empty();
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

std::vector<std::string> batch_columns(const std::vector<BatchRow>& rows, bool with_date) {
  std::vector<std::string> c = {"index", "file"};
  if (with_date) c.push_back("date");
  for (const char* s : {"status", "message", "method", "model", "axis"}) c.push_back(s);
  for (const auto& row : rows)
    for (const Parameter& p : row.result.parameters)
      if (std::find(c.begin(), c.end(), p.name) == c.end())
        for (const std::string& s : {p.name, p.name + "_std", p.name + "_unit"}) c.push_back(s);
  for (const char* s : {"relative_error_percent", "rmse", "rmse_unit", "samples", "sha256"}) c.push_back(s);
  return c;
}

std::string batch_csv(const std::vector<BatchRow>& rows, bool with_date) {
  std::vector<std::map<std::string, nlohmann::json>> cells;
  for (const auto& r : rows) cells.push_back(row_cells(r, with_date));
  return table_csv(batch_columns(rows, with_date), cells);
}

std::string batch_json(const std::vector<BatchRow>& rows, bool with_date) {
  std::vector<std::map<std::string, nlohmann::json>> cells;
  for (const auto& r : rows) cells.push_back(row_cells(r, with_date));
  return table_json("identify", batch_columns(rows, with_date), cells);
}

std::vector<DriftRow> batch_drift(const std::vector<BatchRow>& rows, double threshold) {
  std::vector<DriftSample> samples;
  for (const auto& row : rows) {
    if (!row.result.ok()) continue;
    for (const Parameter& p : row.result.parameters)
      samples.push_back({row.job.file, row.date, p.name, p.value, p.std, p.unit});
  }
  return drift_table(samples, threshold);
}

std::string drift_csv(const std::vector<DriftRow>& rows) { return table_csv(kDriftColumns, drift_cells(rows)); }
std::string drift_json(const std::vector<DriftRow>& rows) { return table_json("drift", kDriftColumns, drift_cells(rows)); }

int run_identify_batch(const std::vector<std::string>& data, const BatchOptions& o, const std::string& json,
                       const std::string& report, const std::string& plot, bool overwrite,
                       const std::function<Result(const std::string& file)>& identify,
                       const std::function<double(const std::string&, const std::string&)>& date_of_column) {
  const std::vector<BatchJob> jobs = batch_jobs(data);  // first: a folder without data names itself
  if (!json.empty())
    throw std::invalid_argument("--json writes one file's result; with several files or a folder use --table OUT.json");
  if (!report.empty())
    throw std::invalid_argument("--report is for one file; with several files or a folder use --table");
  if (!o.date_from.empty() && o.date_from != "name" && !(o.date_from.rfind("column:", 0) == 0 && o.date_from.size() > 7))
    throw std::invalid_argument("--date-from '" + o.date_from + "': expected name or column:NAME");
  const bool dated = !o.date_from.empty();
  if (!dated && !o.drift.empty()) throw std::invalid_argument("--drift needs --date-from (the logs' dates)");
  if (!dated && !plot.empty())
    throw std::invalid_argument("--plot with several files draws the drift figure: it needs --date-from");
  if (o.table != "-" && !o.table.empty()) check_output_file(o.table, overwrite, "--table");
  if (!o.drift.empty()) check_output_file(o.drift, overwrite, "--drift");
  std::vector<std::pair<std::string, std::string>> outputs = {{"--table", o.table}, {"--drift", o.drift}};
  if (!plot.empty()) {
    check_plot(plot, overwrite);
    find_gnuplot();
    const FigureFiles ff = figure_files(plot);
    outputs.insert(outputs.end(), {{"--plot", ff.figure}, {"--plot data", ff.data}, {"--plot script", ff.script}});
  }
  outputs.erase(std::remove_if(outputs.begin(), outputs.end(), [](const auto& p) { return p.second.empty() || p.second == "-"; }),
                outputs.end());
  check_distinct_outputs(outputs);

  progress_start("frictionlab identify (" + std::to_string(jobs.size()) + " files)");
  std::vector<BatchRow> rows = run_batch(jobs, o.jobs, identify, o.date_from, date_of_column);
  std::size_t ok = 0;
  for (auto& r : rows) {
    ok += r.result.ok();
    if (r.result.method.empty()) r.result.method = o.method;
  }

  // Outputs: the drift table and figure first, the table last (the main output; a failure of
  // the others leaves none of them half-written, and no table that claims a finished run).
  std::vector<DriftRow> drift;
  if (dated && ok > 0) drift = batch_drift(rows, o.drift_threshold);
  if (!o.drift.empty())
    write_file_atomic(o.drift, ends_with_json(o.drift) ? drift_json(drift) : drift_csv(drift), {overwrite});
  if (!plot.empty() && !drift.empty()) {
    progress_stage("drawing " + plot);
    write_figure(drift_figure(drift, o.drift_threshold), plot, overwrite);
  }
  const std::string text = !o.table.empty() && o.table != "-" && ends_with_json(o.table) ? batch_json(rows, dated)
                                                                                          : batch_csv(rows, dated);
  if (o.table.empty() || o.table == "-") {
    progress_stop();
    std::cout << text << std::flush;
  } else {
    write_file_atomic(o.table, text, {overwrite});
  }
  progress_stop();
  if (ok == 0) {
    const std::string& first = rows.front().result.message;
    // Exit 2 with the one error line of every failed run; the table holds each file's reason.
    print_error("every file failed (" + std::to_string(rows.size()) + " files" +
                (o.table.empty() || o.table == "-" ? "" : "; table " + o.table) + "); the first: " +
                (first.find(rows.front().job.file) == std::string::npos ? rows.front().job.file + ": " + first : first));
    return 2;
  }
  std::cerr << "frictionlab identify: " << rows.size() << " files: " << ok << " ok, " << rows.size() - ok << " failed";
  if (!o.table.empty() && o.table != "-") std::cerr << "; table " << o.table;
  if (!o.drift.empty()) std::cerr << "; drift " << o.drift;
  if (!plot.empty() && !drift.empty()) std::cerr << "; figure " << plot;
  std::cerr << "\n";
  std::size_t flagged = 0;
  for (const auto& d : drift) flagged += d.flagged;
  if (dated) std::cerr << "drift: " << flagged << " flagged (a change beyond " << o.drift_threshold << " combined std)\n";
  for (const auto& r : rows) {
    if (r.result.ok()) continue;
    const std::string& m = r.result.message;
    std::cerr << "  failed: " << (m.find(r.job.file) == std::string::npos ? r.job.file + ": " + m : m) << "\n";
  }
  return 0;
}

}  // namespace frictionlab::cli
