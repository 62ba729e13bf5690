/* smoke.c - A2's curves, size check and sweep (smoke.h). */
#include "smoke.h"
#include "study/nl_study.h"
#include "texture/nl_texture.h"
#include "base/nl_parallel.h"

#include <stdatomic.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Largest difference of two renders in 8-bit levels. */
static int max_level_diff(const double *a, const double *b, size_t n)
{
  int worst = 0;
  for (size_t k = 0; k < n; k++) {
    int d = abs((int)lround(255.0 * a[k]) - (int)lround(255.0 * b[k]));
    if (d > worst) worst = d;
  }
  return worst;
}

nl_status a2_smoke_render_pair(const nl_noise_perm3 *p, nl_bounds_smoke s, double *img0,
                               double *img1, a2_smoke_pair *t, nl_error *err)
{
  size_t npix = (size_t)s.width * s.height;
  if (s.width < 1 || s.height < 1) /* the size of the temporaries; the renderer checks the rest */
    return nl_fail(err, NL_EINVAL, "smoke: image size must be positive");
  double *own = img0 && img1 ? NULL : nl_xmalloc(2 * npix * sizeof *own);
  double *img[2] = { own ? own : img0, own ? own + npix : img1 };
  nl_status rc = NL_OK;
  for (int inc = 0; inc < 2 && !rc; inc++) {
    nl_bounds_smoke_stats st;
    s.incremental = inc;
    double t0 = nl_time_thread_cpu();
    rc = nl_bounds_smoke_render(p, &s, img[inc], &st, err);
    if (rc) break;
    t->ms[inc] = 1e3 * (nl_time_thread_cpu() - t0);
    t->evals[inc] = st.noise_evals;
    t->samples = st.samples;
    if (inc == 0) t->max_noise = st.max_abs_noise;
  }
  if (!rc) t->diff = max_level_diff(img[0], img[1], npix);
  free(own);
  return rc;
}

/* Plain / bounded; no noise term at all is the same work. */
static double eval_ratio(double plain, double bounded)
{
  return bounded > 0.0 ? plain / bounded : 1.0;
}

/* One render of the curve: item i = row * seeds + k, on nl_parallel_for's
 * thread t with that thread's two image buffers; it writes slot i only. */
typedef struct {
  nl_harness *r;
  const a2_smoke_scene *sc;
  const int *octaves;
  int n, seeds, timed;
  double **img;                       /* 2 per thread */
  double *ev0, *ev1, *ms0, *ms1, *tr; /* per item */
  int *diff;
  double *max_noise;
  nl_image **panels;
  nl_status *st;
  nl_error *err;
  atomic_int done;
} curve_job;

static void curve_item(void *ctx, size_t i, int t)
{
  curve_job *j = ctx;
  int row = (int)(i / (size_t)j->seeds), k = (int)(i % (size_t)j->seeds);
  nl_bounds_smoke s = j->sc->s;
  s.octaves = j->octaves[row] + j->sc->offset;
  double *img0 = j->img[2 * t], *img1 = j->img[2 * t + 1];
  nl_noise_perm3 perm;
  nl_noise_perm3_seed(&perm, nl_seed_replicate(nl_harness_seed(j->r), k));
  if (j->timed) {
    a2_smoke_pair pr;
    if ((j->st[i] = a2_smoke_render_pair(&perm, s, img0, img1, &pr, &j->err[i]))) return;
    j->ev0[i] = (double)pr.evals[0];
    j->ev1[i] = (double)pr.evals[1];
    j->ms0[i] = pr.ms[0];
    j->ms1[i] = pr.ms[1];
    j->tr[i] = pr.ms[0] / pr.ms[1];
    j->diff[i] = pr.diff;
    j->max_noise[i] = pr.max_noise;
  } else {
    nl_bounds_smoke_stats st;
    s.incremental = 1;
    if ((j->st[i] = nl_bounds_smoke_render(&perm, &s, img1, &st, &j->err[i]))) return;
    j->ev0[i] = (double)st.samples * s.octaves;
    j->ev1[i] = (double)st.noise_evals;
    j->ms0[i] = j->ms1[i] = j->tr[i] = 0.0;
    j->diff[i] = 0;
    j->max_noise[i] = 0.0;
  }
  if (k == 0 && j->panels) j->panels[row] = nl_image_from_values(img1, s.width, s.height, 0.0, 1.0);
  int done = atomic_fetch_add(&j->done, 1) + 1;
  if (t == 0) nl_harness_progress(j->r, (double)done / (j->n * j->seeds), "renders");
}

void a2_smoke_curve(nl_harness *r, const a2_smoke_scene *sc, const int *octaves, int n, int seeds,
                    int timed, a2_smoke_point *out, nl_image **panels)
{
  size_t npix = (size_t)sc->s.width * sc->s.height, items = (size_t)n * (size_t)seeds;
  /* Renders are independent: (row, seed) items over the harness's threads.
   * Each render runs on one thread and is timed by that thread's CPU clock
   * (a2_smoke_render_pair), so the time columns stay per render. */
  int nt = nl_parallel_threads(items, nl_harness_threads(r));
  double *img[2 * NL_PARALLEL_MAX];
  for (int t = 0; t < 2 * nt; t++) img[t] = nl_xmalloc(npix * sizeof **img);
  double *v = nl_xmalloc(6 * items * sizeof *v); /* ev0, ev1, ms0, ms1, time ratio, max noise */
  curve_job j = { .r = r,
                  .sc = sc,
                  .octaves = octaves,
                  .n = n,
                  .seeds = seeds,
                  .timed = timed,
                  .img = img,
                  .ev0 = v,
                  .ev1 = v + items,
                  .ms0 = v + 2 * items,
                  .ms1 = v + 3 * items,
                  .tr = v + 4 * items,
                  .max_noise = v + 5 * items,
                  .diff = nl_xmalloc(items * sizeof(int)),
                  .panels = panels,
                  .st = nl_xcalloc(items, sizeof(nl_status)),
                  .err = nl_xmalloc(items * sizeof(nl_error)) };
  atomic_init(&j.done, 0);
  nl_parallel_for(items, nt, curve_item, &j);
  for (size_t i = 0; i < items; i++)
    if (j.st[i]) nl_harness_die(r, 1, "%s", j.err[i].msg);
  double *er = nl_xmalloc((size_t)seeds * sizeof *er);
  for (int row = 0; row < n; row++) { /* reductions in item order, after the join */
    size_t o = (size_t)row * seeds;
    a2_smoke_point *p = &out[row];
    memset(p, 0, sizeof *p);
    p->terms = octaves[row] + sc->offset;
    for (int k = 0; k < seeds; k++) {
      er[k] = eval_ratio(j.ev0[o + k], j.ev1[o + k]);
      p->diff = j.diff[o + k] > p->diff ? j.diff[o + k] : p->diff;
      p->max_noise = fmax(p->max_noise, j.max_noise[o + k]);
    }
    p->plain_evals = nl_stats_mean(j.ev0 + o, seeds, NL_STATS_RUNNING);
    p->bounded_evals = nl_stats_mean(j.ev1 + o, seeds, NL_STATS_RUNNING);
    p->eval_ratio = eval_ratio(p->plain_evals, p->bounded_evals);
    p->eval_ratio_sd = nl_stats_sd(er, seeds, NL_STATS_RUNNING);
    p->plain_ms = nl_stats_mean(j.ms0 + o, seeds, NL_STATS_RUNNING);
    p->plain_ms_sd = nl_stats_sd(j.ms0 + o, seeds, NL_STATS_RUNNING);
    p->bounded_ms = nl_stats_mean(j.ms1 + o, seeds, NL_STATS_RUNNING);
    p->bounded_ms_sd = nl_stats_sd(j.ms1 + o, seeds, NL_STATS_RUNNING);
    p->time_ratio = timed ? p->plain_ms / p->bounded_ms : 0.0;
    p->time_ratio_sd = nl_stats_sd(j.tr + o, seeds, NL_STATS_RUNNING);
  }
  for (int t = 0; t < 2 * nt; t++) free(img[t]);
  free(v);
  free(er);
  free(j.diff);
  free(j.st);
  free(j.err);
}

double a2_smoke_fit(const double *ours, const double *paper, int n, double *rms_factor, int *worst)
{
  double rss = 0.0, big = -1.0;
  for (int i = 0; i < n; i++) {
    double d = log(ours[i]) - log(paper[i]);
    rss += d * d;
    if (fabs(d) > big) {
      big = fabs(d);
      if (worst) *worst = i;
    }
  }
  if (rms_factor) *rms_factor = exp(sqrt(rss / n));
  return rss;
}

int a2_smoke_check_sizes(int width, int *sizes)
{
  int nsizes = 0;
  for (int d = 16; d >= 1; d /= 2) {
    int z = width / d;
    if (d != 2 && z >= 8 && (nsizes == 0 || z > sizes[nsizes - 1])) sizes[nsizes++] = z;
  }
  return nsizes;
}

int a2_smoke_size_check(nl_harness *r, const a2_smoke_scene *sc, const double *slopes, int nslopes,
                        const int *sizes, int nsizes, const int *octaves, int n, int seeds,
                        nl_table **out)
{
  const char *cols[] = { "slope",         "size",           "octaves",           "eval_ratio",
                         "eval_ratio_sd", "ref_eval_ratio", "ref_eval_ratio_sd", "rel_diff",
                         "within" };
  nl_table *t = nl_table_alloc(9, cols);
  a2_smoke_point *pt = nl_xmalloc((size_t)nsizes * n * sizeof *pt);
  int *ok = nl_xmalloc((size_t)nsizes * sizeof *ok);
  for (int z = 0; z < nsizes; z++) ok[z] = 1;
  for (int a = 0; a < nslopes; a++) {
    /* The reference (largest, last) first, so each row can name its distance. */
    for (int z = nsizes - 1; z >= 0; z--) {
      a2_smoke_scene c = *sc;
      c.s.slope = slopes[a];
      c.s.width = c.s.height = sizes[z];
      nl_harness_substage(r, a * nsizes + (nsizes - 1 - z), nslopes * nsizes);
      a2_smoke_curve(r, &c, octaves, n, seeds, 0, pt + (size_t)z * n, NULL);
    }
    const a2_smoke_point *ref = pt + (size_t)(nsizes - 1) * n;
    for (int z = 0; z < nsizes; z++)
      for (int i = 0; i < n; i++) {
        const a2_smoke_point *p = pt + (size_t)z * n + i;
        double d = fabs(p->eval_ratio - ref[i].eval_ratio);
        int within = d <= ref[i].eval_ratio_sd;
        ok[z] &= within;
        nl_table_append(t, "diidddddi", slopes[a], sizes[z], octaves[i], p->eval_ratio,
                        p->eval_ratio_sd, ref[i].eval_ratio, ref[i].eval_ratio_sd,
                        d / ref[i].eval_ratio, within);
      }
  }
  int chosen = sizes[nsizes - 1];
  for (int z = nsizes - 1; z >= 0; z--)
    if (ok[z]) chosen = sizes[z];
  free(pt);
  free(ok);
  *out = t;
  return chosen;
}

/* Sets parameter `name` of the scene to v; returns its old value. */
static double set_param(nl_harness *r, a2_smoke_scene *sc, const char *name, double v)
{
  double old = 0.0, o = sc->offset;
  double *x = !strcmp(name, "slope")          ? &sc->s.slope
              : !strcmp(name, "freq")         ? &sc->s.freq
              : !strcmp(name, "kappa")        ? &sc->s.kappa
              : !strcmp(name, "step")         ? &sc->s.step
              : !strcmp(name, "stop_opacity") ? &sc->s.stop_opacity
              : !strcmp(name, "octave_bound") ? &sc->s.octave_bound
              : !strcmp(name, "offset")       ? &o
                                              : NULL;
  if (!x) nl_harness_die(r, 1, "smoke sweep: no scene parameter '%s'", name);
  old = *x;
  *x = v;
  sc->offset = (int)o;
  return old;
}

double a2_smoke_param(nl_harness *r, const a2_smoke_scene *sc, const char *name)
{
  a2_smoke_scene c = *sc;
  return set_param(r, &c, name, 0.0);
}

/* One reading: its curve into the sweep table, its fit into the fit table;
 * returns rss_log. */
static double sweep_reading(nl_harness *r, const a2_smoke_scene *sc, const char *vary, double value,
                            int is_free, const int *octaves, const double *paper, int n, int seeds,
                            nl_table *sweep, nl_table *fit)
{
  a2_smoke_point *pt = nl_xmalloc((size_t)n * sizeof *pt);
  double *er = nl_xmalloc(2 * (size_t)n * sizeof *er), *tr = er + n;
  a2_smoke_curve(r, sc, octaves, n, seeds, 1, pt, NULL);
  const nl_bounds_smoke *s = &sc->s;
  for (int i = 0; i < n; i++) {
    er[i] = pt[i].eval_ratio;
    tr[i] = pt[i].time_ratio;
    nl_table_append(sweep, "sdddddddiiiddddd", vary, s->slope, s->freq, s->kappa, s->step,
                    s->stop_opacity, s->octave_bound, (double)sc->offset, s->width, octaves[i],
                    pt[i].terms, er[i], pt[i].eval_ratio_sd, tr[i], pt[i].time_ratio_sd, paper[i]);
  }
  double rms, trms;
  int worst = 0;
  double rss = a2_smoke_fit(er, paper, n, &rms, &worst);
  a2_smoke_fit(tr, paper, n, &trms, NULL);
  char label[64];
  snprintf(label, sizeof label, "%s=%g", vary, value);
  nl_table_append(fit, "ssddddddddddidii", vary, label, s->slope, s->freq, s->kappa, s->step,
                  s->stop_opacity, s->octave_bound, (double)sc->offset, rss, rms,
                  exp(fabs(log(er[worst]) - log(paper[worst]))), octaves[worst], trms, 0, is_free);
  free(pt);
  free(er);
  return rss;
}

a2_smoke_scene a2_smoke_sweep(nl_harness *r, const a2_smoke_scene *center, const double *slopes,
                              int nslopes, const a2_smoke_vary *vary, int nvary, const int *octaves,
                              const double *paper, int n, int seeds, nl_table **sweep,
                              nl_table **fit)
{
  const char *scols[] = { "vary",          "slope",        "freq",          "kappa",
                          "step",          "stop_opacity", "octave_bound",  "offset",
                          "size",          "octaves",      "terms",         "eval_ratio",
                          "eval_ratio_sd", "time_ratio",   "time_ratio_sd", "paper_ratio" };
  const char *fcols[] = {
    "vary",          "reading",         "slope",  "freq",    "kappa",      "step",
    "stop_opacity",  "octave_bound",    "offset", "rss_log", "rms_factor", "worst_factor",
    "worst_octaves", "time_rms_factor", "best",   "free"
  };
  *sweep = nl_table_alloc(16, scols);
  *fit = nl_table_alloc(16, fcols);
  int total = nslopes;
  for (int v = 0; v < nvary; v++) total += vary[v].n;
  a2_smoke_scene *sc = nl_xmalloc((size_t)total * sizeof *sc);
  double best_rss = INFINITY;
  int best = 0, k = 0, part = 0;   /* part: the reading's share of the progress bar */
  /* The slope first (the parameter the ratio at N = 0 hangs on), ... */
  for (int a = 0; a < nslopes; a++, k++) {
    sc[k] = *center;
    sc[k].s.slope = slopes[a];
    nl_harness_substage(r, part++, total);
    double rss =
        sweep_reading(r, &sc[k], "slope", slopes[a], 1, octaves, paper, n, seeds, *sweep, *fit);
    if (rss < best_rss) {
      best_rss = rss;
      best = k;
    }
  }
  /* ... then every other parameter one at a time around the best slope. */
  a2_smoke_scene around = sc[best];
  for (int v = 0; v < nvary; v++)
    for (int j = 0; j < vary[v].n; j++) {
      sc[k] = around;
      nl_harness_substage(r, part++, total);
      if (set_param(r, &sc[k], vary[v].name, vary[v].v[j]) == vary[v].v[j])
        continue; /* the slope row */
      double rss = sweep_reading(r, &sc[k], vary[v].name, vary[v].v[j], vary[v].is_free, octaves,
                                 paper, n, seeds, *sweep, *fit);
      if (vary[v].is_free && rss < best_rss) {
        best_rss = rss;
        best = k;
      }
      k++;
    }
  nl_table_set(*fit, (size_t)best, "best", 1.0);
  a2_smoke_scene out = sc[best];
  free(sc);
  return out;
}

size_t a2_smoke_nearest(const nl_table *sweep, int octaves)
{
  size_t best = 0;
  double d = INFINITY;
  for (size_t i = 0; i < sweep->nrows; i++) {
    if (strcmp(nl_table_text(sweep, i, "vary"), "slope") ||
        nl_table_value(sweep, i, "octaves") != octaves)
      continue;
    double e =
        fabs(log(nl_table_value(sweep, i, "eval_ratio") / nl_table_value(sweep, i, "paper_ratio")));
    if (e < d) {
      d = e;
      best = i;
    }
  }
  return best;
}

double a2_smoke_ratio_at(const nl_table *sweep, const char *vary, double slope, int octaves)
{
  for (size_t i = 0; i < sweep->nrows; i++)
    if (!strcmp(nl_table_text(sweep, i, "vary"), vary) &&
        nl_table_value(sweep, i, "slope") == slope &&
        nl_table_value(sweep, i, "octaves") == octaves)
      return nl_table_value(sweep, i, "eval_ratio");
  return NAN;
}

nl_image *a2_smoke_decision_image(nl_harness *r, const nl_noise_perm3 *p, const nl_bounds_smoke *s)
{
  nl_error err;
  size_t n = (size_t)s->width * s->height;
  int *k = nl_xmalloc(n * sizeof *k);
  if (nl_bounds_smoke_decision_map(p, s, 0.0, k, &err)) nl_harness_die(r, 1, "%s", err.msg);
  double *v = nl_xmalloc(n * sizeof *v);
  for (size_t q = 0; q < n; q++) v[q] = k[q];
  /* Colours by the number of octaves that decided the pixel (blue: few,
   * red: all), black where the value is inside (0, 1) and never decided. */
  int top = s->octaves + 1;
  const double pos[] = {
    0.0, 0.25 * s->octaves, 0.5 * s->octaves, 0.75 * s->octaves, s->octaves, s->octaves + 0.5, top
  };
  const float rgb[][3] = { { 0.1f, 0.2f, 0.9f }, { 0.1f, 0.8f, 0.9f },
                           { 0.2f, 0.8f, 0.2f }, { 0.95f, 0.85f, 0.1f },
                           { 0.9f, 0.1f, 0.1f }, { 0.9f, 0.1f, 0.1f },
                           { 0, 0, 0 } };
  nl_texture_ramp ramp = nl_texture_ramp_linear(7, pos, rgb);
  nl_image *im = nl_texture_ramp_image(&ramp, v, s->width, s->height, 0.0, 1.0);
  free(k);
  free(v);
  return im;
}

nl_table *a2_smoke_timing(const a2_smoke_point *pt, const int *octaves, const double (*paper_ms)[2],
                          int n, const nl_table *size_check, double alt_slope)
{
  const char *cols[] = { "octaves",
                         "terms",
                         "plain_ms",
                         "plain_ms_sd",
                         "bounded_ms",
                         "bounded_ms_sd",
                         "ratio",
                         "paper_plain_ms",
                         "paper_bounded_ms",
                         "paper_ratio",
                         "plain_evals",
                         "bounded_evals",
                         "eval_ratio",
                         "eval_ratio_sd",
                         "max_diff_levels",
                         "max_noise",
                         "alt_slope",
                         "alt_eval_ratio",
                         "alt_eval_ratio_sd",
                         "plain_evals_per_term",
                         "plain_ms_per_term",
                         "paper_plain_ms_per_term" };
  nl_table *t = nl_table_alloc(22, cols);
  double ref = 0;
  for (size_t k = 0; k < size_check->nrows; k++)
    ref = fmax(ref, nl_table_value(size_check, k, "size"));
  for (int i = 0; i < n; i++) {
    size_t k = 0;
    while (k < size_check->nrows && !(nl_table_value(size_check, k, "slope") == alt_slope &&
                                      nl_table_value(size_check, k, "size") == ref &&
                                      nl_table_value(size_check, k, "octaves") == octaves[i]))
      k++;
    double alt = k < size_check->nrows ? nl_table_value(size_check, k, "eval_ratio") : NAN;
    double alt_sd = k < size_check->nrows ? nl_table_value(size_check, k, "eval_ratio_sd") : NAN;
    /* the paper's plain sum runs i = 0..N: N + 1 terms */
    nl_table_append(t, "iiddddddddddddiddddddd", octaves[i], pt[i].terms, pt[i].plain_ms,
                    pt[i].plain_ms_sd, pt[i].bounded_ms, pt[i].bounded_ms_sd, pt[i].time_ratio,
                    paper_ms[i][0], paper_ms[i][1], paper_ms[i][0] / paper_ms[i][1],
                    pt[i].plain_evals, pt[i].bounded_evals, pt[i].eval_ratio, pt[i].eval_ratio_sd,
                    pt[i].diff, pt[i].max_noise, alt_slope, alt, alt_sd,
                    pt[i].plain_evals / pt[i].terms, pt[i].plain_ms / pt[i].terms,
                    paper_ms[i][0] / (octaves[i] + 1));
  }
  return t;
}

double a2_smoke_fit_columns(const nl_table *t, const char *ours, const char *paper,
                            double *rms_factor)
{
  double *v = nl_xmalloc(2 * t->nrows * sizeof *v);
  for (size_t k = 0; k < t->nrows; k++) {
    v[k] = nl_table_value(t, k, ours);
    v[t->nrows + k] = nl_table_value(t, k, paper);
  }
  double rss = a2_smoke_fit(v, v + t->nrows, (int)t->nrows, rms_factor, NULL);
  free(v);
  return rss;
}

void a2_smoke_panels(nl_harness *r, nl_image **panels, const int *octaves, int n)
{
  char(*labels)[32] = nl_xmalloc((size_t)n * sizeof *labels);
  const char **lp = nl_xmalloc((size_t)n * sizeof *lp);
  for (int i = 0; i < n; i++) {
    snprintf(labels[i], sizeof labels[i], "N = %d", octaves[i]);
    lp[i] = labels[i];
  }
  nl_study_montage(r, (const nl_image *const *)panels, lp, n, 3, "Smoke ball, incremental bounding",
                   "balls.png");
  nl_harness_write_image(r, panels[n - 1], "ball.png");
  for (int i = 0; i < n; i++) nl_image_free(panels[i]);
  free(labels);
  free(lp);
}
