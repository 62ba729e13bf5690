/* wood.h - Q4's wood panels (wood.c). */
#ifndef Q4_WOOD_H
#define Q4_WOOD_H

#include "study/nl_study.h"

/* ---- Q4: wood (Qin & Yang 2000 Fig. 6) -----------------------------------
 *
 * The GCTBF expr (one octave, scale k, on win; nl_cellular_texture_grid) for
 * K seeds from seed0, through the wood shader wd (nl_texture_wood) and through
 * the ramp (values lo..hi). Dark bands are counted (nl_texture_band_count)
 * along row (vertical 0) or column `index` of each image. Images of the first
 * seed in *rings and *ramped (caller frees); one row appended to table. */
typedef struct {
  double value_sd;                  /* sd of the basis over the panel (mean over seeds) */
  double ring_sd;                   /* sd of the shader's ring profile t */
  double rings, rings_sd;           /* dark bands of the wood shader, mean and sd over seeds */
  double ramp_bands, ramp_bands_sd; /* dark bands of the ramp reading */
  double rings_geometry;            /* dark bands of the shader without the basis (turb * g = 0) */
} nl_study_wood_result;
/* The table nl_study_wood appends to: panel, gctbf, value_sd,
 * perturb_rings_sd (turb * value_sd: how far the basis moves the rings),
 * ring_sd, rings, rings_sd, rings_geometry, ramp_bands, ramp_bands_sd. */
nl_table *nl_study_wood_table(void);
nl_status nl_study_wood(nl_table *table, const char *panel, const char *expr, double k, const nl_noise_window *win,
                        const nl_texture_wood *wd, const nl_texture_ramp *ramp, double lo, double hi, int vertical,
                        int index, unsigned long seed0, int K, nl_image **rings, nl_image **ramped, nl_error *err);

#endif
