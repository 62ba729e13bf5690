/* wood.h - Q4's wood panels (wood.c): Qin & Yang 2000 Fig. 6 name only the
 * basis (F1 - F1F1, F3 - F3F3) inside a RenderMan wood shader they do not
 * print. We run it through the usual solid wood shader (nl_texture_wood) and,
 * as the measured alternative, through a two-colour ramp, and count the dark
 * bands each shows. */
#ifndef Q4_WOOD_H
#define Q4_WOOD_H

#include "study/nl_study.h"

/* One panel's numbers (means over seeds unless named _sd). */
typedef struct {
  double value_sd;       /* sd of the basis over the panel */
  double ring_sd;        /* sd of the shader's ring profile t */
  double rings;          /* dark bands of the wood shader */
  double rings_sd;       /* their sd over seeds */
  double ramp_bands;     /* dark bands of the ramp reading */
  double ramp_bands_sd;  /* their sd over seeds */
  double rings_geometry; /* dark bands of the shader without the basis (turb * g = 0) */
} q4_wood_result;

/* The table q4_wood appends to: panel, gctbf, value_sd,
 * perturb_rings_sd (turb * value_sd: how far the basis moves the rings),
 * ring_sd, rings, rings_sd, rings_geometry, ramp_bands, ramp_bands_sd. */
nl_table *q4_wood_table(void);

/* The GCTBF expr (one octave, scale k, on win; nl_cellular_texture_grid) for
 * K seeds from seed0, through the wood shader wd and through the ramp
 * (values lo..hi). Dark bands are counted (nl_texture_band_count) along row
 * (vertical 0) or column `index` of each image. Images of the first seed in
 * *rings and *ramped (caller frees); one row appended to table. */
nl_status q4_wood(nl_table *table, const char *panel, const char *expr, double k,
                  const nl_noise_window *win, const nl_texture_wood *wd,
                  const nl_texture_ramp *ramp, double lo, double hi, int vertical, int index,
                  unsigned long seed0, int K, nl_image **rings, nl_image **ramped, nl_error *err);

/* rings.tsv from the table of q4_wood (K seeds each): per panel three rows
 * (panel, gctbf, reading, bands, bands_sd, seeds): "ramp" (the GCTBF
 * alone through the ramp: ramp_bands), "wood shader" (rings) and "wood
 * shader without the GCTBF" (rings_geometry, sd 0). Caller frees. */
nl_table *q4_rings_table(const nl_table *wood, int K);

#endif
