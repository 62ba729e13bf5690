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
  for (int t = 0; t < ncase; t++) {
    const nl_study_cheng_thesis_gmm *th = &nl_study_cheng_thesis_gmm_tables[t % NTEX];
    nl_cheng_pool_options p = po;
    if (t < NTEX) {
      /* every reading over pool replicates; replicate 0 also fills the older tables */
      c5_readings_case(&s, &R, &T, th, &p, &mo, &ro, nseeds, 1);
    } else {
      p.low_levels = alt; /* the other split, measured on erosion */
      c5_pool_case(&s, &T, th, &p, &mo, nseeds, 0);
    }
    nl_harness_progress(r, (t + 1.0) / ncase, th->texture);
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
