#pragma once
// Entry points of the 4-wide AVX2 kernels of FrictionLaw::sliding(v, F) (sliding_batch_avx2.cpp)
// and the parameters they take. Plain structs and raw arrays only: that file is compiled with
// -mavx2 -mfma, and an inline function of a shared header used there would be compiled with AVX2
// too, and its copy might be the one the linker keeps for every caller, including callers on
// CPUs without AVX2.

#include <cstddef>

namespace frictionlab::detail {

/// How a Stribeck level Fc + (Fs - Fc) exp(-|v/vs|^delta) is computed, the same choice as the
/// scalar laws make (stribeck_decay in scalar.hpp, SmoothT::sliding); the two sides of an
/// asymmetric law share one form (asymmetric_stribeck_sliding_avx2).
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

// Each kernel writes F[i] for i < n, with n a multiple of 4 (the caller runs the scalar law on the
// rest). v in m/s or rad/s, F in N or N m.

/// stribeck: sign(v) (Fc + (Fs - Fc) decay) + Fv v.
void stribeck_sliding_avx2(const StribeckSide& law, AtZero zero, const double* v, double* F, std::size_t n);
/// stribeck-asymmetric: `pos` for v >= 0, `neg` otherwise.
void asymmetric_stribeck_sliding_avx2(const StribeckSide& pos, const StribeckSide& neg, AtZero zero, const double* v,
                                      double* F, std::size_t n);
/// smooth: s(v/vt) (Fc + (Fs - Fc) decay) + Fv v, s = tanh or (2/pi) atan (`atan_shape`).
void smooth_sliding_avx2(const StribeckSide& level, double vt, bool atan_shape, AtZero zero, const double* v, double* F,
                         std::size_t n);

}  // namespace frictionlab::detail
