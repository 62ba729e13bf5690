/* noiselab check - compare an experiment's new tables with its committed
 * ones, column by column, by the rules the experiment declared
 * (nl_run_check, checks.tsv; see src/report/nl_report.h).
 *
 *   noiselab-check COMMITTED_DIR NEW_DIR              two experiment folders
 *   noiselab-check COMMITTED_ROOT NEW_ROOT NAME...    ROOT/NAME for each name
 *
 * `scripts/noiselab check` reruns the experiments with the committed seed
 * and calls this. Every table (*.tsv but the manifest and checks.tsv) of the
 * committed folder is compared; the rules come from the committed folder's
 * checks.tsv, because the reference says how it may be compared (a changed
 * declaration takes effect when the references are made again). The
 * manifests' seed, seeds, quick and param lines must match exactly.
 *
 * The other manifest lines (commit, versions, cpu, blas*, cflags, started,
 * seconds, peak_rss_mb) are never compared.
 *
 * Output: one tab-separated line per drifted value on stdout
 *   experiment  table  row  column  committed  new  rule[: detail]
 * (row: 1-based data row, with its first text cell as a label), the first
 * 10 of an experiment only unless --all; for an experiment with drift a line
 *   check: EXPERIMENT: D drifted[ (first 10 shown; --all for every one)];
 *     reference vs this run: CPU same|other|unknown (...), BLAS kernel ...
 * ("unknown" when a manifest predates the cpu and blas_core keys), then
 *   check: E experiments, T tables, V values compared, D drifted
 * Exit 0: no drift; 1: drift; 2: bad input (missing folder or manifest,
 * unreadable table, malformed rule or a rule naming a missing column).
 */
#include "report/nl_report.h"
#include "table/nl_table.h"

#include <stdarg.h>
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define NL_CHECK_SHOWN 10   /* drifted values printed per experiment without --all */

typedef struct {
  const char *exp;
  int all;                   /* --all: every drifted value */
  size_t exp_drifted;        /* drift in the current experiment */
  int n_ref, n_new;          /* seeds behind each side's multi-seed summaries */
  nl_table *rules;           /* committed checks.tsv, or NULL: all exact */
  size_t tables, values, drifted;
} nl_check_ctx;

static void nl_check_die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
static void nl_check_die(const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fputs("noiselab-check: ", stderr);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  exit(2);
}

static nl_table *nl_check_read(const char *dir, const char *file, int required)
{
  char *p = nl_path_join(dir, file);
  nl_table *t = NULL;
  nl_error err;
  FILE *fp = fopen(p, "r");
  if (!fp && !required) { free(p); return NULL; }
  if (fp && !required) {
    /* An optional table with a header and no rows (an experiment that
     * declared no rules) means the same as no table. */
    int lines = 0, c, last = '\n';
    while ((c = fgetc(fp)) != EOF) { if (c == '\n' && last != '\n') lines++; last = c; }
    if (last != '\n') lines++;
    fclose(fp);
    if (lines <= 1) { free(p); return NULL; }
  } else if (fp) fclose(fp);
  if (nl_table_read(p, NL_TABLE_TEXT, &t, &err)) nl_check_die("%s", err.msg);
  free(p);
  return t;
}

static void drift(nl_check_ctx *c, const char *table, const char *row, const char *col,
                  const char *ref, const char *new, const char *rule)
{
  c->drifted++;
  if (++c->exp_drifted <= NL_CHECK_SHOWN || c->all)
    printf("%s\t%s\t%s\t%s\t%s\t%s\t%s\n", c->exp, table, row, col, ref, new, rule);
}

/* The rule for table/column: a named column beats "*"; default exact. */
static const char *rule_for(const nl_check_ctx *c, const char *table, const char *col)
{
  const char *star = NULL;
  if (!c->rules) return "exact";
  for (size_t i = 0; i < c->rules->nrows; i++) {
    char **row = c->rules->text + i * c->rules->ncols;
    if (!row[0] || !row[1] || !row[2] || strcmp(row[0], table)) continue;
    if (!strcmp(row[1], col)) return row[2];
    if (!strcmp(row[1], "*")) star = row[2];
  }
  return star ? star : "exact";
}

/* Welch's two-sided t-test of equal means from means, sds and seed counts. */
static double nl_check_welch_p(double m1, double s1, int n1, double m2, double s2, int n2)
{
  double v1 = s1 * s1 / n1, v2 = s2 * s2 / n2;
  double t = fabs(m2 - m1) / sqrt(v1 + v2);
  double df = (v1 + v2) * (v1 + v2) / (v1 * v1 / (n1 - 1) + v2 * v2 / (n2 - 1));
  return 2 * gsl_cdf_tdist_Q(t, df);
}

/* Two-sided F-test of equal variances from two sds over n1, n2 seeds. */
static double nl_check_ftest_p(double s1, int n1, double s2, int n2)
{
  if (s1 == 0 || s2 == 0) return 0;   /* one spread vanished, the other did not */
  double f = (s2 * s2) / (s1 * s1);
  double p = 2 * fmin(gsl_cdf_fdist_P(f, n2 - 1, n1 - 1), gsl_cdf_fdist_Q(f, n2 - 1, n1 - 1));
  return fmin(p, 1.0);
}

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Compares committed a with new b (spreads s1, s2 for welch); returns 1 on
 * drift and writes a detail for the report line. */
static int nl_check_value(const nl_check_ctx *c, const nl_check_rule *rule, double a, double b,
                          double s1, double s2, char *detail, size_t n)
{
  double p;
  *detail = '\0';
  switch (rule->kind) {
  case NL_CHECK_IGNORE: return 0;
  case NL_CHECK_EXACT: return !same_bits(a, b);
  case NL_CHECK_ABS: return !(fabs(b - a) <= rule->tol);
  case NL_CHECK_REL: return !(fabs(b - a) <= rule->tol * fmax(fabs(a), fabs(b)));
  case NL_CHECK_WELCH:
    if (s1 == 0 && s2 == 0) { snprintf(detail, n, ": both spreads 0, compared exactly"); return !same_bits(a, b); }
    p = nl_check_welch_p(a, s1, c->n_ref, b, s2, c->n_new);
    snprintf(detail, n, ": p = %.3g (sd %.3g, %.3g; n %d, %d)", p, s1, s2, c->n_ref, c->n_new);
    return !(p >= rule->tol);
  case NL_CHECK_FTEST:
    if (a == 0 && b == 0) return 0;
    p = nl_check_ftest_p(a, c->n_ref, b, c->n_new);
    snprintf(detail, n, ": p = %.3g (n %d, %d)", p, c->n_ref, c->n_new);
    return !(p >= rule->tol);
  }
  return 1;
}

static void row_label(const nl_table *t, size_t row, char *buf, size_t n)
{
  if (t->ncols > 0 && t->text[row * t->ncols]) snprintf(buf, n, "%zu [%s]", row + 1, t->text[row * t->ncols]);
  else snprintf(buf, n, "%zu", row + 1);
}

/* Parses the rule of a column and finds the welch spread column on both sides. */
static void column_rule(const nl_check_ctx *c, const char *file, const nl_table *ref, const nl_table *new,
                        const char *col, nl_check_rule *rule, long *sd_ref, long *sd_new)
{
  const char *text = rule_for(c, file, col);
  nl_error err;
  if (nl_check_rule_parse(text, rule, &err)) nl_check_die("%s: checks.tsv: %s: %s", c->exp, file, err.msg);
  *sd_ref = *sd_new = -1;
  if (rule->kind == NL_CHECK_WELCH) {
    *sd_ref = nl_table_column(ref, rule->sdcol);
    *sd_new = nl_table_column(new, rule->sdcol);
    if (*sd_ref < 0 || *sd_new < 0)
      nl_check_die("%s: %s: rule '%s' for %s: no column '%s'", c->exp, file, text, col, rule->sdcol);
  }
  if ((rule->kind == NL_CHECK_WELCH || rule->kind == NL_CHECK_FTEST) && (c->n_ref < 2 || c->n_new < 2))
    rule->kind = NL_CHECK_EXACT;   /* one seed has no spread to test against */
}

/* One cell: text compared as text, numbers by the rule. Returns 1 on drift. */
static int nl_check_cell(const nl_check_ctx *c, const nl_check_rule *rule, const nl_table *ref, const nl_table *new,
                         size_t i, size_t cr, size_t cn, long sr, long sn, char *detail, size_t n)
{
  const char *ta = ref->text[i * ref->ncols + cr], *tb = new->text[i * new->ncols + cn];
  *detail = '\0';
  if (ta || tb) return !ta || !tb || strcmp(ta, tb);
  nl_check_rule exact = {.kind = NL_CHECK_EXACT};
  double s1 = 0, s2 = 0;
  if (sr >= 0) {
    /* A text cell in the spread column leaves nothing to test with: exact. */
    if (ref->text[i * ref->ncols + (size_t)sr] || new->text[i * new->ncols + (size_t)sn]) rule = &exact;
    else { s1 = nl_table_get(ref, i, (size_t)sr); s2 = nl_table_get(new, i, (size_t)sn); }
  }
  return nl_check_value(c, rule, nl_table_get(ref, i, cr), nl_table_get(new, i, cn), s1, s2, detail, n);
}

static void nl_check_column(nl_check_ctx *c, const char *file, const nl_table *ref, const nl_table *new,
                            size_t cr, size_t cn, size_t nrows)
{
  nl_check_rule rule;
  long sr, sn;
  const char *col = ref->names[cr], *text = rule_for(c, file, col);
  column_rule(c, file, ref, new, col, &rule, &sr, &sn);
  if (rule.kind == NL_CHECK_IGNORE) return;
  for (size_t i = 0; i < nrows; i++) {
    char a[32], b[32], label[160], detail[160], full[320];
    c->values++;
    if (!nl_check_cell(c, &rule, ref, new, i, cr, cn, sr, sn, detail, sizeof detail)) continue;
    row_label(ref, i, label, sizeof label);
    snprintf(full, sizeof full, "%s%s", text, detail);
    drift(c, file, label, col, nl_table_cell_text(ref, i, (size_t)cr, a), nl_table_cell_text(new, i, (size_t)cn, b), full);
  }
}

/* One table: shape first (rows, columns on either side), then every value. */
static void nl_check_table(nl_check_ctx *c, const char *ref_dir, const char *new_dir, const char *file)
{
  nl_table *ref = nl_check_read(ref_dir, file, 1), *new = nl_check_read(new_dir, file, 0);
  char a[32], b[32];
  c->tables++;
  if (!new) { drift(c, file, "-", "-", "table", "missing", "exact"); nl_table_free(ref); return; }
  if (ref->nrows != new->nrows) {
    snprintf(a, sizeof a, "%zu rows", ref->nrows); snprintf(b, sizeof b, "%zu rows", new->nrows);
    drift(c, file, "-", "-", a, b, "exact");
  }
  size_t nrows = ref->nrows < new->nrows ? ref->nrows : new->nrows;
  for (size_t cr = 0; cr < ref->ncols; cr++) {
    long cn = nl_table_column(new, ref->names[cr]);
    if (cn < 0) drift(c, file, "-", ref->names[cr], "column", "missing", "exact");
    else nl_check_column(c, file, ref, new, cr, (size_t)cn, nrows);
  }
  for (size_t k = 0; k < new->ncols; k++)
    if (nl_table_column(ref, new->names[k]) < 0) drift(c, file, "-", new->names[k], "missing", "column", "exact");
  nl_table_free(ref); nl_table_free(new);
}

/* ---- manifests ------------------------------------------------------------ */

/* Value of a manifest key as text (numbers come back formatted), or NULL. */
static const char *manifest_get(const nl_table *m, const char *key, char *buf)
{
  for (size_t i = 0; i < m->nrows; i++)
    if (m->text[i * 2] && !strcmp(m->text[i * 2], key)) return nl_table_cell_text(m, i, 1, buf);
  return NULL;
}

static int manifest_seeds(const nl_table *m, const char *dir)
{
  char buf[32];
  const char *s = manifest_get(m, "seeds", buf);
  char *end;
  long n = s ? strtol(s, &end, 10) : 0;
  if (!s || *end || n < 1) nl_check_die("%s/manifest.tsv: no valid 'seeds' line", dir);
  return (int)n;
}

/* The run must be the same run: seed, seeds, quick and every param line. */
static void nl_check_manifests(nl_check_ctx *c, const nl_table *ref, const nl_table *new)
{
  static const char *keys[] = {"experiment", "seed", "seeds", "quick"};
  for (int k = 0; k < 4; k++) {
    char ba[32], bb[32];
    const char *a = manifest_get(ref, keys[k], ba), *b = manifest_get(new, keys[k], bb);
    c->values++;
    if (!a || !b || strcmp(a, b)) drift(c, "manifest.tsv", "-", keys[k], a ? a : "missing", b ? b : "missing", "exact");
  }
  for (int side = 0; side < 2; side++) {
    const nl_table *x = side ? new : ref, *y = side ? ref : new;
    for (size_t i = 0; i < x->nrows; i++) {
      const char *p = x->text[i * 2 + 1];
      if (!x->text[i * 2] || strcmp(x->text[i * 2], "param") || !p) continue;
      int found = 0;
      for (size_t j = 0; j < y->nrows && !found; j++)
        found = y->text[j * 2] && !strcmp(y->text[j * 2], "param") && y->text[j * 2 + 1] && !strcmp(y->text[j * 2 + 1], p);
      if (side == 0) c->values++;
      if (!found) drift(c, "manifest.tsv", "-", "param", side ? "-" : p, side ? p : "-", "exact");
    }
  }
}

/* "CPU same (X)", "CPU other (X -> Y)" or "CPU unknown (...)" for one
 * platform key of the two manifests. */
static void platform_phrase(const nl_table *ref, const nl_table *new, const char *key,
                            const char *label, char *out, size_t n)
{
  char ba[32], bb[32];
  const char *a = manifest_get(ref, key, ba), *b = manifest_get(new, key, bb);
  if (!a || !b || !strcmp(a, "unknown") || !strcmp(b, "unknown"))
    snprintf(out, n, "%s unknown (reference: %s, this run: %s)", label, a ? a : "not recorded", b ? b : "not recorded");
  else if (!strcmp(a, b)) snprintf(out, n, "%s same (%s)", label, a);
  else snprintf(out, n, "%s other (reference %s, this run %s)", label, a, b);
}

/* After an experiment with drift: how much, and whether the reference was
 * made on another CPU or BLAS kernel than the new run. */
static void nl_check_summary(const nl_check_ctx *c, const nl_table *ref, const nl_table *new)
{
  char cpu[600], core[300], shown[80] = "";
  if (!c->exp_drifted) return;
  platform_phrase(ref, new, "cpu", "CPU", cpu, sizeof cpu);
  platform_phrase(ref, new, "blas_core", "BLAS kernel", core, sizeof core);
  if (!c->all && c->exp_drifted > NL_CHECK_SHOWN)
    snprintf(shown, sizeof shown, " (first %d shown; --all for every one)", NL_CHECK_SHOWN);
  printf("check: %s: %zu drifted%s; reference vs this run: %s, %s\n", c->exp, c->exp_drifted, shown, cpu, core);
}

/* The committed folder's tables, sorted. */
static char **list_tables(const char *dir, size_t *n)
{
  nl_error err;
  char **names = nl_run_tables(dir, n, &err);
  if (!names) nl_check_die("%s", err.msg);
  return names;
}

static void nl_check_experiment(nl_check_ctx *c, const char *ref_dir, const char *new_dir)
{
  nl_table *mref = nl_check_read(ref_dir, "manifest.tsv", 1), *mnew = nl_check_read(new_dir, "manifest.tsv", 1);
  char buf[32];
  const char *exp = manifest_get(mref, "experiment", buf);
  c->exp = exp ? exp : ref_dir;
  c->n_ref = manifest_seeds(mref, ref_dir);
  c->n_new = manifest_seeds(mnew, new_dir);
  c->rules = nl_check_read(ref_dir, "checks.tsv", 0);
  if (c->rules && c->rules->ncols != 3) nl_check_die("%s/checks.tsv: wanted columns table, column, rule", ref_dir);
  nl_check_manifests(c, mref, mnew);
  size_t n;
  char **tables = list_tables(ref_dir, &n);
  for (size_t i = 0; i < n; i++) { nl_check_table(c, ref_dir, new_dir, tables[i]); free(tables[i]); }
  free(tables);
  nl_table_free(c->rules);
  c->rules = NULL;
  nl_check_summary(c, mref, mnew);
  c->exp_drifted = 0;
  nl_table_free(mref); nl_table_free(mnew);
  c->exp = NULL;
}

int main(int argc, char **argv)
{
  nl_check_ctx c = {0};
  int w = 1;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      printf("usage: noiselab-check [--all] COMMITTED_DIR NEW_DIR\n"
             "       noiselab-check [--all] COMMITTED_ROOT NEW_ROOT EXPERIMENT...\n\n"
             "Compares every table of the committed run with the new run by the rules of\n"
             "the committed checks.tsv; prints one line per drifted value\n"
             "(experiment, table, row, column, committed, new, rule), the first %d of\n"
             "an experiment (--all: every one), a line per drifted experiment naming\n"
             "the CPU and BLAS kernel of both runs, and a summary.\n"
             "Exit 0: no drift, 1: drift, 2: bad input.\n", NL_CHECK_SHOWN);
      return 0;
    }
    if (!strcmp(argv[i], "--all")) { c.all = 1; continue; }
    if (argv[i][0] == '-' && argv[i][1]) nl_check_die("%s: unknown option (see --help)", argv[i]);
    argv[w++] = argv[i];
  }
  argc = w;
  if (argc < 3) nl_check_die("wanted COMMITTED NEW [EXPERIMENT...] (see --help)");
  int nexp = argc > 3 ? argc - 3 : 1;
  if (argc == 3) nl_check_experiment(&c, argv[1], argv[2]);
  for (int i = 3; i < argc; i++) {
    char *a = nl_path_join(argv[1], argv[i]), *b = nl_path_join(argv[2], argv[i]);
    nl_check_experiment(&c, a, b);
    free(a); free(b);
  }
  printf("check: %d experiment%s, %zu tables, %zu values compared, %zu drifted\n",
         nexp, nexp == 1 ? "" : "s", c.tables, c.values, c.drifted);
  return c.drifted ? 1 : 0;
}
