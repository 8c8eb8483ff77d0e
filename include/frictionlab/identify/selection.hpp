#pragma once
// Model selection on held-out data: candidate structures (methods, regressor sets, laws) compared
// by the error with which each predicts data it was not fitted on, never by its fitting error
// alone (a more flexible structure always fits its own data at least as well). The held-out data
// are contiguous time blocks of the record (K-fold cross-validation over time: fit on K-1 blocks,
// predict the remaining one, for each block in turn) or a second record. Physically impossible
// estimates (a negative Coulomb level, Fs below Fc, ...) refuse a candidate with the reason.

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frictionlab/identify/result.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// One half-open block [begin, end) of sample indices.
using SampleBlock = std::pair<Eigen::Index, Eigen::Index>;

/// `folds` contiguous blocks of as equal length as possible covering [0, samples), in order.
/// \throws std::invalid_argument when folds < 2 or samples < 2 folds (each block needs two samples).
std::vector<SampleBlock> contiguous_blocks(Eigen::Index samples, int folds);

/// Held-out errors of one candidate: per block, the squared prediction error and the squared norm
/// of the measured signal on that block (N^2 or (N m)^2 summed over its samples).
struct HeldOutErrors {
  std::vector<double> error_squares;   ///< ||y_k - y_hat_k||^2 per held-out block k
  std::vector<double> signal_squares;  ///< ||y_k||^2 per held-out block k
  std::size_t samples = 0;             ///< samples predicted, over all blocks

  /// Pooled relative error, percent: 100 sqrt(sum error_squares / sum signal_squares); NaN when empty
  /// or any block's error is not finite.
  double relative_error_percent() const;
  /// Per block, percent: 100 sqrt(error_squares_k / signal_squares_k).
  std::vector<double> block_errors_percent() const;
};

/// Held-out errors of the linear model y = X theta: for each block of `blocks`, theta by least
/// squares (column-pivoting QR) on the rows outside the block, then the block's rows predicted.
/// Shapes: X N x p, y length N, blocks within [0, N). A training set with fewer rows than p, or a
/// rank-deficient one, gives a NaN error for that block.
/// \throws std::invalid_argument on unequal row counts or a block outside [0, N).
HeldOutErrors linear_heldout_errors(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                                    const std::vector<SampleBlock>& blocks);

/// Why a result cannot be physical, or "" when it can: status error (its message); a parameter
/// among Fc, Fs, Fv, M, sigma0, sigma1, sigma2 and their _pos/_neg forms that is negative; vs <= 0;
/// Fs_minus_Fc < 0 or Fs < Fc (static level below the Coulomb level); a value that is not finite.
/// E.g. "Fs_minus_Fc = -0.4 N < 0: the static level would be below the Coulomb level".
std::string physical_refusal(const Result& result);

/// One candidate of a selection: a structure fitted on the whole record, with its held-out error.
struct SelectionCandidate {
  std::string name;       ///< e.g. "idim stribeck (vs searched)", "sweep stribeck + M"
  std::string method;     ///< the method that fitted it (identify/method.hpp)
  std::string structure;  ///< terms or law in words ("inertia,viscous,coulomb,offset")
  Result result;          ///< the fit on the whole record
  double training_error_percent = std::numeric_limits<double>::quiet_NaN();  ///< on the data it was fitted on
  double heldout_error_percent = std::numeric_limits<double>::quiet_NaN();   ///< pooled over the held-out blocks
  std::vector<double> block_errors_percent;  ///< per held-out block (or one: the second record)
  /// Why it may not be the answer ("" when it may): physical_refusal of its result, or a held-out
  /// error that could not be computed.
  std::string refusal;

  bool refused() const { return !refusal.empty(); }
};

/// Standard error of a candidate's held-out error, percent: the standard deviation of its block
/// errors over sqrt(blocks); 0 with fewer than two blocks (a second record).
double heldout_standard_error(const SelectionCandidate& candidate);

/// The candidate to answer with, by the one-standard-error rule (Hastie, Tibshirani, Friedman,
/// The Elements of Statistical Learning, 2nd ed., sec. 7.10): among the candidates that are not
/// refused and have a finite held-out error, the lowest error e* (its standard error s*) sets a
/// limit e* + max(s*, min_relative_margin e*), and the first candidate in the list within it is
/// chosen. So list candidates simplest first: a more flexible structure is chosen only when it
/// predicts held-out data clearly better, never for a better fit of its own data. Default margin
/// 0.01 (differences below 1 % of the error are ties: what the second decimal of a percentage
/// says). nullopt when every candidate is refused or none has a finite held-out error.
std::optional<std::size_t> select_candidate(const std::vector<SelectionCandidate>& candidates,
                                            double min_relative_margin = 0.01);

/// The candidates as a JSON array (text), one object each, in the given order: name, method,
/// structure, status ("chosen", "runner-up", "refused"), heldout_error_percent,
/// training_error_percent, block_errors_percent, reason (the refusal, or "" ), parameters
/// {NAME: value}. `chosen` as select_candidate returned.
std::string selection_json(const std::vector<SelectionCandidate>& candidates, std::optional<std::size_t> chosen);

}  // namespace frictionlab
