/* A4 - Arnerin 2009 Fig. 5.7: Perlin noise and the spectrally normalised
 * Nnoise(x) = noise(x / F_sup), both sampled at 2 samples per unit, with the
 * fraction of their energy above the Nyquist frequency (what aliases). */
#include "alias.h"
#include "bounds/nl_bounds.h"
#include "harness/nl_harness.h"
#include "line.h"
#include "report.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdlib.h>

/* F_sup is measured on a finely sampled line: 64 samples per unit, far
 * above the band of one octave. */
#define FINE_RATE 64.0
/* The 2D planes whose energy above Nyquist is measured: 16 samples per
 * unit (what one octave puts above 8 cycles per unit is below 1e-6 T). */
#define PLANE_RATE 16.0
/* Table 5.2's F_sup of the first octave, the divisor of the paper's Nnoise. */
#define PAPER_F_SUP 1.7460938

/* The plane z = 0.5 of noise(f p), size x size pixels over extent units. */
static nl_image *plane_image(const nl_noise_perm3 *p, double f, int size, double extent)
{
  nl_noise_basis b = nl_noise_basis_perm3(p);
  nl_noise_octaves o = nl_noise_octaves_fbm(1, 1.0, 1.0);
  o.freq[0] = f;
  nl_noise_window w = { 0, 0, 0.5, extent, size, size };
  double *v = nl_xmalloc((size_t)size * size * sizeof *v);
  nl_noise_fractal_grid(&b, &o, &w, v);
  nl_image *im = nl_image_from_values(v, size, size, -1.0, 1.0);
  free(v);
  return im;
}

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("a4_normalised", "A4 - Spectrally normalised noise", argc, argv);
  int quick = nl_harness_quick(r);
  int size = (int)nl_harness_param_int(r, "size", quick ? 96 : 256, 8, 4096,
                                       "side in pixels of the 2D noise images (quick 96)");
  double rate2d =
      nl_harness_param(r, "rate", 2.0, 0.1, 1024,
                       "samples per unit of the 2D images and the 1D line (Arnerin Fig. 5.7: 2)");
  double length = nl_harness_param(r, "length", quick ? 128 : 512, 8, 1e6,
                                   "length of the sampled 1D line in noise units (quick 128)");
  double extent = nl_harness_param(r, "extent", quick ? 32 : 64, 4, 1024,
                                   "side in noise units of the 2D planes whose energy above "
                                   "Nyquist is measured, 16 samples per unit (quick 32)");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r) > 64 ? 64 : nl_harness_seeds(r);
  double fs[64], a0[64], a1[64], e[3][64]; /* e: noise, ours, the paper's Nnoise, in T */
  double e2[3][64];                          /* the same on 2D planes */
  nl_error err;
  for (int k = 0; k < seeds; k++) {
    nl_noise_perm3 p;
    nl_noise_perm3_seed(&p, nl_seed_replicate(nl_harness_seed(r), k));
    size_t n;
    /* F_sup of the first octave from the fine sample of the stored value
     * (noise + 1) / 2, whose 8-bit levels T is defined on (sec. 5.2.2). */
    double *x = a4_line_sample(&p, 1.0, length, FINE_RATE, &n);
    double *st = nl_xmalloc(n * sizeof *st);
    for (size_t i = 0; i < n; i++) st[i] = 0.5 * (x[i] + 1.0);
    nl_bounds_bandwidth bw;
    if (nl_bounds_bandwidth_1d(st, n, FINE_RATE, NL_BOUNDS_T, &bw, &err))
      nl_harness_die(r, 1, "%s", err.msg);
    free(st);
    fs[k] = bw.f_sup;
    /* Energy that folds back when sampled at rate2d: above rate2d / 2,
     * before and after the normalisation. */
    if (nl_bounds_psd1_fraction_above(x, n, FINE_RATE, 0.5 * rate2d, &a0[k], &err))
      nl_harness_die(r, 1, "%s", err.msg);
    free(x);
    x = a4_line_sample(&p, 1.0 / fs[k], length, FINE_RATE, &n);
    if (nl_bounds_psd1_fraction_above(x, n, FINE_RATE, 0.5 * rate2d, &a1[k], &err))
      nl_harness_die(r, 1, "%s", err.msg);
    free(x);
    /* The stored value's energy above Nyquist against T (alias.h). */
    const double div[3] = { 1.0, fs[k], PAPER_F_SUP };
    for (int v = 0; v < 3; v++) {
      if (a4_alias_energy(&p, 1.0 / div[v], length, FINE_RATE, 0.5 * rate2d, &e[v][k], &err))
        nl_harness_die(r, 1, "%s", err.msg);
      if (a4_alias_energy2(&p, 1.0 / div[v], extent, PLANE_RATE, 0.5 * rate2d, &e2[v][k], &err))
        nl_harness_die(r, 1, "%s", err.msg);
    }
  }
  nl_table *et = a4_energy_table(e, seeds, nl_stats_mean(fs, seeds, NL_STATS_RUNNING), PAPER_F_SUP);
  nl_harness_write_table(r, et, "aliased_energy.tsv");
  nl_table *et2 =
      a4_energy_table(e2, seeds, nl_stats_mean(fs, seeds, NL_STATS_RUNNING), PAPER_F_SUP);
  nl_harness_write_table(r, et2, "aliased_energy_2d.tsv");
  const char *cols[] = { "signal", "f_sup", "aliased_fraction", "aliased_fraction_sd" };
  nl_table *t = nl_table_alloc(4, cols);
  double mf = nl_stats_mean(fs, seeds, NL_STATS_RUNNING);
  nl_table_append(t, "sddd", "noise(x)", mf, nl_stats_mean(a0, seeds, NL_STATS_RUNNING),
                  nl_stats_sd(a0, seeds, NL_STATS_RUNNING));
  nl_table_append(t, "sddd", "noise(x / F_sup)", 1.0, nl_stats_mean(a1, seeds, NL_STATS_RUNNING),
                  nl_stats_sd(a1, seeds, NL_STATS_RUNNING));
  nl_harness_write_table(r, t, "aliasing.tsv");

  /* Fig. 5.7: the first seed's plane before and after the normalisation,
   * by the paper's F_sup (Table 5.2), the divisor the headline rows use. */
  a4_run run = { rate2d, length, FINE_RATE, mf, seeds, t, extent, PLANE_RATE, PAPER_F_SUP };
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, nl_harness_seed(r));
  nl_image *pan[2] = { plane_image(&p, 1.0, size, size / rate2d),
                       plane_image(&p, 1.0 / PAPER_F_SUP, size, size / rate2d) };
  const char *labels[2] = { "(a) noise(x)", "(b) noise(x / F_sup)" };
  char title[96];
  a4_figure_title(&run, title, sizeof title);
  nl_study_montage(r, (const nl_image *const *)pan, labels, 2, 2, title, "normalised.png");

  a4_report(r, &run);
  a4_report_energy(r, &run, et, et2, 0.5 * rate2d);
  nl_image_free(pan[0]);
  nl_image_free(pan[1]);
  nl_table_free(t);
  nl_table_free(et);
  nl_table_free(et2);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
