#include "noise/nl_noise.h"
#include "noise/nl_noise_alt.h"
#include "nl_test.h"

#include "base/nl_base.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#define GOLDEN_GRAD2 0xb07943882cc7837fULL
#define GOLDEN_IMPROVED3 0x9d5884b94449e989ULL

/* The 2D table (M = 512; caller frees) and the 3D permutation of one seed:
 * most tests check both bases side by side. */
static nl_noise_grad2 *both_tables(unsigned long seed, nl_noise_perm3 *p)
{
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(t, seed);
  nl_noise_perm3_seed(p, seed);
  return t;
}

/* The 3D gradient-table noise written the plain way, as the oracle for
 * nl_noise_grad3: floor() from libm, the mod by a loop, each corner's
 * weight and dot product taken on their own, corners summed in a fixed
 * order. Only the order of the roundings differs from the library's. */
static size_t naive_grad3_index(const nl_noise_grad3 *t, long i, long j, long k)
{
  long m = (long)t->m, c[3] = {i, j, k}, h = 0;
  for (int a = 0; a < 3; a++) {
    long e = c[a] % m;
    while (e < 0) e += m;
    h = (long)t->perm[(h + e) % m];   /* P[i], then P[(h + j) mod m], then with k */
  }
  return (size_t)h;
}

static double naive_grad3(const nl_noise_grad3 *t, double x, double y, double z)
{
  double p[3] = {x, y, z}, sum = 0;
  double cell[3] = {floor(x), floor(y), floor(z)};
  for (int di = 0; di <= 1; di++)
    for (int dj = 0; dj <= 1; dj++)
      for (int dk = 0; dk <= 1; dk++) {
        double c[3] = {cell[0] + di, cell[1] + dj, cell[2] + dk}, w = 1, dot = 0;
        const double *g = t->v + 3 * naive_grad3_index(t, (long)c[0], (long)c[1], (long)c[2]);
        for (int a = 0; a < 3; a++) {
          double d = p[a] - c[a], u = fabs(d);   /* |d| <= 1 */
          w *= 1 - (6 * pow(u, 5) - 15 * pow(u, 4) + 10 * pow(u, 3));
          dot += d * g[a];
        }
        sum += w * dot;
      }
  return sum;
}

/* A coordinate for the grad3 test: mostly uniform on [-300, 300], else on a
 * lattice plane, one ulp either side of one, or -0. */
static double grad3_coordinate(gsl_rng *r)
{
  double u = gsl_rng_uniform(r), x = 600 * gsl_rng_uniform(r) - 300, i = floor(x);
  if (u < 0.1) return i;
  if (u < 0.2) return nextafter(i, -INFINITY);
  if (u < 0.3) return nextafter(i, INFINITY);
  if (u < 0.32) return -0.0;
  return x;
}

NL_TEST(grad3_matches_a_naive_implementation)
{
  /* m = 512 (C8's, a power of two) and 500 (mod by division). */
  size_t sizes[2] = {512, 500};
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  for (int s = 0; s < 2; s++) {
    nl_noise_grad3 *t = nl_noise_grad3_alloc(sizes[s]);
    nl_noise_grad3_seed(t, 17 + (unsigned long)s);
    double worst = 0, top = 0;
    int corners_exact = 1;
    for (int n = 0; n < 100000; n++) {
      double x = grad3_coordinate(r), y = grad3_coordinate(r), z = grad3_coordinate(r);
      double v = nl_noise_grad3_eval(t, x, y, z);
      worst = fmax(worst, fabs(v - naive_grad3(t, x, y, z)));
      top = fmax(top, fabs(v));
      /* eval is the corners' linear form, to the bit. */
      uint32_t e[8];
      double w[24], sum = 0;
      nl_noise_grad3_corners(t, x, y, z, 1.0, e, w);
      for (int q = 0; q < 8; q++) {
        const double *g = t->v + 3 * e[q];
        sum += w[3 * q] * g[0] + w[3 * q + 1] * g[1] + w[3 * q + 2] * g[2];
      }
      corners_exact &= sum == v;
    }
    printf("  m = %zu: max |ours - naive| over 1e5 points %.3g, max |noise| %.4f\n", sizes[s],
           worst, top);
    NL_CHECK(worst <= 1e-14);   /* values below 0.87, a few dozen roundings apart */
    NL_CHECK(corners_exact);
    NL_CHECK(top <= NL_NOISE_GRAD3_BOUND);
    /* 0 at lattice points, negative ones included. */
    NL_CHECK(nl_noise_grad3_eval(t, -3, 7, -129) == 0 && nl_noise_grad3_eval(t, 0, 0, 0) == 0);
    /* Indices wrap with period m in each coordinate, on both sides of 0. */
    long m = (long)sizes[s];
    NL_CHECK(nl_noise_grad3_index(t, -1, -2, -3) == nl_noise_grad3_index(t, m - 1, m - 2, m - 3));
    /* Every entry is a unit vector with its z and phi in step. */
    double unit = 0, angles = 0;
    for (size_t k = 0; k < t->m; k++) {
      const double *g = t->v + 3 * k;
      unit = fmax(unit, fabs(sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) - 1));
      double ph = atan2(g[1], g[0]);
      angles = fmax(angles, fabs(g[2] - t->z[k]));
      angles = fmax(angles, fabs(fabs(remainder(ph - t->phi[k], NL_TWO_PI))));
    }
    NL_CHECK(unit <= 1e-15 && angles <= 1e-15);
    nl_noise_grad3_free(t);
  }
  gsl_rng_free(r);
}

NL_TEST(rows_equal_points_bit_for_bit)
{
  nl_noise_perm3 p;
  nl_noise_grad2 *t = both_tables(7, &p);
  double row[1000], row3[1000];
  double dxs[] = {0.0137, -0.29, 3.7, 1e-4};   /* dense, negative, sparse, tiny */
  for (int d = 0; d < 4; d++) {
    nl_noise_grad2_row(t, -3.3, dxs[d], 5.71, 1000, row);
    nl_noise_perm3_row(&p, -3.3, dxs[d], 5.71, -2.2, 1000, row3);
    int same = 1;
    for (int k = 0; k < 1000; k++) {
      double x = -3.3 + (double)k * dxs[d];
      same &= row[k] == nl_noise_grad2_eval(t, x, 5.71) && row3[k] == nl_noise_perm3_eval(&p, x, 5.71, -2.2);
    }
    NL_CHECK(same);
  }
  nl_noise_grad2_free(t);
}

NL_TEST(zero_at_lattice_points)
{
  nl_noise_perm3 p;
  nl_noise_grad2 *t = both_tables(1, &p);
  double worst = 0;
  for (int i = -40; i < 40; i++)
    for (int j = -40; j < 40; j++)
      worst = fmax(worst, fmax(fabs(nl_noise_grad2_eval(t, i, j)), fabs(nl_noise_perm3_eval(&p, i, j, i - j))));
  NL_CHECK(worst == 0);
  nl_noise_grad2_free(t);
}

NL_TEST(continuous_across_cell_borders)
{
  /* The noise is C2 with gradients bounded by a few units, so values
   * either side of a border 2e-9 apart differ by well under 1e-7. */
  nl_noise_perm3 p;
  nl_noise_grad2 *t = both_tables(2, &p);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  double worst = 0, e = 1e-9;
  for (int k = 0; k < 20000; k++) {
    double i = (double)(int)(100 * gsl_rng_uniform(r)) - 50, y = 100 * gsl_rng_uniform(r) - 50;
    worst = fmax(worst, fabs(nl_noise_grad2_eval(t, i - e, y) - nl_noise_grad2_eval(t, i + e, y)));
    worst = fmax(worst, fabs(nl_noise_grad2_eval(t, y, i - e) - nl_noise_grad2_eval(t, y, i + e)));
    worst = fmax(worst, fabs(nl_noise_perm3_eval(&p, i - e, y, 0.3) - nl_noise_perm3_eval(&p, i + e, y, 0.3)));
    worst = fmax(worst, fabs(nl_noise_perm3_eval(&p, y, 0.3, i - e) - nl_noise_perm3_eval(&p, y, 0.3, i + e)));
  }
  NL_CHECK(worst < 1e-7);
  gsl_rng_free(r);
  nl_noise_grad2_free(t);
}

NL_TEST(values_within_analytic_bounds)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  double m2 = 0, m3 = 0, mf = 0, mt = 0;
  nl_noise_grad2 *t = nl_noise_grad2_alloc(512);
  nl_noise_perm3 p;
  for (unsigned long s = 1; s <= 20; s++) {
    nl_noise_grad2_seed(t, s);
    nl_noise_perm3_seed(&p, s);
    for (int k = 0; k < 20000; k++) {
      double x = 100 * gsl_rng_uniform(r), y = 100 * gsl_rng_uniform(r), z = 100 * gsl_rng_uniform(r);
      m2 = fmax(m2, fabs(nl_noise_grad2_eval(t, x, y)));
      m3 = fmax(m3, fabs(nl_noise_perm3_eval(&p, x, y, z)));
    }
    nl_noise_basis b = nl_noise_basis_perm3(&p);
    nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.9, 2.0), tu = nl_noise_octaves_fractal(6);
    tu.turbulence = 1;
    double row[512], scratch[512];
    for (int k = 0; k < 20; k++) {
      nl_noise_fractal_row(&b, &o, 17.3 * k, 0.031, 3.1 * k, 0.5, 512, row, scratch);
      for (int q = 0; q < 512; q++) mf = fmax(mf, fabs(row[q]) / nl_noise_octaves_bound(&o, b.bound));
      nl_noise_fractal_row(&b, &tu, 17.3 * k, 0.031, 3.1 * k, 0.5, 512, row, scratch);
      for (int q = 0; q < 512; q++) { mt = fmax(mt, row[q] / nl_noise_octaves_bound(&tu, b.bound)); NL_CHECK(row[q] >= 0); }
    }
  }
  printf("  max |noise2| %.4f (bound %.4f), |noise3| %.4f (bound %.4f), fbm %.3f, turbulence %.3f of bound\n",
         m2, NL_NOISE2_BOUND, m3, NL_NOISE3_BOUND, mf, mt);
  NL_CHECK(m2 <= NL_NOISE2_BOUND && m2 > 0.5);
  NL_CHECK(m3 <= NL_NOISE3_BOUND && m3 > 0.8);
  NL_CHECK(mf <= 1 && mt <= 1);
  gsl_rng_free(r);
  nl_noise_grad2_free(t);
}

NL_TEST(same_seed_same_noise)
{
  nl_noise_grad2 *a = nl_noise_grad2_alloc(512), *b = nl_noise_grad2_alloc(512);
  nl_noise_grad2_seed(a, 42);
  nl_noise_grad2_seed(b, 42);
  int same = 1;
  for (size_t k = 0; k < 512; k++) same &= a->angle[k] == b->angle[k] && a->perm[k] == b->perm[k];
  NL_CHECK(same);
  nl_noise_grad2_seed(b, 43);
  NL_CHECK(nl_noise_grad2_eval(a, 0.5, 0.5) != nl_noise_grad2_eval(b, 0.5, 0.5));
  /* Pins the seeding of the 2D table: MT19937 seeded with nl_seed_stream(42, "noise.grad2", 0)
   * (the seed rule, nl_base.h) draws the angles
   * in order, then gsl_ran_shuffle draws the permutation. The value is the one
   * the code gives (printed with %.17g); it moves if the generator, the order of
   * the draws, the shuffle or the seed derivation of nl_noise_grad2_seed changes, and
   * then every committed result made from a table moves too. The 1e-15 is the
   * rounding of the few operations of one noise2 evaluation, far below what any
   * other table would give. */
  double v = nl_noise_grad2_eval(a, 0.3, 0.7);
  printf("  seed 42: noise2(0.3, 0.7) = %.17g\n", v);
  NL_CHECK_NEAR(v, 0.37208493179103724, 1e-15);
  /* the draws themselves, exactly: first and last angle (2 pi U), the shuffle */
  NL_CHECK(a->angle[0] == 5.7728308809606483 && a->angle[511] == 4.8973434909738742);
  NL_CHECK(a->perm[0] == 291 && a->perm[1] == 36 && a->perm[2] == 328 && a->perm[511] == 396);
  nl_noise_grad2_free(a); nl_noise_grad2_free(b);
}

NL_TEST(index_hash_is_cheng_eq_3_1)
{
  nl_noise_grad2 *t = nl_noise_grad2_alloc(16);
  nl_noise_grad2_seed(t, 3);
  for (long i = -20; i < 20; i++)
    for (long j = -20; j < 20; j++) {
      long im = ((i % 16) + 16) % 16, jm = ((j % 16) + 16) % 16;
      NL_CHECK(nl_noise_grad2_index(t, i, j) == t->perm[(t->perm[im] + jm) % 16]);
    }
  nl_noise_grad2_free(t);
}

NL_TEST(octave_builders)
{
  nl_noise_octaves c = nl_noise_octaves_cheng(4, 8, 4);
  NL_CHECK(c.n == 4 && c.freq[0] == 8 && c.freq[3] == 64 && c.amp[0] == 0.25 && c.amp[3] == 1.0 / 32);
  nl_noise_octaves f = nl_noise_octaves_fbm(6, 0.5, 2);
  NL_CHECK_NEAR(nl_noise_octaves_bound(&f, 1.0), 2 - 1.0 / 32, 1e-15);   /* S_n = 2 - 2^(1-n) */
  NL_CHECK(nl_noise_octaves_fbm(99, 1, 1).n == NL_MAX_OCTAVES);
}

/* Lattice coordinates a long cannot hold (fbm --octaves 30 --lacunarity 10
 * reached 4e29, 13.4): defined results, no signed overflow (the sanitizer
 * build checks), finite where the input is finite, NaN where it is not. */
NL_TEST(huge_coordinates_are_safe)
{
  nl_noise_perm3 p;
  nl_noise_grad2 *t = both_tables(3, &p);
  const double xs[] = {1e30, -1e30, 0x1p62, -0x1p63, 0x1p52 + 0.5, 1e308, -1e308, 4503599627370497.0};
  for (size_t k = 0; k < sizeof xs / sizeof *xs; k++) {
    double a = nl_noise_grad2_eval(t, xs[k], 0.25), b = nl_noise_perm3_eval(&p, 0.5, xs[k], xs[k]);
    NL_CHECK(isfinite(a) && isfinite(b));
    double row[8];
    nl_noise_grad2_row(t, xs[k], 0.1, xs[k], 8, row);
    for (int i = 0; i < 8; i++) NL_CHECK(isfinite(row[i]));
    nl_noise_perm3_row(&p, xs[k], xs[k] * 1e-3, 0.5, xs[k], 8, row);
    for (int i = 0; i < 8; i++) NL_CHECK(isfinite(row[i]));
  }
  NL_CHECK(isnan(nl_noise_grad2_eval(t, NAN, 0.5)) && isnan(nl_noise_perm3_eval(&p, 0.5, INFINITY, 0.5)));
  /* Integers beyond 2^53 are lattice points: the noise there is 0. */
  NL_CHECK(nl_noise_grad2_eval(t, 1e20, 3e21) == 0.0 && nl_noise_perm3_eval(&p, 1e20, -1e25, 0x1p70) == 0.0);
  nl_noise_grad2_free(t);
}

int main(void) { return nl_test_run(); }

/* FNV-1a over the bits of a raster. */
static unsigned long long bits_hash(const double *v, size_t n)
{
  unsigned long long h = 1469598103934665603ULL;
  const unsigned char *b = (const unsigned char *)v;
  for (size_t k = 0; k < n * sizeof *v; k++) { h ^= b[k]; h *= 1099511628211ULL; }
  return h;
}

NL_TEST(golden_rasters_are_bit_identical_across_builds)
{
  /* Recorded from the release (-O3) build; the test suite also runs at -O0
   * under the sanitizers, so passing there proves the same seed gives the
   * same bits at both optimisation levels. A change of these hashes is a
   * change of every committed result: update them only on purpose. */
  nl_noise_perm3 p;
  nl_noise_grad2 *t = both_tables(5, &p);
  nl_noise_basis b2 = nl_noise_basis_grad2(t), b3 = nl_noise_basis_perm3(&p);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2.0);
  nl_noise_window w = {-1.3, 0.7, 0.25, 3.0, 64, 64};
  double v[64 * 64];
  nl_noise_fractal_grid(&b2, &o, &w, v);
  unsigned long long h2 = bits_hash(v, 64 * 64);
  nl_noise_fractal_grid(&b3, &o, &w, v);
  unsigned long long h3 = bits_hash(v, 64 * 64);
  printf("  hashes: grad2 %#llx, improved3 %#llx\n", h2, h3);
  NL_CHECK(h2 == GOLDEN_GRAD2);
  NL_CHECK(h3 == GOLDEN_IMPROVED3);
  nl_noise_grad2_free(t);
}

NL_TEST(alternative_noises_of_a3)
{
  /* The table-driven improved noise is nl_noise_perm3_eval up to rounding;
   * every variant is 0 at lattice points (gradient noise) and the 1985
   * gradients are unit vectors; RGBA8 gradients and float32 move the
   * improved noise by about a byte (1/255 per zero component). */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 9);
  nl_noise_alt imp, cub, cla, l1, gpu;
  nl_noise_alt_improved(&imp, &p, 1);
  nl_noise_alt_improved(&cub, &p, 0);
  nl_noise_alt_classic(&cla, &p, 9);
  nl_noise_alt_line1(&l1, &p, 9, 0);
  gpu = imp;
  nl_noise_alt_gpu8(&gpu);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  double worst = 0.0, gpu_diff = 0.0, cub_diff = 0.0;
  for (int k = 0; k < 2000; k++) {
    double x = 600 * gsl_rng_uniform(r) - 300, y = 600 * gsl_rng_uniform(r) - 300, z = 20 * gsl_rng_uniform(r);
    worst = fmax(worst, fabs(nl_noise_alt_eval(&imp, x, y, z) - nl_noise_perm3_eval(&p, x, y, z)));
    gpu_diff = fmax(gpu_diff, fabs(nl_noise_alt_eval(&gpu, x, y, z) - nl_noise_alt_eval(&imp, x, y, z)));
    cub_diff = fmax(cub_diff, fabs(nl_noise_alt_eval(&cub, x, y, z) - nl_noise_alt_eval(&imp, x, y, z)));
    NL_CHECK(fabs(nl_noise_alt_eval(&l1, x, y, z)) <= 0.5);   /* |g t| + ... <= 1/2 at the cell centre */
  }
  NL_CHECK(worst <= 1e-13);
  NL_CHECK(gpu_diff > 1e-4 && gpu_diff < 0.02);
  NL_CHECK(cub_diff > 0.01);
  for (int h = 0; h < 256; h++)
    NL_CHECK_NEAR(sqrt(cla.g[h][0] * cla.g[h][0] + cla.g[h][1] * cla.g[h][1] + cla.g[h][2] * cla.g[h][2]), 1.0, 1e-12);
  NL_CHECK(nl_noise_alt_eval(&cla, 3, -4, 5) == 0.0 && nl_noise_alt_eval(&l1, -7, 0.3, 0.1) == 0.0);
  NL_CHECK(nl_noise_alt_eval(&l1, 2.5, 0, 0) == nl_noise_alt_eval(&l1, 258.5, 9, 1));   /* 256-periodic in x */
  gsl_rng_free(r);
}

NL_TEST(simplex_noises_of_a3)
{
  /* Gustavson's kernel with r2 = 0.5 is continuous; with the published
   * r2 = 0.6 (3D) the value jumps where a corner leaves the simplex: the
   * largest step between samples 1e-5 apart along a line is a jump, not a
   * slope. Both vanish at lattice vertices (integer skewed coordinates). */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 4);
  nl_noise_alt s6, s5, s2;
  nl_noise_alt_simplex(&s6, &p, 0.6);
  nl_noise_alt_simplex(&s5, &p, 0.5);
  nl_noise_alt_simplex2(&s2, &p);
  double step[3] = {0, 0, 0}, prev[3] = {0, 0, 0};
  for (long k = 0; k <= 1000000; k++) {   /* 10 units in steps of 1e-5 */
    double t = 0.3 + k * 1e-5, x = t * 0.809, y = 1.7 + t * 0.5, z = 2.9 + t * 0.309;
    double v[3] = {nl_noise_alt_eval(&s6, x, y, z), nl_noise_alt_eval(&s5, x, y, z), nl_noise_alt_eval(&s2, x, y, 0)};
    for (int q = 0; q < 3 && k > 0; q++) step[q] = fmax(step[q], fabs(v[q] - prev[q]));
    for (int q = 0; q < 3; q++) prev[q] = v[q];
  }
  printf("  largest step over 1e-5: r2 0.6 %g, r2 0.5 %g, 2D %g\n", step[0], step[1], step[2]);
  NL_CHECK(step[1] < 1e-4 && step[2] < 1e-4);
  NL_CHECK(step[0] > 30 * step[1]);   /* measured: 0.0033 against 2.5e-5 */
  NL_CHECK(nl_noise_alt_eval(&s5, 0, 0, 0) == 0.0 && nl_noise_alt_eval(&s2, 0, 0, 0) == 0.0);
}
