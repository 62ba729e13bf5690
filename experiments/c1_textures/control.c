/* C1's "the texture follows the pattern" (Fig 4.1-4.4): per case, r with the
 * pattern against random tables and E_Con against a flat image
 * (nl_study_cheng_control_add); per texture the same two tests pooled over
 * its three patterns, which decide the verdicts; and where the first seed's
 * textures have seams (nl_study_cheng_seams_add). */
#include "c1.h"
#include "stats/nl_stats.h"

#include <stdlib.h>

static const char *const claim_cols[] = {
  "texture",         "patterns",          "seeds",          "r_pattern",
  "r_random_mean",   "r_random_sd",       "n_random",       "p_random",
  "E_con",           "E_con_const",       "con_vs_const",   "p_flat",
  "con_offset_frac", "con_contrast_frac", "con_shape_frac",
};
#define NCLAIM (sizeof claim_cols / sizeof *claim_cols)

nl_table *c1_claims_alloc(void) { return nl_table_alloc(NCLAIM, claim_cols); }

void c1_claims_add(nl_table *t, const char *texture, int np, int k, const nl_cheng_eval *const *evs,
                   const double *const *nulls, int nrand)
{
  /* r: the mean over the patterns of each pattern's mean over the seeds,
   * against the mean over the patterns of one random table each (the
   * patterns' tables are independent draws) */
  double r = 0, *null = nl_xcalloc((size_t)nrand, sizeof *null);
  for (int p = 0; p < np; p++) {
    for (int i = 0; i < k; i++) r += evs[p][i].r_pattern / (k * np);
    for (int j = 0; j < nrand; j++) null[j] += nulls[p][j] / np;
  }
  /* E_Con: per seed the sum over the patterns, against the sum of their flat
   * images' */
  double *e = nl_xcalloc((size_t)k, sizeof *e), e0 = 0, off = 0, con = 0, shp = 0, all = 0;
  for (int p = 0; p < np; p++) {
    e0 += evs[p][0].e_con_const;
    for (int i = 0; i < k; i++) {
      e[i] += evs[p][i].e_con;
      off += evs[p][i].e_con_offset;
      con += evs[p][i].e_con_contrast;
      shp += evs[p][i].e_con_shape;
      all += evs[p][i].e_con;
    }
  }
  double em = nl_stats_mean(e, (size_t)k, NL_STATS_RUNNING);
  size_t q = nl_table_append_empty(t);
  double row[NCLAIM] = { 0,
                         np,
                         k,
                         r,
                         nl_stats_mean(null, (size_t)nrand, NL_STATS_RUNNING),
                         nl_stats_sd(null, (size_t)nrand, NL_STATS_RUNNING),
                         nrand,
                         nl_study_mc_p_greater(null, (size_t)nrand, r),
                         em,
                         e0,
                         em / e0,
                         nl_study_t_below_p(e, (size_t)k, e0),
                         all > 0 ? off / all : 0,
                         all > 0 ? con / all : 0,
                         all > 0 ? shp / all : 0 };
  for (size_t c = 1; c < NCLAIM; c++) nl_table_set(t, q, claim_cols[c], row[c]);
  nl_table_set_text(t, q, "texture", texture);
  free(e);
  free(null);
}

void c1_seams_start(const nl_study_cheng *s, nl_table *seams, const nl_cheng_config *c,
                    const nl_cheng_pattern *pat, const char *pattern)
{
  nl_noise_grad2 *g = nl_noise_grad2_alloc(c->m);
  /* nl_cheng_run's start table of the first seed (nl_study_cheng_runs) */
  nl_noise_grad2_seed(g, nl_seed_replicate(nl_harness_seed(s->r), 0));
  const char *lab[3] = { nl_cheng_con_name(c->con), pattern, "start table" };
  nl_study_cheng_seams_add(seams, 3, lab, (const nl_noise_grad2 *const *)&g, 1, c, pat);
  nl_noise_grad2_free(g);
}

nl_table *c1_uniform_alloc(void)
{
  const char *cols[] = { "texture", "tables", "runs", "E_ks", "p_ks_min", "p_uniform" };
  return nl_table_alloc(6, cols);
}

void c1_uniform_add(nl_table *t, const char *texture, const char *tables, int np, int k,
                    const nl_cheng_eval *const *evs)
{
  double e = 0, pmin = 1;
  for (int p = 0; p < np; p++)
    for (int i = 0; i < k; i++) {
      e += evs[p][i].e_ks / (np * k);
      pmin = evs[p][i].p_ks < pmin ? evs[p][i].p_ks : pmin;
    }
  double n = (double)np * k, pu = n * pmin < 1 ? n * pmin : 1;
  nl_table_append(t, "ssdddd", texture, tables, n, e, pmin, pu);
}

void c1_seams_domain(const nl_study_cheng *s, nl_table *seams, int n, const nl_cheng_config *cs,
                     nl_cheng_pattern *const *pats, const char *const *names)
{
  nl_cheng_config *c0 = nl_xmalloc((size_t)n * sizeof *c0);
  const nl_cheng_pattern **p0 = nl_xmalloc((size_t)n * sizeof *p0);
  nl_noise_grad2 **f0 = nl_xmalloc((size_t)n * sizeof *f0);
  for (int i = 0; i < n; i++) {
    c0[i] = cs[2 * i];
    c0[i].origin = 0;
    p0[i] = pats[i];
  }
  free(nl_study_cheng_runs(s, n, c0, p0, f0));
  for (int i = 0; i < n; i++) {
    const char *sl[3] = { nl_cheng_con_name(c0[i].con), names[i], "optimised" };
    nl_study_cheng_seams_add(seams, 3, sl, (const nl_noise_grad2 *const *)&f0[i], 1, &c0[i], p0[i]);
    nl_noise_grad2_free(f0[i]);
  }
  free(c0);
  free(p0);
  free(f0);
}

void c1_uniformity(const nl_study_cheng *s, nl_table *uni, int ntex, int npat,
                   const nl_cheng_config *cs, nl_cheng_pattern *const *pats,
                   const nl_cheng_eval *evs, int k)
{
  int nh = ntex * npat;
  nl_cheng_config *cw = nl_xmalloc((size_t)nh * sizeof *cw);
  const nl_cheng_pattern **pw = nl_xmalloc((size_t)nh * sizeof *pw);
  for (int i = 0; i < nh; i++) {
    cw[i] = cs[2 * i];
    cw[i].w1 = 0;
    pw[i] = pats[i];
  }
  nl_cheng_eval *ew = nl_study_cheng_runs(s, nh, cw, pw, NULL);
  const nl_cheng_eval **e = nl_xmalloc((size_t)npat * sizeof *e);
  const nl_cheng_eval **w = nl_xmalloc((size_t)npat * sizeof *w);
  for (int t = 0; t < ntex; t++) {
    for (int j = 0; j < npat; j++) {
      e[j] = evs + (size_t)(2 * (t * npat + j)) * k;
      w[j] = ew + (size_t)(t * npat + j) * k;
    }
    c1_uniform_add(uni, nl_cheng_con_name(cs[2 * npat * t].con), "optimised", npat, k, e);
    c1_uniform_add(uni, nl_cheng_con_name(cs[2 * npat * t].con), "w1 = 0", npat, k, w);
  }
  free(e);
  free(w);
  free(cw);
  free(pw);
  free(ew);
}
