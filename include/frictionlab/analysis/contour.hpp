#pragma once
// The circular (ballbar) test of a two-axis machine: the radial error of the measured path
// against angle, the four quadrant glitches at the axis reversals, and the roundness.

#include <array>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Options of analyze_contour.
struct ContourOptions {
  /// Centre of the nominal circle (m). Default: from the reference (xr, yr) when given, else a
  /// least-squares circle fit of the measured path.
  std::optional<std::array<double, 2>> centre;
  /// Radius of the nominal circle (m, > 0). NaN: from the reference when given, else the fit.
  double radius = std::numeric_limits<double>::quiet_NaN();
  /// A glitch's angular extent is where its error exceeds this fraction of its peak (0 < f < 1).
  double extent_fraction = 0.5;

  /// \throws std::invalid_argument naming the field: a centre that is not finite, a radius that
  ///         is neither NaN nor a positive finite number of m, an extent fraction outside (0, 1).
  void validate() const;
};

/// One quadrant glitch: the radial error spike near an axis reversal.
struct QuadrantGlitch {
  double reversal_deg = 0;  ///< the reversal it belongs to: 0, 90, 180 or 270 deg
  /// Peak height (m): the radial error of largest magnitude within +-45 deg of the reversal, less
  /// the median radial error there (the local level of the trace); signed, outward positive.
  double peak_m = 0;
  double angle_deg = 0;   ///< angle of the peak, in [0, 360) deg
  /// Angular extent (deg): the span of the run of samples around the peak (in time order) whose
  /// error, less the local level, exceeds extent_fraction of the peak in magnitude and has its sign.
  double extent_deg = 0;
  double time = 0;  ///< time of the peak (s)
};

/// Result of analyze_contour. Per-sample vectors have the length of the input.
struct ContourResult {
  double centre_x = 0, centre_y = 0;  ///< centre of the nominal circle (m)
  double radius = 0;                  ///< nominal radius R (m)
  std::string centre_source;          ///< "given", "reference" or "fit": where centre and radius came from
  double turns = 0;                   ///< turns the measured path covers (unwrapped angle / 360 deg)
  std::vector<double> angle_deg;      ///< angle of each measured sample about the centre, [0, 360) deg
  std::vector<double> radial_error;   ///< r - R of each sample (m)
  /// Per-axis tracking error x - xr and y - yr of each sample (m); empty without a reference.
  std::vector<double> x_error, y_error;
  std::array<QuadrantGlitch, 4> glitches;  ///< at 0, 90, 180 and 270 deg, in that order
  double roundness_m = 0;                  ///< max - min radial error (m)
  double max_radial_error_m = 0;           ///< max |radial error| (m)
};

/// Analyses a circular test.
/// \param t  sample times (s), strictly increasing; x, y the measured path (m); all of one length n.
/// \param xr yr the reference path (m): both empty, or both of length n.
/// \throws std::invalid_argument when the lengths differ, n < 20, a value is not finite (naming
///         the signal and 1-based sample), t is not strictly increasing, the options are not valid
///         (ContourOptions::validate), the reference is not a circle (radial deviation above 0.1 % of its radius: use a given
///         centre and radius for another path), the path passes through the centre, or the
///         measured path covers less than one turn (not a closed contour).
ContourResult analyze_contour(std::span<const double> t, std::span<const double> x, std::span<const double> y,
                              std::span<const double> xr = {}, std::span<const double> yr = {},
                              const ContourOptions& options = {});

/// The largest |peak| of the four quadrant glitches (m).
double max_quadrant_glitch(const ContourResult& r);

/// The figures of a circular test as JSON text (one line; non-finite numbers are null):
/// {"centre_m": [x, y], "radius_m", "centre_from", "turns", "roundness_m", "max_radial_error_m",
///  "max_quadrant_glitch_m", "quadrant_glitch_m": [four peaks at 0, 90, 180, 270 deg],
///  "quadrant_glitches": [{"reversal_deg", "peak_m", "angle_deg", "extent_deg", "time"} x 4]}
/// (m, deg, s). The per-sample vectors are not written.
std::string contour_json(const ContourResult& r);

/// Least-squares circle through points (x_i, y_i) (algebraic fit: minimises the sum of
/// (x^2 + y^2 + D x + E y + F)^2): {centre x, centre y, radius} (m).
/// \throws std::invalid_argument with fewer than 3 points, lengths that differ, or collinear points.
std::array<double, 3> fit_circle(std::span<const double> x, std::span<const double> y);

}  // namespace frictionlab
