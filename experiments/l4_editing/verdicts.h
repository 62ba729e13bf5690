/* verdicts.h - L4's verdict rows (verdicts.c): the edit's effect on the
 * attenuated bands' power, and morphing as a figure. */
#ifndef L4_VERDICTS_H
#define L4_VERDICTS_H

#include "editing.h"
#include "l4.h"

/* From the K replicates rep (l4_edit_replicate, histogram matching on: the
 * paper's pipeline), per seed over the q->nfine edited bands, weighted by
 * their original luminance power P_k:
 *   R = sum P_k ratio_k / sum P_k      the edited bands' power after the edit,
 *   F = sum P_k floor_k / sum P_k      the same after removing them (the floor:
 *                                      power other bands leak into them),
 *   A = (R - F) / (1 - F)              the attenuation of their own power;
 * writes edit_claims.tsv (quantity, paper, ours, ours_sd, p_below: the
 * one-sided t test of a mean below 1, floor, floor_sd, seeds; rows R, A, and
 * R of rep1, the same replicates with factor 1: the control) and declares
 * R below 1 (Fig. 10 (c), "p 0.01 0.05", independent, control rep1), A
 * against factor^2 ("sd 2 4", by construction: the factor is ours) and
 * morphing (morph.png) qualitative. Returns the table (caller frees). */
nl_table *l4_verdicts(const l4 *q, const l4_edit *rep, const l4_edit *rep1);

#endif
