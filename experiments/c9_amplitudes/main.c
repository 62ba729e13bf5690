/* C9 - beyond the thesis (Cheng 2009 ch. 5: "adjust the amplitude in the
 * fractal sum to achieve much more closely matched the user control pattern"):
 * the octave amplitudes 1/a_l become variables of the same objective (eq. 3.9),
 * each bounded within [1/R, R] x the thesis's (eq. 3.10) and annealed with the
 * gradient angles at the level where its octave enters (nl_cheng.h, OCTAVE
 * AMPLITUDES AS VARIABLES). One pattern per texture of C1 (its first), plus
 * the two rows C1 finds worse than a flat image (cloud/star, fire/gradient):
 * fixed against optimised amplitudes, over the run's seeds, on E_KS, E_Con
 * (and its offset, contrast and shape parts) and controllability, with
 * Welch's t-test between the two; and the same optimisation with the gains'
 * bounds widened (amp_wide), to see whether the bounds set the result. */
#include "c9.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NCASE 6
#define NCOL  5
#define NCOND C9_NCOND /* fixed, optimised within [1/R, R], within the wide bounds */

static const struct {
  nl_cheng_con con;
  const char *pattern;
} cases[NCASE] = { { NL_CHENG_CON_PLAIN, "flower" }, { NL_CHENG_CON_SIN, "rings" },
                   { NL_CHENG_CON_ABS, "disc" },     { NL_CHENG_CON_FIRE, "flower" },
                   { NL_CHENG_CON_PLAIN, "star" },   { NL_CHENG_CON_FIRE, "gradient" } };
static const char *const quantities[] = { "E_ks", "E_con", "r_pattern", "contrast", "roughness" };
static const char *const conds[NCOND] = { "fixed", "optimised", "optimised_wide" };

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c9_amplitudes",
                      "C9 - octave amplitudes optimised with the gradients (thesis ch. 5)", &argc,
                      argv);
  nl_harness *r = s.r;
  int q = nl_harness_quick(r);
  int ncase = (int)nl_harness_param_int(r, "cases", NCASE, 1, NCASE,
                                        "cases run, in order: cloud/flower, marble/rings, "
                                        "erosion/disc, fire/flower, cloud/star, fire/gradient");
  double range = nl_harness_param(r, "amp_range", 4, 1, 64,
                                  "R: each optimised amplitude 1/a_l within [1/R, R] x the "
                                  "thesis's");
  double wide = nl_harness_param(r, "amp_wide", 64, 1, 1e6,
                                 "the wide bounds: the same optimisation with gains within "
                                 "[1/R_wide, R_wide] (do the bounds set the result?)");
  int size = (int)nl_harness_param_int(r, "size", q ? 96 : 192, 16, 2048,
                                       "side in pixels of the value images (quick 96)");
  nl_study_cheng_ready(&s);
  const char *labels[] = { "texture", "pattern", "amplitudes" };
  nl_table *sum = nl_study_cheng_summary_alloc(3, labels);
  c9_tables tb = { sum, c9_parts_alloc(3, labels), c9_gains_alloc(3, labels),
                   c9_timing_alloc(3, labels) };
  nl_table *tests = nl_study_cheng_welch_alloc();
  nl_image *panels[NCOL * NCASE];
  const char *plab[NCOL * NCASE];
  char group[NCASE][48];
  /* Every case, fixed and optimised, over the seeds as one set of independent
   * runs on the run's threads (nl_study_cheng_runs); rows in case order. */
  /* then, per case, the negative control: gains fixed at random (c9.h) */
  nl_cheng_config cs[(NCOND + 1) * NCASE];
  nl_cheng_pattern *pats[NCASE];
  const nl_cheng_pattern *pp[(NCOND + 1) * NCASE];
  nl_noise_grad2 *firsts[(NCOND + 1) * NCASE];
  for (int i = 0; i < ncase; i++) {
    nl_cheng_config *c = cs + NCOND * i;
    c[0] = s.c;
    c[0].con = cases[i].con;
    c[1] = c[2] = c[0];
    c[1].amp_vary = c[2].amp_vary = 1; /* the gains join the level's variables */
    c[1].amp_range = range;
    c[2].amp_range = wide;
    pats[i] = nl_study_cheng_pattern(&s, cases[i].pattern);
    for (int w = 0; w < NCOND; w++) pp[NCOND * i + w] = pats[i];
    cs[NCOND * ncase + i] = c[0];
    cs[NCOND * ncase + i].amp_range = range;
    c9_random_gains(cs + NCOND * ncase + i, nl_harness_seed(r), i);
    pp[NCOND * ncase + i] = pats[i];
  }
  nl_cheng_eval *evs = nl_study_cheng_runs(&s, (NCOND + 1) * ncase, cs, pp, firsts);
  /* the controls' tables: per case the fixed row again, then random gains */
  c9_tables bt = { nl_study_cheng_summary_alloc(3, labels), c9_parts_alloc(3, labels),
                   c9_gains_alloc(3, labels), c9_timing_alloc(3, labels) };
  size_t k = (size_t)nl_harness_seeds(r);
  for (int i = 0; i < ncase; i++) {
    size_t f = NCOND * (size_t)i, o = f + 1; /* fixed and optimised rows; wide: f + 2 */
    nl_cheng_config cf = cs[f];
    nl_cheng_config co = cs[o];
    nl_cheng_pattern *pat = pats[i];
    const char *lab[3] = { nl_cheng_con_name(cf.con), cases[i].pattern, "fixed" };
    for (size_t w = 0; w < NCOND; w++) {
      nl_cheng_config cw = cs[f + w]; /* carries the first seed's optimised gains */
      lab[2] = conds[w];
      c9_rows(&s, &cw, evs + (f + w) * k, &tb, 3, lab, cw.log_gain);
      if (w == 1) co = cw;
    }
    nl_noise_grad2 *gf = firsts[f];
    nl_noise_grad2 *go = firsts[o];
    nl_noise_grad2_free(firsts[f + 2]);
    nl_noise_grad2_free(firsts[NCOND * ncase + i]);
    double ug[NL_CHENG_MAX_OCTAVES];
    lab[2] = "fixed";
    c9_rows(&s, &cf, evs + f * k, &bt, 3, lab, ug);
    lab[2] = "random_gains";
    c9_rows(&s, cs + NCOND * ncase + i, evs + (NCOND * (size_t)ncase + i) * k, &bt, 3, lab, ug);
    snprintf(group[i], sizeof group[i], "%s/%s", lab[0], lab[1]);
    c9_tests_add(tests, &tb, f, group[i], quantities, sizeof quantities / sizeof *quantities);
    nl_image **p = panels + NCOL * i; /* first seed; co carries its optimised gains */
    p[0] = nl_study_cheng_pattern_panel(pat, size);
    p[1] = nl_study_cheng_value_image_raw(gf, &cf, size);
    p[2] = nl_study_cheng_value_image_raw(go, &co, size);
    p[3] = nl_study_cheng_value_image(gf, &cf, size);
    p[4] = nl_study_cheng_value_image(go, &co, size);
    const char *pl[NCOL] = { group[i], "fixed, raw 0..1", "optimised, raw 0..1", "fixed, stretched",
                             "optimised, stretched" };
    for (int c = 0; c < NCOL; c++) plab[NCOL * i + c] = pl[c];
    nl_noise_grad2_free(gf);
    nl_noise_grad2_free(go);
    nl_cheng_pattern_free(pat);
    nl_harness_progress(r, (i + 1.0) / ncase, group[i]);
  }
  free(evs);
  nl_study_cheng_montage(r, panels, plab, NCOL * ncase, NCOL,
                         "C9: fixed vs optimised octave amplitudes (first seed)", "values.png");
  c9_tables_write(r, &tb, &bt, tests);
  c9_intro_text(r, &s, range, wide);
  c9_results_text(r, &tb, tests, range);
  nl_study_cheng_control_text(r, sum, 3);
  c9_verdicts(r, &tb, &bt, tests, ncase);
  c9_timing_text(r, tb.timing, ncase);
  c9_tables_free(&tb);
  nl_table_free(tests);
  c9_tables_free(&bt);
  /* measured tolerances (nl_harness.h; data/blas_spread.tsv) */
  nl_harness_check_measured(r, "*", 100);
  return nl_harness_end(r);
}
