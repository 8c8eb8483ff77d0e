// FrictionLaw::sliding over arrays: the law's type is resolved once per call. Laws without
// transcendental functions loop over their inline scalar formula (which the compiler may
// vectorise); stribeck, stribeck-asymmetric and smooth run the AVX2 kernels of
// sliding_batch_avx2.cpp on whole groups of 4 values when the build has them and the CPU runs
// them, and their scalar formula on the rest.

#include "sliding_batch.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#ifdef FRICTIONLAB_AVX2_KERNELS
#include "sliding_kernels.hpp"
#endif

namespace frictionlab {
namespace detail {
namespace {

template <class Law>
void scalar_loop(const Law& law, std::span<const double> v, std::span<double> F) {
  for (std::size_t i = 0; i < v.size(); ++i) F[i] = law.sliding(v[i]);
}

#ifdef FRICTIONLAB_AVX2_KERNELS
Decay decay_of(double Fc, double Fs, double delta) {
  if (Fs == Fc) return Decay::none;
  if (delta == 2.0) return Decay::gaussian;
  if (delta == 1.0) return Decay::exponential;
  return Decay::power;
}

StribeckSide side_of(const Stribeck& s) { return {s.Fc, s.Fs, s.vs, s.delta, s.Fv, decay_of(s.Fc, s.Fs, s.delta)}; }
StribeckSide side_of(const Smooth& s) { return {s.Fc, s.Fs, s.vs, s.delta, s.Fv, decay_of(s.Fc, s.Fs, s.delta)}; }

template <class Law>
AtZero at_zero(const Law& law) {
  return {law.sliding(0.0), law.sliding(-0.0)};
}

// True when an AVX2 kernel serves `law`: it writes the whole groups of 4 values, the scalar law
// the rest.
template <class Law>
bool run_avx2_kernel(const Law& law, std::span<const double> v, std::span<double> F) {
  const std::size_t n = v.size() - v.size() % 4;
  if constexpr (std::is_same_v<Law, Stribeck>) {
    stribeck_sliding_avx2(side_of(law), at_zero(law), v.data(), F.data(), n);
  } else if constexpr (std::is_same_v<Law, Asymmetric<Stribeck>>) {
    asymmetric_stribeck_sliding_avx2(side_of(law.pos), side_of(law.neg), at_zero(law), v.data(), F.data(), n);
  } else if constexpr (std::is_same_v<Law, Smooth>) {
    smooth_sliding_avx2(side_of(law), law.vt, law.shape == SmoothShape::atan, at_zero(law), v.data(), F.data(), n);
  } else {
    return false;
  }
  scalar_loop(law, v.subspan(n), F.subspan(n));
  return true;
}
#endif

}  // namespace

BatchKernels best_batch_kernels() {
#ifdef FRICTIONLAB_AVX2_KERNELS
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2 ? BatchKernels::avx2 : BatchKernels::scalar;
#else
  return BatchKernels::scalar;
#endif
}

void sliding_batch(const FrictionLaw& law, std::span<const double> v, std::span<double> F,
                   [[maybe_unused]] BatchKernels kernels) {
  std::visit(
      [&](const auto& l) {
        using Law = std::decay_t<decltype(l)>;
        if constexpr (DynamicLaw<Law>) {
          // The steady state of a dynamic law, as the scalar call computes it (not a fast path).
          for (std::size_t i = 0; i < v.size(); ++i) F[i] = law.sliding(v[i]);
        } else {
#ifdef FRICTIONLAB_AVX2_KERNELS
          if (kernels == BatchKernels::avx2 && run_avx2_kernel(l, v, F)) return;
#endif
          scalar_loop(l, v, F);
        }
      },
      law.variant());
}

}  // namespace detail

void FrictionLaw::sliding(std::span<const double> v, std::span<double> F) const {
  if (F.size() != v.size())
    throw std::invalid_argument("FrictionLaw::sliding: F (N or N m) has " + std::to_string(F.size()) +
                                " values but v (m/s or rad/s) has " + std::to_string(v.size()) +
                                "; they must have the same length");
  detail::sliding_batch(*this, v, F, detail::best_batch_kernels());
}

}  // namespace frictionlab
