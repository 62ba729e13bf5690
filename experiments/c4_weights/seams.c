/* C4's seams: the seam ratio (nl_cheng_eval: the largest mean |step| across
 * one column or row boundary of a 128^2 raster over the mean of all) of Table
 * 4.1's optimised panels beside the unoptimised tables they started from, so
 * that a seam the optimisation adds shows as a difference between the two. */
#include "c4.h"
#include "study/nl_study_cheng.h"

#include <stdio.h>
#include <stdlib.h>

/* The k start tables of nl_cheng_run for the run's seeds (nl_study_cheng_runs:
 * seed nl_seed_replicate(seed0, i)), evaluated unoptimised. */
static nl_cheng_eval *start_evals(const nl_study_cheng *s, const nl_cheng_config *c,
                                  const nl_cheng_pattern *pat)
{
  int k = nl_harness_seeds(s->r);
  unsigned long seed0 =
      s->role ? nl_seed_stream(nl_harness_seed(s->r), s->role, 0) : nl_harness_seed(s->r);
  nl_cheng_eval *evs = nl_xmalloc((size_t)k * sizeof *evs);
  for (int i = 0; i < k; i++) {
    nl_error err;
    nl_noise_grad2 *g = nl_noise_grad2_alloc(c->m);
    nl_noise_grad2_seed(g, nl_seed_replicate(seed0, i));
    if (nl_cheng_evaluate(g, c, pat, &evs[i], &err)) nl_harness_die(s->r, 1, "%s", err.msg);
    evs[i].e_con_random = evs[i].e_con;
    nl_noise_grad2_free(g);
  }
  return evs;
}

nl_table *c4_seams(const nl_study_cheng *s, const nl_cheng_config *base,
                   const nl_cheng_pattern *pat, const nl_cheng_eval *main_evs, int npair)
{
  nl_harness *r = s->r;
  const char *labels[] = { "reading", "panel" };
  int k = nl_harness_seeds(r);
  nl_table *t = nl_study_cheng_summary_alloc(2, labels);
  for (int sw = 0; sw < 2; sw++)
    for (int i = 0; i < npair; i++) {
      char panel[4] = { (char)('a' + i), 0 };
      const char *l[2] = { sw ? "swapped" : "printed", panel };
      nl_study_cheng_rows_add(s, t, 2, l, main_evs + (size_t)(2 * i + sw) * k);
    }
  nl_cheng_eval *st = start_evals(s, base, pat);
  const char *lu[2] = { "unoptimised", "-" };
  nl_study_cheng_rows_add(s, t, 2, lu, st);
  free(st);
  size_t u = t->nrows - 1;
  nl_table *wt = nl_study_cheng_welch_alloc();
  double lo[2] = { 1e300, 1e300 }, hi[2] = { 0, 0 }, pmin[2] = { 1, 1 }, pmax[2] = { 0, 0 };
  int above[2] = { 0, 0 }; /* panels significantly above the unoptimised tables */
  for (size_t q = 0; q < u; q++) {
    int sw = q >= (size_t)npair;
    double p = nl_study_cheng_welch_add(wt, t, q, u, "seam_ratio", nl_table_text(t, q, "panel"),
                                        nl_table_text(t, q, "reading"), "unoptimised");
    double v = nl_table_value(t, q, "seam_ratio");
    lo[sw] = v < lo[sw] ? v : lo[sw];
    hi[sw] = v > hi[sw] ? v : hi[sw];
    pmin[sw] = p < pmin[sw] ? p : pmin[sw];
    pmax[sw] = p > pmax[sw] ? p : pmax[sw];
    above[sw] += p < 0.05 && v > nl_table_value(t, u, "seam_ratio");
  }
  nl_harness_write_table(r, t, "seams.tsv");
  nl_harness_write_table(r, wt, "seam_tests.tsv");
  nl_harness_report_table(r, wt,
                          "Seam ratio of each panel against the unoptimised start tables of the "
                          "same seeds: Welch's t-test over seeds",
                          4);
  nl_harness_text(
      r,
      "Seams: the seam ratio (largest mean |step| across one column or row boundary of a 128^2 "
      "raster over the mean of all) is %.3g..%.3g over the printed panels (Welch p against the "
      "unoptimised tables %.2g..%.2g) and %.3g..%.3g over the swapped ones (p %.2g..%.2g), against "
      "%.3g +- %.3g for the unoptimised start tables of the same %d seeds: the optimisation raises "
      "the seam ratio above the unoptimised tables' at alpha = 0.05 in %d of the %d printed and %d "
      "of the %d swapped panels.\n",
      lo[0], hi[0], pmin[0], pmax[0], lo[1], hi[1], pmin[1], pmax[1],
      nl_table_value(t, u, "seam_ratio"), nl_table_value(t, u, "seam_ratio_sd"), k, above[0], npair,
      above[1], npair);
  nl_table_free(wt);
  return t;
}

void c4_seams_domain(const nl_study_cheng *s, const nl_cheng_config *cs, const nl_cheng_pattern *pat,
                     nl_noise_grad2 *const *firsts, int npair)
{
  const char *labels[] = { "panel", "tables_from" };
  nl_table *t = nl_study_cheng_seams_alloc(2, labels);
  nl_cheng_config *c0 = nl_xmalloc((size_t)npair * sizeof *c0);
  const nl_cheng_pattern **pp = nl_xmalloc((size_t)npair * sizeof *pp);
  nl_noise_grad2 **f0 = nl_xmalloc((size_t)npair * sizeof *f0);
  for (int i = 0; i < npair; i++) {
    c0[i] = cs[2 * i];
    c0[i].origin = 0;
    pp[i] = pat;
  }
  free(nl_study_cheng_runs(s, npair, c0, pp, f0));
  for (int o = 1; o >= 0; o--)
    for (int i = 0; i < npair; i++) {
      char panel[4] = { (char)('a' + i), 0 };
      const char *l[2] = { panel, "optimised" };
      nl_study_cheng_seams_add(t, 2, l, (const nl_noise_grad2 *const *)(o ? &firsts[2 * i] : &f0[i]),
                               1, o ? &cs[2 * i] : &c0[i], pat);
    }
  for (int i = 0; i < npair; i++) nl_noise_grad2_free(f0[i]);
  nl_harness_write_table(s->r, t, "seams_domain.tsv");
  nl_study_cheng_seams_text(s->r, t, "Fig 4.8's printed panels (first seed)");
  nl_table_free(t);
  free(c0);
  free(pp);
  free(f0);
}
