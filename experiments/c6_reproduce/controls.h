/* controls.h - C6's negative controls and the rows of sec. 4.4's other
 * claims (controls.c): per texture, filled while the texture's original,
 * pool and reproductions exist (c6_reproduce_cases), decided at the end.
 *
 *   below_ctl.tsv  random (unoptimised) tables in place of reproductions:
 *                  texture, kind "random_tables", error, n, below,
 *                  frac_below, p_sign (below.tsv's columns): the control of
 *                  "often below the original's";
 *   uniform.tsv    "we do not lose the statistical property": texture,
 *                  tables (reproductions, w1 = 0), runs, E_ks, p_ks_min,
 *                  p_uniform = min(1, runs p_ks_min); the control is the same
 *                  texture optimised for E_Con alone (w1 = 0, the run's seeds);
 *   speed.tsv      "real-time": texture, what (reproduction, one frame at 30
 *                  Hz, optimisation), ms, ms_sd, n: a reproduced table (the
 *                  noise the thesis generates; any table's texture costs the
 *                  same to render) below one frame, the optimisation as the
 *                  control;
 *   pool_er.tsv    the pool's E_R (eq. 3.18) below the original table's:
 *                  texture, runs (the pool's best per run, their random
 *                  starts), n, below (runs under the original's E_R),
 *                  frac_below, p_below = P(X >= below), X ~ Binomial(n, 1/2),
 *                  e_original, e_mean.
 */
#ifndef C6_CONTROLS_H
#define C6_CONTROLS_H

#include "study/nl_study_cheng.h"

typedef struct {
  nl_table *below_ctl, *uniform, *speed, *pool_er;
  nl_table *tables;   /* tables.tsv: the montages' tables (texture, table: original, r1..) */
} c6_controls;

void c6_controls_init(c6_controls *k);
void c6_controls_free(c6_controls *k);
/* Texture tex from its original rp (with its pool), config c on pat: the
 * random tables' below counts (nrep tables), the w1 = 0 runs' uniformity,
 * the optimisation's time and the pool's E_R; the reproductions' side from
 * their E_KS eks, KS p-values p and times ms (the table's draw), nrep each. */
void c6_controls_add(c6_controls *k, const nl_study_cheng *s, const char *tex,
                     const nl_cheng_config *c, const nl_cheng_pattern *pat,
                     const nl_study_cheng_repro *rp, const double *eks, const double *p,
                     const double *ms, int nrep);
/* Writes the four tables and declares the verdicts: uniformity and speed
 * per texture, the pool's E_R per texture, each with its control. */
void c6_controls_text(nl_harness *r, const c6_controls *k);

#endif
