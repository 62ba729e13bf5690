/* seeding.h - Q1: what the paper's 16-bit cube seeds do to the count law
 * (seeding.c), and the paper's rule decided against Poisson(lambda).
 *
 * A cube's first draw r depends only on its seed s = PERM(i + PERM(j +
 * PERM(k))) < 2^16 (sec. 3.2.2), so every table draws its counts from one
 * fixed set of 2^16 values of r, whatever the permutation: a fixed bias
 * that a large enough block of cubes detects. The check: the same count
 * rule with r from a full hash of the run's seed and the cube's coordinates
 * (independent per cube). */
#ifndef Q1_SEEDING_H
#define Q1_SEEDING_H

#include "q1.h"

/* Counts per cube of the side^3 block at the origin (as
 * nl_cellular_count_histogram) with r = a 53-bit uniform from a hash of
 * (seed, i, j, k) through c's count rule. */
void q1_full_hash_histogram(const nl_cellular *c, unsigned long seed, int side, double *hist);

/* The count law of the fixed set: the fraction q[m] of the 2^16 cube seeds
 * whose first draw gives m points under c's rule (cubes (i, 0, 0), i < 2^16,
 * whose seeds run over every value once since PERM is a permutation). */
void q1_fixed_set_law(const nl_cellular *c, double *q);

/* Runs the check over q->seeds seeds and writes count_law.tsv (per rule and
 * seeding, pooled over seeds: cubes, mean count, chi-square, df, p),
 * hash_check.tsv (per seed, full hash) and fixed_set.tsv (the fixed set's
 * law against Poisson, and the chi-square it adds to a table of side^3
 * cubes); declares the verdict on the paper's rule; appends the report's
 * paragraph. q->hist must hold the three rules' count fractions. */
void q1_seeding(q1 *q, unsigned long seed0);

#endif
