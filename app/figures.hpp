#pragma once
// The figure a user would draw first for each kind of result, built from the signals the
// library returns (Result::series, Trajectory columns, analysis results). Axis labels carry
// quantities and SI units.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "frictionlab/identify/result.hpp"
#include "frictionlab/io/figure.hpp"
#include "frictionlab/io/report.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/simulate/trajectory.hpp"

namespace frictionlab::cli {

/// The axis a result is on, read off its parameter units (N m, rad: rotary; else linear).
Axis result_axis(const Result& r);

/// The figure of a result by its method: idim (measured and reconstructed force, residual),
/// sweep (friction map: segment means with std error bars and the fitted law), breakaway
/// (applied force and velocity over time, breakaway marked), decay (position, turning points
/// and the fitted envelope), validate (measured and simulated position, velocity, force),
/// lugre (measured and simulated position, force). Empty when the result has no signals for it.
std::optional<Figure> result_figure(const Result& r);

/// The friction-velocity map of a result: idim (each fitted sample's force less the inertia and
/// offset terms, their means and stds in velocity bins, the identified law), sweep (its fit
/// figure), breakaway (applied force against velocity, Fs at rest with its std, the static law),
/// lugre (the identified law's steady state). Empty for other methods or without the signals.
std::optional<Figure> friction_map_figure(const Result& r);

/// The report's figures after the fit figure: "friction-map" (friction_map_figure, except for
/// sweep, whose fit figure is its map) and, when the result carries a cross-test's signals
/// (identify idim --validate), "cross-test" (measured and predicted force on the second record,
/// and their difference). Empty when the result is not ok.
std::vector<ReportFigure> report_extra_figures(const Result& r);

/// A simulation's time series: position, velocity, friction and applied force (and motor
/// current when there is one). `title` names the scenario.
Figure trajectory_figure(const Trajectory& tr, Axis axis, const std::string& title);

/// Free-oscillation decay: the signal with its turning points and fitted envelope, and the half
/// swing amplitudes with the three fitted envelope models.
Figure envelope_figure(std::span<const double> t, std::span<const double> x, const EnvelopeResult& r,
                       const std::string& title);

/// Stick-slip: velocity with the stuck band, and (when given) the friction force with breakaway
/// and re-stick levels marked.
Figure stick_slip_figure(std::span<const double> t, std::span<const double> v, std::span<const double> force,
                         const StickSlipResult& r, const std::string& title);

}  // namespace frictionlab::cli
