#pragma once
// The inner loops of the recursive filters (filtfilt.cpp) built for AVX2 with fused
// multiply-add; private to the library.
//
// Why a second build of them: a recursive filter is a chain of dependent multiply-adds, one link
// per sample and section. Built for the x86-64 baseline (SSE2, no fused multiply-add) each link
// is a multiply and then an add, and four channels take two registers; with FMA a link is one
// instruction and four channels fit one AVX2 register. recursive_kernels_fma.cpp is compiled with
// -mavx2 -mfma (CMakeLists.txt, on x86-64 with GCC or Clang) and runs only on a CPU with both;
// elsewhere filtfilt.cpp runs its portable loops. A fused multiply-add rounds once where the
// portable loop rounds twice, so the two agree to rounding (about 1e-15 relative), not bit for bit.
//
// Coefficients are normalised (a0 = 1). Second-order sections come as filtfilt.cpp holds them:
// row-major, six per section (b0 b1 b2 a0 a1 a2). States as scipy's: two per section, or K for a
// transfer function of order K (direct form II transposed).

// No Eigen here, nor any other header's inline functions in the kernels' file: an inline
// function compiled there with AVX2 could be the copy the linker keeps for the whole library,
// and the library must still start on a CPU without AVX2. Counts are std::ptrdiff_t (what Eigen::Index is).
#include <cstddef>

namespace frictionlab::detail {

/// Whether the kernels below were built and this CPU runs them (AVX2 and FMA; asked once),
/// and the environment variable FRICTIONLAB_FILTER_KERNELS is not "portable" (which runs the
/// portable loops anywhere: the tests run both). Defined in filtfilt.cpp, built for the baseline.
bool fma_filters_available();

/// Whether the AVX-512 kernels (recursive_kernels_avx512.cpp, -mavx512f) were built and this
/// CPU runs them (AVX-512F, AVX2 and FMA), and FRICTIONLAB_FILTER_KERNELS is neither "portable"
/// nor "avx2" (which stops at the AVX2 kernels). Defined in filtfilt.cpp.
bool avx512_filters_available();

/// Each kernel returns false, doing nothing, when `sections` or `order` is outside 1..8 or the
/// kernels were not built (then fma_filters_available() is false too). The block and halves
/// kernels take finite samples only: a NaN must reach every later output, as in the serial
/// recursion, and a block started from a zero state would not carry it (the caller checks).
///
/// Four interleaved channels (x[4 n + c], c = 0..3) through `sections` second-order sections
/// (1..8), in place over `count` samples; step +1 runs forward from x, -1 runs
/// backward (x then points at the last sample). z: 2 states per section and channel,
/// z[(2 r + j) 4 + c], updated.
bool cascade4_fma(const double* coefficients, int sections, double* z, double* x, std::ptrdiff_t count, int step);

/// cascade4_fma forward, reading channel c from in[c][n] and writing out[4 n + c]: filtering and
/// interleaving in one pass over the memory.
bool cascade4_gather_fma(const double* coefficients, int sections, double* z, const double* const in[4],
                         std::ptrdiff_t count, double* out);

/// One channel through a transfer function of order 1..8 (b and a: order + 1
/// normalised coefficients) in direct form II transposed, in place over `count` samples with
/// step +1 or -1 as above; z: the `order` states, updated.
bool lfilter_fma(const double* b, const double* a, int order, double* z, double* x, std::ptrdiff_t count, int step);

/// cascade4_fma (and cascade4_gather_fma) over a long record as two halves at once in the eight
/// lanes of AVX-512: the second half runs from a zero state and then gets the response to its
/// true initial state added over the samples the cascade takes to forget a state (to 2^-70);
/// the same result to rounding in about 0.6 of the time. False, doing nothing, when count < 8192,
/// sections is outside 1..4 or the cascade's memory is longer than a quarter of the record
/// (then call the AVX2 kernel).
bool cascade4_halves_avx512(const double* coefficients, int sections, double* z, double* x, std::ptrdiff_t count, int step);
bool cascade4_gather_halves_avx512(const double* coefficients, int sections, double* z, const double* const in[4],
                                   std::ptrdiff_t count, double* out);

/// lfilter_fma for one long channel, four blocks of it at a time: each block after the first
/// starts from a zero state and then gets the response to its true initial state added over the
/// samples the filter takes to forget a state (to 2^-70). The same result to rounding with a
/// quarter of the recursion's chain. False, doing nothing, when count < 4096 or the filter's
/// memory is longer than an eighth of the record (then call lfilter_fma).
bool lfilter_blocks_fma(const double* b, const double* a, int order, double* z, double* x, std::ptrdiff_t count, int step);

}  // namespace frictionlab::detail
