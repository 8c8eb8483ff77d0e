// FrictionLaw::sliding over arrays: the law's type is resolved once per call. Laws without
// transcendental functions loop over their inline scalar formula (which the compiler may
// vectorise); stribeck, stribeck-asymmetric and smooth run the vector kernels of the widest set
// the build has and the CPU runs (8 wide on AVX-512, 4 on AVX2; sliding_kernels.hpp) on whole
// vectors of values, and their scalar formula on the rest.

#include "sliding_batch.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "sliding_kernels.hpp"

namespace frictionlab {
namespace detail {
namespace {

template <class Law>
void scalar_loop(const Law& law, std::span<const double> v, std::span<double> F) {
  for (std::size_t i = 0; i < v.size(); ++i) F[i] = law.sliding(v[i]);
}

// The kernel table of a set, nullptr for scalar and for a set this build lacks.
const KernelSet* kernel_set(BatchKernels kernels) {
  switch (kernels) {
#ifdef FRICTIONLAB_AVX2_KERNELS
    case BatchKernels::avx2: return &avx2_kernels;
#endif
#ifdef FRICTIONLAB_AVX512_KERNELS
    case BatchKernels::avx512: return &avx512_kernels;
#endif
    default: return nullptr;
  }
}

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

// True when a kernel of `set` serves `law`: it writes the whole vectors of values, the scalar
// law the rest.
template <class Law>
bool run_kernel(const KernelSet& set, const Law& law, std::span<const double> v, std::span<double> F) {
  const std::size_t n = v.size() - v.size() % set.width;
  if constexpr (std::is_same_v<Law, Stribeck>) {
    set.stribeck(side_of(law), at_zero(law), v.data(), F.data(), n);
  } else if constexpr (std::is_same_v<Law, Asymmetric<Stribeck>>) {
    set.asymmetric_stribeck(side_of(law.pos), side_of(law.neg), at_zero(law), v.data(), F.data(), n);
  } else if constexpr (std::is_same_v<Law, Smooth>) {
    set.smooth(side_of(law), law.vt, law.shape == SmoothShape::atan, at_zero(law), v.data(), F.data(), n);
  } else {
    return false;
  }
  scalar_loop(law, v.subspan(n), F.subspan(n));
  return true;
}

// What the CPU runs, asked once.
struct CpuFeatures {
  bool avx2_fma = false;  // AVX2 and FMA
  bool avx512f = false;
};

const CpuFeatures& cpu_features() {
  static const CpuFeatures features = [] {
    CpuFeatures f;
#if defined(FRICTIONLAB_AVX2_KERNELS) || defined(FRICTIONLAB_AVX512_KERNELS)  // x86-64, GCC or Clang
    f.avx2_fma = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    f.avx512f = __builtin_cpu_supports("avx512f");
#endif
    return f;
  }();
  return features;
}

}  // namespace

const char* name_of(BatchKernels kernels) {
  switch (kernels) {
    case BatchKernels::scalar: return "scalar";
    case BatchKernels::avx2: return "avx2";
    case BatchKernels::avx512: return "avx512";
  }
  return "?";
}

bool batch_kernels_built(BatchKernels kernels) {
  return kernels == BatchKernels::scalar || kernel_set(kernels) != nullptr;
}

bool batch_kernels_available(BatchKernels kernels) {
  const CpuFeatures& cpu = cpu_features();
  switch (kernels) {
    case BatchKernels::scalar: return true;
    case BatchKernels::avx2: return batch_kernels_built(kernels) && cpu.avx2_fma;
    case BatchKernels::avx512: return batch_kernels_built(kernels) && cpu.avx512f && cpu.avx2_fma;
  }
  return false;
}

BatchKernels best_batch_kernels() {
  static const BatchKernels best = batch_kernels_available(BatchKernels::avx512) ? BatchKernels::avx512
                                   : batch_kernels_available(BatchKernels::avx2) ? BatchKernels::avx2
                                                                                 : BatchKernels::scalar;
  return best;
}

void sliding_batch(const FrictionLaw& law, std::span<const double> v, std::span<double> F, BatchKernels kernels) {
  const KernelSet* set = kernel_set(kernels);
  std::visit(
      [&](const auto& l) {
        using Law = std::decay_t<decltype(l)>;
        if constexpr (DynamicLaw<Law>) {
          // The steady state of a dynamic law, as the scalar call computes it (not a fast path).
          for (std::size_t i = 0; i < v.size(); ++i) F[i] = law.sliding(v[i]);
        } else {
          if (set != nullptr && run_kernel(*set, l, v, F)) return;
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
