/* A2 - Arnerin 2009 Table 5.1, Fig. 5.1-5.3: the smoke ball CLAMP(a d + 1 +
 * Fnoise(p)) ray-marched in the unit cube, with and without incremental
 * bounding, at 0, 1, 2, 5, 7 and 10 octaves. The paper gives neither the
 * slope a nor f0, kappa: they are fitted jointly (joint.h), the reading of
 * "N octaves" fixed at the paper's N + 1 terms. */
#include "harness/nl_harness.h"
#include "joint.h"
#include "report.h"

enum { NROWS = 6, NCHECK = 2 };
static const int label[NROWS] = { 0, 1, 2, 5, 7, 10 };
static const double paper_ms[NROWS][2] = { { 54.1, 19.1 },  { 71.9, 40.4 },  { 117.5, 49.8 },
                                           { 298.8, 64.6 }, { 460.0, 69.5 }, { 1069.1, 89.4 } };
/* The numbers the paper does not state are fitted jointly over
 * a2_joint_grid_default (joint.h); the defaults are its paper-scale optimum
 * (joint_fit.tsv). Then, around it, the slope alone (the shape of the fit),
 * and the stated numbers and the reading of N, whose rows measure the
 * sensitivity only (free 0). */
static const double slopes[] = { -3, -4, -4.5, -5, -5.25, -5.5, -6, -7, -8 };
static const double quick_slopes[] = { -3, -4, -6 };
static const a2_smoke_vary vary[] = { { "offset", 0, 2, { 0, 1 } },
                                      { "step", 0, 3, { 0.005, 0.01, 0.02 } },
                                      { "stop_opacity", 0, 3, { 0.95, 0.99, 0.999 } },
                                      { "octave_bound", 0, 2, { 1, NL_NOISE3_BOUND } } };
static const double check_slope[NCHECK] = { -4, -6 };

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin(
      "a2_raymarch", "A2 - Incremental bounding on a ray-marched smoke ball", argc, argv);
  int quick = nl_harness_quick(r);
  a2_smoke_scene sc = { nl_bounds_smoke_default(), 1 };
  nl_bounds_smoke *s = &sc.s;
  s->width = s->height = (int)nl_harness_param_int(
      r, "size", quick ? 32 : 512, 8, 4096,
      "image width and height in pixels of the ray-marched smoke ball (quick 32)");
  s->step = nl_harness_param(r, "step", 0.01, 1e-4, 0.5,
                             "ray-march step length in unit-cube units (Arnerin 0.01)");
  s->stop_opacity =
      nl_harness_param(r, "stop_opacity", 0.99, 0.0, 1.0,
                       "a ray stops when its opacity 1 - T reaches this (Arnerin: 0.99)");
  s->slope = nl_harness_param(r, "slope", -5.0, -1e3, -1e-3,
                              "slope a < 0 of the density CLAMP(a d + 1 + Fnoise(p)) (not in the "
                              "paper; fitted, joint_fit.tsv)");
  s->freq = nl_harness_param(
      r, "freq", 2.0, 1e-3, 1e3,
      "frequency f0 of the first noise octave (not in the paper; fitted, joint_fit.tsv)");
  s->kappa = nl_harness_param(r, "kappa", 15360.0, 0.0, 1e6,
                              "extinction per unit density and length, T <- T exp(-kappa density "
                              "h) (not in the paper; fitted, joint_fit.tsv)");
  s->octave_bound = nl_harness_param(r, "octave_bound", NL_NOISE3_BOUND, 0.0, 10.0,
                                     "assumed sup |noise| of one octave in the incremental bound "
                                     "(Arnerin: 1; default measured bound)");
  sc.offset = (int)nl_harness_param_int(
      r, "offset", 1, 0, 1,
      "reading of \"N octaves\": terms = N + offset (1: octaves 0..N; 0: N terms)");
  int sweep_seeds = (int)nl_harness_param_int(r, "sweep_seeds", quick ? 2 : 3, 1, 64,
                                              "seeds of the size check and the sweep (quick 2)");
  nl_harness_params_done(r);
  int seeds = nl_harness_seeds(r);
  double paper[NROWS];
  for (int i = 0; i < NROWS; i++) paper[i] = paper_ms[i][0] / paper_ms[i][1];

  /* Does the evaluation ratio depend on the image size? Sizes size/16 ... size. */
  int sizes[4], nsizes = a2_smoke_check_sizes(s->width, sizes);
  nl_table *sizet;
  /* One progress bar over the four stages; shares from a paper-scale run's
   * stage times (the lines printed off a terminal). */
  nl_harness_stage(r, 0.0, 0.2, "size check");
  int sweep_size = a2_smoke_size_check(r, &sc, check_slope, NCHECK, sizes, nsizes, label, NROWS,
                                       sweep_seeds, &sizet);
  nl_harness_write_table(r, sizet, "size_check.tsv");

  /* The joint fit of the evaluation ratio to the paper's times, then the
   * one-at-a-time sweep around its optimum. */
  a2_smoke_scene center = sc;
  center.s.width = center.s.height = sweep_size;
  nl_table *joint, *sweep, *fit;
  a2_joint_grid grid = a2_joint_grid_default(quick);
  nl_harness_stage(r, 0.2, 0.5, "joint fit");
  center = a2_joint_fit(r, &center, &grid, label, paper, NROWS, sweep_seeds, &joint);
  nl_harness_write_table(r, joint, "joint_fit.tsv");
  int nvary = quick ? 0 : 4;
  nl_harness_stage(r, 0.5, 0.8, "sweep");
  a2_smoke_scene best = a2_smoke_sweep(r, &center, quick ? quick_slopes : slopes, quick ? 3 : 9,
                                       vary, nvary, label, paper, NROWS, sweep_seeds, &sweep, &fit);
  /* the sweep's times go to times.tsv: only Table 5.1's (timing.tsv) are
   * the paper's, and they stay in their table */
  nl_harness_time_column(r, "slope_sweep.tsv", "time_ratio");
  nl_harness_time_column(r, "slope_sweep.tsv", "time_ratio_sd");
  nl_harness_time_column(r, "fit.tsv", "time_rms_factor");
  nl_harness_write_table(r, sweep, "slope_sweep.tsv");
  nl_harness_write_table(r, fit, "fit.tsv");

  /* The headline: the scene of the parameters (defaults: the fitted
   * reading) at full size, over seeds. */
  a2_smoke_point pt[NROWS];
  nl_image *panels[NROWS];
  nl_harness_stage(r, 0.8, 1.0, "headline renders");
  a2_smoke_curve(r, &sc, label, NROWS, seeds, 1, pt, panels);
  nl_table *t = a2_smoke_timing(pt, label, paper_ms, NROWS, sizet, check_slope[0]);
  nl_harness_write_table(r, t, "timing.tsv");
  /* Wall-clock times depend on the machine and its load: the regression
   * check skips them and holds the noise-call counts and images exact. */
  const char *ms[] = { "plain_ms",      "plain_ms_sd", "bounded_ms",
                       "bounded_ms_sd", "ratio",       "plain_ms_per_term" };
  for (int k = 0; k < 6; k++) nl_harness_check(r, "timing.tsv", ms[k], "ignore");
  a2_smoke_panels(r, panels, label, NROWS);

  /* Fig. 5.3 at the largest N in the plane z = 0, and the paper's |noise| <= 1. */
  nl_noise_perm3 p;
  nl_noise_perm3_seed(&p, nl_harness_seed(r));
  s->octaves = label[NROWS - 1] + sc.offset;
  nl_image *dm = a2_smoke_decision_image(r, &p, s);
  nl_harness_write_image(r, dm, "bounds.png");
  a2_smoke_pair unit;
  nl_bounds_smoke su = *s;
  su.octave_bound = 1.0;
  nl_error err;
  if (a2_smoke_render_pair(&p, su, NULL, NULL, &unit, &err)) nl_harness_die(r, 1, "%s", err.msg);

  nl_table *growth = a2_joint_growth(pt, paper, NROWS, joint);
  nl_harness_write_table(r, growth, "growth.tsv");
  a2_run run = { .sc = &sc,
                 .best = &best,
                 .label = label,
                 .n = NROWS,
                 .paper_ms = paper_ms,
                 .paper = paper,
                 .check_slope = check_slope,
                 .seeds = seeds,
                 .sweep_seeds = sweep_seeds,
                 .sweep_size = sweep_size,
                 .vary = vary,
                 .nvary = nvary,
                 .pt = pt,
                 .timing = t,
                 .fit = fit,
                 .sweep = sweep,
                 .joint = joint,
                 .growth = growth,
                 .size_check = sizet,
                 .unit = &unit };
  a2_report_fit(r, &run);
  a2_verdicts(r, &run);
  a2_report_images(r, &run);
  nl_image_free(dm);
  nl_table_free(t);
  nl_table_free(sizet);
  nl_table_free(sweep);
  nl_table_free(fit);
  nl_table_free(joint);
  nl_table_free(growth);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
