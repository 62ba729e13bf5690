/* C8's report (report.c): the prose beside summary.tsv and levels.tsv and the
 * figures' captions. */
#ifndef C8_REPORT_H
#define C8_REPORT_H

#include "sphere.h"

/* The caption of slices_PATTERN.png (file), added to the report. */
void c8_slices_figure(nl_harness *r, const char *pattern, const char *file);
/* The multi-level rule's entries per level (lv, cnt from c8_levels_table). */
void c8_levels_report(nl_harness *r, const nl_table *lv, const nl_cheng3_config *c,
                      const size_t *cnt);
/* The setting (c, grid, k seeds), summary.tsv (sum) with a paragraph per
 * pattern, the verdicts with their baselines (base, baselines.tsv), and the
 * uniformity and volume figures. */
void c8_report(nl_harness *r, const nl_table *sum, const nl_table *base,
               const nl_cheng3_config *c, int grid, int k);

#endif
