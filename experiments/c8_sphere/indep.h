/* indep.h - C8's test that z = cos(polar) and phi are independent.
 *
 * Directions are uniform on the sphere iff (z, phi) is uniform on
 * [-1, 1] x [0, 2 pi) (Archimedes: the area element is dz dphi), i.e. iff
 * both margins are uniform AND z and phi are independent. E_stat tests the
 * margins only (a table could pair them). Here the M pairs fall in a
 * bins x bins grid of equal cells: Pearson's chi-square of independence of
 * the contingency table (expected R_i C_j / M, df (bins - 1)^2) and of
 * uniformity of the whole grid (expected M / bins^2, df bins^2 - 1).
 *
 *   c8_indep res;
 *   c8_indep_test(t, 8, &res);   // 512 pairs, 64 cells of 8 expected
 */
#ifndef C8_INDEP_H
#define C8_INDEP_H

#include "cheng/nl_cheng3.h"

typedef struct {
  double chi2_indep, p_indep; /* contingency: independence of z and phi */
  double chi2_joint, p_joint; /* the grid against equal counts: uniform on the sphere */
  int df_indep, df_joint;
} c8_indep;

/* bins >= 2; a margin with an empty bin leaves that row or column out of
 * the independence statistic and df. */
void c8_indep_test(const nl_cheng3_table *t, int bins, c8_indep *out);
/* The same from M pairs (z in [-1, 1], phi in [0, 2 pi)). */
void c8_indep_pairs(const double *z, const double *phi, size_t m, int bins, c8_indep *out);
/* The same M values of z and of phi paired by rank (the k-th smallest z with
 * the k-th smallest phi): both margins, and so E_stat, unchanged, z and phi
 * as dependent as they can be. The independence verdict's negative control:
 * a table E_stat cannot tell from the optimised one, which the test must
 * reject. */
void c8_indep_paired(const double *z, const double *phi, size_t m, int bins, c8_indep *out);

#endif
