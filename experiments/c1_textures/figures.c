/* C1's figures (Cheng 2009 Fig 4.1-4.4): one montage per texture from the
 * first seed's tables, each with its caption in the report. */
#include "c1.h"
#include "harness/nl_harness.h"

#include <stdio.h>
#include <stdlib.h>

#define NCOL 5 /* panels per pattern */

void c1_figures(nl_harness *r, int ntex, int npat, const nl_cheng_config *cs,
                nl_noise_grad2 *const *firsts, nl_cheng_pattern **pats, const char *const *names,
                const char *const *equation, int size)
{
  nl_image **panels = nl_xmalloc((size_t)(NCOL * npat) * sizeof *panels);
  const char **plab = nl_xmalloc((size_t)(NCOL * npat) * sizeof *plab);
  for (int t = 0; t < ntex; t++) {
    nl_cheng_config c = cs[2 * npat * t];
    nl_cheng_config cl = cs[2 * npat * t + 1];
    const char *name = nl_cheng_con_name(c.con);
    for (int j = 0; j < npat; j++) {
      int i = t * npat + j;
      nl_noise_grad2 *first = firsts[2 * i];
      nl_noise_grad2 *lit = firsts[2 * i + 1];
      nl_image **p = panels + NCOL * j;
      p[0] = nl_study_cheng_pattern_panel(pats[i], size);
      p[1] = nl_study_cheng_value_image_raw(first, &c, size);
      p[2] = nl_study_cheng_value_image(first, &c, size);
      p[3] = nl_study_cheng_texture_image(first, &c, size);
      p[4] = nl_study_cheng_value_image(lit, &cl, size);
      const char *pl[NCOL] = { names[i], "c, raw 0..1", "c, stretched", name, "literal c" };
      for (int q = 0; q < NCOL; q++) plab[NCOL * j + q] = pl[q];
      nl_cheng_pattern_free(pats[i]);
      nl_harness_progress(r, (i + 1.0) / (ntex * npat), name);
    }
    char title[96], file[64];
    snprintf(title, sizeof title, "Fig 4.%d: %s (%s)", t + 1, name, equation[t]);
    snprintf(file, sizeof file, "%s.png", name);
    nl_study_cheng_montage(r, panels, plab, NCOL * npat, NCOL, title, file);
    c1_figure_text(r, t, c.con, equation[t], file);
  }
  free(panels);
  free(plab);
}
