#pragma once
// The reusable memory of the zero-phase section filters (sosfiltfilt_columns, decimate_columns).

#include <cstddef>
#include <span>
#include <vector>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// Work space of sosfiltfilt_columns and decimate_columns: the padded, interleaved copy of up to
/// four columns that the forward and backward passes run over ((N + 2 padlen) x 4 doubles for
/// columns of N samples). The calls without a workspace make their own for the call; a caller
/// that filters many records in a loop (a vs search, a batch of logs) can hold one and pass it to
/// each call, so that the memory is taken once. Results do not depend on it: a reused workspace
/// gives the same numbers, to the bit, as a fresh one.
///
/// The caller owns it: it grows to the largest call it served and keeps that memory until it is
/// destroyed or release() is called. One workspace serves one call at a time (a thread each).
class FilterWorkspace {
 public:
  /// `doubles` values of work space (contents unspecified), valid until the next call of
  /// block() or release(). Grows the memory held when it is smaller. \throws std::bad_alloc.
  std::span<double> block(std::size_t doubles) {
    if (block_.size() < doubles) block_.resize(doubles);
    return {block_.data(), doubles};
  }

  /// Doubles of memory held now.
  std::size_t capacity() const noexcept { return block_.capacity(); }

  /// Frees the memory held (the next call takes it again).
  void release() noexcept { std::vector<double>().swap(block_); }

 private:
  std::vector<double> block_;
};

}  // namespace frictionlab
