#include "report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "frictionlab/format.hpp"
#include "frictionlab/identify/diagnostic_units.hpp"
#include "frictionlab/identify/method.hpp"
#include "io/atomic_write.hpp"

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

std::string esc(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

// A number in a table cell: format_number, "n/a" for NaN (a figure not computed).
std::string general(double x, int digits = 6) { return std::isnan(x) ? "n/a" : format_number(x, digits); }

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S UTC", &tm);
  return buf;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the figure back");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// gnuplot's SVG as an inline element: the XML prolog and doctype are dropped.
std::string inline_svg(const std::string& svg) {
  const auto start = svg.find("<svg");
  if (start == std::string::npos) throw std::runtime_error("figure is not SVG");
  return svg.substr(start);
}

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", "Liberation Sans", Arial, sans-serif; color: #1a1a1a; max-width: 1060px;
       margin: 1.5em auto; padding: 0 1em; line-height: 1.45; }
h1 { font-size: 1.6em; margin-bottom: 0.1em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; padding-bottom: 0.15em; margin-top: 1.6em; }
h3 { font-size: 1.05em; margin-bottom: 0.3em; }
.sub { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 0.4em 0 0.8em 0; }
th, td { border: 1px solid #d0d0d0; padding: 0.25em 0.7em; text-align: left; vertical-align: top; }
th { background: #f1f3f5; }
td.num { text-align: right; font-variant-numeric: tabular-nums; font-family: "DejaVu Sans Mono", monospace; }
code, .mono { font-family: "DejaVu Sans Mono", monospace; font-size: 0.92em; word-break: break-all; }
.status-ok { color: #1b7a2f; font-weight: bold; }
.status-error { color: #b00020; font-weight: bold; }
.warnings li { color: #8a4b00; }
.error { background: #fdecea; border: 1px solid #f5c2c0; padding: 0.6em 1em; }
figure { margin: 1em 0 1.6em 0; }
figure svg, figure img { max-width: 100%; height: auto; border: 1px solid #e0e0e0; }
figcaption { color: #444; font-size: 0.95em; margin-top: 0.3em; }
.note { color: #555; font-size: 0.9em; }
)";

void table_head(std::ostringstream& h, std::initializer_list<const char*> cols) {
  h << "<table><thead><tr>";
  for (const char* c : cols) h << "<th>" << c << "</th>";
  h << "</tr></thead><tbody>\n";
}

// A validation's further figures (ValidationFigures::json_sections), one table each: an object of
// objects (validate's "contour": measured, simulated, difference, ...) as rows of the inner keys
// whose values are numbers or lists of numbers, one column per outer key.
void validation_sections_html(std::ostringstream& h, const ValidationFigures& v) {
  for (const auto& [key, text] : v.json_sections) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (!j.is_object()) continue;
    std::vector<std::string> columns, rows;
    for (const auto& [outer, inner] : j.items()) {
      if (!inner.is_object()) continue;
      columns.push_back(outer);
      for (const auto& [name, value] : inner.items()) {
        const bool numbers = value.is_number() || (value.is_array() && !value.empty() && value.front().is_number());
        if (numbers && std::find(rows.begin(), rows.end(), name) == rows.end()) rows.push_back(name);
      }
    }
    if (columns.empty() || rows.empty()) continue;
    h << "<h3>" << esc(key) << "</h3>\n<table><thead><tr><th>figure</th>";
    for (const auto& c : columns) h << "<th>" << esc(c) << "</th>";
    h << "</tr></thead><tbody>\n";
    for (const auto& row : rows) {
      h << "<tr><td>" << esc(row) << "</td>";
      for (const auto& c : columns) {
        const nlohmann::json& x = j[c].contains(row) ? j[c][row] : nlohmann::json();
        std::string cell;
        if (x.is_number()) cell = general(x.get<double>(), 4);
        if (x.is_array())
          for (const auto& e : x) cell += (cell.empty() ? "" : ", ") + (e.is_number() ? general(e.get<double>(), 4) : std::string("n/a"));
        h << "<td class=\"num\">" << cell << "</td>";
      }
      h << "</tr>\n";
    }
    h << "</tbody></table>\n";
  }
}

void diagnostics_html(std::ostringstream& h, const Result& r) {
  const Diagnostics& d = r.diagnostics;
  h << "<h2 id=\"diagnostics\">Diagnostics</h2>\n";
  const bool any = std::isfinite(d.condition_number) || !d.numbers.empty() || !d.groups.empty() || !d.lists.empty() ||
                   !d.texts.empty();
  if (!any) {
    h << "<p class=\"note\">No diagnostics.</p>\n";
    return;
  }
  if (std::isfinite(d.condition_number) || !d.numbers.empty() || !d.texts.empty()) {
    table_head(h, {"figure", "value"});
    for (const auto& [k, v] : d.texts) h << "<tr><td>" << esc(k) << "</td><td>" << esc(v) << "</td></tr>\n";
    if (std::isfinite(d.condition_number))
      h << "<tr><td>condition number</td><td class=\"num\">" << general(d.condition_number, 4) << "</td></tr>\n";
    for (const auto& [k, v] : d.numbers)
      h << "<tr><td>" << esc(k) << "</td><td class=\"num\">" << general(v) << "</td></tr>\n";
    h << "</tbody></table>\n";
  }
  for (const auto& [name, group] : d.groups) {
    h << "<h3>" << esc(name) << "</h3>\n";
    table_head(h, {"name", "value", "unit"});  // the figures' units (identify/diagnostic_units.hpp)
    for (const auto& [k, v] : group)
      h << "<tr><td>" << esc(k) << "</td><td class=\"num\">" << general(v) << "</td><td>"
        << esc(diagnostic_unit(r, name, k)) << "</td></tr>\n";
    h << "</tbody></table>\n";
  }
  // Lists can be long (one record per segment or cycle): the first rows are shown, the count said.
  constexpr std::size_t kRows = 25;
  for (const auto& [name, records] : d.lists) {
    h << "<h3>" << esc(name) << " (" << records.size() << (records.size() == 1 ? " record" : " records") << ")</h3>\n";
    if (records.empty()) continue;
    std::vector<std::string> cols;
    std::set<std::string> seen;
    for (const auto& rec : records)
      for (const auto& [k, v] : rec)
        if (seen.insert(k).second) cols.push_back(k);
    h << "<table><thead><tr><th>#</th>";
    for (const auto& c : cols) h << "<th>" << esc(c) << "</th>";
    h << "</tr></thead><tbody>\n";
    for (std::size_t i = 0; i < std::min(records.size(), kRows); ++i) {
      h << "<tr><td class=\"num\">" << i + 1 << "</td>";
      for (const auto& c : cols) {
        const auto it = records[i].find(c);
        h << "<td class=\"num\">" << (it == records[i].end() ? "" : general(it->second)) << "</td>";
      }
      h << "</tr>\n";
    }
    h << "</tbody></table>\n";
    if (records.size() > kRows)
      h << "<p class=\"note\">" << records.size() - kRows << " more records are in the JSON result.</p>\n";
  }
}

bool valid_name(const std::string& n) {
  if (n.empty()) return false;
  return std::all_of(n.begin(), n.end(), [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '_'; });
}

}  // namespace

void check_report_dir(const std::string& dir, bool overwrite) {
  if (dir.empty()) throw std::invalid_argument("--report: expected a directory name");
  std::error_code ec;
  const fs::path p(dir);
  if (!fs::exists(p, ec)) {
    const fs::path parent = p.parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
      throw std::invalid_argument(dir + ": parent directory " + parent.string() + " does not exist");
    return;
  }
  if (!fs::is_directory(p, ec)) throw std::invalid_argument(dir + " exists and is not a directory (--report)");
  if (overwrite) return;
  if (!fs::is_empty(p, ec)) throw std::invalid_argument(dir + " exists and is not empty; pass --overwrite to replace it");
}

std::string report_html(const Result& r, const std::vector<std::pair<std::string, std::string>>& figures,
                        const ReportInfo& info) {
  const std::string title = info.title.empty() ? "frictionlab " + r.method : info.title;
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>" << esc(title) << (r.data_file.empty() ? "" : ": " + esc(fs::path(r.data_file).filename().string()))
    << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  h << "<h1>" << esc(title) << "</h1>\n<p class=\"sub\">Report written " << now_utc() << " by frictionlab "
    << esc(info.version) << ". Status: "
    << (r.ok() ? "<span class=\"status-ok\" id=\"status\">ok</span>" : "<span class=\"status-error\" id=\"status\">error</span>")
    << "</p>\n";
  if (!r.ok()) h << "<p class=\"error\" id=\"message\">" << esc(r.message) << "</p>\n";

  // Data and method.
  h << "<h2 id=\"data\">Data and method</h2>\n<table><tbody>\n";
  h << "<tr><th>data file</th><td><code>" << esc(r.data_file) << "</code></td></tr>\n"
    << "<tr><th>SHA-256</th><td><code>" << esc(r.data_sha256) << "</code></td></tr>\n";
  if (r.validation)
    h << "<tr><th>validation file</th><td><code>" << esc(r.validation->file) << "</code></td></tr>\n"
      << "<tr><th>its SHA-256</th><td><code>" << esc(r.validation->sha256) << "</code></td></tr>\n";
  std::string summary;  // the library's line on the method, when it is one of the library's
  for (const auto& m : identification_methods())
    if (m.name == r.method) summary = m.summary;
  h << "<tr><th>method</th><td>" << esc(r.method) << (summary.empty() ? "" : ": " + esc(summary)) << "</td></tr>\n"
    << "<tr><th>model</th><td>" << esc(r.model) << "</td></tr>\n";
  if (!info.command_line.empty())
    h << "<tr><th>command</th><td><code>" << esc(info.command_line) << "</code></td></tr>\n";
  h << "</tbody></table>\n";
  // Parameters.
  h << "<h2 id=\"parameters\">Parameters</h2>\n";
  if (r.parameters.empty()) {
    h << "<p class=\"note\">No parameters.</p>\n";
  } else {
    h << "<table id=\"parameter-table\"><thead><tr><th>parameter</th><th>value</th><th>&plusmn; std</th><th>unit</th>"
      << "<th>relative std</th></tr></thead><tbody>\n";
    for (const auto& p : r.parameters) {
      const auto [v, s] = format_with_std(p.value, p.std);
      const double rel = std::abs(p.value) > 0 ? 100.0 * p.std / std::abs(p.value) : NAN;
      h << "<tr><td><b>" << esc(p.name) << "</b></td><td class=\"num\" title=\"" << general(p.value, 17) << "\">" << v
        << "</td><td class=\"num\">" << (p.flag.empty() ? s : "n/a (" + esc(p.flag) + ")") << "</td><td>" << esc(p.unit) << "</td><td class=\"num\">"
        << (std::isfinite(rel) ? general(rel, 2) + " %" : "n/a") << "</td></tr>\n";
    }
    h << "</tbody></table>\n";
  }

  // Fit and validation figures.
  // The fitted signal and its unit come with the result (set by its method).
  const auto [fit_signal, fit_unit] = fit_signal_and_unit(r);
  const std::string rmse_unit = fit_unit.empty() ? "" : " " + fit_unit;
  h << "<h2 id=\"fit\">Fit</h2>\n";
  table_head(h, {"data", "relative error", "rmse", "samples"});
  h << "<tr><td>identification: <code>" << esc(fs::path(r.data_file).filename().string()) << "</code></td><td class=\"num\">"
    << general(r.fit.relative_error_percent, 4) << " %</td><td class=\"num\">" << general(r.fit.rmse, 4) << rmse_unit
    << "</td><td class=\"num\">" << r.fit.samples << "</td></tr>\n";
  if (r.validation)
    h << "<tr><td>cross-test: <code>" << esc(fs::path(r.validation->file).filename().string())
      << "</code></td><td class=\"num\">" << general(r.validation->relative_error_percent, 4)
      << " %</td><td class=\"num\">" << general(r.validation->rmse, 4) << rmse_unit << "</td><td class=\"num\">"
      << r.validation->samples << "</td></tr>\n";
  h << "</tbody></table>\n<p class=\"note\">Relative error = 100 &middot; ||y &minus; &#375;|| / ||y||; rmse in the "
       "unit of the fitted signal"
    << (fit_signal.empty() ? "" : " (" + esc(fit_signal) + ")") << ".</p>\n";
  if (r.validation && !r.validation->signal_errors_percent.empty()) {
    // validate: each simulated signal against the measured one.
    h << "<h2 id=\"validation\">Validation</h2>\n";
    table_head(h, {"signal", "relative error"});
    for (const auto& [name, e] : r.validation->signal_errors_percent)
      h << "<tr><td>" << esc(name) << "</td><td class=\"num\">" << general(e, 4) << " %</td></tr>\n";
    h << "</tbody></table>\n";
    validation_sections_html(h, *r.validation);
  }

  // Warnings.
  h << "<h2 id=\"warnings\">Warnings</h2>\n";
  if (r.diagnostics.warnings.empty()) {
    h << "<p class=\"note\">None.</p>\n";
  } else {
    h << "<ul class=\"warnings\">\n";
    for (const auto& w : r.diagnostics.warnings) h << "<li>" << esc(w) << "</li>\n";
    h << "</ul>\n";
  }

  // Figures.
  h << "<h2 id=\"figures\">Figures</h2>\n";
  if (figures.empty()) h << "<p class=\"note\">No figures.</p>\n";
  for (std::size_t i = 0; i < figures.size(); ++i)
    h << "<figure id=\"figure-" << i + 1 << "\">\n"
      << figures[i].second << "\n<figcaption>Figure " << i + 1 << ". " << esc(figures[i].first)
      << "</figcaption>\n</figure>\n";
  if (!figures.empty())
    h << "<p class=\"note\">Each figure's data (<code>NAME.svg.dat</code>) and gnuplot script (<code>NAME.svg.gp</code>) "
         "are next to this page: edit the script and run <code>gnuplot NAME.svg.gp</code> in this directory to "
         "restyle it.</p>\n";

  if (!info.options.empty()) {
    h << "<h2 id=\"options\">Options</h2>\n";
    table_head(h, {"option", "value", "unit"});
    for (const ReportOption& o : info.options)
      h << "<tr><td><code>" << esc(o.name) << "</code></td><td>" << esc(o.value) << "</td><td>" << esc(o.unit)
        << "</td></tr>\n";
    h << "</tbody></table>\n";
  }

  diagnostics_html(h, r);
  h << "</body>\n</html>\n";
  return h.str();
}

std::string write_report(const Result& result, const std::vector<ReportFigure>& figures, const ReportInfo& info,
                         const std::string& dir, bool overwrite) {
  check_report_dir(dir, overwrite);
  for (const auto& f : figures)
    if (!valid_name(f.name) || f.name == "report")
      throw std::invalid_argument("report figure name '" + f.name + "': expected letters, digits, '-' or '_'");
  if (!figures.empty()) find_gnuplot();  // fail before anything is written

  std::error_code ec;
  const bool fresh = !fs::exists(dir, ec);
  // A new directory is built under a temporary name and renamed into place at the end; an
  // existing one (empty, or --overwrite) gets each file replaced atomically, and nothing else in
  // it is touched.
  std::string work = dir;
  if (fresh) {
    std::string tmpl = (fs::path(dir).lexically_normal().string());
    while (tmpl.size() > 1 && tmpl.back() == '/') tmpl.pop_back();
    tmpl += ".tmp-XXXXXX";
    if (!::mkdtemp(tmpl.data()))
      throw std::runtime_error(dir + ": cannot create a temporary directory next to it (is the parent writable?)");
    work = tmpl;
    const mode_t mask = ::umask(0);  // mkdtemp makes it 0700; give it the usual permissions
    ::umask(mask);
    ::chmod(work.c_str(), 0777 & ~mask);
  }
  try {
    std::vector<std::pair<std::string, std::string>> inlined;
    for (const auto& f : figures) {
      const std::string path = (fs::path(work) / (f.name + ".svg")).string();
      write_figure(f.figure, path, true);
      // The caption names the file, whose data and script sit next to it.
      inlined.emplace_back(f.caption + (f.caption.empty() ? "" : " ") + "(" + f.name + ".svg)",
                           inline_svg(read_file(path)));
    }
    AtomicWriteOptions w;
    w.overwrite = true;
    write_file_atomic((fs::path(work) / "report.html").string(), report_html(result, inlined, info), w);
    if (fresh) {
      if (std::rename(work.c_str(), dir.c_str()) != 0)
        throw std::runtime_error(dir + ": cannot rename the temporary directory into place (did it appear meanwhile?)");
    }
  } catch (...) {
    if (fresh) fs::remove_all(work, ec);
    throw;
  }
  return (fs::path(dir) / "report.html").string();
}

}  // namespace frictionlab
