/* nl_study_exemplars.h - exemplar photographs for the noise-by-example
 * experiments: the --exemplars DIR option and the PNG files of a folder,
 * read as luminance (harness side: argv, folders).
 */
#ifndef NL_STUDY_EXEMPLARS_H
#define NL_STUDY_EXEMPLARS_H

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

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

#ifdef __cplusplus
}
#endif

#endif
