/* C8 - controllable noise in 3D (Cheng 2009, ch. 5 future work; beyond the
 * thesis): the gradients are unit vectors on the sphere, the uniformity term
 * is KS on z = cos(polar) and on the azimuth phi (E_stat = max of the two D's),
 * control points on a G^3 grid follow a volume (torus, ball, slab), E = w1
 * E_stat + w2 E_Con (eq. 3.9) annealed with the 2D schedule (nl_cheng3.h).
 * Reported per pattern for the optimised and the random start tables: the
 * uniformity tests (KS z, KS phi, Kuiper phi, Rayleigh) and C1's
 * controllability columns. No thesis number exists: no verdicts. */
#include "sphere.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define NPAT 3
static const char *const patterns[NPAT] = {"torus", "ball", "slab"};

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin("c8_sphere", "C8 - controllable noise in 3D: gradients on the sphere", argc, argv);
  int q = nl_harness_quick(r);
  nl_cheng3_config c = nl_cheng3_config_default();
  int grid = (int)nl_harness_param_int(r, "grid", q ? 8 : 16, 2, 64, "control grid G: G^3 control cells over the unit cube (quick 8)");
  c.w1 = nl_harness_param(r, "w1", c.w1, 0, 1e6, "weight of E_stat = max(D_z, D_phi) in E = w1 E_stat + w2 E_Con (eq. 3.9; thesis 0.995)");
  c.w2 = nl_harness_param(r, "w2", c.w2, 0, 1e6, "weight of E_Con (eq. 3.9; thesis 0.005)");
  c.octaves = (int)nl_harness_param_int(r, "octaves", c.octaves, 1, 6, "octaves F of the 3D fractal sum (eq. 3.10 in 3D)");
  c.f1 = nl_harness_param(r, "f1", c.f1, 0.5, 64, "starting frequency f1, f_l = f1 2^(l-1) (f1 2^(F-1) = G puts cell centres mid-cell)");
  c.sched.n_temps = (int)nl_harness_param_int(r, "temps", q ? 8 : c.sched.n_temps, 1, 100000, "annealing temperature steps (quick 8)");
  c.sched.moves_per_var = nl_harness_param(r, "moves_per_var", q ? 5 : c.sched.moves_per_var, 1e-3, 1e6,
                                           "moves per temperature, as a multiple of the M table entries (quick 5)");
  int size = (int)nl_harness_param_int(r, "size", q ? 64 : 160, 16, 1024, "side in pixels of each slice panel (quick 64)");
  int vox = (int)nl_harness_param_int(r, "voxels", q ? 16 : 32, 4, 96, "side of the voxel raster of the volume figure (quick 16)");
  nl_harness_params_done(r);
  nl_error err;
  if (nl_cheng_config_check(&c, &err) != NL_OK) nl_harness_die(r, 2, "%s", err.msg);
  int k = nl_harness_seeds(r);
  nl_table *sum = nl_study_cheng3_summary_alloc();
  for (int p = 0; p < NPAT; p++) {
    nl_cheng3_pattern *pat;
    if (nl_cheng3_pattern_shape(patterns[p], grid, &pat, &err) != NL_OK) nl_harness_die(r, 2, "%s", err.msg);
    nl_cheng3_table *t0, *t = nl_study_cheng3_seeds(r, &c, pat, sum, patterns[p], &t0, NULL);
    nl_image *panels[8];
    const char *labels[8];
    nl_study_cheng3_slices(t, t0, &c, pat, size, panels, labels);
    char file[64], title[128], cap[320];
    snprintf(file, sizeof file, "slices_%s.png", patterns[p]);
    snprintf(title, sizeof title, "C8: %s, slices of the 3D control value (first seed)", patterns[p]);
    nl_study_montage(r, (const nl_image *const *)panels, labels, 8, 4, title, file);
    for (int i = 0; i < 8; i++) nl_image_free(panels[i]);
    snprintf(cap, sizeof cap, "%s: slices xy at z = 1/2 (top) and xz at y = 1/2 (bottom): pattern D | optimised c on 0..1 | "
             "the same stretched to its 1st..99th percentile (str) | the random start table's c, stretched (first seed)", patterns[p]);
    nl_harness_figure(r, file, cap);
    if (p == 0) {   /* the headline pattern's uniformity and volume tables (gnuplot) */
      nl_table *u = nl_study_cheng3_ecdf_table(t, t0), *v = nl_study_cheng3_voxel_table(t, &c, pat, vox);
      nl_harness_write_table(r, u, "ecdf.tsv");
      nl_harness_write_table(r, v, "voxels.tsv");
      size_t cnt[NL_CHENG_MAX_OCTAVES];
      nl_table *lv = nl_study_cheng3_levels_table(t, &c, cnt);
      nl_harness_write_table(r, lv, "levels.tsv");
      nl_harness_text(r, "**Levels.** Multi-level annealing (sec. 3.4.2) gives level l the table entries first used by "
                         "octave l's lattice. In 3D with M = %zu: octave 1 (f = %g) uses %d entries, octave 2 adds %d, "
                         "so %.0f%% of the table belongs to the first two levels and the last level owns %d. We "
                         "anneal all entries against all octaves in one level (levels.tsv).\n", c.m, c.f1, (int)cnt[0],
                      c.octaves > 1 ? (int)cnt[1] : 0, 100.0 * (cnt[0] + (c.octaves > 1 ? cnt[1] : 0)) / c.m, (int)cnt[c.octaves - 1]);
      nl_harness_report_table(r, lv, "Entries per annealing level under the thesis's multi-level rule (first seed's permutation)", 3);
      nl_table_free(u); nl_table_free(v); nl_table_free(lv);
    }
    nl_cheng3_table_free(t); nl_cheng3_table_free(t0); nl_cheng3_pattern_free(pat);
  }
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_text(r, "**Setting (beyond the thesis).** %d^3 control cells, M = %zu unit gradients, F = %d octaves from "
                     "f1 = %g (a1 = %g), w1 = %g, w2 = %g, %d temperatures x %g moves per entry, %d seeds per row. "
                     "E_stat = max(D_z, D_phi): KS of z = cos(polar) against U(-1, 1) and of phi against U(0, 2 pi), "
                     "uniform on the sphere iff both hold independently; p_stat = min(1, 2 min(p_z, p_phi)) "
                     "(Bonferroni). Kuiper on phi and Rayleigh's test (3 M R^2 ~ chi2_3, R the mean resultant) "
                     "are checks the objective does not optimise.\n", grid, c.m, c.octaves, c.f1, c.a1, c.w1, c.w2,
                  c.sched.n_temps, c.sched.moves_per_var, k);
  nl_harness_report_columns(r, sum, "summary.tsv", "pattern,table,seeds,E_stat,E_stat_sd,p_stat_min,uniform,p_kuiper_min,"
                            "p_rayleigh_min,E_con,E_con_sd,r_pattern,r_pattern_sd,contrast,E_con_random,E_con_const,con_vs_const",
                            "Per pattern: optimised tables against their random start tables (mean and spread over seeds)", 4);
  for (size_t i = 0; i + 1 < sum->nrows; i += 2) {   /* rows: optimised, random per pattern */
    double e = nl_table_value(sum, i, "E_con"), e0 = nl_table_value(sum, i, "E_con_const");
    double er = nl_table_value(sum, i + 1, "E_con");
    nl_harness_text(r, "%s: E_stat %.4f (random tables %.4f), smallest p_stat %.3f, smallest Rayleigh p %.3f; "
                       "E_Con %.4g +- %.3g, %.0f%% below the random tables' %.4g, r with the pattern %.2f (random %.2f), "
                       "contrast %.3f. %s (best constant volume: E_Con %.4g, ratio %.2f; the pattern's own sd is %.3f).\n",
                    nl_table_cell_text(sum, i, 0, (char[64]){0}), nl_table_value(sum, i, "E_stat"),
                    nl_table_value(sum, i + 1, "E_stat"), nl_table_value(sum, i, "p_stat_min"),
                    nl_table_value(sum, i, "p_rayleigh_min"), e, nl_table_value(sum, i, "E_con_sd"), 100 * (1 - e / er), er,
                    nl_table_value(sum, i, "r_pattern"), nl_table_value(sum, i + 1, "r_pattern"), nl_table_value(sum, i, "contrast"),
                    e > e0 ? "**Worse than the best constant volume** in the E_Con sense" : "Better than the best constant volume",
                    e0, e / e0, sqrt(e0 / (double)grid / grid / grid));
  }
  nl_harness_figure(r, "uniformity.png", "Uniformity on the sphere (torus, first seed): ECDF minus the uniform CDF of "
                                         "(z + 1)/2 and phi / 2 pi, optimised and random start table");
  nl_harness_figure(r, "volume.png", "Torus (first seed): the voxels inside the pattern (left) and the voxels of the "
                                     "optimised c above the level that encloses the same volume (right)");
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h; data/blas_spread.tsv) */
  return nl_harness_end(r);
}
