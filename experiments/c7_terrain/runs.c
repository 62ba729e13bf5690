/* C7's runs: nl_study_cheng_runs's seeds, keeping every seed's optimised
 * table, since the seam measurements are over all of them, and the same
 * runs' unoptimised start tables as the baseline. */
#include "c7.h"
#include "base/nl_parallel.h"

#include <stdlib.h>

typedef struct {
  const nl_cheng_config *c;
  const nl_cheng_pattern *pat;
  unsigned long seed0;
  nl_cheng_eval *evs;
  nl_noise_grad2 **tables;
  nl_status *st;
  nl_error *err;
} job;

/* Seed i at nl_seed_replicate(seed0, i), as nl_study_cheng_runs: the same
 * runs and results, whatever the thread count. */
static void item(void *ctx, size_t i, int thread)
{
  (void)thread;
  job *j = ctx;
  j->st[i] = nl_cheng_run(j->c, j->pat, nl_seed_replicate(j->seed0, (long)i), &j->evs[i], NULL,
                          &j->tables[i], &j->err[i]);
}

static unsigned long seed0(const nl_study_cheng *s)
{
  unsigned long seed = nl_harness_seed(s->r);
  return s->role ? nl_seed_stream(seed, s->role, 0) : seed;
}

nl_cheng_eval *c7_runs(const nl_study_cheng *s, const nl_cheng_config *c,
                       const nl_cheng_pattern *pat, nl_noise_grad2 **tables)
{
  int k = nl_harness_seeds(s->r);
  nl_cheng_eval *evs = nl_xmalloc((size_t)k * sizeof *evs);
  nl_status *st = nl_xmalloc((size_t)k * sizeof *st);
  nl_error *err = nl_xmalloc((size_t)k * sizeof *err);
  job j = { c, pat, seed0(s), evs, tables, st, err };
  nl_parallel_for((size_t)k, nl_harness_threads(s->r), item, &j);
  for (int i = 0; i < k; i++)
    if (st[i]) nl_harness_die(s->r, 1, "%s", err[i].msg);
  free(st);
  free(err);
  return evs;
}

void c7_start_tables(const nl_study_cheng *s, const nl_cheng_config *c, nl_noise_grad2 **tables)
{
  for (int i = 0; i < nl_harness_seeds(s->r); i++) {
    tables[i] = nl_noise_grad2_alloc(c->m);
    nl_noise_grad2_seed(tables[i], nl_seed_replicate(seed0(s), i)); /* as nl_cheng_run */
  }
}

void c7_seam_controls(const nl_study_cheng *s, nl_table *seams, const nl_cheng_config *c,
                      const nl_cheng_pattern *pat, const char *name)
{
  int k = nl_harness_seeds(s->r);
  nl_noise_grad2 **t = nl_xmalloc((size_t)k * sizeof *t);
  /* without the control term (w2 = 0), and without eq. 3.13's propagation */
  const char *what[2] = { "w2=0", "no propagation" };
  for (int v = 0; v < 2; v++) {
    nl_cheng_config cv = *c;
    if (v == 0)
      cv.w2 = 0;
    else
      cv.propagate = 0;
    free(c7_runs(s, &cv, pat, t));
    const char *lab[2] = { name, what[v] };
    /* measured under the thesis's config: the same value and octaves */
    nl_study_cheng_seams_add(seams, 2, lab, (const nl_noise_grad2 *const *)t, k, c, pat);
    for (int i = 0; i < k; i++) nl_noise_grad2_free(t[i]);
  }
  c7_start_tables(s, c, t);
  const char *lab[2] = { name, "start table" };
  nl_study_cheng_seams_add(seams, 2, lab, (const nl_noise_grad2 *const *)t, k, c, pat);
  for (int i = 0; i < k; i++) nl_noise_grad2_free(t[i]);
  free(t);
}
