/* report.c - A2's report prose (report.h). */
#include "report.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Where the paper's ratios appear among the slope rows of the sweep: the
 * slope nearest the paper at the first N and what it gives at the largest,
 * and the reverse; the slopes whose rows 0..2 dip at row 1 as the paper's
 * do. */
static void report_shape(nl_harness *r, const nl_table *sweep, const int *octaves, int n)
{
  int last = octaves[n - 1];
  size_t n0 = a2_smoke_nearest(sweep, octaves[0]), nl = a2_smoke_nearest(sweep, last);
  double a0 = nl_table_value(sweep, n0, "slope"), al = nl_table_value(sweep, nl, "slope");
  double p0 = nl_table_value(sweep, n0, "paper_ratio"),
         pl = nl_table_value(sweep, nl, "paper_ratio");
  double r0 = nl_table_value(sweep, n0, "eval_ratio"), rl = nl_table_value(sweep, nl, "eval_ratio");
  double r0l = a2_smoke_ratio_at(sweep, "slope", a0, last);
  double rl0 = a2_smoke_ratio_at(sweep, "slope", al, octaves[0]);
  /* The dip: ratio(N = octaves[1]) below both neighbours, as in the paper. */
  double dip_lo = INFINITY, dip_hi = -INFINITY, steep = INFINITY, flat = -INFINITY;
  for (size_t i = 0; i < sweep->nrows; i++) {
    if (strcmp(nl_table_text(sweep, i, "vary"), "slope")) continue;
    if (nl_table_value(sweep, i, "octaves") != octaves[0]) continue;
    double a = nl_table_value(sweep, i, "slope");
    double x0 = nl_table_value(sweep, i, "eval_ratio");
    double x1 = a2_smoke_ratio_at(sweep, "slope", a, octaves[1]);
    double x2 = a2_smoke_ratio_at(sweep, "slope", a, octaves[2]);
    steep = fmin(steep, a);
    flat = fmax(flat, a);
    if (x1 < x0 && x1 < x2) {
      dip_lo = fmin(dip_lo, a);
      dip_hi = fmax(dip_hi, a);
    }
  }
  char dip[160];
  if (dip_lo <= dip_hi)
    snprintf(dip, sizeof dip,
             "The paper's dip at N = %d appears for slopes %g to %g of the %g ... %g swept.",
             octaves[1], dip_hi, dip_lo, flat, steep);
  else
    snprintf(dip, sizeof dip,
             "The paper's dip at N = %d appears at no slope of the %g ... %g swept.", octaves[1],
             flat, steep);
  const char *ends = a0 == al ? "Both ends are nearest at the same slope."
                              : "No slope of the sweep gives both ends at once.";
  nl_harness_text(r,
                  "**Where the paper's numbers appear:** its N = %d ratio %.2f is met nearest at a "
                  "= %g (ours %.2f), where N = %d gives %.2f against the paper's %.2f; its N = %d "
                  "ratio is met nearest at a = %g (ours %.2f), where N = %d gives %.2f. %s %s\n",
                  octaves[0], p0, a0, r0, last, r0l, pl, last, al, rl, octaves[0], rl0, ends, dip);
}

/* One sentence per free parameter of vary[] with at least three values (a
 * number, not a two-way reading) whose value in the best reading is the
 * first or last value tried: the fit may improve beyond. */
static void report_edges(nl_harness *r, const a2_smoke_scene *best, const a2_smoke_vary *vary,
                         int nvary)
{
  for (int v = 0; v < nvary; v++) {
    if (!vary[v].is_free || vary[v].n < 3) continue;
    double x = a2_smoke_param(r, best, vary[v].name);
    double lo = vary[v].v[0], hi = vary[v].v[vary[v].n - 1];
    if (x == lo || x == hi)
      nl_harness_text(r,
                      "The best %s = %g is at the edge of the values tried (%g ... %g): the fit "
                      "may improve beyond it.\n",
                      vary[v].name, x, lo, hi);
  }
}

void a2_report_fit(nl_harness *r, const a2_run *run)
{
  const nl_bounds_smoke *s = &run->sc->s;
  const nl_table *fit = run->fit, *t = run->timing, *sizet = run->size_check;
  const int *label = run->label;
  int n = run->n, last = n - 1;
  size_t fb = 0;
  while (nl_table_value(fit, fb, "best") != 1.0) fb++;
  double rms, rms_alt, size_dev = 0;
  a2_smoke_fit_columns(t, "eval_ratio", "paper_ratio", &rms);
  a2_smoke_fit_columns(t, "alt_eval_ratio", "paper_ratio", &rms_alt);
  for (size_t k = 0; k < sizet->nrows; k++)
    if (nl_table_value(sizet, k, "size") == run->sweep_size)
      size_dev = fmax(size_dev, nl_table_value(sizet, k, "rel_diff"));
  nl_harness_text(
      r,
      "**Paper (Table 5.1, GPU):** 512 x 512, step 0.01, stop at 99%% opacity; plain / bounded ms "
      "at N = %d ... %d octaves: %.1f/%.1f ... %.1f/%.1f (ratio %.2f to %.2f). It gives the "
      "density CLAMP(a d + 1 + Fnoise(p)) but not the slope a, the base frequency or the "
      "absorption. **Ours:** one CPU thread, orthographic along +z through [-1/2, 1/2]^3, "
      "Beer-Lambert absorption, seeds = permutation tables.\n\n"
      "**Fit:** the fitted quantity is the ratio of noise evaluations plain / bounded (a "
      "deterministic count); our times are CPU clocks on a shared machine and are only reported. "
      "Least squares on the log ratio, rss = sum over the %d rows of (ln ours - ln paper)^2, rms "
      "factor exp(sqrt(rss / %d)) (fit.tsv). Image size: at slopes %g and %g (%d seeds) the "
      "smallest size checked whose ratios all lie within one seed sd of the %d px ratios is %d px "
      "(largest relative difference %.2g, size_check.tsv); the sweep ran there with %d seeds "
      "(slope_sweep.tsv). Best reading: **%s** (rss %.3f, rms factor %.3f, worst factor %.2f at "
      "N = %d).\n",
      label[0], label[last], run->paper_ms[0][0], run->paper_ms[0][1], run->paper_ms[last][0],
      run->paper_ms[last][1], run->paper[0], run->paper[last], n, n, run->check_slope[0],
      run->check_slope[1], run->sweep_seeds, s->width, run->sweep_size, size_dev, run->sweep_seeds,
      nl_table_text(fit, fb, "reading"), nl_table_value(fit, fb, "rss_log"),
      nl_table_value(fit, fb, "rms_factor"), nl_table_value(fit, fb, "worst_factor"),
      (int)nl_table_value(fit, fb, "worst_octaves"));
  report_shape(r, run->sweep, label, n);
  report_edges(r, run->best, run->vary, run->nvary);
  double er2 = nl_table_value(t, 2, "eval_ratio");
  nl_harness_text(
      r, "From N = %d to %d the paper's ratio grows %.1fx, this run's evaluation ratio %.1fx.\n",
      label[2], label[last], run->paper[last] / run->paper[2], run->pt[last].eval_ratio / er2);
  nl_harness_text(
      r,
      "**This run** (Table below, %d x %d, %d seeds): a = %g, f0 = %g, kappa = %g, step %g, stop "
      "at %g, terms = N + %d (the best reading: a = %g, terms = N + %d); rms factor %.3f against "
      "the paper. The measured alternative a = %g (columns alt_*, %d seeds) has rms factor %.3f. "
      "The per-octave bound is %.4f (analytic bound of improved noise; the paper assumes |noise| "
      "<= 1); the largest |noise| met was %.4f.\n",
      s->width, s->height, run->seeds, s->slope, s->freq, s->kappa, s->step, s->stop_opacity,
      run->sc->offset, run->best->s.slope, run->best->offset, rms, run->check_slope[0],
      run->sweep_seeds, rms_alt, s->octave_bound, run->pt[last].max_noise);
  nl_harness_report_table(r, t, "Plain against incrementally bounded march; paper beside ours", 4);
  nl_harness_report_table(r, fit,
                          "Fit of the evaluation ratio to the paper's time ratios, per reading", 4);
}

void a2_report_images(nl_harness *r, const a2_run *run)
{
  int last = run->n - 1, worst_diff = 0;
  for (int i = 0; i < run->n; i++)
    worst_diff = run->pt[i].diff > worst_diff ? run->pt[i].diff : worst_diff;
  const a2_smoke_pair *unit = run->unit;
  nl_harness_text(r,
                  "Bounded and plain images differ by at most %d 8-bit levels at any octave count "
                  "(they are the same sums in the same order). With the paper's unit bound at N = "
                  "%d the images differ by %d levels and the march evaluates %.1fx fewer octaves "
                  "than plain (against %.1fx with the analytic bound).\n",
                  worst_diff, run->label[last], unit->diff,
                  (double)unit->evals[0] / (double)unit->evals[1], run->pt[last].eval_ratio);
  char list[128] = "", cap[256];
  for (int i = 0; i < run->n; i++) {
    size_t used = strlen(list);
    snprintf(list + used, sizeof list - used, "%s%d", i ? ", " : "", run->label[i]);
  }
  snprintf(cap, sizeof cap, "Fig. 5.2: the smoke ball at N = %s (bounded march)", list);
  nl_harness_figure(r, "balls.png", cap);
  snprintf(cap, sizeof cap,
           "Fig. 5.3: octaves needed to decide each pixel of the slice z = 0 at N = %d (blue few "
           "... red all; black: inside the band, never decided)",
           run->label[last]);
  nl_harness_figure(r, "bounds.png", cap);
  snprintf(cap, sizeof cap, "Table 5.1 as ratios: the paper's times, our fitted reading and a = %g",
           run->check_slope[0]);
  nl_harness_figure(r, "timing.png", cap);
}
