/* C4's runs: a case of Table 4.1 or the sweep as weights and labels, every
 * case of the run, and Fig 4.8 and its tables from the first seed of each
 * pair (Cheng 2009 sec. 4.3.2). */
#include "c4.h"
#include "harness/nl_harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PANEL 160   /* side in pixels of Fig 4.8's panels */
#define MAXPAIR 8

void c4_case_set(nl_cheng_config *c, c4_case *w, const char *reading, const char *panel,
                 double w1, double w2)
{
  c->w1 = w1;
  c->w2 = w2;
  nl_table_format_double(w->txt[0], w1);
  nl_table_format_double(w->txt[1], w2);
  w->lab[0] = reading;
  w->lab[1] = panel;
  w->lab[2] = w->txt[0];
  w->lab[3] = w->txt[1];
}

void c4_cases_set(nl_cheng_config *cs, c4_case *wc, const nl_cheng_config *base,
                  const c4_thesis_row *thesis, const char *const *panel_name, int npair, double lo,
                  double hi, int nsweep, double *rhos)
{
  for (int q = 0; q < 2 * npair + nsweep; q++) {
    cs[q] = *base;
    if (q < 2 * npair) {
      int i = q / 2, sw = q % 2;
      double w1 = thesis[i][sw ? 2 : 0], w2 = thesis[i][sw ? 0 : 2];
      c4_case_set(&cs[q], &wc[q], sw ? "swapped" : "printed", panel_name[i], w1, w2);
    } else {
      int j = q - 2 * npair;
      double rho = rhos[j] = lo * pow(hi / lo, (double)j / (nsweep - 1));
      c4_case_set(&cs[q], &wc[q], "sweep", "-", rho / (1 + rho), 1 / (1 + rho));
    }
  }
}

void c4_tables_write(nl_harness *r, const c4_case *wc, nl_noise_grad2 *const *firsts, int n)
{
  const char *tl[] = { "reading", "panel" };
  nl_table *tabs = nl_study_cheng_tables_alloc(2, tl);
  for (int q = 0; q < n; q++) nl_study_cheng_tables_add(tabs, 2, wc[q].lab, firsts[q]);
  nl_harness_write_table(r, tabs, "tables.tsv");
  nl_table_free(tabs);
}

void c4_fig48(nl_harness *r, const nl_cheng_pattern *pat, nl_noise_grad2 *const *firsts,
              int npair, const nl_cheng_config *c)
{
  nl_image *panels[2 * (MAXPAIR + 1)];
  char lab[2 * (MAXPAIR + 1)][32];
  const char *labp[2 * (MAXPAIR + 1)];
  int cols = npair + 1;
  if (npair > MAXPAIR) nl_harness_die(r, 1, "Fig 4.8: %d pairs, at most %d", npair, MAXPAIR);
  for (int row = 0; row < 2; row++) {
    panels[row * cols] = nl_study_cheng_pattern_panel(pat, PANEL);
    snprintf(lab[row * cols], sizeof lab[0], "pattern");
    for (int i = 0; i < npair; i++) {
      panels[row * cols + 1 + i] = nl_study_cheng_value_image_raw(firsts[2 * i + row], c, PANEL);
      snprintf(lab[row * cols + 1 + i], sizeof lab[0], "(%c) %s", 'a' + i,
               row ? "swapped" : "printed");
    }
  }
  for (int i = 0; i < 2 * cols; i++) labp[i] = lab[i];
  nl_study_cheng_montage(r, panels, labp, 2 * cols, cols,
                         "Fig 4.8: controlled value, printed (top) and swapped (bottom) weights",
                         "textures.png");
}
