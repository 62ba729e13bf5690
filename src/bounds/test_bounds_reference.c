/* test_bounds_reference.c - Arnerin's smoke ball (Table 5.1, Fig. 5.1-5.3)
 * rendered by nl_bounds_smoke_render, plain and with incremental bounding,
 * against a naive ray marcher written here from nl_bounds.h's description
 * on Perlin's published noise (tests/reference/perlin_improved_noise.c):
 * per pixel centre (x, y) in [-1/2, 1/2]^2, samples at z_i = -1/2 + i h,
 * i = 0..floor(1/h), density CLAMP(a |p| + 1 + sum_l 2^-l noise(f0 2^l p))
 * with every term evaluated, T <- T exp(-kappa density h), colour += the
 * drop in T, stop once 1 - T reaches the stop opacity. No bounds, no
 * batches, no packing.
 *
 * Settings: 0, 1, 3, 6 and 11 octaves, slopes -2 to -6, f0 2 to 8, kappa
 * 0 to 120, steps 0.01 to 0.05, stop opacity 0.99, 1 and 0 (never, always):
 * 10 renders of 24 x 20 pixels, both modes (9,600 pixel values). The
 * library's octave bound is Perlin's NL_NOISE3_BOUND (the one that holds),
 * so the incremental render must give the plain render's values.
 *
 * Tolerance 1e-12 absolute on colours in [0, 1]: the noise differs from
 * Perlin's by at most 1e-15 (test_noise_reference.c), so a density by
 * 2e-15 times the octaves' amplitude sum; each of at most 100 steps
 * multiplies T by exp(-kappa d h) with kappa h <= 1.2: the colour moves by
 * less than 100 x 1.2 x 4e-15. A stop decided one step apart (T within
 * 1e-15 of the threshold) would show as O(kappa h); none occurred.
 * The sample counts must be equal. Measured: 7.8e-16.
 */
#include "bounds/nl_bounds.h"
#include "nl_test.h"
#include "reference/direct_dft.h"
#include "reference/perlin_improved_noise.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>

static double clamp01(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

static long naive_render(const nl_bounds_smoke *s, double *img)
{
  long samples = 0;
  long nsteps = (long)floor(1.0 / s->step);
  for (int r = 0; r < s->height; r++)
    for (int c = 0; c < s->width; c++) {
      double x = -0.5 + (c + 0.5) / s->width, y = -0.5 + (r + 0.5) / s->height;
      double T = 1, colour = 0;
      for (long i = 0; i <= nsteps && T > 1 - s->stop_opacity; i++) {
        double z = -0.5 + (double)i * s->step, sum = 0;
        for (int l = 0; l < s->octaves; l++) {
          double f = s->freq * ldexp(1.0, l);
          sum += ldexp(1.0, -l) * perlin_improved_noise(f * x, f * y, f * z);
        }
        double d = clamp01(s->slope * sqrt(x * x + y * y + z * z) + 1 + sum);
        double T1 = T * exp(-s->kappa * d * s->step);
        colour += T - T1;
        T = T1;
        samples++;
      }
      img[r * s->width + c] = colour;
    }
  return samples;
}

NL_TEST(smoke_matches_a_naive_ray_marcher)
{
  static const struct { int octaves; double slope, freq, kappa, step, stop; } v[] = {
    {0, -4, 4, 30, 0.01, 0.99}, {1, -4, 4, 30, 0.02, 0.99}, {3, -2, 2, 60, 0.01, 0.99},
    {6, -5, 8, 120, 0.01, 0.99}, {11, -4, 4, 30, 0.05, 0.99}, {6, -6, 3, 0, 0.02, 0.99},
    {3, -3, 4, 30, 0.01, 1.0}, {3, -3, 4, 30, 0.01, 0.0}, {11, -2.5, 5, 90, 0.03, 0.99},
    {6, -4, 4, 30, 0.013, 0.99}};
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  enum { W = 24, H = 20 };
  double got[W * H], want[W * H], worst = 0;
  long bad_counts = 0, values = 0;
  for (size_t k = 0; k < sizeof v / sizeof *v; k++) {
    nl_bounds_smoke s = nl_bounds_smoke_default();
    s.width = W;
    s.height = H;
    s.octaves = v[k].octaves;
    s.slope = v[k].slope;
    s.freq = v[k].freq;
    s.kappa = v[k].kappa;
    s.step = v[k].step;
    s.stop_opacity = v[k].stop;
    long samples = naive_render(&s, want);
    for (int inc = 0; inc <= 1; inc++) {
      s.incremental = inc;
      nl_bounds_smoke_stats st;
      NL_CHECK(nl_bounds_smoke_render(&p, &s, got, &st, NULL) == NL_OK);
      for (int q = 0; q < W * H; q++)
        worst = fmax(worst, fabs(got[q] - want[q]));
      bad_counts += st.samples != samples;
      values += W * H;
    }
  }
  printf("  %ld pixel values, max |ours - naive march| %.3g, sample counts differing: %ld\n",
         values, worst, bad_counts);
  NL_CHECK(worst <= 1e-12);
  NL_CHECK(bad_counts == 0);
}

/* Smallest index k with gamma[k] <= e (m - 1 if none), and how close the
 * decision came: min |gamma[j] - e| / e over j <= k (a near-tie when small). */
static size_t tail_index(const long double *gamma, size_t m, long double e, double *margin)
{
  *margin = INFINITY;
  for (size_t k = 0; k < m; k++) {
    if (e > 0)
      *margin = fmin(*margin, (double)(fabsl(gamma[k] - e) / e));
    if (gamma[k] <= e)
      return k;
  }
  return m - 1;
}

/* Arnerin's bandwidth [F_inf, F_sup] (sec. 5.2) of nl_bounds_bandwidth_1d
 * and nl_bounds_psd1_fraction_above, against the one-sided periodogram of
 * the direct DFT (long double), its tail sums and their inverse as
 * nl_bounds.h defines them, the sd over n. Signals: 200 lines of n = 16..256
 * samples (fractal sums of Perlin's noise along random lines with offsets,
 * white noise, sums of two cosines), rates 1..64, T the paper's (2/255)^2 or
 * 10^-4..10^-1. The three frequencies must be the same bins (a bin whose
 * tail sum lies within 1e-9 of the threshold is a near-tie and skipped,
 * counted); mean and sigma within 1e-13 relative; the fraction above a
 * random cut within 1e-12 (sums of powers of one FFT: its 1e-15 bound).
 * Measured: no bin differs, 1.1e-15, 2.8e-13 (n up to 512). */
NL_TEST(bandwidth_matches_the_dft_tails)
{
  gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(r, 2009);
  double x[512], worst = 0, worst_frac = 0;
  long double F[1024], gamma[257];
  long signals = 0, ties = 0, bad = 0;
  for (int t = 0; t < 200; t++) {
    size_t n = 16 + gsl_rng_uniform_int(r, 241), m = n / 2 + 1;
    double rate = 1 + 63 * gsl_rng_uniform(r), off = 2 * gsl_rng_uniform(r) - 1;
    double T = t % 2 ? NL_BOUNDS_T : pow(10, -1 - 3 * gsl_rng_uniform(r));
    double o[3] = {300 * gsl_rng_uniform(r), 300 * gsl_rng_uniform(r), 300 * gsl_rng_uniform(r)};
    double d[3] = {0.6, 0.48, 0.64};
    for (size_t k = 0; k < n; k++) {
      double s = (double)k / rate, v = 0;
      if (t % 3 == 0)
        for (int l = 0; l < 6; l++) {
          double f = ldexp(1.0, l);
          v += perlin_improved_noise(f * (o[0] + s * d[0]), f * (o[1] + s * d[1]),
                                     f * (o[2] + s * d[2])) / f;
        }
      else if (t % 3 == 1)
        v = gsl_rng_uniform(r) - 0.5;
      else
        v = cos(2 * M_PI * 3.3 * s) + 0.2 * cos(2 * M_PI * 0.1 * rate * k);
      x[k] = v + off;
    }
    direct_dft2(x, (int)n, 1, F);
    long double sum = 0;
    for (size_t k = m; k-- > 0;) {
      long double pw = (F[2 * k] * F[2 * k] + F[2 * k + 1] * F[2 * k + 1]) / ((long double)n * n);
      sum += k == 0 || 2 * k == n ? pw : 2 * pw;
      gamma[k] = sum;
    }
    long double mean = 0, ss = 0;
    for (size_t k = 0; k < n; k++)
      mean += x[k];
    mean /= n;
    for (size_t k = 0; k < n; k++)
      ss += (x[k] - mean) * (x[k] - mean);
    long double sigma = sqrtl(ss / n), lo = sigma - sqrtl(T), rms = sqrtl(gamma[0]) - sqrtl(T);
    double m1, m2, m3;
    size_t ks = tail_index(gamma, m, T, &m1);
    size_t ki = tail_index(gamma, m, lo > 0 ? lo * lo : 0, &m2);
    size_t kr = tail_index(gamma, m, rms > 0 ? rms * rms : 0, &m3);
    nl_bounds_bandwidth bw;
    NL_CHECK(nl_bounds_bandwidth_1d(x, n, rate, T, &bw, NULL) == NL_OK);
    worst = fmax(worst, fabs((double)((bw.mean - mean) / fmaxl(fabsl(mean), sigma))));
    worst = fmax(worst, fabs((double)((bw.sigma - sigma) / sigma)));
    if (fmin(m1, fmin(m2, m3)) < 1e-9) {
      ties++;
    } else {
      bad += bw.f_sup != (double)ks * rate / (double)n;
      bad += bw.f_inf != (double)ki * rate / (double)n;
      bad += bw.f_inf_rms != (double)kr * rate / (double)n;
    }
    double cut = 0.5 * rate * gsl_rng_uniform(r), frac;
    NL_CHECK(nl_bounds_psd1_fraction_above(x, n, rate, cut, &frac, NULL) == NL_OK);
    long double above = 0;
    for (size_t k = 1; k < m; k++)
      if ((double)k * rate / (double)n > cut)
        above += gamma[k] - (k + 1 < m ? gamma[k + 1] : 0);
    worst_frac = fmax(worst_frac, fabs((double)(frac - above / gamma[1])));
    signals++;
  }
  printf("  %ld signals (%ld near-ties skipped): %ld frequencies differ; mean, sigma %.3g;"
         " fraction above %.3g\n", signals, ties, bad, worst, worst_frac);
  NL_CHECK(bad == 0 && ties <= 10);
  NL_CHECK(worst <= 1e-13);
  NL_CHECK(worst_frac <= 1e-12);
  gsl_rng_free(r);
}

int main(void) { return nl_test_run(); }
