/* expect - check a TSV table from a test script, one condition per argument.
 *
 *   expect TABLE.tsv COND...
 *     rows=N  rows>=N         number of data rows
 *     A<=B  A<B  A>=B  A>B  A==B  A!=B
 *                             for every row; A is a column, B a column or a
 *                             number, optionally scaled: B*1.5
 *     A~B:TOL                 |A - B| <= TOL on every row
 *     file:NAME               NAME exists beside the table and is not empty
 *     image:NAME              as file:NAME when the run wrote images: the
 *                             manifest.tsv beside the table says "images yes";
 *                             a run with --no-images ("images no") writes none,
 *                             and the condition holds
 * Prints the first failing row and exits 1; exits 2 on a malformed call.
 */
#include "table/nl_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static nl_table *t;
static const char *path;

static double operand(const char *s, size_t row)
{
  char buf[256];
  snprintf(buf, sizeof buf, "%s", s);
  double scale = 1;
  char *star = strchr(buf, '*');
  if (star) { *star = '\0'; scale = atof(star + 1); }
  long c = nl_table_column(t, buf);
  if (c >= 0) {
    if (t->text[row * t->ncols + (size_t)c]) { fprintf(stderr, "expect: %s: column %s is text\n", path, buf); exit(2); }
    return scale * nl_table_get(t, row, (size_t)c);
  }
  char *end;
  double v = strtod(buf, &end);
  if (*end || end == buf) { fprintf(stderr, "expect: %s: no column '%s' (and not a number)\n", path, buf); exit(2); }
  return scale * v;
}

/* NAME beside the table, as a path (the caller frees it). */
static char *beside(const char *name)
{
  char *dir = nl_xstrdup(path);
  char *slash = strrchr(dir, '/');
  if (slash)
    *slash = '\0';
  else
    strcpy(dir, ".");
  char *f = nl_path_join(dir, name);
  free(dir);
  return f;
}

static int file_ok(const char *name)
{
  char *f = beside(name);
  struct stat st;
  int ok = stat(f, &st) == 0 && st.st_size > 0;
  if (!ok)
    fprintf(stderr, "expect: %s missing or empty\n", f);
  free(f);
  return ok;
}

/* Whether the run that wrote the table wrote images: the "images" row of the
 * manifest beside it (the harness writes "yes", or "no" under --no-images).
 * A manifest without that row is a malformed call: exit 2. */
static int run_wrote_images(void)
{
  char *m = beside("manifest.tsv");
  nl_table *man;
  nl_error err;
  if (nl_table_read(m, NL_TABLE_TEXT, &man, &err)) {
    fprintf(stderr, "expect: image: needs the run's manifest: %s\n", err.msg);
    exit(2);
  }
  int wrote = -1;
  for (size_t r = 0; r < man->nrows; r++) {
    const char *key = nl_table_text(man, r, "key");
    const char *value = nl_table_text(man, r, "value");
    if (key && value && !strcmp(key, "images"))
      wrote = !strcmp(value, "yes");
  }
  nl_table_free(man);
  if (wrote < 0) {
    fprintf(stderr, "expect: %s has no 'images' row\n", m);
    exit(2);
  }
  free(m);
  return wrote;
}

static int check(const char *cond)
{
  if (!strncmp(cond, "file:", 5))
    return file_ok(cond + 5);
  if (!strncmp(cond, "image:", 6))
    return !run_wrote_images() || file_ok(cond + 6);
  if (!strncmp(cond, "rows", 4)) {
    int ge = cond[4] == '>';
    long n = atol(cond + (ge ? 6 : 5));
    int ok = ge ? (long)t->nrows >= n : (long)t->nrows == n;
    if (!ok) fprintf(stderr, "expect: %s: %zu rows, wanted %s\n", path, t->nrows, cond);
    return ok;
  }
  static const char *ops[] = {"<=", ">=", "==", "!=", "<", ">", "~"};
  for (int k = 0; k < 7; k++) {
    const char *p = strstr(cond, ops[k]);
    if (!p) continue;
    char lhs[256], rhs[256];
    snprintf(lhs, sizeof lhs, "%.*s", (int)(p - cond), cond);
    snprintf(rhs, sizeof rhs, "%s", p + strlen(ops[k]));
    double tol = 0;
    if (k == 6) {
      char *colon = strrchr(rhs, ':');
      if (!colon) { fprintf(stderr, "expect: '%s' needs :TOL\n", cond); exit(2); }
      *colon = '\0';
      tol = atof(colon + 1);
    }
    for (size_t r = 0; r < t->nrows; r++) {
      double a = operand(lhs, r), b = operand(rhs, r);
      int ok = k == 0 ? a <= b : k == 1 ? a >= b : k == 2 ? a == b : k == 3 ? a != b
             : k == 4 ? a < b : k == 5 ? a > b : fabs(a - b) <= tol;
      if (!ok) {
        fprintf(stderr, "expect: %s: row %zu: %s fails (%.10g vs %.10g)\n", path, r + 1, cond, a, b);
        return 0;
      }
    }
    return 1;
  }
  fprintf(stderr, "expect: cannot parse condition '%s'\n", cond);
  exit(2);
}

int main(int argc, char **argv)
{
  if (argc < 3) { fprintf(stderr, "usage: expect TABLE.tsv COND...\n"); return 2; }
  path = argv[1];
  nl_error err;
  if (nl_table_read(path, NL_TABLE_TEXT, &t, &err)) { fprintf(stderr, "expect: %s\n", err.msg); return 1; }
  int ok = 1;
  for (int i = 2; i < argc; i++) ok &= check(argv[i]);
  nl_table_free(t);
  return ok ? 0 : 1;
}
