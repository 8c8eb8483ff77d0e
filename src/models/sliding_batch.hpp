#pragma once
// The run-time choice behind FrictionLaw::sliding(v, F), private to the library. The tests and
// benchmarks call sliding_batch with each kernel set this build and CPU run.

#include <span>

#include "frictionlab/models/friction_law.hpp"

namespace frictionlab::detail {

/// How the laws with transcendental functions (stribeck, stribeck-asymmetric, smooth) run:
/// their scalar formula value by value, or vector kernels (sliding_kernels.hpp), 4 wide on AVX2
/// or 8 wide on AVX-512.
enum class BatchKernels { scalar, avx2, avx512 };

/// "scalar", "avx2" or "avx512".
const char* name_of(BatchKernels kernels);

/// Whether this build has the set: scalar always; avx2 and avx512 on x86-64 with GCC or Clang
/// where glibc's libmvec has the vector functions of that width (CMakeLists.txt).
bool batch_kernels_built(BatchKernels kernels);

/// Whether the set runs here: built, and the CPU has its instructions (avx2: AVX2 and FMA;
/// avx512: AVX-512F, AVX2 and FMA).
bool batch_kernels_available(BatchKernels kernels);

/// The widest available set: avx512, else avx2, else scalar.
BatchKernels best_batch_kernels();

/// F[i] = law.sliding(v[i]) (v in m/s or rad/s, F in N or N m) with the given kernels, which
/// must be available (a set this build lacks runs scalar; one the CPU lacks stops the program on
/// an illegal instruction). v and F have equal sizes (FrictionLaw::sliding checks).
void sliding_batch(const FrictionLaw& law, std::span<const double> v, std::span<double> F, BatchKernels kernels);

}  // namespace frictionlab::detail
