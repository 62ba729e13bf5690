/* C1 - Cheng 2009 Fig 4.1-4.4 (sec. 4.1): cloud, marble, erosion and fire
 * textures, each from three control patterns with its own control term
 * (eq. 3.8, 4.1, 4.2, 4.3); one montage per texture: pattern | controlled
 * value without and with the display stretch | texture | the literal
 * formula's value. Each panel also runs with the thesis's formulas taken
 * literally (V unscaled: c = V, sin V, |V|), the reading beside ours.
 * "The texture follows the pattern" is decided per texture (claims.tsv,
 * control.c) by r against random tables and E_Con against flat images. */
#include "c1.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdlib.h>

#define NTEX 4
#define NPAT 3

/* Per texture, in nl_cheng_con's order (cloud, marble, erosion, fire): its
 * patterns and its control term's equation. */
static const char *const patterns[NTEX][NPAT] = {
  { "flower", "x", "star" },
  { "rings", "spiral", "letter" },
  { "disc", "star", "x" },
  { "flower", "gradient", "letter" },
};
static const char *const equation[NTEX] = { "eq. 3.8", "eq. 4.1", "eq. 4.2", "eq. 4.3" };
static const char *const formula[2] = { "rescaled", "literal" };

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c1_textures",
                      "C1 - controlled cloud, marble, erosion and fire (Fig 4.1-4.4)", &argc, argv);
  nl_harness *r = s.r;
  int size = (int)nl_harness_param_int(r, "size", nl_harness_quick(r) ? 128 : 256, 16, 2048,
                                       "side in pixels of the texture and control-value images "
                                       "(quick 128)");
  int nrand =
      (int)nl_harness_param_int(r, "random_tables", nl_harness_quick(r) ? 99 : 999, 9, 1000000,
                                "random (unoptimised) tables per case: the null "
                                "distribution of r with the pattern (quick 99)");
  nl_study_cheng_ready(&s);
  const nl_cheng_config base = s.c;
  int k = nl_harness_seeds(r);
  const char *labels[] = { "texture", "pattern", "formula" };
  nl_table *sum = nl_study_cheng_summary_alloc(3, labels);
  s.cost = c1_cost_alloc();

  /* Every (texture, pattern, formula) case over the seeds as one set of
   * independent runs on the run's threads; rows in case order. */
  enum { NCASE = 2 * NTEX * NPAT };
  nl_cheng_config cs[NCASE];
  nl_cheng_pattern *pats[NTEX * NPAT];
  const nl_cheng_pattern *pp[NCASE];
  const char *names[NTEX * NPAT]; /* each headline case's pattern */
  nl_noise_grad2 *firsts[NCASE];
  nl_noise_grad2 **tables = nl_xmalloc((size_t)NCASE * (size_t)k * sizeof *tables);
  for (int i = 0; i < NTEX * NPAT; i++) {
    cs[2 * i] = base;
    cs[2 * i].con = (nl_cheng_con)(i / NPAT); /* eq. 3.8, 4.1, 4.2, 4.3 */
    cs[2 * i + 1] = cs[2 * i];
    cs[2 * i + 1].literal = 1;
    names[i] = patterns[i / NPAT][i % NPAT];
    pats[i] = nl_study_cheng_pattern(&s, names[i]);
    pp[2 * i] = pats[i];
    pp[2 * i + 1] = pats[i];
  }
  nl_cheng_eval *evs = nl_study_cheng_runs_tables(&s, NCASE, cs, pp, tables);
  for (int i = 0; i < NCASE; i++) firsts[i] = tables[(size_t)i * k];
  nl_table *ctl = nl_study_cheng_control_alloc(3, labels), *claims = c1_claims_alloc();
  const char *blabels[] = { "texture", "pattern", "baseline" };
  nl_table *bl = nl_study_cheng_control_alloc(3, blabels);
  const char *slabels[] = { "texture", "pattern", "tables_from" };
  nl_table *seams = nl_study_cheng_seams_alloc(3, slabels);
  double *nulls = nl_xmalloc((size_t)NCASE * (size_t)nrand * sizeof *nulls);
  for (int i = 0; i < NCASE; i++) {
    const char *lab[3] = { nl_cheng_con_name(cs[i].con), patterns[i / 2 / NPAT][i / 2 % NPAT],
                           formula[i % 2] };
    nl_study_cheng_rows_add(&s, sum, 3, lab, evs + (size_t)i * k);
    unsigned long rs = nl_seed_stream(nl_harness_seed(r), "c1.random_r", (unsigned long)i);
    nl_study_cheng_control_add(&s, ctl, 3, lab, &cs[i], pp[i], evs + (size_t)i * k, nrand, rs,
                               nulls + (size_t)i * nrand);
    const char *sl[3] = { lab[0], lab[1], "optimised" };
    if (i % 2 == 0) { /* the headline (rescaled) cases' first-seed tables */
      nl_study_cheng_seams_add(seams, 3, sl, (const nl_noise_grad2 *const *)&firsts[i], 1, &cs[i],
                               pp[i]);
      /* the per-pattern verdicts' negative controls */
      nl_study_cheng_baselines_add(&s, bl, 3, lab, &cs[i], pp[i], tables + (size_t)i * k, nrand,
                                   rs);
    }
  }
  c1_seams_start(&s, seams, &cs[0], pp[0], patterns[0][0]);
  /* The alternative domain [0, 1]^2 (origin 0; nl_cheng.h READINGS): the
   * headline cases again, the seams of their first seed's tables. */
  c1_seams_domain(&s, seams, NTEX * NPAT, cs, pats, names);
  /* "statistics kept": the headline cases' uniformity against the same
   * cases optimised for E_Con alone (w1 = 0) */
  nl_table *uni = c1_uniform_alloc();
  c1_uniformity(&s, uni, NTEX, NPAT, cs, pats, evs, k);
  /* pooled over each texture's patterns (no verdict: each pattern decides) */
  for (int t = 0; t < NTEX; t++) {
    const nl_cheng_eval *e[NPAT];
    const double *nl[NPAT];
    for (int j = 0; j < NPAT; j++) {
      e[j] = evs + (size_t)(2 * (t * NPAT + j)) * k;
      nl[j] = nulls + (size_t)(2 * (t * NPAT + j)) * nrand;
    }
    c1_claims_add(claims, nl_cheng_con_name(cs[2 * NPAT * t].con), NPAT, k, e, nl, nrand);
  }
  free(nulls);
  free(evs);

  /* the first seed's tables behind the figures (tests/oracle_cheng.c) */
  nl_table *tabs = nl_study_cheng_tables_alloc(3, labels);
  for (int i = 0; i < NCASE; i++) {
    const char *lab[3] = { nl_cheng_con_name(cs[i].con), patterns[i / 2 / NPAT][i / 2 % NPAT],
                           formula[i % 2] };
    nl_study_cheng_tables_add(tabs, 3, lab, firsts[i]);
  }
  nl_harness_write_table(r, tabs, "tables.tsv");
  nl_table_free(tabs);
  /* Fig 4.1-4.4, one montage per texture, first seed: pattern | value on its
   * own 0..1 scale | stretched | texture | the literal formula's value. */
  c1_figures(r, NTEX, NPAT, cs, firsts, pats, names, equation, size);
  nl_harness_write_table(r, sum, "summary.tsv");
  nl_harness_write_table(r, ctl, "control.tsv");
  nl_harness_write_table(r, claims, "pooled.tsv");
  nl_harness_write_table(r, bl, "baselines.tsv");
  nl_harness_write_table(r, uni, "uniformity.tsv");
  nl_harness_write_table(r, seams, "seams.tsv");
  c1_text(r, sum, &base, s.grid);
  c1_control_text(r, claims, ctl, bl, uni, seams);
  for (size_t i = 0; i < (size_t)NCASE * k; i++) nl_noise_grad2_free(tables[i]);
  free(tables);
  nl_table_free(bl);
  nl_table_free(uni);
  nl_table_free(ctl);
  nl_table_free(claims);
  nl_table_free(seams);
  c1_cost_report(r, s.cost);
  nl_table_free(s.cost);
  nl_table_free(sum);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
