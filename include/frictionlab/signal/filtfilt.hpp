#pragma once
// Zero-phase forward-backward filtering, as scipy.signal.filtfilt and sosfiltfilt with odd
// padding and steady-state initial conditions (lfilter_zi / sosfilt_zi). MATLAB's filtfilt
// equals filtfilt(b, a, x, padlen = 3 * (max(len(a), len(b)) - 1)).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "frictionlab/signal/filter_workspace.hpp"
#include "frictionlab/signal/transfer_function.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Columns of equal length that live elsewhere (filtered without first copying them into a matrix).
using ColumnViews = std::vector<Eigen::Map<const Eigen::VectorXd>>;

/// Options of filtfilt / sosfiltfilt.
struct FiltfiltOptions {
  /// Samples of odd reflection (2 x(0) - x(k)) added at each end before filtering.
  /// Default (empty): scipy's, 3 * max(len(a), len(b)) for filtfilt and 3 * (2 * sections + 1
  /// - trailing zero taps) for sosfiltfilt. 0 turns padding off. Must be < x.size().
  std::optional<Eigen::Index> padlen;
};

/// Direct-form II transposed filtering, scipy.signal.lfilter(b, a, x, zi=zi). Shapes: x of
/// length N, zi of length max(len(a), len(b)) - 1 (empty: zero state); returns length N.
/// \throws std::invalid_argument if a is empty or a(0) == 0, or zi has the wrong length.
Eigen::VectorXd lfilter(const TransferFunction& tf, const Eigen::VectorXd& x, const Eigen::VectorXd& zi = {});

/// Steady-state initial state of lfilter for a unit step input, scipy.signal.lfilter_zi.
/// Shape: max(len(a), len(b)) - 1. \throws std::invalid_argument if a(0) == 0.
Eigen::VectorXd lfilter_zi(const TransferFunction& tf);

/// Zero-phase filtering, scipy.signal.filtfilt(b, a, x, padtype='odd', padlen=...).
/// Shapes: x of length N > padlen; returns length N.
/// \throws std::invalid_argument when N <= padlen (message gives both), or a(0) == 0.
Eigen::VectorXd filtfilt(const TransferFunction& tf, const Eigen::VectorXd& x, const FiltfiltOptions& options = {});

/// The padding filtfilt uses for a signal of n samples: options.padlen, or scipy's default.
/// \throws std::invalid_argument when n <= padlen (message gives both) or padlen < 0.
Eigen::Index filtfilt_padlen(const TransferFunction& tf, const FiltfiltOptions& options, Eigen::Index n);

/// filtfilt without allocating the result: x holds the signal at [padlen, padlen + N) on entry;
/// the padding on both sides is filled here (odd reflection) and the whole buffer filtered
/// forward and backward, so the filtered signal is x.segment(padlen, N) on return.
/// Shapes: x of length N + 2 padlen. \throws std::invalid_argument when N <= padlen or a(0) == 0.
void filtfilt_in_place(const TransferFunction& tf, Eigen::Ref<Eigen::VectorXd> x, Eigen::Index padlen);

/// Cascade filtering through second-order sections, scipy.signal.sosfilt(sos, x, zi=zi).
/// zi: sections x 2 (empty: zero state). Returns length N.
/// \throws std::invalid_argument if zi has the wrong shape or a section has a0 == 0.
Eigen::VectorXd sosfilt(const SecondOrderSections& sos, const Eigen::VectorXd& x,
                        const Eigen::MatrixX2d& zi = Eigen::MatrixX2d());

/// Steady-state section states for a unit step, scipy.signal.sosfilt_zi. Shape: sections x 2.
Eigen::MatrixX2d sosfilt_zi(const SecondOrderSections& sos);

/// Zero-phase filtering through second-order sections, scipy.signal.sosfiltfilt(sos, x,
/// padtype='odd', padlen=...). Shapes: x of length N > padlen; returns length N.
/// \throws std::invalid_argument when N <= padlen.
Eigen::VectorXd sosfiltfilt(const SecondOrderSections& sos, const Eigen::VectorXd& x,
                            const FiltfiltOptions& options = {});

/// sosfiltfilt of every column of x, each on its own (the same numbers as calling sosfiltfilt
/// column by column, computed several columns at a time; a constant column comes out as the
/// constant times the squared DC gain without being filtered, which equals filtering it up to
/// rounding), keeping rows 0, keep_every,
/// 2 keep_every, ... (decimate keeps every q-th without storing the rest).
/// Shapes: x is N x C with N > padlen; returns ceil(N / keep_every) x C.
/// \throws std::invalid_argument when N <= padlen, keep_every < 1 or a section has a0 == 0.
Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const Eigen::MatrixXd& x,
                                    const FiltfiltOptions& options = {}, Eigen::Index keep_every = 1);

/// The same for columns held elsewhere; they must all have the same length N (else
/// std::invalid_argument naming the column).
Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const ColumnViews& x,
                                    const FiltfiltOptions& options = {}, Eigen::Index keep_every = 1);

/// The same with the caller's work space (filter_workspace.hpp), for calls in a loop: the
/// numbers equal those of the call without it.
/// 	hrows std::invalid_argument as above; std::bad_alloc when the workspace cannot grow.
Eigen::MatrixXd sosfiltfilt_columns(const SecondOrderSections& sos, const ColumnViews& x, const FiltfiltOptions& options,
                                    Eigen::Index keep_every, FilterWorkspace& workspace);

}  // namespace frictionlab
