/* Q2 - Qin & Yang 2000 Fig. 2 (sec. 4.1, eq. 4): colour mapping
 * pattern(x) = spline(clamp(GCTBF(x), 0, 1), c1..c13) with the 13 blue-marble
 * knots of sec. 4.1, for Perlin noise and five GCTBF combinations. */
#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"
#include "q2.h"
#include "study/nl_study.h"
#include "texture/nl_texture.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>

/* Our reading of the five (unlabelled in the text) combinations: two of
 * Worley's linear ones and three with products. */
static const char *combos[5] = { "F1", "F2 - F1", "F1F2", "F2 - F1 - F1F1", "F1F2 + F2F3" };

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("q2_colour", "Q2 - GCTBF colour mapping with the 13-knot spline",
                                   argc, argv);
  int size = (int)nl_harness_param_int(r, "size", nl_harness_quick(r) ? 96 : 256, 8, 4096,
                                       "side in pixels of the colour-mapped images (quick 96)");
  double extent = nl_harness_param(r, "extent", 4.0, 1e-3, 1e4,
                                   "side of the square [0, extent)^2 the images cover, in "
                                   "feature-cube units");
  double perlin_freq =
      nl_harness_param(r, "perlin_freq", 2.0, 1e-3, 1e3, "frequency of the Perlin noise panel");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r);
  size_t npix = (size_t)size * size;
  nl_noise_window win = { 0, 0, 0.5, extent, size, size };
  /* Perlin's octave off the lattice planes (NL_STUDY_SLICE_Z): on z 2 = 1
   * its gradients would line up with the axes. */
  nl_noise_window pwin = { 0, 0, NL_STUDY_SLICE_Z, extent, size, size };
  nl_texture_ramp ramp = nl_texture_ramp_cellular_marble();
  double *v = nl_xmalloc(npix * sizeof *v);
  nl_image *panels[6];
  const char *labels[6] = { "Perlin noise" };

  const char *cols[] = { "pattern", "mean", "sd", "min", "max" };
  nl_table *t = nl_table_alloc(5, cols);
  for (int pat = 0; pat < 6; pat++) {
    double st[4] = { 0, 0, 0, 0 };
    for (int k = 0; k < seeds; k++) {
      unsigned long seed = nl_seed_replicate(nl_harness_seed(r), k);
      if (pat == 0) {
        /* RenderMan's noise() lies in [0, 1] around 1/2: 0.5 + 0.5 Perlin. */
        nl_noise_perm3 p;
        nl_noise_perm3_seed(&p, seed);
        nl_noise_basis b = nl_noise_basis_perm3(&p);
        nl_noise_octaves o = nl_noise_octaves_fbm(1, 0.5, 1.0);
        o.freq[0] = perlin_freq;
        nl_noise_fractal_grid(&b, &o, &pwin, v);
        for (size_t q = 0; q < npix; q++) v[q] = 0.5 + 0.5 * v[q];
      } else {
        nl_cellular *c;
        nl_cellular_gctbf g;
        nl_error err;
        if (nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, seed, &c, &err))
          nl_harness_die(r, 1, "%s", err.msg);
        if (nl_cellular_gctbf_parse(combos[pat - 1], &g, &err)) nl_harness_die(r, 2, "%s", err.msg);
        nl_cellular_gctbf_grid(c, &g, &win, v);
        nl_cellular_free(c);
        labels[pat] = combos[pat - 1];
      }
      double mn;
      double mx;
      gsl_stats_minmax(&mn, &mx, v, 1, npix);
      st[0] += gsl_stats_mean(v, 1, npix) / seeds;
      st[1] += gsl_stats_sd(v, 1, npix) / seeds;
      st[2] = k ? fmin(st[2], mn) : mn;
      st[3] = k ? fmax(st[3], mx) : mx;
      if (k == 0) panels[pat] = nl_texture_ramp_image(&ramp, v, size, size, 0.0, 1.0);
    }
    nl_table_append(t, "sdddd", labels[pat], st[0], st[1], st[2], st[3]);
  }
  nl_harness_write_table(r, t, "values.tsv");
  nl_study_montage(r, (const nl_image *const *)panels, labels, 6, 3, "Fig. 2: spline colour map",
                   "colour.png");

  q2_report(r, &win, &pwin, perlin_freq, t);
  for (int k = 0; k < 6; k++) nl_image_free(panels[k]);
  free(v);
  nl_table_free(t);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
