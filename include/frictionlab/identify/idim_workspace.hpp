#pragma once
// The reusable memory of identify_idim, idim_regression and cross_test (identify/idim.hpp).

#include <cstddef>
#include <span>
#include <vector>

#include "frictionlab/signal/filter_workspace.hpp"

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Work space of the IDIM recipe for records of N samples: the filter input with its padding
/// (N + 2 padlen doubles), the filtered velocity and acceleration (N each), the columns of terms
/// that fill their own (N each), and the decimation filter's block (FilterWorkspace). A vs search
/// (IdimOptions::search_stribeck_vs) runs the recipe about 40 times on one record; the calls
/// without a workspace make one for the call and share it over the search, and a caller that
/// identifies many records (a batch, a study) can hold one and pass it to each call, so that the
/// memory is taken once. Results do not depend on it: a reused workspace gives the same numbers,
/// to the bit, as a fresh one.
///
/// The caller owns it: it grows to the largest record it served and keeps that memory until it is
/// destroyed or release() is called. One workspace serves one call at a time (a thread each); a
/// term's column function that runs IDIM itself must not pass the workspace of the call it is in.
class IdimWorkspace {
 public:
  /// Buffer `index` (0, 1, 2, ...) with room for `doubles` values (contents unspecified), used by
  /// the recipe. Valid until buffer(index, ...) is asked again with more values, or release().
  /// Taking a new index never moves the others. \throws std::bad_alloc.
  std::span<double> buffer(std::size_t index, std::size_t doubles) {
    if (buffers_.size() <= index) buffers_.resize(index + 1);
    std::vector<double>& b = buffers_[index];
    if (b.size() < doubles) b.resize(doubles);
    return {b.data(), doubles};
  }

  /// The decimation filter's work space.
  FilterWorkspace& filter() noexcept { return filter_; }

  /// Doubles of memory held now (buffers and filter).
  std::size_t capacity() const noexcept {
    std::size_t total = filter_.capacity();
    for (const auto& b : buffers_) total += b.capacity();
    return total;
  }

  /// Frees the memory held (the next call takes it again).
  void release() noexcept {
    std::vector<std::vector<double>>().swap(buffers_);
    filter_.release();
  }

 private:
  std::vector<std::vector<double>> buffers_;
  FilterWorkspace filter_;
};

}  // namespace frictionlab
