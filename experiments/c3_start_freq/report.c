/* C3's report prose (Cheng 2009 sec. 4.3.1, Fig 4.7): every number
 * formatted from the summary table or the run's setting. */
#include "c3.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <string.h>

/* "v0, v1, ..." of n values, each formatted by fmt. */
static void list(char *buf, size_t len, const char *fmt, const double *v, int n)
{
  buf[0] = 0;
  for (int i = 0; i < n; i++) {
    size_t used = strlen(buf);
    if (i) used += (size_t)snprintf(buf + used, len - used, ", ");
    snprintf(buf + used, len - used, fmt, v[i]);
  }
}

void c3_intro_text(nl_harness *r, const nl_study_cheng *s, const char *pattern,
                   const double *f1s, int n, const nl_table *sum)
{
  const nl_cheng_config *c = &s->c;
  nl_harness_text(r,
                  "**Thesis:** the controlled fractal sum for f1 = 2, 4, 6, 8 (Fig 4.7, images "
                  "only); \"the appearance of lower starting frequency is smoother\". **Ours:** "
                  "pattern %s, %d x %d control grid, F = %d, a1 = %g, w1 = %g, w2 = %g, %d seeds "
                  "per f1. Smoothness is measured as the rms gradient of the control value "
                  "(\"roughness\", per unit length).\n",
                  pattern, s->grid, s->grid, c->octaves, c->a1, c->w1, c->w2,
                  nl_harness_seeds(r));
  char f1_list[128], cap[192];
  list(f1_list, sizeof f1_list, "%g", f1s, n);
  snprintf(cap, sizeof cap, "Controlled value (top) and cloud texture (bottom) for f1 = %s",
           f1_list);
  nl_harness_figure(r, "panels.png", cap);
  nl_harness_report_columns(r, sum, "summary.tsv", "f1,seeds," NL_STUDY_CHENG_STORY,
                            "Statistics per f1 (mean and spread over seeds)", 4);
}

void c3_result_text(nl_harness *r, const nl_table *sum, const double *f1s, int n)
{
  double ro[16], ec[16];
  int best = 0, monotone = 1;
  if (n > 16) n = 16;
  for (int i = 0; i < n; i++) {
    ro[i] = nl_table_value(sum, (size_t)i, "roughness");
    ec[i] = nl_table_value(sum, (size_t)i, "E_con");
    if (i && !(ro[i] > ro[i - 1])) monotone = 0;
    if (ec[i] < ec[best]) best = i;
  }
  char f1_list[128], ro_list[256], ec_list[256];
  list(f1_list, sizeof f1_list, "%g", f1s, n);
  list(ro_list, sizeof ro_list, "%.3g", ro, n);
  list(ec_list, sizeof ec_list, "%.4g", ec, n);
  nl_harness_text(r,
                  "Roughness %s for f1 = %s: %s. E_Con %s is lowest at f1 = %g (the thesis gives "
                  "no E_Con per f1 to compare).\n",
                  ro_list, f1_list,
                  monotone ? "strictly increasing with f1, so lower f1 is smoother, as the thesis "
                             "says"
                           : "NOT monotone in f1",
                  ec_list, f1s[best]);
}
