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
#include "reference/perlin_improved_noise.h"

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

int main(void) { return nl_test_run(); }
