/* L2's exemplar photographs (photos.c): true weights unknown, so each
 * estimator's weights are judged by how well a re-synthesis matches the
 * photograph's band powers. */
#ifndef L2_PHOTOS_H
#define L2_PHOTOS_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* "--exemplars DIR" (default data/exemplars) removed from argv (before
 * nl_harness_begin sees it) and the PNG files of DIR, *n of them, sorted by
 * name (free with nl_study_paths_free); on error prints "PROG: message" and
 * exits 2, before the harness touches anything. */
char **l2_exemplars_option(int *argc, char **argv, const char *prog, const char **dir, int *n);
/* Every photograph's fit by every estimator (nl_byexample_fit_all on its
 * luminance cropped about the centre to max, taper fraction frac): rows
 * exemplar (file name), width, height, bands, estimator, resid_raw,
 * resid_taper. A/resynthesis seeds from nl_seed_stream(seed,
 * "l2.photo_transfer" / "l2.photo", i). The fits are nl_parallel_for items
 * on the run's threads. An unreadable or too small (< NL_BYEXAMPLE_MIN_SIZE)
 * image: nl_harness_die, exit 2. */
nl_table *l2_exemplar_fits(nl_harness *r, char *const *paths, int n, int max, int tile, double frac,
                           int nseeds, int nsyn, unsigned long seed);

#endif
