/* joint.h - A2's joint fit (Arnerin 2009, Table 5.1): the three scene
 * parameters the paper does not state (slope a, base frequency f0,
 * extinction kappa) varied together over a grid, the reading of "N
 * octaves" fixed at the paper's terms = N + 1 (its eq. 5.4 and cost sum
 * run i = 0..N).
 *
 * Each grid point is an untimed curve (smoke.h: the bounded march only,
 * the plain count samples * terms) fitted to the paper's six time ratios by
 * rss_log; the best point is a fit of 3 parameters to 6 numbers. Its growth
 * r(N_last) / r(N_2), the ratio at the largest N over the ratio at the
 * third, does not involve the slope's level: the table gives it for every
 * grid point, so that no choice of the three can be said to reach the
 * paper's.
 *
 *   nl_table *jt;
 *   a2_smoke_scene best = a2_joint_fit(r, &center, &grid, label, paper, 6, 3, &jt);
 */
#ifndef A2_JOINT_H
#define A2_JOINT_H

#include "smoke.h"

enum { A2_JOINT_MAX = 12 };
/* The grid: every combination of the values of the three parameters. */
typedef struct {
  int ns, nf, nk;
  double slope[A2_JOINT_MAX], freq[A2_JOINT_MAX], kappa[A2_JOINT_MAX];
} a2_joint_grid;

/* The grid of A2: slope -3 ... -8 (9 values), f0 1, 2, 4, 8, kappa 15 ...
 * 15360 (doubling, 11 values: a one-at-a-time sweep found its optimum at
 * the edge of 15 ... 120, a joint one at the edge of 15 ... 960); quick: 2
 * slopes x 2 kappas at f0 = 2. */
a2_joint_grid a2_joint_grid_default(int quick);

/* joint_fit.tsv: slope, freq, kappa, rss_log, rms_factor, worst_factor,
 * worst_octaves, growth (eval ratio at octaves[n-1] over octaves[2]), best
 * (1 on the smallest rss_log), edge (on the best row: 1 when a parameter
 * with three values or more sits at the first or last of its values).
 * Curves over `seeds` at center's image size and step, stop and bound.
 * Returns the best point's scene (offset 1). */
a2_smoke_scene a2_joint_fit(nl_harness *r, const a2_smoke_scene *center, const a2_joint_grid *g,
                            const int *octaves, const double *paper, int n, int seeds,
                            nl_table **out);

/* growth.tsv, one row: quantity, paper_growth (paper[n-1] / paper[2]),
 * growth (pt[n-1].eval_ratio / pt[2].eval_ratio), growth_sd (propagated
 * from the two sds as if independent), grid_min, grid_max (column growth
 * of the joint table), readings (its rows). */
nl_table *a2_joint_growth(const a2_smoke_point *pt, const double *paper, int n,
                          const nl_table *joint);

#endif
