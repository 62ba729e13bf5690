/* test_vectors.h - loading the committed reference vectors of
 * tests/data/stats (made by tests/reference/make_stats_vectors.py). */
#ifndef NL_TEST_VECTORS_H
#define NL_TEST_VECTORS_H

#include "table/nl_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef NL_STATS_DATA
#error "NL_STATS_DATA (the tests/data/stats directory) must be defined by meson"
#endif

/* Reads tests/data/stats/NAME (text columns allowed); aborts the test
 * program if missing: without its vectors a test proves nothing. */
static inline nl_table *vec_read(const char *name)
{
  char *p = nl_path_join(NL_STATS_DATA, name);
  nl_table *t = NULL;
  nl_error err;
  if (nl_table_read(p, NL_TABLE_TEXT, &t, &err) != NL_OK) {
    fprintf(stderr, "%s\n", err.msg);
    exit(99);
  }
  free(p);
  return t;
}

static inline double vec_get(const nl_table *t, size_t r, const char *col)
{
  long c = nl_table_column(t, col);
  if (c < 0) { fprintf(stderr, "no column %s\n", col); exit(99); }
  return nl_table_get(t, r, (size_t)c);
}

static inline const char *vec_text(const nl_table *t, size_t r, const char *col)
{
  long c = nl_table_column(t, col);
  if (c < 0 || !t->text[r * t->ncols + (size_t)c]) { fprintf(stderr, "no text %s\n", col); exit(99); }
  return t->text[r * t->ncols + (size_t)c];
}

/* A numeric table as a row-major n x d matrix (caller frees). */
static inline double *vec_matrix(const char *name, size_t *n, size_t *d)
{
  nl_table *t = vec_read(name);
  double *x = nl_xmalloc(t->nrows * t->ncols * sizeof(double));
  for (size_t k = 0; k < t->nrows * t->ncols; k++) x[k] = t->num[k];
  *n = t->nrows;
  *d = t->ncols;
  nl_table_free(t);
  return x;
}

/* |a - b| <= rel |b| + abs_tol */
static inline int vec_close(double a, double b, double rel, double abs_tol)
{
  int ok = fabs(a - b) <= rel * fabs(b) + abs_tol;
  if (!ok) fprintf(stderr, "  got %.17g, want %.17g (rel %.3g)\n", a, b, fabs(a - b) / fabs(b));
  return ok;
}

#endif
