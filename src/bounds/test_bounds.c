#include "bounds/nl_bounds.h"
#include "nl_test.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void random_point(gsl_rng *r, double *xyz)
{
  for (int a = 0; a < 3; a++) xyz[a] = 200.0 * gsl_rng_uniform(r) - 100.0;
}

NL_TEST(series_values)
{
  NL_CHECK(nl_bounds_octave(0) == 1.0 && nl_bounds_octave(3) == 0.125);
  NL_CHECK(nl_bounds_series(0) == 1.0 && nl_bounds_series(1) == 1.5);
  NL_CHECK(nl_bounds_series(3) == 1.875);
  NL_CHECK(nl_bounds_fractal(0) == 0.0 && nl_bounds_fractal(1) == 1.0);
  NL_CHECK(nl_bounds_fractal(4) == 1.875);
  /* S_n equals the sum of the octave bounds 2^-i, i = 0..n (eq. 4.2). */
  double s = 0;
  for (int i = 0; i <= 20; i++) { s += nl_bounds_octave(i); NL_CHECK(s == nl_bounds_series(i)); }
  nl_noise_octaves o = nl_noise_octaves_fractal(5);
  double rem[6];
  nl_bounds_remainders(&o, 1.0, rem);
  for (int k = 0; k <= 5; k++)
    NL_CHECK_NEAR(rem[k], nl_bounds_fractal(5) - nl_bounds_fractal(k), 1e-15);
  NL_CHECK_NEAR(rem[0], nl_noise_octaves_bound(&o, 1.0), 1e-15);
}

/* 20000 random points, 1..12 octaves: the fractal bound (eq. 4.2) with the
 * basis bound of improved noise, and every incremental interval (eq. 5.4),
 * contain the full sum. */
NL_TEST(random_sums_stay_within_bounds)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 7);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 11);
  long violations = 0, checks = 0;
  double max_noise = 0;
  for (int it = 0; it < 20000; it++) {
    double xyz[3];
    random_point(r, xyz);
    int n = 1 + (int)gsl_rng_uniform_int(r, 12);
    nl_noise_octaves o = nl_noise_octaves_fractal(n);
    double rem[NL_MAX_OCTAVES + 1], partial[NL_MAX_OCTAVES + 1] = {0};
    nl_bounds_remainders(&o, NL_NOISE3_BOUND, rem);
    for (int l = 0; l < n; l++) {
      double f = o.freq[l], v = nl_noise_perm3_eval(&p, f * xyz[0], f * xyz[1], f * xyz[2]);
      if (fabs(v) > max_noise) max_noise = fabs(v);
      partial[l + 1] = partial[l] + o.amp[l] * v;
    }
    double full = partial[n];
    violations += fabs(full) > NL_NOISE3_BOUND * nl_bounds_fractal(n);
    for (int k = 0; k <= n; k++, checks++) {
      nl_bounds_interval iv = nl_bounds_incremental(partial[k], rem[k]);
      violations += !(iv.lo <= full && full <= iv.hi);
    }
  }
  NL_CHECK(violations == 0);
  NL_CHECK(checks > 100000);
  NL_CHECK(max_noise <= NL_NOISE3_BOUND);
  NL_CHECK(max_noise > 0.8);   /* the sample reaches near the extremes */
  gsl_rng_free(r);
}

/* Incremental and plain evaluation of CLAMP(base + Fnoise) agree bit for
 * bit, and the incremental one skips terms somewhere. */
NL_TEST(incremental_clamp_equals_plain)
{
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, 3);
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 5);
  nl_noise_octaves o = nl_noise_octaves_fractal(8);
  double rem[NL_MAX_OCTAVES + 1];
  nl_bounds_remainders(&o, NL_NOISE3_BOUND, rem);
  long diff = 0, tp = 0, ti = 0;
  for (int it = 0; it < 20000; it++) {
    double xyz[3], base = 6.0 * gsl_rng_uniform(r) - 2.5;
    random_point(r, xyz);
    int a, b;
    double vp = nl_bounds_clamped_fractal(&p, &o, rem, base, xyz, 0, &a, NULL);
    double vi = nl_bounds_clamped_fractal(&p, &o, rem, base, xyz, 1, &b, NULL);
    diff += vp != vi;
    tp += a; ti += b;
    NL_CHECK(a == 8 && b <= 8);
  }
  NL_CHECK(diff == 0);
  NL_CHECK(ti < tp / 2);
  gsl_rng_free(r);
}

/* A small smoke ball (the paper's settings otherwise) on the table of seed 1. */
static nl_bounds_smoke small_smoke(nl_noise_perm3 *p, int size, int octaves)
{
  nl_noise_perm3_seed(p, 1);
  nl_bounds_smoke s = nl_bounds_smoke_default();
  s.width = s.height = size;
  s.octaves = octaves;
  return s;
}

NL_TEST(smoke_bounded_equals_plain)
{
  nl_noise_perm3 p;
  nl_bounds_smoke s = small_smoke(&p, 24, 6);
  double *a = malloc(24 * 24 * sizeof *a), *b = malloc(24 * 24 * sizeof *b);
  nl_bounds_smoke_stats sa, sb;
  NL_CHECK(nl_bounds_smoke_render(&p, &s, a, &sa, NULL) == NL_OK);
  s.incremental = 1;
  NL_CHECK(nl_bounds_smoke_render(&p, &s, b, &sb, NULL) == NL_OK);
  double worst = 0, sum = 0;
  for (int k = 0; k < 24 * 24; k++) { worst = fmax(worst, fabs(a[k] - b[k])); sum += a[k]; }
  NL_CHECK(worst == 0.0);
  NL_CHECK(sum > 10.0);                      /* the ball is visible */
  NL_CHECK(sa.samples == sb.samples);
  NL_CHECK(sb.noise_evals < sa.noise_evals / 2);
  NL_CHECK(sa.noise_evals == 6 * sa.samples);
  s.slope = 1.0;
  NL_CHECK(nl_bounds_smoke_render(&p, &s, b, &sb, NULL) == NL_EINVAL);
  free(a); free(b);
}

/* The march ray by ray: one sample at a time through
 * nl_bounds_clamped_fractal, for the bit-identity check below. */
static void reference_render(const nl_noise_perm3 *p, const nl_bounds_smoke *s, double *img,
                             nl_bounds_smoke_stats *st)
{
  nl_noise_octaves o = nl_noise_octaves_fractal(s->octaves);
  for (int l = 0; l < o.n; l++) o.freq[l] *= s->freq;
  double rem[NL_MAX_OCTAVES + 1];
  nl_bounds_remainders(&o, s->octave_bound, rem);
  memset(st, 0, sizeof *st);
  long nsteps = (long)floor(1.0 / s->step);
  for (int r = 0; r < s->height; r++)
    for (int c = 0; c < s->width; c++) {
      double trans = 1.0, colour = 0.0, stop = 1.0 - s->stop_opacity;
      for (long i = 0; i <= nsteps && trans > stop; i++) {
        double xyz[3] = {-0.5 + (c + 0.5) / s->width, -0.5 + (r + 0.5) / s->height,
                         -0.5 + (double)i * s->step};
        double d = sqrt(xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]);
        int terms;
        double dens = nl_bounds_clamped_fractal(p, &o, rem, s->slope * d + 1.0, xyz, s->incremental,
                                                &terms, &st->max_abs_noise);
        st->samples++;
        st->noise_evals += terms;
        double t1 = trans * exp(-s->kappa * dens * s->step);
        colour += trans - t1;
        trans = t1;
      }
      img[(size_t)r * s->width + c] = colour;
    }
}

/* The batched march (blocks of rays, octaves through the point kernel)
 * gives the bits and counts of the ray-by-ray one: both modes, a size that
 * leaves a partial block, N = 0 (no noise), a unit bound that decides
 * early, stop opacities 0 and 1, and every SIMD level this CPU has. */
NL_TEST(smoke_batched_equals_ray_by_ray)
{
  nl_noise_perm3 p;
  nl_bounds_smoke s = small_smoke(&p, 8, 6);
  s.width = 37; s.height = 23;
  s.slope = -5; s.freq = 2; s.kappa = 120;
  size_t npix = (size_t)s.width * s.height;
  double *a = malloc(npix * sizeof *a), *b = malloc(npix * sizeof *b);
  const struct { int octaves; double bound, stop, kappa; } v[] = {
    {6, NL_NOISE3_BOUND, 0.99, 120}, {0, NL_NOISE3_BOUND, 0.99, 120}, {11, 1.0, 0.99, 120},
    {3, NL_NOISE3_BOUND, 1.0, 30}, {3, NL_NOISE3_BOUND, 0.0, 30}, {11, NL_NOISE3_BOUND, 0.999, 0}};
  int level0 = nl_noise_simd_get(), compared = 0;
  for (int L = NL_NOISE_SIMD_SCALAR; L <= NL_NOISE_SIMD_AVX512; L++) {
    if (!nl_noise_simd_supported(L)) continue;
    NL_CHECK(nl_noise_simd_set(L) == 0);
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
      for (int inc = 0; inc < 2; inc++) {
        nl_bounds_smoke c = s;
        c.octaves = v[k].octaves;
        c.octave_bound = v[k].bound;
        c.stop_opacity = v[k].stop;
        c.kappa = v[k].kappa;
        c.incremental = inc;
        nl_bounds_smoke_stats sa, sb;
        reference_render(&p, &c, a, &sa);
        NL_CHECK(nl_bounds_smoke_render(&p, &c, b, &sb, NULL) == NL_OK);
        NL_CHECK(memcmp(a, b, npix * sizeof *a) == 0);
        NL_CHECK(sa.samples == sb.samples && sa.noise_evals == sb.noise_evals);
        NL_CHECK(memcmp(&sa.max_abs_noise, &sb.max_abs_noise, sizeof sa.max_abs_noise) == 0);
        compared++;
      }
  }
  nl_noise_simd_set(level0);
  NL_CHECK(compared >= 12);
  free(a); free(b);
}

NL_TEST(decision_map_range)
{
  nl_noise_perm3 p;
  nl_bounds_smoke s = small_smoke(&p, 32, 5);
  int t[32 * 32], seen[7] = {0};
  NL_CHECK(nl_bounds_smoke_decision_map(&p, &s, 0.0, t, NULL) == NL_OK);
  for (int k = 0; k < 32 * 32; k++) {
    NL_CHECK(t[k] >= 0 && t[k] <= 6);
    if (t[k] >= 0 && t[k] <= 6) seen[t[k]] = 1;
  }
  /* the rim is never decided; far from it a few octaves decide */
  NL_CHECK(seen[6] && (seen[1] || seen[2] || seen[3]));
}

/* Parseval (eq. 4.4) and the bandwidth of a pure sinusoid at bin 37. */
NL_TEST(psd_and_bandwidth)
{
  size_t n = 1024;
  double rate = 8.0, *x = malloc(n * sizeof *x), f[513], P[513], g[513];
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  double ms = 0;
  for (size_t k = 0; k < n; k++) { x[k] = gsl_rng_uniform(r) - 0.3; ms += x[k] * x[k]; }
  NL_CHECK(nl_spectrum_psd1(x, n, rate, f, P, NULL) == NL_OK);
  double s = 0;
  for (int k = 0; k < 513; k++) s += P[k];
  NL_CHECK_NEAR(s, ms / n, 1e-12);
  nl_bounds_psd1_tail(P, 513, g);
  NL_CHECK_NEAR(g[0], s, 1e-12);
  for (size_t k = 0; k < n; k++) x[k] = 0.25 + 0.5 * sin(NL_TWO_PI * 37.0 * k / n);
  nl_bounds_bandwidth bw;
  NL_CHECK(nl_bounds_bandwidth_1d(x, n, rate, NL_BOUNDS_T, &bw, NULL) == NL_OK);
  NL_CHECK_NEAR(bw.resolution, rate / n, 0);
  NL_CHECK_NEAR(bw.f_sup, 38 * rate / n, 1e-12);
  NL_CHECK_NEAR(bw.f_inf, 38 * rate / n, 1e-12);
  NL_CHECK_NEAR(bw.sigma, 0.5 / sqrt(2.0), 1e-12);
  NL_CHECK_NEAR(bw.mean, 0.25, 1e-12);
  double frac;
  NL_CHECK(nl_bounds_psd1_fraction_above(x, n, rate, 0.2, &frac, NULL) == NL_OK);
  NL_CHECK_NEAR(frac, 1.0, 1e-12);
  NL_CHECK(nl_bounds_psd1_fraction_above(x, n, rate, 0.3, &frac, NULL) == NL_OK);
  NL_CHECK_NEAR(frac, 0.0, 1e-12);
  NL_CHECK(nl_bounds_bandwidth_1d(x, n, rate, 0.0, &bw, NULL) == NL_EINVAL);
  /* The estimator's readings: all 0 is the plain call's bits; each one
   * moves the band as its definition says, on the 37-cycle sine (bin 37,
   * whose band starts one bin up, at the first bin below T). */
  nl_bounds_bandwidth b0, b1;
  nl_bounds_bandwidth_options o = {0};
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b0, NULL) == NL_OK);
  NL_CHECK(memcmp(&b0, &bw, sizeof bw) == 0);
  o.radians = 1;
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b1, NULL) == NL_OK);
  NL_CHECK_NEAR(b1.f_sup, 2 * M_PI * b0.f_sup, 1e-12);
  o = (nl_bounds_bandwidth_options){.bin_edge = 1};
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b1, NULL) == NL_OK);
  NL_CHECK_NEAR(b1.f_sup, b0.f_sup - 0.5 * rate / n, 1e-12);
  o = (nl_bounds_bandwidth_options){.sigma_rms = 1};
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b1, NULL) == NL_OK);
  NL_CHECK(b1.f_inf <= b0.f_inf && b1.f_sup == b0.f_sup);   /* a larger sigma: F_inf no higher */
  o = (nl_bounds_bandwidth_options){.no_dc = 1};
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b1, NULL) == NL_OK);
  NL_CHECK(b1.f_inf_rms >= b0.f_inf_rms);   /* less energy in Gamma: F_inf_rms no lower */
  o = (nl_bounds_bandwidth_options){.two_sided = 1, .window = NL_SPECTRUM_HANN};
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, NL_BOUNDS_T, &o, &b1, NULL) == NL_OK);
  NL_CHECK(b1.f_sup >= 37 * rate / n && b1.f_sup <= 40 * rate / n);
  NL_CHECK(nl_bounds_bandwidth_1d_with(x, n, rate, 0.0, &o, &b1, NULL) == NL_EINVAL);
  /* the moments are the bandwidth's own bits */
  double mean, sigma;
  nl_bounds_moments(x, n, &mean, &sigma);
  NL_CHECK(mean == bw.mean && sigma == bw.sigma);
  gsl_rng_free(r);
  free(x);
}

int main(void) { return nl_test_run(); }
