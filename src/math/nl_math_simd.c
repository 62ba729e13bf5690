/* nl_math_simd.c - nl_math_sinpi_n at the library's vector level
 * (simd/nl_simd.h): the kernels of nl_math_simd_body.h, or the scalar
 * function, which every level's bits equal. */
#include "math/nl_math.h"
#include "simd/nl_simd.h"

#include <stddef.h>

void nl_math__sinpi_n_sse2(size_t n, const double *x, double *y);
void nl_math__sinpi_n_avx2(size_t n, const double *x, double *y);
void nl_math__sinpi_n_avx512(size_t n, const double *x, double *y);

void nl_math_sinpi_n(size_t n, const double *x, double *y)
{
  switch (nl_simd_get()) {
#if NL_SIMD_X86
  case NL_SIMD_SSE2: nl_math__sinpi_n_sse2(n, x, y); return;
  case NL_SIMD_AVX2: nl_math__sinpi_n_avx2(n, x, y); return;
  case NL_SIMD_AVX512: nl_math__sinpi_n_avx512(n, x, y); return;
#endif
  default:
    for (size_t j = 0; j < n; j++) y[j] = nl_math_sinpi(x[j]);
  }
}
