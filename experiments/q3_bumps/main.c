/* Q3 - Qin & Yang 2000 Fig. 4 (sec. 4.3, eq. 6): fractal bump wrinkles,
 * GCTBF = F2 - F1 - F1F1, octaves 0 to 4, the plane displaced by
 * bump = fractal^3 along its normal and shaded under one light. */
#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"
#include "q3.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>

/* The steepest slope of the height field h (w x w samples `spacing` apart):
 * the largest |grad h| by central differences, at displacement amp = 1. */
static double slope_max(const double *h, int w, double spacing)
{
  double top = 0;
  for (int y = 1; y < w - 1; y++)
    for (int x = 1; x < w - 1; x++) {
      double gx = (h[(size_t)y * w + x + 1] - h[(size_t)y * w + x - 1]) / (2 * spacing);
      double gy = (h[(size_t)(y + 1) * w + x] - h[(size_t)(y - 1) * w + x]) / (2 * spacing);
      top = fmax(top, sqrt(gx * gx + gy * gy));
    }
  return top;
}

int main(int argc, char **argv)
{
  nl_harness *r =
      nl_harness_begin("q3_bumps", "Q3 - Fractal bump wrinkles with F2 - F1 - F1F1", argc, argv);
  int size = (int)nl_harness_param_fft_size(r, "size", nl_harness_quick(r) ? 96 : 256, 8, 4096,
                                       "side in pixels of the shaded bump images (quick 96)");
  double extent = nl_harness_param(r, "extent", 2.0, 1e-3, 1e4,
                                   "side of the square of the plane the images cover, in "
                                   "feature-cube units");
  double k = nl_harness_param(r, "k", 3.0, 1e-3, 1e3,
                              "scale k of the fractal bump's octaves (Qin & Yang eq. 5's example: "
                              "3)");
  int max_oct = (int)nl_harness_param_int(r, "octaves", 4, 0, 30,
                                          "highest octave of the fractal bump; panels show octaves "
                                          "0..this");
  double amp = nl_harness_param(r, "amp", 0.05, 1e-6, 1e3,
                                "displacement amplitude: the plane moves by amp x bump along its "
                                "normal");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r);
  size_t npix = (size_t)size * size;
  nl_noise_window win = { 0, 0, 0.5, extent, size, size };
  /* One light from the upper left, 45 degrees high. */
  const double light[3] = { -0.5, 0.5, 0.70710678118654752 };
  double *h = nl_xmalloc(npix * sizeof *h);   /* bump height */
  double *sh = nl_xmalloc(npix * sizeof *sh); /* its shading */
  int npan = max_oct + 2;
  nl_image **panels = nl_xmalloc((size_t)npan * sizeof *panels);
  char **labels = nl_xmalloc((size_t)npan * sizeof *labels);

  const char *cols[] = {
    "octaves", "bump_mean", "bump_max", "shade_mean", "shade_sd", "slope_max"
  };
  nl_table *t = nl_table_alloc(6, cols);
  /* centroid.tsv: octaves 0..max_oct of eq. 6, then max_oct at one scale */
  double *cen = nl_xmalloc(((size_t)npan + 1) * seeds * sizeof *cen);
  for (int i = 0; i < npan; i++) labels[i] = nl_xmalloc(32);
  for (int i = 0; i < npan; i++) snprintf(labels[i], 32, i ? "octaves = %d" : "original", i - 1);
  for (int pan = 0; pan < npan; pan++) {
    double st[5] = { 0, 0, 0, 0, 0 };
    for (int s = 0; s < seeds; s++) {
      nl_cellular *c;
      nl_error err;
      unsigned long seed = nl_seed_replicate(nl_harness_seed(r), s);
      if (nl_cellular_alloc(4.0, 50, NL_COUNT_INVERSE_CDF, seed, &c, &err))
        nl_harness_die(r, 1, "%s", err.msg);
      nl_cellular_gctbf_basis gb = { c, { 0 } };
      nl_cellular_gctbf_parse("F2 - F1 - F1F1", &gb.g, NULL);
      if (pan == 0) {
        for (size_t q = 0; q < npix; q++) h[q] = 0.0; /* the flat plane */
      } else {
        nl_cellular_gctbf_fractal_bump_grid(&gb, pan - 1, k, &win, h);
        cen[(size_t)pan * seeds + s] = q3_centroid(h, size, extent);
        if (pan == npan - 1) {
          q3_bump_one_scale(&gb, pan - 1, k, &win, sh);
          cen[(size_t)npan * seeds + s] = q3_centroid(sh, size, extent); /* sh: scratch */
        }
      }
      /* displacement amp * bump: the same as spacing / amp */
      nl_cellular_heightfield_shade(h, size, size, extent / size / amp, light, sh);
      st[0] += gsl_stats_mean(h, 1, npix) / seeds;
      st[1] = fmax(st[1], gsl_stats_max(h, 1, npix));
      st[2] += gsl_stats_mean(sh, 1, npix) / seeds;
      st[3] += gsl_stats_sd(sh, 1, npix) / seeds;
      st[4] = fmax(st[4], slope_max(h, size, extent / size));
      if (s == 0) panels[pan] = nl_image_from_values(sh, size, size, 0.0, 1.0);
      nl_cellular_free(c);
    }
    nl_table_append(t, "iddddd", pan - 1, st[0], st[1], st[2], st[3], st[4]);
  }
  nl_harness_write_table(r, t, "bumps.tsv");
  const char *ccols[] = { "octaves", "scales", "centroid", "centroid_sd", "seeds" };
  nl_table *ct = nl_table_alloc(5, ccols);
  for (int pan = 1; pan <= npan; pan++) {
    const double *c = cen + (size_t)pan * seeds;
    nl_table_append(ct, "isddi", pan < npan ? pan - 1 : max_oct,
                    pan < npan ? "2^i k" : "k", gsl_stats_mean(c, 1, seeds),
                    seeds > 1 ? gsl_stats_sd(c, 1, seeds) : 0, seeds);
  }
  nl_harness_write_table(r, ct, "centroid.tsv");
  /* Fig. 4's wrinkles grow finer as octaves are added: the centroid of the
   * bump's power at octaves 0 below octaves max_oct. Control: the same sum
   * with every octave at scale k, no finer octave in it. */
  nl_harness_verdict_less(r, "centroid.tsv", ct, 0, (size_t)max_oct,
                          "spectral centroid of the bump, octaves 0 below the last",
                          "each octave adds wrinkles at twice the frequency (eq. 6)", "centroid",
                          "centroid_sd", "seeds", 0.01, "independent");
  nl_harness_verdict_control_less(r, "the same octaves all at scale k (no doubling)",
                                  "centroid.tsv", ct, 0, (size_t)max_oct + 1);
  nl_image *m = nl_image_montage((const nl_image *const *)panels, (const char *const *)labels, npan,
                                 3, "Fig. 4: F2 - F1 - F1F1 wrinkles");
  nl_harness_write_image(r, m, "bumps.png");

  q3_report(r, extent, k, amp, light, max_oct, t, ct);
  nl_table_free(ct);
  free(cen);
  for (int i = 0; i < npan; i++) {
    nl_image_free(panels[i]);
    free(labels[i]);
  }
  free(panels);
  free(labels);
  nl_image_free(m);
  free(h);
  free(sh);
  nl_table_free(t);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
