#include "report/figure.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "frictionlab/format.hpp"

extern char** environ;

namespace frictionlab {
namespace {

namespace fs = std::filesystem;

// Okabe-Ito colours: distinguishable with the common colour-vision deficiencies.
constexpr const char* kPalette[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// A gnuplot single-quoted string: backslashes are literal, a quote is doubled.
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out + "'";
}

// Axis labels are drawn as enhanced text so that "m/s^2" shows a superscript; the other
// enhanced-text control characters are escaped.
std::string enhanced(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '_' || c == '@' || c == '&' || c == '{' || c == '}' || c == '~') out += '\\';
    out += c;
  }
  return gp_quote(out);
}

// A data file value: gnuplot's "NaN" for a gap, else 10 significant digits (a figure's precision).
std::string number(double x) { return std::isfinite(x) ? format_number(x, 10) : "NaN"; }

bool drawable(const FigureSeries& s) { return !s.x.empty(); }

void check_figure(const Figure& f) {
  if (f.panels.empty()) throw std::invalid_argument("figure '" + f.title + "': no panels to draw");
  bool any = false;
  for (const auto& p : f.panels)
    for (const auto& s : p.series) {
      if (s.x.size() != s.y.size())
        throw std::invalid_argument("figure '" + f.title + "', series '" + s.name + "': x has " +
                                    std::to_string(s.x.size()) + " values but y has " + std::to_string(s.y.size()));
      if (s.style == SeriesStyle::errorbars && s.y_error.size() != s.y.size())
        throw std::invalid_argument("figure '" + f.title + "', series '" + s.name + "': y_error has " +
                                    std::to_string(s.y_error.size()) + " values, expected " +
                                    std::to_string(s.y.size()));
      any = any || drawable(s);
    }
  if (!any) throw std::invalid_argument("figure '" + f.title + "': no data to draw");
}

// The legend's place in gnuplot words: outside the axes, never over data or labels (see
// FigurePanel::key). Inside positions and "below" (drawn over the x label: tests/figures) become
// "above".
std::string key_position(const std::string& key) {
  if (key.rfind("outside", 0) == 0) return key;
  return "above";
}

std::string terminal(FigureFormat format, const Figure& f) {
  const int rows = static_cast<int>(f.panels.size());
  const int height = f.panel_height * rows + (f.title.empty() ? 0 : 40);
  std::ostringstream t;
  switch (format) {
    // Fonts sized for a figure seen at its own width in a browser window or a report page.
    case FigureFormat::svg:
      t << "set terminal svg size " << f.width << "," << height << " dynamic enhanced font 'Sans,16' background '#ffffff'";
      break;
    case FigureFormat::png:
      t << "set terminal pngcairo size " << f.width << "," << height << " enhanced font 'Sans,13' background '#ffffff'";
      break;
    case FigureFormat::pdf:  // pdfcairo sizes are in inches; 100 px per inch keeps the proportions
      t << "set terminal pdfcairo size " << f.width / 100.0 << "in," << height / 100.0 << "in enhanced font 'Sans,11'";
      break;
  }
  return t.str();
}

// A unique temporary next to `path` (same file system, so the final rename is atomic).
std::string temporary(const std::string& path) {
  std::string tmpl = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0)
    throw std::runtime_error(path + ": cannot create a temporary file next to it (does the directory exist and is it "
                                    "writable?)");
  ::close(fd);
  return tmpl;
}

void write_text(const std::string& file, const std::string& text, const std::string& target) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error(target + ": write failed (disk full?)");
}

// Removes the temporaries unless released (after the renames).
struct Temporaries {
  std::vector<std::string> files;
  ~Temporaries() {
    for (const auto& f : files) std::remove(f.c_str());
  }
};

bool executable(const fs::path& p) { return ::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p); }

// Runs `argv` without a shell; returns its exit status and what it wrote to stdout and stderr.
int run(const std::vector<std::string>& argv, const std::string& log_file, std::string& output) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error(argv[0] + ": cannot start it (" + std::generic_category().message(rc) + ")");
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error(argv[0] + ": lost track of the process");
  std::ifstream in(log_file);
  output.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

FigureFormat figure_format(const std::string& path) {
  const std::string ext = lower(fs::path(path).extension().string());
  if (ext == ".svg") return FigureFormat::svg;
  if (ext == ".png") return FigureFormat::png;
  if (ext == ".pdf") return FigureFormat::pdf;
  throw std::invalid_argument(path + ": unsupported figure type '" + (ext.empty() ? std::string("(none)") : ext) +
                              "'; use .svg, .png or .pdf");
}

FigureFiles figure_files(const std::string& path) { return {path, path + ".dat", path + ".gp"}; }

void check_figure_path(const std::string& path, bool overwrite) {
  // The name goes into gnuplot's script (its comments, the output file): a control character (a
  // newline) would end a line of it, so gnuplot would fail or run what follows.
  for (const char c : path)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw std::invalid_argument("--plot: the file name holds a control character (" +
                                  std::string(c == '\n' ? "a newline" : c == '\t' ? "a tab" : "code " + std::to_string(static_cast<int>(c))) +
                                  "); expected a name gnuplot can be given");
  figure_format(path);
  const FigureFiles files = figure_files(path);
  const fs::path dir = fs::path(path).parent_path();
  if (!dir.empty() && !fs::is_directory(dir))
    throw std::invalid_argument(path + ": directory " + dir.string() + " does not exist");
  if (overwrite) return;
  for (const auto& f : {files.figure, files.data, files.script})
    if (fs::exists(f)) throw std::invalid_argument(f + " exists; pass --overwrite to replace it");
}

std::string find_gnuplot() {
  if (const char* env = std::getenv("FRICTIONLAB_GNUPLOT"); env && *env) {
    if (executable(env)) return env;
    throw std::runtime_error(std::string("gnuplot not found (FRICTIONLAB_GNUPLOT=") + env +
                             "): install Debian package gnuplot-nox");
  }
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');) {
    const fs::path p = fs::path(d.empty() ? "." : d) / "gnuplot";
    if (executable(p)) return p.string();
  }
  throw std::runtime_error("gnuplot not found: install Debian package gnuplot-nox");
}

std::string gnuplot_data(const Figure& figure) {
  check_figure(figure);
  std::ostringstream d;
  d << "# frictionlab figure data: " << figure.title << "\n"
    << "# One block per series (gnuplot 'index' 0, 1, ...), blocks separated by two blank lines.\n";
  int index = 0;
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const FigurePanel& panel = figure.panels[p];
    for (const auto& s : panel.series) {
      if (!drawable(s)) continue;
      if (index > 0) d << "\n\n";
      d << "# index " << index << ": panel " << p + 1 << ", series '" << s.name << "'\n# columns: " << panel.x_label
        << " | " << panel.y_label;
      if (s.style == SeriesStyle::errorbars) d << " | std of " << panel.y_label;
      d << "\n";
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        d << number(s.x[i]) << ' ' << number(s.y[i]);
        if (s.style == SeriesStyle::errorbars) d << ' ' << number(s.y_error[i]);
        d << '\n';
      }
      ++index;
    }
  }
  return d.str();
}

std::string gnuplot_script(const Figure& figure, const std::string& path) {
  check_figure(figure);
  const FigureFormat format = figure_format(path);
  const FigureFiles files = figure_files(path);
  const std::string name = fs::path(files.figure).filename().string();
  const std::string data = fs::path(files.data).filename().string();
  std::ostringstream g;
  g << "# frictionlab figure: " << figure.title << "\n"
    << "# Redraw it after restyling: cd to this directory and run  gnuplot " << name << ".gp\n"
    << "# (another format: gnuplot -e \"outfile='fig.png'\" and change the terminal line).\n"
    << "# The data is in " << data << ", one block per series (see the comments there).\n"
    << "if (!exists(\"datafile\")) datafile = " << gp_quote(data) << "\n"
    << "if (!exists(\"outfile\")) outfile = " << gp_quote(name) << "\n"
    << terminal(format, figure) << "\n"
    << "set output outfile\n"
    << "set encoding utf8\n"
    // No "set datafile missing 'NaN'": declared missing, a NaN would be skipped and the line
    // joined across it; left undeclared it breaks the line (a law's jump at v = 0, a gap).
    << "set border lw 1\n"
    << "set grid back lc rgb '#d0d0d0' lw 1 dt 1\n"
    << "set tics nomirror out\n"
    << "set border 3\n"
    << "set mxtics\nset mytics\n"
    << "set lmargin 12\nset rmargin 4\n";
  if (figure.panels.size() > 1 || !figure.title.empty()) {
    g << "set multiplot layout " << figure.panels.size() << ",1";
    if (!figure.title.empty()) g << " title " << gp_quote(figure.title) << " noenhanced font ',18'";
    g << "\n";
  }
  int index = 0, colour = 0;
  bool equal_before = false;  // the panel before set an aspect ratio: the next resets it
  for (const FigurePanel& panel : figure.panels) {
    g << "\n# panel: " << (panel.title.empty() ? panel.y_label : panel.title) << "\n";
    g << "set title " << gp_quote(panel.title) << " noenhanced\n"
      << "set xlabel " << enhanced(panel.x_label) << "\n"
      << "set ylabel " << enhanced(panel.y_label) << "\n"
      << "set key " << key_position(panel.key) << " box lc rgb '#a0a0a0' samplen 2 spacing 1.1 noenhanced\n"
      << "set autoscale\n"
      << (panel.log_x ? "set logscale x 10\n" : "unset logscale x\n")
      << (panel.log_y ? "set logscale y 10\n" : "unset logscale y\n")
      << (panel.tight_x ? "set autoscale xfix\nset offsets 0, 0, graph 0.05, graph 0.05\n"
                        : "set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05\n")
      << (panel.zero_line ? "set xzeroaxis lt -1 lw 1 lc rgb '#606060'\n" : "unset xzeroaxis\n")
      << (panel.zero_x_line ? "set yzeroaxis lt -1 lw 1 lc rgb '#606060'\n" : "unset yzeroaxis\n")
      << (panel.equal_axes ? "set size ratio -1\n" : equal_before ? "set size noratio\n" : "");
    equal_before = panel.equal_axes;
    std::vector<std::string> plots;
    for (const FigureSeries& s : panel.series) {
      if (!drawable(s)) continue;
      const std::string c = s.color.empty() ? kPalette[colour++ % std::size(kPalette)] : s.color;
      std::ostringstream p;
      p << (plots.empty() ? "datafile" : "''") << " index " << index++;
      const auto size = [&](double fallback) { return number(s.point_size > 0 ? s.point_size : fallback); };
      const auto width = [&](double fallback) { return number(s.line_width > 0 ? s.line_width : fallback); };
      const std::string dash = s.dashed ? " dt (8,6)" : "";
      switch (s.style) {
        case SeriesStyle::lines: p << " using 1:2 with lines lw " << width(1.6) << dash; break;
        case SeriesStyle::steps: p << " using 1:2 with steps lw " << width(1.6) << dash; break;
        case SeriesStyle::points: p << " using 1:2 with points pt 7 ps " << size(0.7); break;
        case SeriesStyle::errorbars:
          p << " using 1:2:3 with yerrorbars pt 7 ps " << size(0.8) << " lw " << width(1.2);
          break;
      }
      p << " lc rgb " << gp_quote(c) << " title " << (s.name.empty() ? std::string("''") : gp_quote(s.name));
      plots.push_back(p.str());
    }
    if (plots.empty()) {  // a panel whose series are all empty still gets its axes
      g << "set label 1 'no data' at graph 0.5, graph 0.5 center\nset xrange [0:1]\nset yrange [0:1]\n"
        << "plot NaN notitle\nunset label 1\n";
      continue;
    }
    g << "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i) g << (i ? ", \\\n     " : "") << plots[i];
    g << "\n";
  }
  if (figure.panels.size() > 1 || !figure.title.empty()) g << "unset multiplot\n";
  g << "set output\n";
  return g.str();
}

FigureFiles write_figure(const Figure& figure, const std::string& path, bool overwrite) {
  check_figure_path(path, overwrite);
  const std::string script = gnuplot_script(figure, path);
  const std::string data = gnuplot_data(figure);
  const std::string gnuplot = find_gnuplot();
  const FigureFiles files = figure_files(path);

  Temporaries tmp;
  const std::string tmp_data = temporary(files.data);
  tmp.files.push_back(tmp_data);
  const std::string tmp_script = temporary(files.script);
  tmp.files.push_back(tmp_script);
  const std::string tmp_figure = temporary(files.figure);
  tmp.files.push_back(tmp_figure);
  const std::string tmp_log = temporary(files.figure + ".log");
  tmp.files.push_back(tmp_log);
  write_text(tmp_data, data, files.data);
  write_text(tmp_script, script, files.script);

  std::string output;
  const int status = run({gnuplot, "-e", "datafile=" + gp_quote(tmp_data) + "; outfile=" + gp_quote(tmp_figure), tmp_script},
                         tmp_log, output);
  std::error_code ec;
  if (status != 0 || fs::file_size(tmp_figure, ec) == 0) {
    while (!output.empty() && std::isspace(static_cast<unsigned char>(output.back()))) output.pop_back();
    throw std::runtime_error(path + ": gnuplot failed (exit " + std::to_string(status) + ")" +
                             (output.empty() ? std::string() : ": " + output));
  }
  // Usual permissions for the results (mkstemp made them 0600; umask applies).
  const mode_t mask = ::umask(0);
  ::umask(mask);
  for (const auto& f : {tmp_data, tmp_script, tmp_figure}) ::chmod(f.c_str(), 0666 & ~mask);
  if (!overwrite)  // the files may have appeared while gnuplot ran
    for (const auto& f : {files.figure, files.data, files.script})
      if (fs::exists(f)) throw std::invalid_argument(f + " exists; pass --overwrite to replace it");
  const std::pair<std::string, std::string> moves[] = {
      {tmp_data, files.data}, {tmp_script, files.script}, {tmp_figure, files.figure}};
  for (const auto& [from, to] : moves)
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw std::runtime_error(to + ": cannot rename the temporary file into place");
  tmp.files = {tmp_log};
  return files;
}

}  // namespace frictionlab
