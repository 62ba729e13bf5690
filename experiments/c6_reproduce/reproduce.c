/* C6's reproductions (reproduce.h): per texture the original, its pool, the
 * matched-K0 mixture and reproductions drawn from it, with and without the
 * swap of the high entries. */
#include "reproduce.h"
#include "controls.h"
#include "stats/nl_stats.h"
#include "base/nl_parallel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* clang-format off */
static const char *const c6_rep_cols[] = {
  "texture", "swap", "rep", "E_ks", "p_ks", "E_con", "ks2_D", "ms_reproduce", "ms_texture"
};
/* the last four: controllability (nl_study_cheng_control_text) */
static const char *const c6_sum_cols[] = {
  "texture", "kind", "n", "E_ks", "E_ks_sd", "E_con", "E_con_sd", "p_ks_min", "ks2_D", "ks2_D_sd",
  "below_ks", "below_con", "ms_reproduce", "ms_texture", "seconds_opt", "K", "r_pattern",
  "contrast", "E_con_random", "E_con_const"
};
/* clang-format on */

typedef struct {
  double ks[4096], con[4096], p[4096], d[4096], ms[4096], mst[4096], rp[4096], ct[4096];
} samples;

/* One reproduction's evaluation, item i of a nl_parallel_for: the texture a
 * user waits for (its time added to the draw's), E_KS, E_Con and the
 * two-sample D against the original's angles, into slot i of s. The draws
 * themselves stay on the calling thread, in order, from the one generator
 * (nl_cheng_reproduce), so the tables are those of the serial loop. */
typedef struct {
  const nl_study_cheng_repro *rp;
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  nl_noise_grad2 **out;
  samples *s;
  nl_status *st;
  nl_error *err;
} reps_job;

static void evaluate_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  reps_job *j = ctx;
  samples *s = j->s;
  double t0 = nl_time_now();
  /* what a user waits for: table + texture */
  nl_image *tex = nl_study_cheng_texture_image(j->out[i], j->c, C6_TEXTURE_SIDE);
  s->mst[i] = s->ms[i] + 1e3 * (nl_time_now() - t0);
  nl_image_free(tex);
  nl_cheng_eval ev;
  nl_stats_ks_result ks;
  if ((j->st[i] = nl_cheng_evaluate(j->out[i], j->c, j->pat, &ev, &j->err[i])) ||
      (j->st[i] = nl_stats_ks2_test(j->out[i]->angle, j->out[i]->m, j->rp->opt->angle,
                                    j->rp->opt->m, &ks, &j->err[i])))
    return;
  s->ks[i] = ev.e_ks;
  s->con[i] = ev.e_con;
  s->p[i] = ev.p_ks;
  s->d[i] = ks.d;
  s->rp[i] = ev.r_pattern;
  s->ct[i] = ev.contrast;
}

/* nrep reproductions of rp's model m with the given swap into out[0..nrep-1]
 * and slots 0..nrep-1 of s: drawn in order on this thread, evaluated on the
 * run's threads. */
static void reproduce_all(nl_harness *r, const nl_study_cheng_repro *rp, const nl_cheng_model *m,
                          const nl_cheng_config *c, const nl_cheng_pattern *pat, double swap,
                          gsl_rng *rng, nl_noise_grad2 **out, samples *s, int nrep)
{
  nl_error err;
  for (int i = 0; i < nrep; i++) {
    out[i] = nl_noise_grad2_alloc(rp->opt->m);
    double t0 = nl_time_now();
    if (nl_cheng_reproduce(rp->opt, m, swap, rng, out[i], &err))
      nl_harness_die(r, 1, "%s", err.msg);
    s->ms[i] = 1e3 * (nl_time_now() - t0);
  }
  nl_status *st = nl_xcalloc((size_t)nrep, sizeof *st);
  nl_error *errs = nl_xmalloc((size_t)nrep * sizeof *errs);
  reps_job j = { rp, c, pat, out, s, st, errs };
  nl_parallel_for((size_t)nrep, nl_harness_threads(r), evaluate_item, &j);
  for (int i = 0; i < nrep; i++) /* the first failure in order, as a serial loop met it */
    if (st[i]) nl_harness_die(r, 1, "%s", errs[i].msg);
  free(st);
  free(errs);
}

static double frac_below(const double *x, int n, double v)
{
  int b = 0;
  for (int i = 0; i < n; i++) b += x[i] < v;
  return (double)b / n;
}

static void summary_row(nl_table *t, const char *tex, const char *kind, const samples *s, int n,
                        const nl_study_cheng_repro *rp, size_t k)
{
  nl_table_append(
      t, "ssdddddddddddddddddd", tex, kind, (double)n, nl_stats_mean(s->ks, n, NL_STATS_RUNNING),
      nl_stats_sd(s->ks, n, NL_STATS_RUNNING), nl_stats_mean(s->con, n, NL_STATS_RUNNING),
      nl_stats_sd(s->con, n, NL_STATS_RUNNING), nl_stats_min(s->p, n),
      nl_stats_mean(s->d, n, NL_STATS_RUNNING), nl_stats_sd(s->d, n, NL_STATS_RUNNING),
      frac_below(s->ks, n, rp->ev.e_ks), frac_below(s->con, n, rp->ev.e_con),
      nl_stats_mean(s->ms, n, NL_STATS_RUNNING), nl_stats_mean(s->mst, n, NL_STATS_RUNNING),
      rp->seconds_opt, (double)k, nl_stats_mean(s->rp, n, NL_STATS_RUNNING),
      nl_stats_mean(s->ct, n, NL_STATS_RUNNING), rp->ev.e_con_random, rp->ev.e_con_const);
}

/* Montage: the original texture and C6_NSHOW reproductions, E_KS / E_Con under each. */
static void montage(nl_harness *r, const char *tex, const nl_cheng_config *c,
                    nl_noise_grad2 *const *g, const samples *s, const nl_study_cheng_repro *rp)
{
  nl_image *im[C6_NSHOW + 1];
  char lab[C6_NSHOW + 1][80], title[96], file[64];
  const char *labp[C6_NSHOW + 1];
  for (int i = 0; i <= C6_NSHOW; i++) {
    im[i] = nl_study_cheng_texture_image(i ? g[i - 1] : rp->opt, c, 192);
    if (i)
      snprintf(lab[i], sizeof lab[i], "r%d %.4f / %.0f", i, s->ks[i - 1], s->con[i - 1]);
    else
      snprintf(lab[i], sizeof lab[i], "orig %.4f / %.0f", rp->ev.e_ks, rp->ev.e_con);
    labp[i] = lab[i];
  }
  snprintf(title, sizeof title, "%s: E_KS / E_Con", tex);
  nl_image *m = nl_image_montage((const nl_image *const *)im, labp, C6_NSHOW + 1, 3, title);
  snprintf(file, sizeof file, "textures_%s.png", tex);
  nl_harness_write_image(r, m, file);
  nl_image_free(m);
  for (int i = 0; i <= C6_NSHOW; i++) nl_image_free(im[i]);
}

nl_table *c6_reps_alloc(void)
{
  return nl_table_alloc(sizeof c6_rep_cols / sizeof *c6_rep_cols, c6_rep_cols);
}

nl_table *c6_reps_summary_alloc(void)
{
  return nl_table_alloc(sizeof c6_sum_cols / sizeof *c6_sum_cols, c6_sum_cols);
}

/* The mixture of the pool with the cutoff matched to the thesis's initial K
 * (cutoff < 0, target_k = th->k0) and the run's seed; exit 1 on error. */
static nl_cheng_model *matched_model(nl_harness *r, const nl_cheng_pool *pool,
                                     const nl_study_cheng_thesis_gmm *th,
                                     const nl_cheng_model_options *mo)
{
  nl_cheng_model_options o = *mo;
  o.cutoff = -1; /* the cutoff that gives the thesis's initial K */
  o.target_k = (size_t)th->k0;
  o.gmm.seed = nl_harness_seed(r);
  nl_cheng_model *m;
  nl_error err;
  if (nl_cheng_model_fit(pool, &o, nl_harness_seed(r), &m, &err))
    nl_harness_die(r, 1, "%s", err.msg);
  return m;
}

/* Texture th from its original and pool (rp) on: mixture, reproductions,
 * rows, montage and CDF table. */
static void reproduce_from(const nl_study_cheng *st, nl_table *reps, nl_table *sum,
                           const nl_study_cheng_thesis_gmm *th, const nl_cheng_config *cp,
                           const nl_cheng_pattern *pat, nl_study_cheng_repro *rp,
                           const nl_cheng_model_options *mo, int nrep, double swap,
                           c6_controls *ctl)
{
  nl_harness *r = st->r;
  const nl_cheng_config c = *cp;
  samples *s = nl_xcalloc(1, sizeof *s);
  nl_cheng_model *m = matched_model(r, rp->pool, th, mo);
  s->ks[0] = rp->ev.e_ks;
  s->con[0] = rp->ev.e_con;
  s->p[0] = rp->ev.p_ks;
  s->rp[0] = rp->ev.r_pattern;
  s->ct[0] = rp->ev.contrast;
  summary_row(sum, th->texture, "original", s, 1, rp, m->k);
  if (!m->gmm) { /* degenerate model: reported, nothing to reproduce */
    nl_harness_text(r, "%s: no mixture (%s), no reproductions.\n", th->texture, m->msg);
  } else {
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, nl_seed_stream(nl_harness_seed(r), "c6.reproduce", 0));
    nl_noise_grad2 **g = nl_xmalloc((size_t)nrep * sizeof *g);
    const double swaps[2] = { swap, 0.0 }; /* and without the swap, to separate the two effects */
    for (int w = 0; w < 2; w++) {
      reproduce_all(r, rp, m, &c, pat, swaps[w], rng, g, s, nrep);
      for (int i = 0; i < nrep; i++)
        nl_table_append(reps, "sdddddddd", th->texture, swaps[w], (double)i, s->ks[i], s->p[i],
                        s->con[i], s->d[i], s->ms[i], s->mst[i]);
      char kind[48];
      snprintf(kind, sizeof kind, "reproduced_swap_%g", swaps[w]);
      summary_row(sum, th->texture, kind, s, nrep, rp, m->k);
      if (w == 0) {
        c6_controls_add(ctl, st, th->texture, &c, pat, rp, s->ks, s->p, s->ms, nrep);
        for (int i = 0; i <= C6_NSHOW; i++) { /* the montage's tables (tests/oracle_cheng.c) */
          char name[16];
          snprintf(name, sizeof name, i ? "r%d" : "original", i);
          const char *l[2] = { th->texture, name };
          nl_study_cheng_tables_add(ctl->tables, 2, l, i ? g[i - 1] : rp->opt);
        }
        montage(r, th->texture, &c, g, s, rp);
        const nl_noise_grad2 *tabs[C6_NSHOW + 1] = { rp->opt };
        const char *names[C6_NSHOW + 1] = { "original", "r1", "r2", "r3", "r4",
                                            "r5",       "r6", "r7", "r8" };
        for (int i = 0; i < C6_NSHOW; i++) tabs[i + 1] = g[i];
        nl_table *cdf = nl_study_cheng_cdf_table(tabs, names, C6_NSHOW + 1);
        char file[64];
        snprintf(file, sizeof file, "cdf_%s.tsv", th->texture);
        nl_harness_write_table(r, cdf, file);
        nl_table_free(cdf);
      }
      for (int i = 0; i < nrep; i++) nl_noise_grad2_free(g[i]);
    }
    free(g);
    gsl_rng_free(rng);
  }
  nl_cheng_model_free(m);
  free(s);
}

/* The n textures' originals (one multi-level run each, serial inside) as
 * items of one nl_parallel_for: each writes its own rp[i], st[i], err[i]. */
typedef struct {
  const nl_cheng_config *c;
  nl_cheng_pattern **pat;
  unsigned long seed;
  nl_study_cheng_repro *rp;
  nl_status *st;
  nl_error *err;
} originals_job;

static void original_item(void *ctx, size_t i, int thread)
{
  (void)thread;
  originals_job *j = ctx;
  j->st[i] = nl_study_cheng_repro_original(&j->c[i], j->pat[i], j->seed, &j->rp[i], &j->err[i]);
}

void c6_reproduce_cases(const nl_study_cheng *st, nl_table *reps, nl_table *sum,
                        const nl_study_cheng_thesis_gmm *ths, int n,
                        const nl_cheng_pool_options *po, const nl_cheng_model_options *mo, int nrep,
                        double swap, c6_controls *ctl)
{
  nl_harness *r = st->r;
  nl_cheng_config *c = nl_xmalloc((size_t)n * sizeof *c);
  nl_cheng_pattern **pat = nl_xmalloc((size_t)n * sizeof *pat);
  nl_study_cheng_repro *rp = nl_xcalloc((size_t)n, sizeof *rp);
  nl_status *sts = nl_xcalloc((size_t)n, sizeof *sts);
  nl_error *errs = nl_xmalloc((size_t)n * sizeof *errs);
  for (int i = 0; i < n; i++) { /* the texture's pattern and control term */
    pat[i] = nl_study_cheng_pattern(st, ths[i].pattern);
    c[i] = st->c;
    c[i].con = ths[i].con;
  }
  originals_job j = { c, pat, nl_harness_seed(r), rp, sts, errs };
  nl_parallel_for((size_t)n, nl_harness_threads(r), original_item, &j);
  for (int i = 0; i < n; i++) {
    nl_error err;
    if (sts[i]) nl_harness_die(r, 1, "%s: %s", ths[i].texture, errs[i].msg);
    if (nl_study_cheng_repro_pool(&rp[i], &c[i], pat[i], po, nl_harness_seed(r),
                                  &err)) /* Q runs on the run's threads */
      nl_harness_die(r, 1, "%s: %s", ths[i].texture, err.msg);
    reproduce_from(st, reps, sum, &ths[i], &c[i], pat[i], &rp[i], mo, nrep, swap, ctl);
    nl_study_cheng_repro_clear(&rp[i]);
    nl_cheng_pattern_free(pat[i]);
    nl_harness_progress(r, (i + 1.0) / n, ths[i].texture);
  }
  free(c);
  free(pat);
  free(rp);
  free(sts);
  free(errs);
}
