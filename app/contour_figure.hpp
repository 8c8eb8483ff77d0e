#pragma once
// The circular test's figure (analyze contour): the polar error plot an engineer reads a ballbar
// test from, the radial error against angle, and the per-axis tracking error over time.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/analysis/contour.hpp"
#include "frictionlab/identify/result.hpp"
#include "report/figure.hpp"
#include "report/report.hpp"
#include "frictionlab/simulate/trajectory.hpp"

namespace frictionlab::cli {

/// The magnification of the polar plot: the radial error drawn `factor` times its size about the
/// nominal circle, and a round error `ring_m` (m) drawn as the dashed rings at +-ring_m.
struct PolarScale {
  double factor = 1;
  double ring_m = 0;
};

/// A 1-2-5 magnification that draws the largest |radial error| `max_error_m` at about a quarter
/// of the radius `radius_m` (m), and a round ring near half that error. factor >= 1.
PolarScale polar_scale(double radius_m, double max_error_m);

/// Panels, in order: the polar plot (nominal circle, measured path with its radial error
/// magnified, rings at +-ring, the scale stated in the panel's title; mm about the centre, equal
/// axes), the radial error against angle (um), and with a reference x - xr and y - yr against time
/// `t` (s, um). `t` has the length of r's per-sample vectors. `title` names the data file.
Figure contour_figure(std::span<const double> t, const ContourResult& r, const std::string& title);

/// validate on a two-axis table: the figures of the report, in order. "contour": with both
/// contours, the measured and the simulated radial error in one polar plot at one magnification,
/// and against angle; without (the reference is not a circle) the measured and simulated paths
/// and the reference in the plane (mm). "axes": per axis, the tracking error (position less the
/// simulated reference, um), velocity and (when measured) drive force, measured and simulated
/// over time. "measured-contour" and "simulated-contour": contour_figure of each (with both).
/// `r` is validate_axes's result (its series), `title` names the data file.
std::vector<ReportFigure> xy_validation_figures(const Result& r, const std::optional<ContourResult>& measured,
                                                const std::optional<ContourResult>& simulated, const std::string& title);

/// simulate --plot on a two-axis table (contacts "x" and "y"): when the reference runs a circle
/// of at least one turn, contour_figure of the run; else the path and its reference in the plane
/// (mm, equal axes) and the per-axis error over time. nullopt for other plants.
std::optional<Figure> xy_figure(const Trajectory& tr, const std::string& title);

}  // namespace frictionlab::cli
