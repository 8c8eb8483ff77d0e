#pragma once
// The vector kernels of FrictionLaw::sliding(v, F) as sliding_batch.cpp sees them: one table of
// entry points per instruction set (avx2_kernels: 4 wide, sliding_batch_avx2.cpp; avx512_kernels:
// 8 wide, sliding_batch_avx512.cpp; both compile the one kernel body sliding_kernels_impl.hpp)
// and the parameters they take. Plain structs and raw arrays only: those files are compiled with
// -mavx2 -mfma or -mavx512f, and an inline function of a shared header used there would be
// compiled with those instructions too, and its copy might be the one the linker keeps for every
// caller, including callers on CPUs without them.

#include <cstddef>

namespace frictionlab::detail {

/// How a Stribeck level Fc + (Fs - Fc) exp(-|v/vs|^delta) is computed, the same choice as the
/// scalar laws make (stribeck_decay in scalar.hpp, SmoothT::sliding); the two sides of an
/// asymmetric law share one form (KernelSet::asymmetric_stribeck).
enum class Decay {
  none,         ///< Fs == Fc: the level is Fc
  exponential,  ///< delta == 1: exp(-|v/vs|)
  gaussian,     ///< delta == 2: exp(-(v/vs)^2)
  power,        ///< any other delta: exp(-exp(delta log|v/vs|))
};

/// One Stribeck parameter set (N or N m, m/s or rad/s, N s/m or N m s/rad) with its decay form.
struct StribeckSide {
  double Fc, Fs, vs, delta, Fv;
  Decay decay;
};

/// The scalar law's sliding(+0.0) and sliding(-0.0) (N or N m): the kernels return these at v = 0,
/// so that zero velocity gives the scalar call's value exactly.
struct AtZero {
  double plus, minus;
};

/// The kernels of one instruction set. Each writes F[i] for i < n, with n a multiple of `width`
/// (the caller runs the scalar law on the rest). v in m/s or rad/s, F in N or N m.
struct KernelSet {
  std::size_t width;  ///< values per vector: 4 (AVX2) or 8 (AVX-512)
  /// stribeck: sign(v) (Fc + (Fs - Fc) decay) + Fv v.
  void (*stribeck)(const StribeckSide& law, AtZero zero, const double* v, double* F, std::size_t n);
  /// stribeck-asymmetric: `pos` for v >= 0, `neg` otherwise.
  void (*asymmetric_stribeck)(const StribeckSide& pos, const StribeckSide& neg, AtZero zero, const double* v,
                              double* F, std::size_t n);
  /// smooth: s(v/vt) (Fc + (Fs - Fc) decay) + Fv v, s = tanh or (2/pi) atan (`atan_shape`).
  void (*smooth)(const StribeckSide& level, double vt, bool atan_shape, AtZero zero, const double* v, double* F,
                 std::size_t n);
};

/// Defined only in builds with that set (FRICTIONLAB_AVX2_KERNELS, FRICTIONLAB_AVX512_KERNELS);
/// to be called only on CPUs that run it (batch_kernels_available in sliding_batch.hpp).
extern const KernelSet avx2_kernels;
extern const KernelSet avx512_kernels;

}  // namespace frictionlab::detail
