/* test_wavelet_simd.c - every vector level this CPU runs gives the scalar
 * bits of nl_wavelet_row's sample loop (nl_wavelet_simd_*.c): compared with
 * memcmp, so signed zeros count. */
#include "wavelet/nl_wavelet.h"
#include "nl_test.h"
#include "simd/test_simd_rows.h"   /* coord, same, levels, random_row, compared */

#include <stdlib.h>

/* Wavelet noise rows:
 * 2D tiles of power-of-two and other periods and a 3D tile, rows dense and
 * sparse, either direction, added into values already there. */
NL_TEST(wavelet_rows_match_scalar)
{
  find_levels();
  struct { int dim, n; } tiles[] = {{2, 64}, {2, 10}, {3, 16}};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 77);
  double *init = malloc(MAXROW * sizeof *init), *ref = malloc(MAXROW * sizeof *ref);
  double *got = malloc(MAXROW * sizeof *got);
  int bad = 0;
  for (int ti = 0; ti < 3; ti++) {
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(tiles[ti].dim, tiles[ti].n);
    nl_wavelet_tile_seed(t, 3 + (unsigned long)ti);
    for (int row = 0; row < NROWS; row++) {
      double x0, dx, y = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
      double z = gsl_rng_uniform(r) < 0.9 ? 100 * gsl_rng_uniform(r) - 50 : coord(r);
      double weight = gsl_rng_uniform(r) < 0.2 ? 1.0 : 4 * gsl_rng_uniform(r) - 2;
      size_t n;
      random_row(r, &x0, &dx, &n);
      if (row % 7 == 0)   /* p - 1/2 = integer */
        x0 = 0.5 + (double)((long)gsl_rng_uniform_int(r, 200) - 100);
      for (size_t k = 0; k < n; k++)
        init[k] = gsl_rng_uniform(r) < 0.5 ? 0.0 : gsl_rng_uniform(r) - 0.5;
      nl_simd_set(NL_SIMD_SCALAR);
      memcpy(ref, init, n * sizeof *ref);
      nl_wavelet_row(t, x0, dx, y, z, n, weight, ref);
      for (int L = 0; L < nlevels; L++) {
        nl_simd_set(levels[L]);
        memcpy(got, init, n * sizeof *got);
        nl_wavelet_row(t, x0, dx, y, z, n, weight, got);
        if (!same(got, ref, n) && bad++ < 5)
          fprintf(stderr, "  wavelet %dD n=%d %s row x0=%a dx=%a n=%zu differs\n",
                  tiles[ti].dim, tiles[ti].n, nl_simd_name(levels[L]), x0, dx, n);
        compared += (long)n;
      }
    }
    nl_wavelet_tile_free(t);
  }
  NL_CHECK(bad == 0);
  nl_simd_set(nl_simd_best());
  free(init);
  free(ref);
  free(got);
  gsl_rng_free(r);
}

int main(void)
{
  int rc = nl_test_run();
  printf("  %ld values compared bit for bit with the scalar path\n", compared);
  return rc;
}
