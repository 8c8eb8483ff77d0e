#pragma once
// Figures drawn by gnuplot: a plain description of what to draw (panels stacked vertically, each
// with labelled axes and named series), written as a figure file plus, next to it, the data and
// the gnuplot script that drew it, so that a user can restyle the figure and run the script again.
//
// The project does not draw figures itself: gnuplot (Debian package gnuplot-nox, which has the
// svg, pngcairo and pdfcairo terminals) is a well-kept plotting program; frictionlab only writes
// its input.

#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// How a series is drawn.
enum class SeriesStyle {
  lines,      ///< a line through the points (signals over time, fitted curves)
  points,     ///< markers only (measured points, peaks)
  errorbars,  ///< markers with vertical error bars of +- y_error (measured means with their std)
  steps,      ///< a staircase (discrete states)
};

/// One named series of a panel. x, y (and y_error when given) have the same length.
struct FigureSeries {
  std::string name;              ///< legend entry; empty: no legend entry
  std::vector<double> x;         ///< in the unit of the panel's x axis
  std::vector<double> y;         ///< in the unit of the panel's y axis
  std::vector<double> y_error;   ///< +- error of each y (errorbars style), same unit as y
  SeriesStyle style = SeriesStyle::lines;
  /// Colour as "#rrggbb"; empty: the next colour of the figure's palette.
  std::string color;
  /// Marker size (points, errorbars) relative to gnuplot's default marker; 0: the style's default
  /// (0.7 for points, 0.8 for errorbars). Small for dense clouds of samples.
  double point_size = 0;
  /// Line width (lines, steps, error bars) in gnuplot's units; 0: the style's default (1.6 for
  /// lines and steps, 1.2 for error bars).
  double line_width = 0;
  /// Draw the line dashed (lines and steps styles): rings, bounds and references that frame the data.
  bool dashed = false;
};

/// One panel (a pair of axes). Labels carry the quantity and its unit, e.g. "time (s)".
struct FigurePanel {
  std::string title;    ///< optional, drawn above the panel
  std::string x_label;  ///< e.g. "velocity (rad/s)"
  std::string y_label;  ///< e.g. "friction torque (N m)"
  std::vector<FigureSeries> series;
  bool zero_line = false;  ///< draw the y = 0 line (signed quantities: velocity, force)
  bool zero_x_line = false;  ///< draw the x = 0 line (maps against a signed x, e.g. velocity)
  bool tight_x = false;    ///< x range exactly the data's (time axes); else rounded to tics
  bool equal_axes = false;  ///< one unit as long on x as on y (a path in the plane: a circle stays round)
  /// Where the legend goes, always outside the data and clear of the axis labels: "above" (between
  /// the panel's title and its axes, entries side by side; the default) or "outside right top"
  /// (beside the axes; for equal-axes panels whose width is fixed). Any other position, inside the
  /// axes ("top left", ...) or "below" (gnuplot draws it over the x label), is drawn as "above".
  std::string key = "above";
  bool log_x = false;  ///< logarithmic x axis (every x > 0; gnuplot `set logscale x`, decades as 10^n)
  bool log_y = false;  ///< logarithmic y axis (every y > 0)
};

/// A figure: a title and one or more panels stacked vertically (sharing nothing but the width).
struct Figure {
  std::string title;
  std::vector<FigurePanel> panels;
  int width = 1000;         ///< pixels (svg, png) or 1/100 inch (pdf)
  int panel_height = 360;   ///< pixels per panel
};

/// The file formats write_figure draws, chosen by the figure path's extension.
enum class FigureFormat { svg, png, pdf };

/// The format for a figure path by its extension (.svg, .png, .pdf; case-insensitive).
/// \throws std::invalid_argument "PATH: unsupported figure type '.EXT'; use .svg, .png or .pdf".
FigureFormat figure_format(const std::string& path);

/// The files write_figure writes for `path`: the figure, PATH.dat (the data, one gnuplot data
/// block per series, with a comment naming the panel, series and columns) and PATH.gp (the script).
struct FigureFiles {
  std::string figure;
  std::string data;
  std::string script;
};

/// The file names write_figure would write for `path`.
FigureFiles figure_files(const std::string& path);

/// Checks, before any work: the extension is supported, and unless `overwrite` none of the
/// figure, its data and its script exists (an edited script is never silently replaced).
/// \throws std::invalid_argument naming the path and what was expected.
void check_figure_path(const std::string& path, bool overwrite);

/// The gnuplot program to run: $FRICTIONLAB_GNUPLOT if set, else "gnuplot" looked up on PATH.
/// \throws std::runtime_error "gnuplot not found: install Debian package gnuplot-nox" when absent.
std::string find_gnuplot();

/// The gnuplot script for `figure` (as written to PATH.gp). It reads the data file and writes the
/// figure named by the gnuplot variables `datafile` and `outfile`, defaulting to the files' base
/// names so that `gnuplot FIG.svg.gp` run in the figure's directory redraws it.
std::string gnuplot_script(const Figure& figure, const std::string& path);

/// The data file text of `figure` (as written to PATH.dat): one block per series, blocks
/// separated by two blank lines (gnuplot `index`); columns x, y[, y_error]. Non-finite values
/// are written as NaN (gnuplot leaves a gap).
std::string gnuplot_data(const Figure& figure);

/// Draws `figure` to `path` (svg, png or pdf by extension) with gnuplot, writing PATH.dat and
/// PATH.gp next to it. Each file goes through a temporary and a rename, so a failure never leaves
/// a half-written figure.
/// \throws std::invalid_argument for an unsupported extension, an existing file without
///         `overwrite`, or a figure without panels or with series of unequal lengths;
///         std::runtime_error when gnuplot is missing ("gnuplot not found: install Debian package
///         gnuplot-nox") or fails (with its message), or a file cannot be written.
FigureFiles write_figure(const Figure& figure, const std::string& path, bool overwrite);

}  // namespace frictionlab
