/* photos.h - L3 on photographs (photos.c): Lagae et al. 2010 sec. 5 applied
 * to the real exemplars of data/exemplars. */
#ifndef L3_PHOTOS_H
#define L3_PHOTOS_H

#include "harness/nl_harness.h"
#include "study/nl_study.h"

/* Removes "--exemplars DIR" from argv (before nl_harness_begin sees it) and
 * sets *dir to DIR, or "data/exemplars" (experiments run from the repository
 * root, as with --patterns). */
nl_status l3_photos_dir_parse(int *argc, char **argv, const char **dir, nl_error *err);

/* Reads the first max photographs of dir (its PNG files sorted by name,
 * nl_study_pngs) into photos, their names without ".png" into names. Returns
 * how many; -1 and err when the folder cannot be read or a photograph does
 * not read (the others freed), 0 and err when it holds none. */
int l3_photos_load(const char *dir, char (*names)[64], nl_image **photos, int max, nl_error *err);

/* Every photograph with three representations (gauss33, paper10 as the
 * paper synthesises, and calibrated = gauss33 with NL_BYEXAMPLE_CALIBRATE
 * rounds, the `example` command's default) and K replicates
 * (nl_seed_replicate(seed, s), the same for all; rows carry the replicate),
 * compared by nl_study_example_compare with the criteria min_share,
 * max_ratio, max_ks: writes photos.tsv (bands), photos_summary.tsv (one row
 * per replicate), photos_mean.tsv (over replicates: mean KS, tails, speckle,
 * the checked band whose mean power is farthest from the photo's, passes of
 * K, replicates failing by KS and by band, the photo's largest saturation)
 * and the montage photos_montage.png (photo | gauss33 | paper10 | calibrated
 * per row, top-left 256^2 crops); returns the photos_mean table (caller
 * frees). The analyses (one per photo and representation) and the
 * syntheses (one per replicate) run on the harness's threads, rows added in
 * order afterwards: the tables do not depend on the thread count. */
nl_table *l3_photos(nl_harness *r, char (*names)[64], nl_image **photos, int np, int size, int K,
                    unsigned long seed, double min_share, double max_ratio, double max_ks);

#endif
