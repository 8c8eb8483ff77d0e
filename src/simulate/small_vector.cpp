#include "small_vector.hpp"

#include <nvector/nvector_serial.h>

#include <algorithm>
#include <cmath>

namespace frictionlab::detail {

namespace {

inline sunindextype len(N_Vector v) { return NV_LENGTH_S(v); }
inline sunrealtype* data(N_Vector v) { return NV_DATA_S(v); }

void linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}

void constant(sunrealtype c, N_Vector z) {
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = c;
}

void prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = xd[i] * yd[i];
}

void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = c * xd[i];
}

void absolute(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = std::abs(xd[i]);
}

void inverse(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = 1.0 / xd[i];
}

void add_const(N_Vector x, sunrealtype b, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) zd[i] = xd[i] + b;
}

sunrealtype wsqrsum(N_Vector x, N_Vector w) {
  const sunrealtype *xd = data(x), *wd = data(w);
  sunrealtype sum = 0.0;
  for (sunindextype i = 0, n = len(x); i < n; ++i) {
    const sunrealtype p = xd[i] * wd[i];
    sum += p * p;
  }
  return sum;
}

sunrealtype wrms_norm(N_Vector x, N_Vector w) { return std::sqrt(wsqrsum(x, w) / static_cast<sunrealtype>(len(x))); }

sunrealtype max_norm(N_Vector x) {
  const sunrealtype* xd = data(x);
  sunrealtype m = 0.0;
  for (sunindextype i = 0, n = len(x); i < n; ++i) m = std::max(m, std::abs(xd[i]));
  return m;
}

// z = sum_j c[j] X[j]; z may be one of the X[j] (each entry is read before it is written).
int linear_combination(int nvec, sunrealtype* c, N_Vector* X, N_Vector z) {
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = len(z); i < n; ++i) {
    sunrealtype s = c[0] * data(X[0])[i];
    for (int j = 1; j < nvec; ++j) s += c[j] * data(X[j])[i];
    zd[i] = s;
  }
  return 0;
}

// Z[j] = a[j] x + Y[j].
int scale_add_multi(int nvec, sunrealtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const sunrealtype* xd = data(x);
  for (int j = 0; j < nvec; ++j) {
    const sunrealtype* yd = data(Y[j]);
    sunrealtype* zd = data(Z[j]);
    for (sunindextype i = 0, n = len(x); i < n; ++i) zd[i] = a[j] * xd[i] + yd[i];
  }
  return 0;
}

}  // namespace

void use_small_vector_ops(N_Vector v) {
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = linear_sum;
  ops->nvconst = constant;
  ops->nvprod = prod;
  ops->nvscale = scale;
  ops->nvabs = absolute;
  ops->nvinv = inverse;
  ops->nvaddconst = add_const;
  ops->nvwrmsnorm = wrms_norm;
  ops->nvwsqrsumlocal = wsqrsum;
  ops->nvmaxnorm = max_norm;
  ops->nvlinearcombination = linear_combination;
  ops->nvscaleaddmulti = scale_add_multi;
}

}  // namespace frictionlab::detail
