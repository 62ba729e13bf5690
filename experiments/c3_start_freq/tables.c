/* C3's first-seed tables (c3.h): the tables behind the figure, the seams
 * of tables run on the alternative domain, and the lowest f1's control
 * against its pattern - kept apart so that main.c reads as the method. */
#include "c3.h"
#include "harness/nl_harness.h"

void c3_tables_write(nl_harness *r, const double *f1s, nl_noise_grad2 *const *firsts, int n)
{
  const char *labels[] = { "f1" };
  nl_table *tabs = nl_study_cheng_tables_alloc(1, labels);
  for (int i = 0; i < n; i++) {
    char f[32];
    nl_table_format_double(f, f1s[i]);
    const char *l[1] = { f };
    nl_study_cheng_tables_add(tabs, 1, l, firsts[i]);
  }
  nl_harness_write_table(r, tabs, "tables.tsv");
  nl_table_free(tabs);
}

void c3_seams_add(nl_table *seams, const double *f1s, const nl_cheng_config *cs,
                  nl_noise_grad2 **firsts, int n, const nl_cheng_pattern *pat)
{
  for (int i = 0; i < n; i++) {
    char f[32];
    nl_table_format_double(f, f1s[i]);
    const char *sl[2] = { f, "optimised" };
    nl_study_cheng_seams_add(seams, 2, sl, (const nl_noise_grad2 *const *)&firsts[i], 1, &cs[i],
                             pat);
    nl_noise_grad2_free(firsts[i]);
  }
}

void c3_low_control(const nl_study_cheng *s, nl_table *ctl, nl_table *bl, const nl_cheng_config *c,
                    const nl_cheng_pattern *pat, const nl_cheng_eval *evs,
                    nl_noise_grad2 *const *tables, int nrand, double f1)
{
  char f[32];
  nl_table_format_double(f, f1);
  const char *l[1] = { f };
  unsigned long cseed = nl_seed_stream(nl_harness_seed(s->r), "c3.random_r", 0);
  nl_study_cheng_control_add(s, ctl, 1, l, c, pat, evs, nrand, cseed, NULL);
  nl_study_cheng_baselines_add(s, bl, 2, l, c, pat, tables, nrand, cseed);
}
