/* sphere.h - the harness side of C8 (controllable noise in 3D,
 * nl_cheng3.h): runs over seeds into a summary table, the uniformity and
 * volume tables the gnuplot scripts read, and slice images.
 *
 *   nl_table *sum = c8_summary_alloc();
 *   nl_cheng3_table *t0;   // rows: optimised, random
 *   nl_table *base = c8_baselines_alloc();
 *   nl_cheng3_table *t = c8_seeds(r, &c, pat, sum, base, "torus", &t0, NULL);
 *   nl_table *u = c8_ecdf_table(t, t0);   // ECDFs of z and phi
 *   nl_table *v = c8_voxel_table(t, &c, pat, 24);
 *   nl_image *panels[C8_NPANELS];
 *   const char *labels[C8_NPANELS];
 *   c8_slices(t, t0, &c, pat, 128, panels, labels);
 */
#ifndef C8_SPHERE_H
#define C8_SPHERE_H

#include "cheng/nl_cheng3.h"
#include "harness/nl_harness.h"
#include "image/nl_image.h"
#include "table/nl_table.h"

/* Columns: pattern, table (optimised | random), seeds, then mean (and _sd or
 * _min) over seeds of E_stat, D_z, p_z, D_phi, p_phi, p_stat, V_kuiper,
 * p_kuiper, R_rayleigh, p_rayleigh, E_con, rms_con, E, r_pattern, contrast,
 * E_con_random, E_con_const, con_vs_const (E_con / E_con_const: > 1 is
 * worse than the best constant volume), uniform (fraction of seeds with
 * p_stat >= 0.05), then E_Con's parts (nl_cheng3_eval) con_offset_frac,
 * con_contrast_frac, con_shape_frac (each a fraction of its run's E_Con,
 * averaged), E_con_offset (mean), mean_D (the pattern's), and the z-phi
 * test (indep.h, C8_INDEP_BINS^2 cells): chi2_indep, p_indep (mean, min),
 * p_indep_bonf = min(1, seeds x min p_indep) (every seed's table
 * independent), p_indep_pooled (the seeds' chi2_indep summed against chi2
 * with the summed df: a consistent pairing), p_joint (mean, min). */
#define C8_INDEP_BINS 8 /* 8 x 8 cells: 8 of the M = 512 pairs expected per cell */
nl_table *c8_summary_alloc(void);
/* The baselines of C8's verdicts (baselines.tsv): per pattern the rows
 * optimised (E_Con mean and sd over seeds), flat (the best constant
 * volume's E_Con, sd 0), random (the start tables' E_Con) and paired (the
 * optimised tables' z and phi paired by rank, indep.h: mean chi2_indep and
 * p_indep_bonf = min(1, seeds x smallest p)); columns pattern, table, seeds,
 * E_con, E_con_sd, chi2_indep, p_indep_bonf (n/a where a row has none). */
nl_table *c8_baselines_alloc(void);
/* The run's seeds (nl_seed_replicate of the base seed, nl_harness_seeds of
 * them) on pat: one row for the optimised tables and one for their random
 * start tables, and the pattern's four rows of base. Returns the first seed's optimised table and (in *start)
 * its start table (caller frees both). Exit 1 on error. *cpu_s: the
 * optimisations' summed wall time (not written in any table). */
nl_cheng3_table *c8_seeds(nl_harness *r, const nl_cheng3_config *c, const nl_cheng3_pattern *pat,
                          nl_table *sum, nl_table *base, const char *name,
                          nl_cheng3_table **start, double *seconds);
/* ECDFs: F = i/M, then sorted u = (z + 1)/2 and phi / 2 pi of each table:
 * columns F, z_opt, phi_opt, z_rand, phi_rand. */
nl_table *c8_ecdf_table(const nl_cheng3_table *opt, const nl_cheng3_table *rnd);
/* n^3 raster of the unit cube: x, y, z, D (the pattern's cell), c, in_pattern
 * (D >= 1/2) and top_c (c among the highest fraction of the raster equal
 * to the pattern's fraction with D >= 1/2: the iso-surface of c that
 * encloses the pattern's volume). */
nl_table *c8_voxel_table(const nl_cheng3_table *t, const nl_cheng3_config *c,
                         const nl_cheng3_pattern *pat, int n);
#define C8_NPANELS 8 /* slice panels: D, c, c stretched, random c; xy and xz */
/* C8_NPANELS panels of size x size: for the slice z = 1/2 (xy) and y = 1/2 (xz): the
 * pattern D, c on its own 0..1 scale, c stretched to its 1st..99th
 * percentile, and the random start table's c stretched. labels[8] filled
 * with short static strings ("D xy", "c xy", "c xy str", "rand xy", ... xz). */
void c8_slices(const nl_cheng3_table *t, const nl_cheng3_table *t0, const nl_cheng3_config *c,
               const nl_cheng3_pattern *pat, int size, nl_image **panels, const char **labels);
/* Under the thesis's multi-level rule: octave, frequency, lattice_points,
 * new_entries (entries first used by that octave's lattice) and
 * fraction_of_M; the counts also in cnt[octaves]. */
nl_table *c8_levels_table(const nl_cheng3_table *t, const nl_cheng3_config *c, size_t *cnt);

#endif
