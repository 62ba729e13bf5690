/* continuity.h - Q1: F_i across the faces of the unit cubes (continuity.c).
 * Sec. 3.1 says F_i is a continuous function of x. A distance to the i-th
 * nearest point of a fixed set is 1-Lipschitz; the algorithm searches the
 * 27 cubes around x, a set that changes where x crosses a cube face, so a
 * jump can only happen there, when the i-th nearest point of the 27 cubes
 * is farther than the block's boundary. */
#ifndef Q1_CONTINUITY_H
#define Q1_CONTINUITY_H

#include "cellular/nl_cellular.h"
#include "q1.h"

/* At `points` faces x = i (1 <= i < 999) at random (y, z) in [0, 1000)^2
 * (MT19937 from seed): F1..F4 at x = i -+ h/2 (nl_cellular_eval, or with
 * own != 0 the points of x's own cube alone, the search without its 26
 * neighbours). *jumps counts faces where some F_i moves by more than 2 h,
 * *max_ratio the largest |dF_i| / h (at most 1 for a continuous F_i, up to
 * rounding). */
void q1_face_jumps(const nl_cellular *c, int own, long points, unsigned long seed, double h,
                   long *jumps, double *max_ratio);

/* Sec. 3.1's "F_i is a continuous function of x", across cube faces, for
 * the paper's rule as written and for its control, the search without the
 * 26 neighbouring cubes: continuity.tsv, the verdict, a paragraph. */
void q1_continuity(q1 *q, unsigned long seed0);

#endif
