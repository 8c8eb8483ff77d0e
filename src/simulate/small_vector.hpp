#pragma once
// N_Vector kernels for the engine's few-state vectors (2 to ~10 entries).

#include <sundials/sundials_nvector.h>

namespace frictionlab::detail {

/// Replaces the hot operations of a serial N_Vector (linear sums and combinations, scaling,
/// weighted norms, the error-weight helpers) with plain loops. The serial kernels are written
/// for long vectors: for a 3-state system their dispatch and special cases cost more than the
/// arithmetic (a third of a Canudas stick-slip run went to them). Results equal the serial
/// kernels' up to rounding (a x + b y where those factor a (x + y) when b = a). Clones of v
/// (CVODE's work vectors) inherit the operations.
void use_small_vector_ops(N_Vector v);

}  // namespace frictionlab::detail
