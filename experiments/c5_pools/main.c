/* C5 - Cheng 2009 sec. 3.5, Tables 4.2-4.4: noise reproduction's model.
 * For erosion, marble and cloud: the original optimised table, a solution
 * pool of E_R (eq. 3.16-3.18) over the low-frequency entries (Q runs, N
 * solutions each within epsilon of the run's best), complete-linkage
 * clustering for the initial K, GMM by EM with the AIC rule; the thesis's
 * table beside ours; K against the cutoff; the other low/high split on
 * erosion; and, beyond the paper, whether the mixture describes the pool
 * (held-out likelihood, per-angle KS) for three model variants. */
#include "pools.h"
#include "readings.h"
#include "report.h"
#include "harness/nl_harness.h"

#define NTEX 3 /* erosion, marble, cloud (Tables 4.2, 4.3, 4.4) */

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c5_pools",
                      "C5 - noise reproduction: pools, clustering, GMM/AIC (Tables 4.2-4.4)", &argc,
                      argv);
  nl_harness *r = s.r;
  nl_cheng_pool_options po;
  nl_cheng_model_options mo;
  nl_study_cheng_repro_params(r, &po, &mo);
  /* the run's AIC paths keep their models' large arrays for the next ones */
  mo.gmm.workspace = nl_gmm_workspace_alloc();
  c5_readings_options ro;
  c5_readings_params(r, &ro);
  int alt = (int)nl_harness_param_int(r, "alt_low_levels", nl_harness_quick(r) ? 2 : 0, 0, 7,
                                      "C5 repeats erosion with this low/high split (low_levels); "
                                      "0: no repeat (paper scale: cut for time)");
  nl_study_cheng_ready(&s);
  nl_harness_note(r, "pool_threads", "%d (results do not depend on it)", po.threads);
  int nseeds = nl_harness_seeds(r);
  if (nseeds > C5_MAXSEEDS) nseeds = C5_MAXSEEDS;

  c5_pools T;
  c5_pools_alloc(&T);
  c5_readings R;
  c5_readings_alloc(&R);
  int ncase = NTEX + (alt && alt != po.low_levels && alt < s.c.octaves);
  /* Units (shards, nl_harness.h): texture t's replicate k is unit t reps + k;
   * the other split on erosion, when asked, is the last. Each is computed
   * from its own seeds, so any shard computes it alike; the tables are made
   * from the stored units in this order. */
  long nunits = (long)NTEX * ro.reps + (ncase > NTEX);
  /* Replicate 0 also makes the older tables, the all-rows fits and C6's
   * draws: 105+ CPU s against 21 for another replicate at paper scale (one
   * thread, load 12); the other split's case, its older tables only. */
  double *cost = nl_xmalloc((size_t)nunits * sizeof *cost);
  for (long u = 0; u < nunits; u++) cost[u] = u >= (long)NTEX * ro.reps ? 3 : u % ro.reps ? 1 : 6;
  nl_harness_units_weighted(r, nunits, cost);
  free(cost);
  for (int t = 0; t < ncase; t++) {
    const nl_study_cheng_thesis_gmm *th = &nl_study_cheng_thesis_gmm_tables[t % NTEX];
    long u0 = (long)t * ro.reps;
    int mine = 0;
    long u1 = t < NTEX ? u0 + ro.reps : nunits;
    for (long u = u0; u < u1; u++) mine += nl_harness_unit_mine(r, u);
    if (!mine) continue;
    if (t < NTEX) {
      /* every reading over pool replicates; replicate 0 also fills the older tables */
      nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, th->pattern);
      nl_cheng_config c = s.c;
      c.con = th->con;
      nl_cheng_model_options mm = mo; /* the texture's fits share one memo of EM fits */
      mm.gmm.memo = nl_gmm_memo_alloc();
      for (int k = 0; k < ro.reps; k++) {
        if (!nl_harness_unit_mine(r, u0 + k)) continue;
        nl_harness_unit_begin(r, u0 + k);
        c5_readings_unit(&s, th, &po, &mm, &ro, nseeds, 1, k, pat, &c);
        nl_harness_unit_end(r);
      }
      nl_gmm_memo_free(mm.gmm.memo);
      nl_cheng_pattern_free(pat);
    } else {
      nl_cheng_pool_options p = po;
      p.low_levels = alt; /* the other split, measured on erosion */
      c5_pools Tu;
      c5_pools_alloc(&Tu);
      nl_harness_unit_begin(r, u0);
      c5_pool_case(&s, &Tu, th, &p, &mo, nseeds, 0);
      c5_pools_put(r, &Tu);
      nl_harness_unit_end(r);
      c5_pools_free(&Tu);
    }
    nl_harness_progress(r, (t + 1.0) / ncase, th->texture);
  }
  nl_gmm_workspace_free(mo.gmm.workspace); /* every model is freed by now */
  mo.gmm.workspace = NULL;
  nl_harness_units_done(r); /* --shard: its file written, the run ends here */
  for (int t = 0; t < ncase; t++) {
    const nl_study_cheng_thesis_gmm *th = &nl_study_cheng_thesis_gmm_tables[t % NTEX];
    if (t < NTEX)
      c5_readings_gather(&s, &R, &T, th, &ro, (long)t * ro.reps);
    else {
      c5_pools_get(r, (long)t * ro.reps, &T);
      nl_harness_unit_notes(r, (long)t * ro.reps);
    }
  }
  c5_pools_write(r, &T);

  /* EM's sums go through BLAS: their tolerances are measured (below). */
  const char *best = c5_readings_write(r, &R);
  c5_readings_report(r, &R, best); /* the headline reading and its verdicts */
  c5_report(r, &T, &po, &mo, &s.c, s.grid, nseeds);
  c5_pools_free(&T);
  c5_readings_free(&R);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
