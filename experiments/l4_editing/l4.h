/* l4.h - L4's run (main.c) and its report prose (report.c). */
#ifndef L4_H
#define L4_H

#include "harness/nl_harness.h"

/* The run's parameters and tables, as main.c fills them. */
typedef struct {
  nl_harness *r;
  int size;           /* side of the exemplar and the syntheses */
  int K;              /* seeds of the editing replicates */
  unsigned long seed; /* the run's seed, the first replicate's */
  int nfine;          /* finest bands the edit attenuates */
  double factor;      /* what their weights are multiplied by */
  nl_table *edit;     /* editing.tsv (l4_edit_tables) */
  nl_table *solid;    /* solid.tsv */
  nl_table *summary;  /* editing_summary.tsv, one row */
  nl_table *morph;    /* morph.tsv */
  nl_table *claims;   /* edit_claims.tsv (l4_verdicts) */
} l4;

/* Editing (Fig. 10c) and its measured cause, solid extrapolation (Fig. 10d)
 * and morphing (Fig. 12): the report's text, tables and figures. */
void l4_report(const l4 *q);

#endif
