/* C3 - Cheng 2009 Fig 4.7 (sec. 4.3.1): the starting frequency f1 = 2, 4, 6,
 * 8 of the controlled fractal sum (eq. 3.10: f_l = f1 2^(l-1)); lower f1
 * should look smoother. */
#include "c3.h"
#include "study/nl_study_cheng.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NF    4
#define PANEL 160   /* side in pixels of the panels */

static const double f1s[NF] = { 2, 4, 6, 8 };
static const char *const pattern = "star";

int main(int argc, char **argv)
{
  nl_study_cheng s;
  nl_study_cheng_open(&s, "c3_start_freq", "C3 - starting frequency f1 (Fig 4.7)", &argc, argv);
  nl_study_cheng_ready(&s);
  nl_harness *r = s.r;
  const nl_cheng_config base = s.c;
  nl_cheng_pattern *pat = nl_study_cheng_pattern(&s, pattern);
  const char *labels[] = { "f1" };
  nl_table *sum = nl_study_cheng_summary_alloc(1, labels);

  /* Fig 4.7: the controlled value (top row) and the cloud texture (bottom)
   * per f1, first seed, each row after the pattern. */
  enum { COLS = NF + 1 };
  nl_image *panels[2 * COLS];
  char lab[2 * COLS][48];
  const char *labp[2 * COLS];
  for (int row = 0; row < 2; row++) {
    panels[row * COLS] = nl_study_cheng_pattern_panel(pat, PANEL);
    snprintf(lab[row * COLS], sizeof lab[0], "pattern");
  }
  for (int i = 0; i < NF; i++) {
    nl_cheng_config c = base;
    c.f1 = f1s[i];
    char f[32];
    nl_table_format_double(f, f1s[i]);
    const char *l[1] = { f };
    nl_noise_grad2 *first = nl_study_cheng_seeds(&s, &c, pat, sum, 1, l);
    panels[1 + i] = nl_study_cheng_value_image(first, &c, PANEL);
    panels[COLS + 1 + i] = nl_study_cheng_texture_image(first, &c, PANEL);
    snprintf(lab[1 + i], sizeof lab[0], "(%c) f1=%g", 'a' + i, f1s[i]);
    snprintf(lab[COLS + 1 + i], sizeof lab[0], "(%c) f1=%g cloud", 'a' + i, f1s[i]);
    nl_noise_grad2_free(first);
    nl_harness_progress(r, (i + 1.0) / NF, "f1");
  }
  for (int i = 0; i < 2 * COLS; i++) labp[i] = lab[i];
  nl_study_cheng_montage(r, panels, labp, 2 * COLS, COLS,
                         "Fig 4.7: starting frequency f1 (first seed)", "panels.png");
  nl_harness_write_table(r, sum, "summary.tsv");
  c3_intro_text(r, &s, pattern, f1s, NF, sum);
  c3_result_text(r, sum, f1s, NF);
  nl_study_cheng_control_text(r, sum, 1);
  nl_table_free(sum);
  nl_cheng_pattern_free(pat);
  nl_harness_check_measured(r, "*", 100);   /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
