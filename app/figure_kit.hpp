#pragma once
// The pieces every method's figures are built from (app/methods/*.cpp, app/figures.cpp): axis
// labels with units, series and panels in the project's style, a result's signals by name, a
// law's curve, friction binned by velocity, and measured-against-simulated panels.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "frictionlab/analysis/envelope.hpp"
#include "frictionlab/identify/result.hpp"
#include "report/figure.hpp"
#include "frictionlab/models/parameter.hpp"

namespace frictionlab::cli {

/// "QUANTITY (UNIT)", e.g. label("velocity", Quantity::velocity, Axis::rotary) = "velocity (rad/s)".
std::string label(std::string_view quantity, Quantity q, Axis axis);
/// "torque" on a rotary axis, else "force".
std::string force_name(Axis axis);
/// The result's signal `name` (Result::series), or nullptr when absent or empty.
const std::vector<double>* find(const Result& r, const std::string& name);
/// A series of the shorter length of x and y.
FigureSeries series(std::string name, std::vector<double> x, std::vector<double> y,
                    SeriesStyle style = SeriesStyle::lines, std::string color = {});
/// A panel over time (s), tight on x, with a zero line unless told otherwise.
FigurePanel time_panel(std::string y_label, bool zero_line = true);
/// The file name of a path, without its directories.
std::string file_name(const std::string& path);
/// "WHAT - FILE" with the result's data file (or `what` alone without one).
std::string title_for(const Result& r, const std::string& what);
/// The value of parameter `name`, NaN when the result has none.
double parameter(const Result& r, const std::string& name);
/// A law's curve (v ascending) with a gap at v = 0, where it jumps.
FigureSeries gapped_at_zero(const std::string& name, const std::vector<double>& v, const std::vector<double>& F);
/// The panels of a force fit against time t (s): the drive force measured and as `model` gives it
/// (series `model_name`; thinner with `thin_model`, so that the measurement shows where they
/// differ), then their difference (series `difference`, e.g. "measured - model"). Without a model
/// (nullptr) the measurement alone. N or N m by `axis`.
void add_force_fit_panels(Figure& f, Axis axis, const std::vector<double>& t, const std::vector<double>& measured,
                          const std::vector<double>* model, const std::string& model_name,
                          const std::string& difference, bool thin_model = false);
/// Measured against simulated ("NAME" and "NAME_sim" series of position, velocity, force), one
/// panel per signal; `force_word` names the force ("applied", "drive"), `file` goes in the title.
Figure compare_figure(const Result& r, const std::string& what, const std::string& force_word,
                      const std::string& file);
/// Velocities for drawing a law: lo < 0 draws [lo, 0), hi > 0 draws (0, hi], NaN between.
std::vector<double> law_grid(double lo, double hi);
/// The identified law's sliding force over [lo, hi]; empty when the result has no law.
std::optional<FigureSeries> law_curve(const Result& r, double lo, double hi, const std::string& name);
/// Largest finite |v|.
double max_abs(const std::vector<double>& v);
/// Friction samples binned by velocity (each sign apart): mean +- std per bin.
FigureSeries binned(const std::vector<double>& v, const std::vector<double>& F, double vmax);
/// An empty friction-velocity panel with units of `axis`.
FigurePanel map_panel(Axis axis);
/// True when any series has points.
bool has_data(const Figure& f);
/// A free oscillation with its turning points and (when given) the fitted envelope +-A(t).
FigurePanel position_with_envelope(std::span<const double> t, std::span<const double> x,
                                   const std::vector<double>& peak_t, const std::vector<double>& peak_x,
                                   const std::optional<EnvelopeResult>& env, const std::string& y_label);

}  // namespace frictionlab::cli
