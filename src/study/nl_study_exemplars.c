/* Exemplar photographs: --exemplars DIR and the folder's PNG files. */
#include "study/nl_study_exemplars.h"

#include <dirent.h>
#include <stdio.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

nl_status nl_study_dir_option(int *argc, char **argv, const char *option, const char *def,
                              const char **dir, nl_error *err)
{
  int w = 1;
  *dir = def;
  for (int i = 1; i < *argc; i++) {
    if (!strcmp(argv[i], option)) {
      if (i + 1 >= *argc) return nl_fail(err, NL_EINVAL, "%s: missing value", option);
      if (!argv[i + 1][0]) return nl_fail(err, NL_EINVAL, "%s: empty folder name", option);
      *dir = argv[++i];
      continue;
    }
    argv[w++] = argv[i];
  }
  *argc = w;
  argv[w] = NULL;
  return NL_OK;
}

static int cmp_str(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

nl_status nl_study_pngs(const char *dir, char ***paths, int *n, nl_error *err)
{
  struct stat st;
  *n = 0;
  *paths = nl_xcalloc(1, sizeof **paths);
  if (stat(dir, &st)) {
    if (errno == ENOENT) return NL_OK;   /* no photographs yet */
    return nl_fail(err, NL_EIO, "%s: %s", dir, strerror(errno));
  }
  DIR *d = S_ISDIR(st.st_mode) ? opendir(dir) : NULL;
  if (!d) return nl_fail(err, NL_EIO, "%s: not a readable folder", dir);
  struct dirent *e;
  while ((e = readdir(d))) {
    size_t len = strlen(e->d_name);
    if (len <= 4 || e->d_name[0] == '.' || strcasecmp(e->d_name + len - 4, ".png")) continue;
    *paths = nl_xrealloc(*paths, (size_t)(*n + 2) * sizeof **paths);
    (*paths)[(*n)++] = nl_path_join(dir, e->d_name);
  }
  closedir(d);
  qsort(*paths, (size_t)*n, sizeof **paths, cmp_str);
  (*paths)[*n] = NULL;
  return NL_OK;
}

void nl_study_paths_free(char **paths)
{
  for (int k = 0; paths && paths[k]; k++) free(paths[k]);
  free(paths);
}
