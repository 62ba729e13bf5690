/* q4.h - Q4's run (main.c) and its report prose (report.c).
 *
 * Qin & Yang 2000 Fig. 5 and 6: the eq. 7 clouds and the GCTBF textures.
 * main.c fills a q4 with the run's parameters and tables; q4_report writes
 * the report's text, tables and figure captions from them, every number
 * formatted from the run. */
#ifndef Q4_H
#define Q4_H

#include "harness/nl_harness.h"
#include "noise/nl_noise.h"
#include "texture/nl_texture.h"

typedef struct {
  nl_harness *r;
  int size;            /* side in pixels of the images */
  int octaves;         /* octaves above the first in eq. 7 and the flame */
  int seeds;           /* seeds averaged in the tables */
  double k;            /* scale between octaves (eq. 7) */
  double rings;        /* wood: rings per unit of distance to the axis */
  double turb;         /* wood: rings added per unit of the basis */
  nl_noise_window win; /* plane z = 0.5, [0, 2)^2 (Perlin: z NL_STUDY_SLICE_Z) */
  nl_table *t;         /* textures.tsv: one row per texture */
  nl_table *wood;      /* wood.tsv: one row per wood panel (wood.h) */
} q4;

/* The report of Q4: the paper and our readings, the two tables, the three
 * figures (clouds.png, textures.png, wood.png). */
void q4_report(const q4 *q);

/* One texture over the seeds (textures.c): kind an nl_cellular_gctbf_texture,
 * expr its GCTBF (NULL: Perlin's octaves), through ramp over [lo, hi] (NULL:
 * eq. 7's cloud colours); appends label's mean and sd to q->t and returns
 * the first seed's image. */
nl_image *q4_texture(q4 *q, int kind, const char *label, const char *expr,
                     const nl_texture_ramp *ramp, double lo, double hi);

/* Per wood panel of q->wood, its dark bands through the ramp below those
 * through the wood shader, with the shader without the GCTBF as control
 * (verdicts.c): writes rings.tsv and returns it. */
nl_table *q4_wood_verdicts(const q4 *q);

#endif
