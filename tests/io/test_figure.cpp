// Figures (gnuplot input, files next to the figure, atomic write) and HTML reports.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "report/figure.hpp"
#include "report/report.hpp"

namespace fs = std::filesystem;
using namespace frictionlab;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("frictionlab_test_figure_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool have_gnuplot() {
  try {
    find_gnuplot();
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

Figure sample_figure() {
  Figure f;
  f.title = "Friction map";
  FigurePanel p;
  p.x_label = "velocity (m/s)";
  p.y_label = "friction force (N)";
  p.series.push_back({"segments", {-1, 1, 2}, {-2, 2, 2.5}, {0.1, 0.1, 0.2}, SeriesStyle::errorbars, ""});
  p.series.push_back({"law", {-1, 1, 2}, {-2, 2, 2.5}, {}, SeriesStyle::lines, "#d55e00"});
  p.series.push_back({"empty", {}, {}, {}, SeriesStyle::points, ""});
  f.panels.push_back(p);
  FigurePanel q;
  q.x_label = "time (s)";
  q.y_label = "acceleration (m/s^2)";
  q.series.push_back({"it's quoted", {0, 1}, {0, std::nan("")}, {}, SeriesStyle::lines, ""});
  f.panels.push_back(q);
  return f;
}

Result sample_result() {
  Result r;
  r.method = "idim";
  r.model = "coulomb-viscous";
  r.data_file = "/data/run<1>.mat";
  r.data_sha256 = "abc123";
  r.parameters = {{"M", 95.10074896, 0.10997, "kg", ""}, {"Fc", 20.388, 0.1026, "N", ""}, {"sigma0", 1.234e5, 2.1e3, "N/m", ""}};
  r.fit.relative_error_percent = 4.137;
  r.fit.rmse = 2.213;
  r.fit.samples = 2480;
  r.diagnostics.condition_number = 26;
  r.diagnostics.numbers["dt"] = 0.01;
  r.diagnostics.groups["readoff"] = {{"Fs", 0.1}};
  for (int i = 0; i < 30; ++i) r.diagnostics.lists["points"].push_back({{"velocity", i * 1.0}, {"force", 2.0 * i}});
  r.diagnostics.warnings.push_back("Fc < 0 & <script>alert(1)</script>");
  return r;
}

}  // namespace

TEST(Figure, FormatByExtension) {
  EXPECT_EQ(figure_format("a/b.svg"), FigureFormat::svg);
  EXPECT_EQ(figure_format("B.PNG"), FigureFormat::png);
  EXPECT_EQ(figure_format("c.pdf"), FigureFormat::pdf);
  for (const char* bad : {"x.jpg", "x", "x.svgz", "x.eps"}) {
    try {
      figure_format(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("use .svg, .png or .pdf"), std::string::npos) << e.what();
    }
  }
}

TEST(Figure, FilesNextToTheFigure) {
  const FigureFiles f = figure_files("out/fit.svg");
  EXPECT_EQ(f.figure, "out/fit.svg");
  EXPECT_EQ(f.data, "out/fit.svg.dat");
  EXPECT_EQ(f.script, "out/fit.svg.gp");
}

TEST(Figure, CheckPathRefusesExistingFilesWithoutOverwrite) {
  const fs::path dir = scratch("check");
  const std::string fig = (dir / "f.svg").string();
  EXPECT_NO_THROW(check_figure_path(fig, false));
  std::ofstream(fig + ".gp") << "edited by the user";
  EXPECT_THROW(check_figure_path(fig, false), std::invalid_argument);  // an edited script is kept
  EXPECT_NO_THROW(check_figure_path(fig, true));
  EXPECT_THROW(check_figure_path((dir / "missing" / "f.svg").string(), true), std::invalid_argument);
  EXPECT_THROW(check_figure_path((dir / "f.gif").string(), true), std::invalid_argument);
  fs::remove_all(dir);
}

TEST(Figure, DataBlocksAndScript) {
  const Figure f = sample_figure();
  const std::string data = gnuplot_data(f);
  // Three drawable series: three blocks (the empty one is left out), NaN kept as a gap.
  EXPECT_NE(data.find("# index 0: panel 1, series 'segments'"), std::string::npos);
  EXPECT_NE(data.find("-1 -2 0.1"), std::string::npos);
  EXPECT_NE(data.find("# index 2: panel 2"), std::string::npos);
  EXPECT_EQ(data.find("# index 3"), std::string::npos);
  EXPECT_NE(data.find("1 NaN"), std::string::npos);

  const std::string gp = gnuplot_script(f, "dir/map.png");
  EXPECT_NE(gp.find("set terminal pngcairo"), std::string::npos);
  EXPECT_NE(gp.find("datafile = 'map.png.dat'"), std::string::npos);
  EXPECT_NE(gp.find("outfile = 'map.png'"), std::string::npos);
  EXPECT_NE(gp.find("set multiplot layout 2,1"), std::string::npos);
  EXPECT_NE(gp.find("set xlabel 'velocity (m/s)'"), std::string::npos);
  EXPECT_NE(gp.find("with yerrorbars"), std::string::npos);
  EXPECT_NE(gp.find("title 'it''s quoted'"), std::string::npos);  // gnuplot quoting
  EXPECT_NE(gnuplot_script(f, "m.svg").find("set terminal svg"), std::string::npos);
  EXPECT_NE(gnuplot_script(f, "m.pdf").find("set terminal pdfcairo"), std::string::npos);
}

TEST(Figure, MapStyleMarkerSizesLineWidthsAndZeroLines) {
  // A friction map: a dense cloud of small samples, binned means with visible error bars, a
  // heavy law curve, and both zero lines (velocity and force are signed).
  Figure f;
  FigurePanel p;
  p.x_label = "velocity (m/s)";
  p.y_label = "friction force (N)";
  p.zero_line = true;
  p.zero_x_line = true;
  FigureSeries cloud{"samples", {-1, 1}, {-2, 2}, {}, SeriesStyle::points, "#a8a8a8"};
  cloud.point_size = 0.25;
  FigureSeries bins{"bin mean +- std", {-1, 1}, {-2, 2}, {0.3, 0.3}, SeriesStyle::errorbars, ""};
  FigureSeries law{"law", {-1, std::nan(""), 1}, {-2, std::nan(""), 2}, {}, SeriesStyle::lines, ""};
  law.line_width = 2.2;
  p.series = {cloud, bins, law};
  f.panels.push_back(p);
  const std::string gp = gnuplot_script(f, "map.svg");
  EXPECT_NE(gp.find("with points pt 7 ps 0.25"), std::string::npos) << gp;
  EXPECT_NE(gp.find("with yerrorbars pt 7 ps 0.8 lw 1.2"), std::string::npos) << gp;  // the defaults
  EXPECT_NE(gp.find("with lines lw 2.2"), std::string::npos) << gp;
  EXPECT_NE(gp.find("\nset xzeroaxis"), std::string::npos);
  EXPECT_NE(gp.find("\nset yzeroaxis"), std::string::npos);
  // Without them: the defaults, and no vertical zero line carried over from an earlier panel.
  const std::string plain = gnuplot_script(sample_figure(), "m.svg");
  EXPECT_NE(plain.find("with lines lw 1.6"), std::string::npos);
  EXPECT_EQ(plain.find("\nset yzeroaxis"), std::string::npos);
  EXPECT_NE(plain.find("unset yzeroaxis"), std::string::npos);
}

TEST(Figure, LogAxesDashedLinesAndLegendOutside) {
  // A log-spaced axis is a true logarithmic axis (its ticks are values, not log10 values); a
  // dashed series is drawn dashed; a legend asked for inside the axes goes above them.
  Figure f;
  FigurePanel p;
  p.x_label = "V0 (m/s)";
  p.y_label = "c (N s/m)";
  p.log_x = true;
  p.key = "top left";
  FigureSeries ring{"ring", {0.01, 0.1}, {1, 2}, {}, SeriesStyle::lines, ""};
  ring.dashed = true;
  p.series = {ring};
  f.panels.push_back(p);
  FigurePanel q = p;
  q.log_x = false;
  q.log_y = true;
  q.key = "outside right top";
  q.series[0].dashed = false;
  f.panels.push_back(q);
  const std::string gp = gnuplot_script(f, "map.svg");
  const auto second = gp.find("# panel: c (N s/m)", gp.find("# panel: c (N s/m)") + 1);
  ASSERT_NE(second, std::string::npos) << gp;
  const std::string one = gp.substr(0, second), two = gp.substr(second);
  EXPECT_NE(one.find("set logscale x 10\n"), std::string::npos) << one;
  EXPECT_NE(one.find("unset logscale y\n"), std::string::npos) << one;
  EXPECT_NE(one.find("with lines lw 1.6 dt (8,6)"), std::string::npos) << one;
  EXPECT_NE(one.find("set key above "), std::string::npos) << one;
  EXPECT_EQ(one.find("top left"), std::string::npos) << one;
  EXPECT_NE(two.find("unset logscale x\n"), std::string::npos) << two;
  EXPECT_NE(two.find("set logscale y 10\n"), std::string::npos) << two;
  EXPECT_EQ(two.find("dt (8,6)"), std::string::npos) << two;
  EXPECT_NE(two.find("set key outside right top "), std::string::npos) << two;
  FigurePanel under = q;
  under.key = "below";  // gnuplot draws a key below over the x label: above instead
  Figure g;
  g.panels = {under};
  EXPECT_NE(gnuplot_script(g, "b.svg").find("set key above "), std::string::npos);
}

TEST(Figure, RefusesBadFigures) {
  Figure f;
  EXPECT_THROW(gnuplot_data(f), std::invalid_argument);  // no panels
  f.panels.push_back({});
  EXPECT_THROW(gnuplot_data(f), std::invalid_argument);  // no data
  f.panels[0].series.push_back({"a", {1, 2}, {1}, {}, SeriesStyle::lines, ""});
  EXPECT_THROW(gnuplot_data(f), std::invalid_argument);  // unequal lengths
}

TEST(Figure, WritesEachFormat) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const fs::path dir = scratch("write");
  const Figure f = sample_figure();
  const std::string svg = (dir / "f.svg").string(), png = (dir / "f.png").string(), pdf = (dir / "f.pdf").string();
  write_figure(f, svg, false);
  write_figure(f, png, false);
  write_figure(f, pdf, false);
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
  EXPECT_EQ(slurp(png).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(slurp(pdf).substr(0, 5), "%PDF-");
  EXPECT_FALSE(slurp(svg + ".dat").empty());
  EXPECT_FALSE(slurp(svg + ".gp").empty());
  EXPECT_THROW(write_figure(f, svg, false), std::invalid_argument);
  EXPECT_NO_THROW(write_figure(f, svg, true));
  for (const auto& e : fs::directory_iterator(dir))  // no temporaries left
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
  fs::remove_all(dir);
}

TEST(Figure, MissingGnuplotNamesThePackage) {
  const fs::path dir = scratch("nognuplot");
  ::setenv("FRICTIONLAB_GNUPLOT", (dir / "none").c_str(), 1);
  try {
    write_figure(sample_figure(), (dir / "f.svg").string(), false);
    ADD_FAILURE() << "no error without gnuplot";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("install Debian package gnuplot-nox"), std::string::npos) << e.what();
  }
  ::unsetenv("FRICTIONLAB_GNUPLOT");
  EXPECT_TRUE(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST(Report, HtmlHasTheTablesEscapedText) {
  ReportInfo info;
  info.title = "frictionlab identify idim";
  info.command_line = "frictionlab identify idim run.mat --gain 'a b'";
  info.options = {{"--cutoff", "100 (default)", "Hz"}};
  const std::string h = report_html(sample_result(), {{"Fit & residual", "<svg id=\"x\"></svg>"}}, info);
  EXPECT_NE(h.find("id=\"parameter-table\""), std::string::npos);
  EXPECT_NE(h.find(">95.10<"), std::string::npos);  // value to the std's precision
  EXPECT_NE(h.find(">0.11<"), std::string::npos);
  EXPECT_NE(h.find(">20.39<"), std::string::npos);
  EXPECT_NE(h.find("1.234e+05"), std::string::npos);  // large values in scientific notation
  EXPECT_NE(h.find("/data/run&lt;1&gt;.mat"), std::string::npos);
  EXPECT_NE(h.find("&lt;script&gt;"), std::string::npos);
  EXPECT_EQ(h.find("<script>"), std::string::npos);
  EXPECT_NE(h.find("Fit &amp; residual"), std::string::npos);
  EXPECT_NE(h.find("<svg id=\"x\">"), std::string::npos);
  EXPECT_NE(h.find("--cutoff"), std::string::npos);
  EXPECT_NE(h.find("<td>100 (default)</td><td>Hz</td>"), std::string::npos);  // the unit in a column of its own
  EXPECT_NE(h.find("points (30 records)"), std::string::npos);
  EXPECT_NE(h.find("5 more records"), std::string::npos);  // long lists are summarised
  EXPECT_NE(h.find("2.213 N"), std::string::npos);
}

TEST(Report, DirectoryRules) {
  const fs::path dir = scratch("reportdir");
  EXPECT_NO_THROW(check_report_dir((dir / "new").string(), false));
  EXPECT_NO_THROW(check_report_dir(dir.string(), false));  // empty
  std::ofstream(dir / "notes.txt") << "x";
  EXPECT_THROW(check_report_dir(dir.string(), false), std::invalid_argument);
  EXPECT_NO_THROW(check_report_dir(dir.string(), true));
  EXPECT_THROW(check_report_dir((dir / "notes.txt").string(), true), std::invalid_argument);
  EXPECT_THROW(check_report_dir((dir / "no" / "such").string(), false), std::invalid_argument);
  fs::remove_all(dir);
}

TEST(Report, WritesSelfContainedPage) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const fs::path dir = scratch("report");
  const std::string out = (dir / "rep").string();
  const std::string page = write_report(sample_result(), {{"fit", "The fit.", sample_figure()}}, {}, out, false);
  const std::string h = slurp(page);
  EXPECT_NE(h.find("<svg"), std::string::npos);
  EXPECT_EQ(h.find("<?xml"), std::string::npos);  // the prolog is dropped when inlined
  EXPECT_EQ(h.find("http://fonts"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "rep" / "fit.svg.gp"));
  EXPECT_THROW(write_report(sample_result(), {}, {}, out, false), std::invalid_argument);
  std::ofstream(dir / "rep" / "mine.txt") << "kept";
  EXPECT_NO_THROW(write_report(sample_result(), {}, {}, out, true));
  EXPECT_TRUE(fs::exists(dir / "rep" / "mine.txt"));
  EXPECT_THROW(write_report(sample_result(), {{"../x", "", sample_figure()}}, {}, (dir / "r2").string(), false),
               std::invalid_argument);
  fs::remove_all(dir);
}

TEST(Report, FiguresInOrderEachWithItsFilesAndCaption) {
  // identify's report: the fit, the friction map and the cross-test, in that order.
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot not installed (Debian package gnuplot-nox)";
  const fs::path dir = scratch("report3");
  const std::string out = (dir / "rep").string();
  Figure map = sample_figure();
  map.panels.resize(1);
  map.title = "Friction map";
  Figure cross = sample_figure();
  cross.title = "Cross-test";
  const std::string page = write_report(sample_result(),
                                        {{"fit", "The fit.", sample_figure()},
                                         {"friction-map", "Friction against velocity.", map},
                                         {"cross-test", "Measured and predicted force.", cross}},
                                        {}, out, false);
  const std::string h = slurp(page);
  for (const char* name : {"fit", "friction-map", "cross-test"})
    for (const char* ext : {".svg", ".svg.dat", ".svg.gp"})
      EXPECT_TRUE(fs::exists(dir / "rep" / (std::string(name) + ext))) << name << ext;
  const auto fit = h.find("The fit."), m = h.find("Friction against velocity."), c = h.find("Measured and predicted force.");
  ASSERT_NE(fit, std::string::npos);
  ASSERT_NE(m, std::string::npos);
  ASSERT_NE(c, std::string::npos);
  EXPECT_LT(fit, m);
  EXPECT_LT(m, c);
  EXPECT_NE(h.find("id=\"figure-3\""), std::string::npos);
  std::size_t svgs = 0;
  for (auto at = h.find("<svg"); at != std::string::npos; at = h.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 3u);
  fs::remove_all(dir);
}
