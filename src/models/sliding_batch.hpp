#pragma once
// The run-time choice behind FrictionLaw::sliding(v, F), private to the library. The tests call
// sliding_batch with BatchKernels::scalar to run the fallback on a CPU that has AVX2.

#include <span>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab::detail {

/// How the laws with transcendental functions (stribeck, stribeck-asymmetric, smooth) run:
/// their scalar formula value by value, or 4-wide AVX2 kernels (sliding_kernels.hpp).
enum class BatchKernels { scalar, avx2 };

/// avx2 when this build has the kernels (x86-64, GCC or Clang, glibc's libmvec) and the CPU has
/// AVX2 and FMA; scalar otherwise.
BatchKernels best_batch_kernels();

/// F[i] = law.sliding(v[i]) (v in m/s or rad/s, F in N or N m) with the given kernels; avx2 in a
/// build without them runs scalar. v and F have equal sizes (FrictionLaw::sliding checks).
void sliding_batch(const FrictionLaw& law, std::span<const double> v, std::span<double> F, BatchKernels kernels);

}  // namespace frictionlab::detail
