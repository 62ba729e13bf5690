/* noiselab patterns - writes the control patterns of Cheng 2009 (Fig 3.7
 * convention: black = 0, red = 1 in the red channel, alpha 0 = no control)
 * as RGBA PNGs, one per built-in shape of nl_study_cheng_shape():
 *
 *   noiselab patterns DIR [--size N]      (default 128; data/patterns ships them)
 *
 * DIR is made if missing; its parent must exist (as render's -o).
 *
 * Errors: one line, exit 2 (bad arguments) or 1 (a file could not be written).
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"
#include "study/nl_study_cheng.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* DIR/SHAPE.png for shape k. Caller frees. */
static char *shape_path(const char *dir, int k)
{
  char file[64];
  snprintf(file, sizeof file, "%s.png", nl_study_cheng_shape_names[k]);
  return nl_path_join(dir, file);
}

int main(int argc, char **argv)
{
  nl_tool_start("noiselab patterns");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  const char *dir = NULL;
  long size = 128;
  nl_error err;
  static const nl_opt_spec spec[] = {{"size", 0, 1}, {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser p;
  nl_opt_begin(&p, argc, argv, 1, spec);
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    if (k == NL_OPT_ERROR) {
      nl_message(stderr, "patterns: %s (usage: noiselab patterns DIR [--size N])", err.msg);
      nl_opt_end(&p);
      return 2;
    }
    if (k == 0) {
      if (nl_parse_long("--size", p.value[0], 8, 4096, &size, &err)) {
        nl_message(stderr, "patterns: %s", err.msg);
        nl_opt_end(&p);
        return 2;
      }
    } else if (k == 1) {
      printf("usage: noiselab patterns DIR [--size N]\nshapes:");
      for (int j = 0; nl_study_cheng_shape_names[j]; j++) printf(" %s", nl_study_cheng_shape_names[j]);
      printf("\n");
      nl_opt_end(&p);
      return 0;
    } else if (dir) {
      nl_message(stderr, "patterns: unexpected argument '%s' "
                 "(usage: noiselab patterns DIR [--size N])", p.value[0]);
      nl_opt_end(&p);
      return 2;
    } else dir = p.value[0];
  }
  nl_opt_end(&p);
  if (!dir) { fprintf(stderr, "patterns: missing output folder (usage: noiselab patterns DIR [--size N])\n"); return 2; }
  /* DIR is made if missing, but not its parents: a mistyped path is named,
   * as render names an output's missing folder, instead of growing a tree. */
  struct stat st;
  if (stat(dir, &st) != 0) {
    if (nl_path_check_writable(dir, &err)) { nl_message(stderr, "patterns: %s", err.msg); return 2; }
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
      nl_message(stderr, "patterns: %s: cannot make the folder: %s", dir, strerror(errno));
      return 1;
    }
  }
  /* Every file is checked before the first is written (a folder that is not
   * writable, a name taken by a directory): all are refused alike. */
  for (int k = 0; nl_study_cheng_shape_names[k]; k++) {
    char *path = shape_path(dir, k);
    nl_tool_check_output(path, NULL, 0);   /* not the shipped data/patterns */
    nl_status c = nl_path_check_writable(path, &err);
    free(path);
    if (c) { nl_message(stderr, "patterns: %s", err.msg); return 1; }
  }
  for (int k = 0; nl_study_cheng_shape_names[k]; k++) {
    char *path = shape_path(dir, k);
    nl_image *im = nl_study_cheng_shape(nl_study_cheng_shape_names[k], (int)size);
    nl_status s = nl_image_write(im, path, 8, &err);
    nl_image_free(im);
    if (s) { nl_message(stderr, "patterns: %s", err.msg); free(path); return 1; }
    printf("%s\n", path);
    free(path);
  }
  return 0;
}
