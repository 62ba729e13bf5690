/* q1.h - Q1's run (main.c) and its report prose (report.c). */
#ifndef Q1_H
#define Q1_H

#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"

#define NRULE 3 /* closest, inverse-cdf, closest-last (nl_cellular_count_rule) */

typedef struct {
  nl_harness *r;
  double lambda; /* Poisson mean of feature points per unit cube */
  int M;         /* most points a cube may hold */
  int side;      /* cubes per side of the tested block */
  long points;   /* random points at which F1 is tested */
  int seeds;     /* permutation tables */
  /* fraction of cubes with m points per rule, mean over seeds */
  double hist[NRULE][NL_CELLULAR_MAX_M + 1];
  double theory;  /* mean F1 of the nearest-neighbour law */
  nl_table *sum;  /* summary.tsv: one row per rule */
  nl_table *dist; /* counts.tsv: fraction of cubes with m points */
} q1;

/* The paper's rule against Poisson and the nearest-neighbour law, and its
 * ties: text, tables and figures. pmf: Poisson(lambda)'s p(0..M). */
void q1_report(const q1 *q, const double *pmf);

/* The seeding paragraph (seeding.h): the tables count_law, hash_check and
 * fixed_set, and how many full-hash seeds chi-square rejects at 0.01. */
void q1_report_seeding(const q1 *q, const nl_table *law, const nl_table *hash,
                       const nl_table *fixed, int rejects);

#endif
