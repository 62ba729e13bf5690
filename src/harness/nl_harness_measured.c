/* Regression tolerances from a measurement (nl_harness_check_measured in
 * nl_harness.h): the spread of each column over the CPU-dependent
 * configurations, measured by bench/blas-spread.sh into
 * data/blas_spread.tsv, times a stated multiple. */
#include "harness/nl_harness.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness/nl_build_info.h"   /* NL_SOURCE_ROOT */

/* Relative spreads above this are of values that are themselves rounding
 * noise (an orthogonality error of 1e-16, a p-value near 0): their relative
 * change says nothing, so the tolerance is absolute. */
#define NL_MEASURED_REL_LIMIT 1e-3

static nl_table *spread_table(nl_harness *r)
{
  static nl_table *t;
  static int tried;
  if (tried) return t;
  tried = 1;
  const char *env = getenv("NL_BLAS_SPREAD");   /* tests point it elsewhere */
  char *path = env && *env ? nl_xstrdup(env) : nl_path_join(NL_SOURCE_ROOT, "data/blas_spread.tsv");
  nl_error err;
  if (nl_table_read(path, NL_TABLE_TEXT, &t, &err)) nl_harness_die(r, 1, "tolerances: %s", err.msg);
  free(path);
  return t;
}

void nl_harness_check_measured(nl_harness *r, const char *table, double multiple)
{
  /* bench/blas-spread.sh sets this: the run is the measurement itself. */
  const char *measuring = getenv("NL_MEASURING");
  if (measuring && *measuring == '1') return;
  nl_table *t = spread_table(r);
  long ce = nl_table_column(t, "experiment"), cs = nl_table_column(t, "scale"),
       ct = nl_table_column(t, "table"), cc = nl_table_column(t, "column"),
       cr = nl_table_column(t, "max_rel_spread"), ca = nl_table_column(t, "max_abs_spread"),
       cg = nl_table_column(t, "configs");
  if (ce < 0 || cs < 0 || ct < 0 || cc < 0 || cr < 0 || ca < 0 || cg < 0)
    nl_harness_die(r, 1, "tolerances: data/blas_spread.tsv lacks a column (experiment, scale, table, "
                   "column, max_rel_spread, max_abs_spread, configs)");
  const char *scale = nl_harness_quick(r) ? "quick" : "full";
  int all = !strcmp(table, "*");
  /* A scale not measured borrows the other scale's spreads, and says so. */
  int borrowed = 0;
  {
    int have = 0;
    char b0[64], b1[64];
    for (size_t i = 0; i < t->nrows && !have; i++)
      have = !strcmp(nl_table_cell_text(t, i, (size_t)ce, b0), nl_harness_name(r)) && !strcmp(nl_table_cell_text(t, i, (size_t)cs, b1), scale);
    if (!have) { scale = nl_harness_quick(r) ? "full" : "quick"; borrowed = 1; }
  }
  char b[6][64];
  int found = 0, ndiff = 0, nabs = 0;
  double worst = 0, worst_abs = 0;
  char worst_abs_at[256] = "";
  char worst_at[256] = "", configs[1024] = "", moved[1024] = "", last[128] = "";
  for (size_t i = 0; i < t->nrows; i++) {
    const char *tab = nl_table_cell_text(t, i, (size_t)ct, b[2]);
    if (strcmp(nl_table_cell_text(t, i, (size_t)ce, b[0]), nl_harness_name(r)) || strcmp(nl_table_cell_text(t, i, (size_t)cs, b[1]), scale) ||
        (!all && strcmp(tab, table))) continue;
    found = 1;
    const char *col = nl_table_cell_text(t, i, (size_t)cc, b[3]);
    double rel = strtod(nl_table_cell_text(t, i, (size_t)cr, b[4]), NULL), ab = strtod(nl_table_cell_text(t, i, (size_t)ca, b[5]), NULL);
    const char *g = t->text[i * t->ncols + (size_t)cg];
    snprintf(configs, sizeof configs, "%s", g ? g : "");
    if (rel == 0) continue;   /* identical under every configuration: stays exact */
    const char *had = nl_harness_check_rule(r, tab, col);
    if (had && strcmp(had, "exact")) continue;   /* welch, ftest, ignore: the experiment's own */
    char rule[64];
    ndiff++;
    if (rel > NL_MEASURED_REL_LIMIT) { snprintf(rule, sizeof rule, "abs %.2g", multiple * ab); nabs++; }
    else snprintf(rule, sizeof rule, "rel %.2g", multiple * rel);
    nl_harness_check(r, tab, col, rule);
    if (strcmp(last, tab)) {   /* rows of one table are consecutive */
      size_t n = strlen(moved);
      snprintf(moved + n, sizeof moved - n, "%s`%s`", n ? ", " : "", tab);
      snprintf(last, sizeof last, "%s", tab);
    }
    if (rel > worst && rel <= NL_MEASURED_REL_LIMIT) {
      worst = rel;
      snprintf(worst_at, sizeof worst_at, "%s %s", tab, col);
    }
    if (rel > NL_MEASURED_REL_LIMIT && ab > worst_abs) {
      worst_abs = ab;
      snprintf(worst_abs_at, sizeof worst_abs_at, "%s %s", tab, col);
    }
  }
  if (!found)
    nl_harness_die(r, 1, "tolerances: no measured spread for %s %s (%s scale) in data/blas_spread.tsv; "
                   "run bench/blas-spread.sh%s %s", nl_harness_name(r), table, scale,
               nl_harness_quick(r) ? " --quick" : "", nl_harness_name(r));
  int nconf = 0;
  for (const char *p = configs; *p; p++) nconf += (p == configs || p[-1] == ' ') && *p != ' ';
  /* bench/arch-spread.sh --merge adds the arm64 run to the configurations */
  const char *kinds = strstr(configs, "aarch64") ? "OpenBLAS kernels, BLAS threads, libm without FMA, arm64"
                                                 : "OpenBLAS kernels, BLAS threads, libm without FMA";
  /* These sentences are about the regression check's tolerances, not the
   * results: every value above was computed by this run. */
  if (borrowed)
    nl_harness_text(r, "Regression tolerances are borrowed from the %s-scale measurement: how this "
                       "scale's values move across CPU configurations has not been measured.\n", scale);
  if (ndiff == 0) {
    nl_harness_text(r, "Regression rules: exact; no value of %s moved over %d CPU configurations "
                       "(%s; `data/blas_spread.tsv`).\n",
                   all ? "any table" : table, nconf, kinds);
    return;
  }
  char largest[320] = "";
  if (worst > 0) snprintf(largest, sizeof largest, ", the largest relative spread %.2g (%s)", worst, worst_at);
  else if (nabs) snprintf(largest, sizeof largest, ", the largest absolute spread %.2g (%s)", worst_abs, worst_abs_at);
  nl_harness_text(r, "Regression rules: %d column%s of %s moved over %d CPU configurations (%s; "
                     "`data/blas_spread.tsv`)%s; each is compared "
                     "within %g x its measured spread (%s); the other columns keep their declared rule "
                     "(exact unless stated).\n",
                 ndiff, ndiff == 1 ? "" : "s", moved, nconf, kinds, largest, multiple,
                 nabs == ndiff ? "absolute: the values move at rounding level"
                 : nabs        ? "relative; absolute for values at rounding level"
                               : "relative");
}
