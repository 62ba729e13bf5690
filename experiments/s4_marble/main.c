/* S4 - Shaffer's marble: p.y += a * fractal_sum(p); u = (1 + sin(p.y)) / 2,
 * mapped through a colour ramp (slides "Marble", panels (a)-(c)). */
#include "noise/nl_noise.h"
#include "harness/nl_harness.h"
#include "arcsine.h"
#include "bend.h"
#include "s4.h"
#include "study/nl_study.h"
#include "texture/nl_texture.h"

#include <gsl/gsl_histogram.h>
#include <gsl/gsl_statistics_double.h>
#include <stdio.h>
#include <stdlib.h>

#define NA    4
#define NBINS 20

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("s4_marble", "S4 - Marble through a colour ramp", argc, argv);
  int size = (int)nl_harness_param_int(r, "size", nl_harness_quick(r) ? 128 : 512, 16, 4096,
                                       "side in pixels of the marble images (quick 128)");
  int octaves = (int)nl_harness_param_int(r, "octaves", 6, 1, 30,
                                          "octaves of the turbulence that perturbs the stripes");
  double stripes = nl_harness_param(r, "stripes", 1.0, 1e-3, 1e3,
                                    "stripes per unit along y: u = (1 + sin(2 pi stripes p.y)) / "
                                    "2, p.y displaced by turbulence");
  double extent = nl_harness_param(r, "extent", 4.0, 1e-3, 1e4,
                                   "side of the noise-space square [0, extent)^2 the images cover");
  nl_harness_params_done(r);

  const double amps[NA] = { 0, 0.25, 0.5, 1.0 };
  nl_noise_octaves o = nl_noise_octaves_fractal(octaves);
  nl_noise_window win = { 0, 0, NL_STUDY_SLICE_Z, extent, size, size };
  nl_texture_ramp ramp = nl_texture_ramp_marble();
  size_t npix = (size_t)size * size;
  double *u = nl_xmalloc(npix * sizeof *u);
  const char *hcols[NA + 1] = { "u", "a=0", "a=0.25", "a=0.5", "a=1" };
  nl_table *hist = nl_table_alloc(NA + 1, hcols);
  for (int b = 0; b < NBINS; b++) {
    size_t row = nl_table_append_empty(hist);
    nl_table_set(hist, row, "u", (b + 0.5) / NBINS);
  }
  const char *dcols[] = { "a", "u_mean", "u_mean_sd", "u_sd", "u_sd_sd", "cdf_gap" };
  nl_table *dist = nl_table_alloc(6, dcols);
  nl_image *panels[NA];
  char labels[NA][32];
  const char *lab[NA];
  int nseeds = nl_harness_seeds(r);
  double *m = nl_xmalloc((size_t)nseeds * sizeof *m);
  double *sd = nl_xmalloc((size_t)nseeds * sizeof *sd);
  /* bend.tsv: rows 0..NA-1 the marble at each a, NA.. the rows-only
   * control at each a > 0 (bend.h) */
  const char *bcols[] = { "a", "displacement", "gx_share", "gx_share_sd", "seeds" };
  nl_table *bend = nl_table_alloc(5, bcols);
  double *gx = nl_xmalloc(2 * (size_t)NA * nseeds * sizeof *gx);
  gsl_histogram *h = gsl_histogram_alloc(NBINS);
  gsl_histogram_set_ranges_uniform(h, 0.0, 1.0 + 1e-12);
  for (int i = 0; i < NA; i++) {
    gsl_histogram_reset(h);
    for (int k = 0; k < nseeds; k++) {
      nl_noise_perm3 p;
      nl_noise_perm3_seed(&p, nl_seed_replicate(nl_harness_seed(r), k));
      nl_noise_basis b = nl_noise_basis_perm3(&p);
      nl_texture_marble_grid(&b, &o, &win, NL_TWO_PI * stripes, amps[i], u);
      m[k] = gsl_stats_mean(u, 1, npix);
      sd[k] = gsl_stats_sd_m(u, 1, npix, m[k]);
      for (size_t q = 0; q < npix; q++) gsl_histogram_increment(h, u[q]);
      if (k == 0) panels[i] = nl_texture_ramp_image(&ramp, u, size, size, 0, 1);
      gx[(size_t)i * nseeds + k] = s4_bend_share(u, size, size);
      s4_marble_rows(&b, &o, &win, NL_TWO_PI * stripes, amps[i], u);
      gx[(size_t)(NA + i) * nseeds + k] = s4_bend_share(u, size, size);
    }
    /* density: samples per bin over all seeds, per unit of u */
    double dens[NBINS];
    for (int bin = 0; bin < NBINS; bin++) {
      dens[bin] = gsl_histogram_get(h, bin) / ((double)npix * nseeds) * NBINS;
      nl_table_set(hist, (size_t)bin, hcols[i + 1], dens[bin]);
    }
    double m_sd = nseeds > 1 ? gsl_stats_sd(m, 1, nseeds) : 0;
    double sd_sd = nseeds > 1 ? gsl_stats_sd(sd, 1, nseeds) : 0;
    nl_table_append(dist, "dddddd", amps[i], gsl_stats_mean(m, 1, nseeds), m_sd,
                    gsl_stats_mean(sd, 1, nseeds), sd_sd, s4_arcsine_gap(dens, NBINS));
    snprintf(labels[i], sizeof labels[i], "(%c) a = %g", 'a' + i, amps[i]);
    lab[i] = labels[i];
  }
  nl_image *mont = nl_image_montage((const nl_image *const *)panels, lab, NA, NA,
                                    "marble: u = (1 + sin(2 pi (y + a fractal_sum(p)))) / 2");
  nl_harness_write_image(r, mont, "panels.png");
  for (int i = 0; i < 2 * NA; i++) {
    if (i == NA) continue; /* a = 0 once: the control's a = 0 is the same raster */
    const double *g = gx + (size_t)i * nseeds;
    nl_table_append(bend, "dsddi", amps[i % NA], i < NA ? "fractal sum" : "row's first pixel",
                    gsl_stats_mean(g, 1, nseeds), nseeds > 1 ? gsl_stats_sd(g, 1, nseeds) : 0,
                    nseeds);
  }
  nl_harness_write_table(r, bend, "bend.tsv");
  nl_harness_write_table(r, hist, "u_density.tsv");
  nl_harness_write_table(r, dist, "distribution.tsv");
  /* Regression rules: u_mean and u_sd are means over seeds with their spreads
   * beside them (statistical rules, see nl_harness.h); the density is a count
   * of samples per bin and stays exact. */
  nl_harness_check(r, "distribution.tsv", "u_mean", "welch u_mean_sd 1e-3");
  nl_harness_check(r, "distribution.tsv", "u_sd", "welch u_sd_sd 1e-3");
  nl_harness_check(r, "distribution.tsv", "u_mean_sd", "ftest 1e-3");
  nl_harness_check(r, "distribution.tsv", "u_sd_sd", "ftest 1e-3");

  /* "we need to add some noise first": the noise bends the stripes, u
   * varies along x (a = 0.25, the sweep's smallest, against a = 0). The
   * control displaces each row by one value of the same sum: the stripes
   * move as much but stay straight. */
  nl_harness_verdict_less(r, "bend.tsv", bend, 0, 1,
                          "share of u's variation along the stripes, a = 0 below a = 0.25",
                          "p.y + a fractal_sum(p) turns the ramp's stripes into marble veins",
                          "gx_share", "gx_share_sd", "seeds", 0.01, "independent");
  nl_harness_verdict_control_less(r, "each row displaced by the sum at its first pixel",
                                  "bend.tsv", bend, 0, NA);
  nl_harness_verdict_figure(r, "marble through a colour ramp",
                            "turbulent marble veins (images only)", "panels.png",
                            "the amplitude a is not given: ours a sweep");
  s4_report(r, stripes, octaves, &win, dist, bend, NBINS, s4_uniform_gap(NBINS));
  gsl_histogram_free(h);
  for (int i = 0; i < NA; i++) nl_image_free(panels[i]);
  nl_image_free(mont);
  nl_table_free(hist);
  nl_table_free(dist);
  nl_table_free(bend);
  free(gx);
  free(u);
  free(m);
  free(sd);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
