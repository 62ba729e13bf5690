/* C8 - controllable noise in 3D (Cheng 2009, ch. 5 future work; beyond the
 * thesis): the gradients are unit vectors on the sphere, the uniformity term
 * is KS on z = cos(polar) and on the azimuth phi (E_stat = max of the two D's),
 * control points on a G^3 grid follow a volume (torus, ball, slab), E = w1
 * E_stat + w2 E_Con (eq. 3.9) annealed with the 2D schedule (nl_cheng3.h).
 * Reported per pattern for the optimised and the random start tables: the
 * uniformity tests (KS z, KS phi, Kuiper phi, Rayleigh) and C1's
 * controllability columns, E_Con's split into offset, contrast and shape,
 * and a chi-square test of the independence of z and phi (indep.h), the
 * half of "uniform on the sphere" the margins do not test: a verdict row
 * per pattern (no thesis number exists to compare with). */
#include "report.h"
#include "sphere.h"
#include "study/nl_study.h"

#include <stdio.h>

#define NPAT 3

static const char *const patterns[NPAT] = { "torus", "ball", "slab" };

int main(int argc, char **argv)
{
  nl_harness *r = nl_harness_begin(
      "c8_sphere", "C8 - controllable noise in 3D: gradients on the sphere", argc, argv);
  int q = nl_harness_quick(r);
  nl_cheng3_config c = nl_cheng3_config_default();
  int grid =
      (int)nl_harness_param_int(r, "grid", q ? 8 : 16, 2, 64,
                                "control grid G: G^3 control cells over the unit cube (quick 8)");
  c.w1 = nl_harness_param(
      r, "w1", c.w1, 0, 1e6,
      "weight of E_stat = max(D_z, D_phi) in E = w1 E_stat + w2 E_Con (eq. 3.9; thesis 0.995)");
  c.w2 = nl_harness_param(r, "w2", c.w2, 0, 1e6, "weight of E_Con (eq. 3.9; thesis 0.005)");
  c.octaves = (int)nl_harness_param_int(r, "octaves", c.octaves, 1, 6,
                                        "octaves F of the 3D fractal sum (eq. 3.10 in 3D)");
  c.f1 = nl_harness_param(
      r, "f1", c.f1, 0.5, 64,
      "starting frequency f1, f_l = f1 2^(l-1) (f1 2^(F-1) = G puts cell centres mid-cell)");
  c.sched.n_temps = (int)nl_harness_param_int(r, "temps", q ? 8 : c.sched.n_temps, 1, 100000,
                                              "annealing temperature steps (quick 8)");
  c.sched.moves_per_var =
      nl_harness_param(r, "moves_per_var", q ? 5 : c.sched.moves_per_var, 1e-3, 1e6,
                       "moves per temperature, as a multiple of the M table entries (quick 5)");
  int size = (int)nl_harness_param_int(r, "size", q ? 64 : 160, 16, 1024,
                                       "side in pixels of each slice panel (quick 64)");
  int vox = (int)nl_harness_param_int(r, "voxels", q ? 16 : 32, 4, 96,
                                      "side of the voxel raster of the volume figure (quick 16)");
  nl_harness_params_done(r);
  nl_error err;
  if (nl_cheng_config_check(&c, &err) != NL_OK) nl_harness_die(r, 2, "%s", err.msg);
  int k = nl_harness_seeds(r);
  nl_table *sum = c8_summary_alloc();
  nl_table *base = c8_baselines_alloc();
  for (int p = 0; p < NPAT; p++) {
    nl_cheng3_pattern *pat;
    if (nl_cheng3_pattern_shape(patterns[p], grid, &pat, &err) != NL_OK)
      nl_harness_die(r, 2, "%s", err.msg);
    nl_cheng3_table *t0, *t = c8_seeds(r, &c, pat, sum, base, patterns[p], &t0, NULL);
    nl_image *panels[C8_NPANELS];
    const char *labels[C8_NPANELS];
    c8_slices(t, t0, &c, pat, size, panels, labels);
    char file[64];
    char title[128];
    snprintf(file, sizeof file, "slices_%s.png", patterns[p]);
    snprintf(title, sizeof title, "C8: %s, slices of the 3D control value (first seed)",
             patterns[p]);
    nl_study_montage(r, (const nl_image *const *)panels, labels, C8_NPANELS, 4, title, file);
    for (int i = 0; i < C8_NPANELS; i++) nl_image_free(panels[i]);
    c8_slices_figure(r, patterns[p], file);
    if (p == 0) { /* the headline pattern's uniformity and volume tables (gnuplot) */
      nl_table *u = c8_ecdf_table(t, t0);
      nl_table *v = c8_voxel_table(t, &c, pat, vox);
      nl_harness_write_table(r, u, "ecdf.tsv");
      nl_harness_write_table(r, v, "voxels.tsv");
      size_t cnt[NL_CHENG_MAX_OCTAVES];
      nl_table *lv = c8_levels_table(t, &c, cnt);
      nl_harness_write_table(r, lv, "levels.tsv");
      c8_levels_report(r, lv, &c, cnt);
      nl_table_free(u);
      nl_table_free(v);
      nl_table_free(lv);
    }
    nl_cheng3_table_free(t);
    nl_cheng3_table_free(t0);
    nl_cheng3_pattern_free(pat);
  }
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_write_table(r, base, "baselines.tsv");
  c8_report(r, sum, base, &c, grid, k);
  nl_table_free(sum);
  nl_table_free(base);
  /* measured tolerances (nl_harness.h; data/blas_spread.tsv) */
  nl_harness_check_measured(r, "*", 100);
  return nl_harness_end(r);
}
