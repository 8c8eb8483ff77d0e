#pragma once
// The figures a user would draw first for each kind of result, built from the signals the
// library returns (Result::series, Trajectory columns, analysis results). Axis labels carry
// quantities and SI units.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/analysis/stick_slip.hpp"
#include "frictionlab/identify/result.hpp"
#include "report/figure.hpp"
#include "report/report.hpp"
#include "frictionlab/models/parameter.hpp"
#include "frictionlab/simulate/trajectory.hpp"

namespace frictionlab::cli {

/// The figures of a result, in order: the first ("fit") is what --plot draws and the report shows
/// first; the others follow in the report ("friction-map", "cross-test", ...). Each method
/// declares its figures and captions in its file under app/methods/ (methods/method.hpp); a
/// result of no registered method gets its measured and simulated signals, if it has any. Figures
/// without data are left out; empty when there is nothing to draw.
std::vector<ReportFigure> result_figures(const Result& r);

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
