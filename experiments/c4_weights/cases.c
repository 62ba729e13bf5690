/* C4's runs: a case of Table 4.1 or the sweep as weights and labels, and
 * Fig 4.8 from the first seed of each pair (Cheng 2009 sec. 4.3.2). */
#include "c4.h"
#include "harness/nl_harness.h"

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
