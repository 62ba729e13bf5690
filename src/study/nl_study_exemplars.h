/* nl_study_exemplars.h - exemplar photographs for the noise-by-example
 * experiments: the --exemplars DIR option and the PNG files of a folder,
 * read as luminance (harness side: argv, folders).
 */
#ifndef NL_STUDY_EXEMPLARS_H
#define NL_STUDY_EXEMPLARS_H

#include "base/nl_base.h"
#include "harness/nl_harness.h"
#include "table/nl_table.h"

/* Removes "OPTION DIR" from argv (before nl_harness_begin sees it) and sets
 * *dir to DIR, else to def; "OPTION: missing value" / "empty folder name". */
nl_status nl_study_dir_option(int *argc, char **argv, const char *option, const char *def,
                              const char **dir, nl_error *err);
/* The files of dir ending in .png (any case), sorted by name, as paths
 * DIR/NAME; *n of them (0 when the folder does not exist). NULL-terminated;
 * free with nl_study_paths_free. NL_EIO if dir exists and is not a readable
 * folder. */
nl_status nl_study_pngs(const char *dir, char ***paths, int *n, nl_error *err);
void nl_study_paths_free(char **paths);
/* Both for a program: "--exemplars DIR" (default data/exemplars) removed
 * from argv and the PNG files of DIR; on error prints "PROG: message" and
 * exits 2 (before the harness touches anything). With glibc it also keeps
 * freed large buffers in the process (mallopt; speed only, see the .c). */
char **nl_study_exemplars_option(int *argc, char **argv, const char *prog, const char **dir, int *n);
/* Every photograph's fit by every estimator (nl_byexample_fit_all on its
 * luminance cropped to max, taper fraction frac): rows exemplar (file name), width, height,
 * bands, estimator, resid_raw, resid_taper. A/resynthesis seeds from
 * nl_seed_stream(seed, "l2.photo_transfer" / "l2.photo", i). An unreadable
 * or too small (< NL_EXAMPLE_MIN_SIZE) image: nl_harness_die, exit 2. */
nl_table *nl_study_exemplar_fits(nl_harness *r, char *const *paths, int n, int max, int tile, double frac,
                                 int nseeds, int nsyn, unsigned long seed);
/* The luminance (nl_byexample_luminance) of the image at path, cropped about
 * its centre to at most max x max pixels: *w x *h doubles, caller frees. */
nl_status nl_study_exemplar_luminance(const char *path, int max, double **out, int *w, int *h,
                                      nl_error *err);

#endif
