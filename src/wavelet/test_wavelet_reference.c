/* test_wavelet_reference.c - wavelet noise against Cook & DeRose's appendix
 * code (tests/reference/cook_derose_wavelet_noise.c): the tile construction
 * (downsampling, upsampling, the band as noise minus its coarse part, the
 * odd shift), the B-spline evaluation at points and along rows at every
 * SIMD level, and the sum of bands.
 *
 * Tiles: both shift loops (nl_wavelet_tile_seed against the shifted copy,
 * nl_wavelet_tile_seed_transposed against the appendix's loop as printed),
 * in 2D and 3D, periods from 8 (the 32-tap filter wraps 4 times) to 256, odd
 * halves (n = 10, 26: offset n/2 already odd) and even ones, three seeds
 * each: every coefficient compared, 659,232 in all. Both sides start
 * from the same white noise (step 1: the library's Gaussian stream).
 *
 * Tile tolerance: 2e-5 absolute on coefficients of magnitude up to ~6. The
 * appendix builds the tile in float: each pass sums 33 products into a float
 * (about 33 roundings of half an ulp of values up to ~8, 2^-21 each) and 2
 * more when upsampling; the library sums in double and rounds to float once
 * a pass. Its filter also differs from the printed one in one tap, 0.003545
 * for 0.003546 (the library mirrors the first 16 values), 1e-6 times a value
 * below ~5 per pass. Three passes, then the subtraction and the shift's
 * addition: measured 5.8e-6 over all tiles. A wrong tap, axis, stride,
 * offset or transposition moves coefficients by O(0.1..1); one filter tap
 * off by 1e-5 already shows (7e-5).
 *
 * Evaluation: the library's tiles, 2^17 points each through eval2/eval3 and
 * rows through nl_wavelet_row at each level, against WNoise at the same
 * tile. Coordinates uniform in [-4n, 4n], or lattice points, half-integers
 * (p - 1/2 an integer, where ceil moves the taps), an ulp either side of
 * them, multiples of the period n and tiny values of either sign.
 * Tolerance 1e-14: the same 9 or 27 products of B-spline weights (in [0, 1],
 * summing to 1) and coefficients below ~6 in magnitude, the library
 * collapsing y and z before x, WNoise summing x fastest: a dozen roundings
 * of values below 8, 2^-50 each; measured 1.3e-15.
 *
 * Bands: 2e-13. The library steps along a row (x0 + k dx), the sum here
 * computes s (x + 1/2) + o_k: positions up to ~100 differ by an ulp there,
 * 2^-46, times the noise's slope (below ~10 per unit), per band, six bands
 * of weight up to 2; measured 5.4e-14.
 */
#include "base/nl_base.h"
#include "simd/nl_simd.h"
#include "wavelet/nl_wavelet.h"
#include "nl_test.h"
#include "reference/cook_derose_wavelet_noise.h"

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TILE_TOL 2e-5
#define EVAL_TOL 1e-14
#define BANDS_TOL 2e-13
#define EVAL_POINTS (1 << 17)

static size_t tile_size(const nl_wavelet_tile *t)
{
  return (size_t)t->n * t->n * (t->dim == 3 ? (size_t)t->n : 1);
}

/* Step 1 as the library draws it: the white noise both sides start from. */
static float *white_noise(int dim, int n, unsigned long seed)
{
  size_t total = (size_t)n * n * (dim == 3 ? (size_t)n : 1);
  float *w = malloc(total * sizeof *w);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, nl_seed_stream(seed, "wavelet.tile", 0));
  for (size_t i = 0; i < total; i++)
    w[i] = (float)gsl_ran_gaussian_ziggurat(rng, 1.0);
  gsl_rng_free(rng);
  return w;
}

NL_TEST(tile_construction_matches_the_appendix)
{
  static const struct { int dim, n; } tiles[] = {
    {2, 8}, {2, 10}, {2, 26}, {2, 32}, {2, 64}, {2, 256}, {3, 8}, {3, 10}, {3, 16}, {3, 32}};
  double worst = 0;
  long compared = 0, bad = 0;
  for (size_t ti = 0; ti < sizeof tiles / sizeof *tiles; ti++)
    for (unsigned long seed = 1; seed <= 3; seed++)
      for (int literal = 0; literal <= 1; literal++) {
        int dim = tiles[ti].dim, n = tiles[ti].n;
        nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, n);
        if (literal)
          nl_wavelet_tile_seed_transposed(t, seed);
        else
          nl_wavelet_tile_seed(t, seed);
        float *ref = white_noise(dim, n, seed);
        cd_generate_tile(ref, n, dim, literal);
        double here = 0;
        for (size_t i = 0; i < tile_size(t); i++)
          here = fmax(here, fabs((double)t->data[i] - (double)ref[i]));
        if (!(here <= TILE_TOL) && !bad++)
          printf("  %dD n=%d seed %lu %s shift: max |ours - appendix| %.3g\n", dim, n, seed,
                 literal ? "transposed" : "plain", here);
        worst = fmax(worst, here);
        compared += (long)tile_size(t);
        free(ref);
        nl_wavelet_tile_free(t);
      }
  printf("  %ld coefficients, max |ours - appendix| %.3g\n", compared, worst);
  NL_CHECK(bad == 0 && worst <= TILE_TOL);
}

/* A coordinate: uniform in [-4n, 4n] or, half the time, an awkward one. */
static double coord(gsl_rng *r, int n)
{
  double u = gsl_rng_uniform(r);
  if (u < 0.5)
    return 8.0 * n * gsl_rng_uniform(r) - 4.0 * n;
  double m = (double)((long)gsl_rng_uniform_int(r, 8 * (unsigned long)n + 1) - 4 * n);
  double s = gsl_rng_uniform(r) < 0.5 ? -1.0 : 1.0;
  if (u < 0.6) return m;                                   /* lattice point */
  if (u < 0.7) return m + 0.5;                             /* taps move here */
  if (u < 0.8) return nextafter(u < 0.75 ? m : m + 0.5, s * INFINITY);
  if (u < 0.9) {                                           /* the period */
    double p = n * (double)((long)gsl_rng_uniform_int(r, 9) - 4);
    return gsl_rng_uniform(r) < 0.5 ? p : nextafter(p, s * INFINITY);
  }
  return s * ldexp(1.0, -1 - (int)gsl_rng_uniform_int(r, 1074));   /* tiny */
}

typedef struct { double worst; long n; } stat;

static void note(stat *s, const nl_wavelet_tile *t, const double *p, double got)
{
  double d = fabs(got - cd_wnoise(t->data, t->n, t->dim, p));
  s->n++;
  if (!(d <= s->worst))
    s->worst = d;
}

static void report(const char *what, int dim, int n, const stat *s)
{
  printf("  %-10s %dD n=%-3d %8ld values, max |ours - WNoise| %.3g\n", what, dim, n, s->n,
         s->worst);
  NL_CHECK(s->worst <= EVAL_TOL);
}

NL_TEST(evaluation_matches_wnoise)
{
  static const struct { int dim, n; } tiles[] = {{2, 64}, {2, 10}, {3, 16}, {3, 10}};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2005);
  for (size_t ti = 0; ti < sizeof tiles / sizeof *tiles; ti++) {
    int dim = tiles[ti].dim, n = tiles[ti].n;
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, n);
    nl_wavelet_tile_seed(t, 11 + ti);
    stat s = {0};
    for (int k = 0; k < EVAL_POINTS; k++) {
      double p[3] = {coord(r, n), coord(r, n), coord(r, n)};
      double got = dim == 2 ? nl_wavelet_eval2(t, p[0], p[1])
                            : nl_wavelet_eval3(t, p[0], p[1], p[2]);
      note(&s, t, p, got);
    }
    report("eval", dim, n, &s);
    /* rows: dense and sparse, either way, from awkward origins, at each level */
    enum { ROW = 300 };
    static const double steps[] = {1.0 / 64, 0.37, -0.29, 0.5, 1.0, 3.7, -1.0 / 3, 0x1p-40};
    for (int l = NL_SIMD_SCALAR; l <= NL_SIMD_AVX512; l++) {
      if (!nl_simd_supported(l))
        continue;
      nl_simd_set(l);
      stat sr = {0};
      for (int row = 0; row < 200; row++) {
        double out[ROW] = {0}, dx = steps[row % 8];
        double p[3] = {coord(r, n), coord(r, n), coord(r, n)}, x0 = p[0];
        nl_wavelet_row(t, x0, dx, p[1], p[2], ROW, 1.0, out);
        for (int k = 0; k < ROW; k++) {
          p[0] = x0 + (double)k * dx;
          note(&sr, t, p, out[k]);
        }
      }
      report(nl_simd_name(l), dim, n, &sr);
    }
    nl_simd_set(nl_simd_best());
    nl_wavelet_tile_free(t);
  }
  gsl_rng_free(r);
}

/* nl_wavelet_bands_grid against the sum it documents, each band by WNoise:
 * out = sum_k w[k] N(2^-k scale (x + 1/2, y + 1/2, z) + o_k). */
NL_TEST(bands_grid_is_the_sum_of_wnoise_bands)
{
  enum { W = 48, H = 40 };
  double w[6] = {1.0, -0.7, 2.0, 0.0, 0.3, 1.5}, worst = 0;
  static double out[W * H];
  for (int dim = 2; dim <= 3; dim++) {
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, dim == 2 ? 32 : 16);
    nl_wavelet_tile_seed(t, 4);
    nl_wavelet_bands b;
    NL_CHECK(nl_wavelet_bands_init(&b, 6, w, t->n, 9, NULL) == NL_OK);
    double scale = 1.37, z = -3.25;
    nl_wavelet_bands_grid(t, &b, W, H, z, scale, out);
    for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++) {
        double want = 0;
        for (int k = 0; k < b.nbands; k++) {
          double s = scale * ldexp(1.0, -k);
          double p[3] = {s * (x + 0.5) + b.off[k][0], s * (y + 0.5) + b.off[k][1],
                         s * z + b.off[k][2]};
          want += b.w[k] * cd_wnoise(t->data, t->n, dim, p);
        }
        worst = fmax(worst, fabs(out[y * W + x] - want));
      }
    nl_wavelet_tile_free(t);
  }
  printf("  %d pixels, max |ours - sum of WNoise bands| %.3g\n", 2 * W * H, worst);
  NL_CHECK(worst <= BANDS_TOL);
}

/* The variance readings L1 reports, each against its documented mean of
 * WNoise^2 taken here point by point (nl_wavelet.h): the volume mean on a
 * grid of per_unit samples per unit, the slice z (and its mean), the
 * lattice shifted by frac, Cook & DeRose's multiband sum with unit weights,
 * and the mean at random points (drawn here from the same stream). Small
 * tiles keep the direct sums short. Tolerance 1e-13 relative: means of
 * 10^3..10^4 squares, each within EVAL_TOL of WNoise's, summed in another
 * order; measured 4.6e-16. */
NL_TEST(variance_readings_are_their_means)
{
  double worst = 0;
  for (int dim = 2; dim <= 3; dim++) {
    int n = dim == 2 ? 16 : 8;
    nl_wavelet_tile *t = nl_wavelet_tile_alloc(dim, n);
    nl_wavelet_tile_seed(t, 21);
    for (int per = 1; per <= 3; per++) {
      int m = n * per, planes = dim == 3 ? m : 1;
      double d = 1.0 / per, vol = 0, sl = 0, s1 = 0, z = -1.3, mean;
      for (int iz = 0; iz < planes; iz++)
        for (int iy = 0; iy < m; iy++)
          for (int ix = 0; ix < m; ix++) {
            double p[3] = {(ix + 0.5) * d, (iy + 0.5) * d, (iz + 0.5) * d};
            double v = cd_wnoise(t->data, n, dim, p);
            vol += v * v;
          }
      for (int iy = 0; iy < m; iy++)
        for (int ix = 0; ix < m; ix++) {
          double p[3] = {(ix + 0.5) * d, (iy + 0.5) * d, z};
          double v = cd_wnoise(t->data, n, dim, p);
          sl += v * v;
          s1 += v;
        }
      vol /= (double)m * m * planes;
      sl /= (double)m * m;
      double got = nl_wavelet_tile_variance(t, per);
      double slv = nl_wavelet_slice_variance(t, z, per, &mean);
      worst = fmax(worst, fabs(got - vol) / vol);
      worst = fmax(worst, fabs(slv - sl) / sl);
      worst = fmax(worst, fabs(mean - s1 / ((double)m * m)) / sqrt(sl));
      /* multiband, 3 bands of weight 1 on the slice grid: sum_b N(2^-b p) */
      double mb = 0;
      for (int iy = 0; iy < m; iy++)
        for (int ix = 0; ix < m; ix++) {
          double v = 0;
          for (int b = 0; b < 3; b++) {
            double s = ldexp(1.0, -b);
            double p[3] = {(ix + 0.5) * d * s, (iy + 0.5) * d * s, z * s};
            v += cd_wnoise(t->data, n, dim, p);
          }
          mb += v * v;
        }
      mb /= (double)m * m * 3;
      double got_mb = nl_wavelet_multiband_variance(t, 3, z, per);
      worst = fmax(worst, fabs(got_mb - mb) / mb);
    }
    static const double fracs[] = {0.0, 0.5, 0.25, -0.75};
    for (int f = 0; f < 4; f++) {
      double lat = 0;
      int planes = dim == 3 ? n : 1;
      for (int iz = 0; iz < planes; iz++)
        for (int iy = 0; iy < n; iy++)
          for (int ix = 0; ix < n; ix++) {
            double p[3] = {ix + fracs[f], iy + fracs[f], iz + fracs[f]};
            double v = cd_wnoise(t->data, n, dim, p);
            lat += v * v;
          }
      lat /= (double)n * n * planes;
      worst = fmax(worst, fabs(nl_wavelet_lattice_variance(t, fracs[f]) - lat) / lat);
    }
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, nl_seed_stream(5, "wavelet.points", 0));
    double pt = 0;
    for (int k = 0; k < 4000; k++) {
      double p[3] = {n * gsl_rng_uniform(rng), n * gsl_rng_uniform(rng), n * gsl_rng_uniform(rng)};
      if (dim == 2)
        p[2] = 0;
      double v = cd_wnoise(t->data, n, dim, p);
      pt += v * v;
    }
    gsl_rng_free(rng);
    pt /= 4000;
    worst = fmax(worst, fabs(nl_wavelet_point_variance(t, 4000, 5) - pt) / pt);
    nl_wavelet_tile_free(t);
  }
  printf("  variance readings: max relative |ours - mean of WNoise^2| %.3g\n", worst);
  NL_CHECK(worst <= 1e-13);
}

int main(void) { return nl_test_run(); }
