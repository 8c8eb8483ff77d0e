#pragma once
// The Stribeck column of idim's regression for any Stribeck velocity without refiltering, and the
// search of that velocity, shared by identify_idim (--vs search) and identify_auto (its Stribeck
// candidate's held-out search). Only the Stribeck column depends on vs, and decimation is linear
// and column by column, so the recipe runs once and each trial rebuilds and decimates that one
// column (the same numbers as running the whole recipe per trial).

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "frictionlab/identify/idim.hpp"
#include "frictionlab/identify/idim_workspace.hpp"

namespace frictionlab::detail {

/// The regression of `options` (resolved for the data's sample rate, as identify_idim) once,
/// with its Stribeck column remade for any vs. Holds references to `data` and `workspace`: both
/// must outlive it, and the workspace must not be used by anything else meanwhile.
class StribeckColumns {
 public:
  /// \throws std::invalid_argument as idim_regression for bad data or options, and when the
  ///         terms have no "stribeck" term.
  StribeckColumns(const IdimData& data, const IdimOptions& options, IdimWorkspace& workspace);
  ~StribeckColumns();
  StribeckColumns(const StribeckColumns&) = delete;
  StribeckColumns& operator=(const StribeckColumns&) = delete;

  /// The options resolved for the data (cut-off, decimation and skip chosen from the rate).
  const IdimOptions& options() const;
  /// The regression; its Stribeck column is the last vs asked for (options().stribeck_vs first).
  const IdimRegression& regression() const;
  /// False when no vs can give a fit: no motion above the no-motion speed, or a force that is
  /// zero throughout (identify_idim then says why).
  bool usable() const;
  /// The regression with its Stribeck column at `vs` (m/s or rad/s, > 0).
  const IdimRegression& at(double vs);
  /// The relative error (%) of the least-squares fit at `vs`; +infinity when the fit is refused
  /// (rank, condition above options().max_condition) or not finite.
  double error_percent(double vs);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The trial velocities of the search: 40 values on a log grid from 1e-4 to 0.5 of `top_speed`
/// (m/s or rad/s), ascending.
std::vector<double> stribeck_vs_grid(double top_speed);

/// The Stribeck velocity whose fit has the least relative error: the best of the grid
/// (stribeck_vs_grid of the regression's top speed), then refined by a golden-section search on
/// log vs between that point's neighbours (the grid steps by a quarter of a decade; Fc and Fv move
/// with vs); the refined value only when its error is lower. options().stribeck_vs when no trial
/// gives a fit or the columns are not usable.
double searched_stribeck_vs(StribeckColumns& columns);

}  // namespace frictionlab::detail
