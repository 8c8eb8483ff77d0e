#pragma once
// A self-contained HTML report of an identification or validation: one report.html that opens
// in any browser without network access (styles inline, figures inline as SVG), with the data
// file and its hash, the method and its options, the parameter table with standard deviations
// and units, fit and validation figures, diagnostics, warnings and the figures. The figures'
// files (with their data and gnuplot scripts) sit next to it in the report directory.

#include <string>
#include <utility>
#include <vector>

#include "frictionlab/identify/result.hpp"
#include "report/figure.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// A figure of the report: drawn to DIR/NAME.svg (plus NAME.svg.dat and NAME.svg.gp).
struct ReportFigure {
  std::string name;     ///< file stem, e.g. "fit" (letters, digits, '-', '_')
  std::string caption;  ///< one sentence under the figure
  Figure figure;
};

/// A row of the report's Options table.
struct ReportOption {
  std::string name;   ///< "--kp", "--velocity", "DATA"
  std::string value;  ///< as given, or the default the run used with " (default)"
  std::string unit;   ///< of the value on the run's axis ("1/s", "rad/s" for a velocity column); "" when none
};

/// What the report says about how it was made.
struct ReportInfo {
  std::string title;         ///< e.g. "frictionlab identify idim"; empty: from the result's method
  std::string command_line;  ///< the command that produced the result, as typed
  /// The options that applied to the run and their values (given or default), in display order.
  std::vector<ReportOption> options;
  std::string version;       ///< tool version
};

/// Checks, before any work, that `dir` can take a report: it does not exist, is an empty
/// directory, or `overwrite` is set (then it must still be a directory, not a file).
/// \throws std::invalid_argument "DIR exists and is not empty; pass --overwrite to replace it".
void check_report_dir(const std::string& dir, bool overwrite);

/// The report page for `result`; `figures` are (caption, inline SVG text) pairs in order.
/// All text from the result and the info is HTML-escaped.
std::string report_html(const Result& result, const std::vector<std::pair<std::string, std::string>>& figures,
                        const ReportInfo& info);

/// Writes DIR/report.html and the figures (DIR/NAME.svg with .dat and .gp, drawn by gnuplot).
/// Everything is written into a temporary directory next to DIR that then takes DIR's place, so a
/// failure leaves DIR as it was. Returns the path of report.html.
/// \throws std::invalid_argument as check_report_dir, or for a bad figure name; std::runtime_error
///         when gnuplot is missing ("gnuplot not found: install Debian package gnuplot-nox") or
///         fails, or the directory cannot be written.
std::string write_report(const Result& result, const std::vector<ReportFigure>& figures, const ReportInfo& info,
                         const std::string& dir, bool overwrite);

}  // namespace frictionlab
