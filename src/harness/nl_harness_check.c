/* The regression check's engine: an experiment's new tables against its
 * committed ones, column by column, by the rules of the committed checks.tsv
 * (nl_harness_check; see nl_harness.h). tools/check.c is its command line.
 * Every function returns a status instead of exiting, so a bad input is one
 * message for the caller and drift is a count. */
#include "harness/nl_harness.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct {
  nl_harness_check_state *s;
  const char *exp;
  size_t exp_drifted;        /* drift in the current experiment */
  int n_ref, n_new;          /* seeds behind each side's multi-seed summaries */
  nl_table *rules;           /* committed checks.tsv, or NULL: all exact */
} check_ctx;

static FILE *out_of(const nl_harness_check_state *s) { return s->out ? s->out : stdout; }

/* Reads DIR/FILE as text cells into *t. An optional table that is missing, or
 * has a header and no rows (an experiment that declared no rules), is NULL. */
static nl_status check_read(const char *dir, const char *file, int required, nl_table **t, nl_error *err)
{
  char *p = nl_path_join(dir, file);
  *t = NULL;
  FILE *fp = fopen(p, "r");
  if (!fp && !required) { free(p); return NL_OK; }
  if (fp && !required) {
    int lines = 0, c, last = '\n';
    while ((c = fgetc(fp)) != EOF) { if (c == '\n' && last != '\n') lines++; last = c; }
    if (last != '\n') lines++;
    fclose(fp);
    if (lines <= 1) { free(p); return NL_OK; }
  } else if (fp) fclose(fp);
  nl_status st = nl_table_read(p, NL_TABLE_TEXT, t, err);
  free(p);
  return st;
}

static void drift(check_ctx *c, const char *table, const char *row, const char *col,
                  const char *ref, const char *new, const char *rule)
{
  if (c->s->drifted++ == 0)
    fputs("experiment\ttable\trow\tcolumn\tcommitted\tnew\trule\n", out_of(c->s));
  if (++c->exp_drifted <= NL_CHECK_SHOWN || c->s->all)
    fprintf(out_of(c->s), "%s\t%s\t%s\t%s\t%s\t%s\t%s\n", c->exp, table, row, col, ref, new, rule);
}

/* The rule for table/column: a named column beats "*"; default exact. */
static const char *rule_for(const check_ctx *c, const char *table, const char *col)
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

static int same_bits(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* Compares committed a with new b (spreads s1, s2 for welch); returns 1 on
 * drift and writes a detail for the report line. A summary the tests refuse
 * (a negative or infinite sd) has p = NaN: drift. */
static int check_value(const check_ctx *c, const nl_harness_rule *rule, double a, double b,
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
    if (nl_stats_welch_p(a, s1, (size_t)c->n_ref, b, s2, (size_t)c->n_new, &p, NULL)) p = NAN;
    snprintf(detail, n, ": p = %.3g (sd %.3g, %.3g; n %d, %d)", p, s1, s2, c->n_ref, c->n_new);
    return !(p >= rule->tol);
  case NL_CHECK_FTEST:
    if (a == 0 && b == 0) return 0;
    if (nl_stats_ftest_p(a, (size_t)c->n_ref, b, (size_t)c->n_new, &p, NULL)) p = NAN;
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
static nl_status column_rule(const check_ctx *c, const char *file, const nl_table *ref, const nl_table *new,
                             const char *col, nl_harness_rule *rule, long *sd_ref, long *sd_new, nl_error *err)
{
  const char *text = rule_for(c, file, col);
  nl_error e;
  if (nl_harness_rule_parse(text, rule, &e))
    return nl_fail(err, NL_EFORMAT, "%s: checks.tsv: %s: %s", c->exp, file, e.msg);
  *sd_ref = *sd_new = -1;
  if (rule->kind == NL_CHECK_WELCH) {
    *sd_ref = nl_table_column(ref, rule->sdcol);
    *sd_new = nl_table_column(new, rule->sdcol);
    if (*sd_ref < 0 || *sd_new < 0)
      return nl_fail(err, NL_EFORMAT, "%s: %s: rule '%s' for %s: no column '%s'", c->exp, file, text, col, rule->sdcol);
  }
  if ((rule->kind == NL_CHECK_WELCH || rule->kind == NL_CHECK_FTEST) && (c->n_ref < 2 || c->n_new < 2))
    rule->kind = NL_CHECK_EXACT;   /* one seed has no spread to test against */
  return NL_OK;
}

/* One cell: text compared as text, numbers by the rule. Returns 1 on drift. */
static int check_cell(const check_ctx *c, const nl_harness_rule *rule, const nl_table *ref, const nl_table *new,
                      size_t i, size_t cr, size_t cn, long sr, long sn, char *detail, size_t n)
{
  const char *ta = ref->text[i * ref->ncols + cr], *tb = new->text[i * new->ncols + cn];
  *detail = '\0';
  if (ta || tb) return !ta || !tb || strcmp(ta, tb);
  nl_harness_rule exact = {.kind = NL_CHECK_EXACT};
  double s1 = 0, s2 = 0;
  if (sr >= 0) {
    /* A text cell in the spread column leaves nothing to test with: exact. */
    if (ref->text[i * ref->ncols + (size_t)sr] || new->text[i * new->ncols + (size_t)sn]) rule = &exact;
    else { s1 = nl_table_get(ref, i, (size_t)sr); s2 = nl_table_get(new, i, (size_t)sn); }
  }
  return check_value(c, rule, nl_table_get(ref, i, cr), nl_table_get(new, i, cn), s1, s2, detail, n);
}

static nl_status check_column(check_ctx *c, const char *file, const nl_table *ref, const nl_table *new,
                              size_t cr, size_t cn, size_t nrows, nl_error *err)
{
  nl_harness_rule rule;
  long sr = -1, sn = -1;
  const char *col = ref->names[cr], *text = rule_for(c, file, col);
  nl_status st = column_rule(c, file, ref, new, col, &rule, &sr, &sn, err);
  if (st || rule.kind == NL_CHECK_IGNORE) return st;
  for (size_t i = 0; i < nrows; i++) {
    char a[32], b[32], label[160], detail[160], full[320];
    c->s->values++;
    if (!check_cell(c, &rule, ref, new, i, cr, cn, sr, sn, detail, sizeof detail)) continue;
    row_label(ref, i, label, sizeof label);
    snprintf(full, sizeof full, "%s%s", text, detail);
    drift(c, file, label, col, nl_table_cell_text(ref, i, (size_t)cr, a), nl_table_cell_text(new, i, (size_t)cn, b), full);
  }
  return NL_OK;
}

/* The new run's table: NULL and "missing" when there is no such file, NULL
 * and the reader's message ("DIR/t.tsv:3: NUL byte in column 1") when it
 * cannot be read. Either is drift in that run, not bad input: the run wrote
 * no table to compare, and the other tables are still compared. */
static nl_table *check_read_new(const char *dir, const char *file, char *why, size_t n)
{
  char *p = nl_path_join(dir, file);
  nl_table *t = NULL;
  nl_error e;
  if (access(p, F_OK) != 0 && errno == ENOENT) snprintf(why, n, "missing");
  else if (nl_table_read(p, NL_TABLE_TEXT, &t, &e)) snprintf(why, n, "unreadable: %s", e.msg);
  free(p);
  return t;
}

/* Every rule of checks.tsv for this table names one of its columns (or *):
 * a rule for a column the reference does not have would compare nothing. */
static nl_status check_rule_columns(const check_ctx *c, const char *ref_dir, const char *file,
                                    const nl_table *ref, nl_error *err)
{
  for (size_t i = 0; c->rules && i < c->rules->nrows; i++) {
    char **row = c->rules->text + i * c->rules->ncols;
    if (!row[0] || !row[1] || strcmp(row[0], file) || !strcmp(row[1], "*")) continue;
    if (nl_table_column(ref, row[1]) < 0)
      return nl_fail(err, NL_EFORMAT, "%s/checks.tsv:%zu: rule '%s' for %s column %s: %s/%s has "
                     "no such column", ref_dir, i + 2, row[2] ? row[2] : "", file, row[1], ref_dir,
                     file);
  }
  return NL_OK;
}

/* One table: shape first (rows, columns on either side), then every value. */
static nl_status check_table(check_ctx *c, const char *ref_dir, const char *new_dir, const char *file, nl_error *err)
{
  nl_table *ref, *new;
  char why[NL_ERROR_LEN + 16];
  nl_status st = check_read(ref_dir, file, 1, &ref, err);
  if (st) return st;
  if ((st = check_rule_columns(c, ref_dir, file, ref, err))) { nl_table_free(ref); return st; }
  new = check_read_new(new_dir, file, why, sizeof why);
  char a[32], b[32];
  c->s->tables++;
  if (!new) { drift(c, file, "-", "-", "table", why, "exact"); nl_table_free(ref); return NL_OK; }
  if (ref->nrows != new->nrows) {
    snprintf(a, sizeof a, "%zu rows", ref->nrows); snprintf(b, sizeof b, "%zu rows", new->nrows);
    drift(c, file, "-", "-", a, b, "exact");
  }
  size_t nrows = ref->nrows < new->nrows ? ref->nrows : new->nrows;
  for (size_t cr = 0; cr < ref->ncols && !st; cr++) {
    long cn = nl_table_column(new, ref->names[cr]);
    nl_harness_rule gone;
    nl_error e;
    /* A column the reference's rules ignore is never compared, so a run
     * without it (a time, moved to times.tsv by nl_harness_time_column)
     * has not drifted. */
    if (cn < 0 && !nl_harness_rule_parse(rule_for(c, file, ref->names[cr]), &gone, &e) &&
        gone.kind == NL_CHECK_IGNORE)
      continue;
    if (cn < 0) drift(c, file, "-", ref->names[cr], "column", "missing", "exact");
    else st = check_column(c, file, ref, new, cr, (size_t)cn, nrows, err);
  }
  for (size_t k = 0; k < new->ncols && !st; k++)
    if (nl_table_column(ref, new->names[k]) < 0) drift(c, file, "-", new->names[k], "missing", "column", "exact");
  nl_table_free(ref); nl_table_free(new);
  return st;
}

/* ---- manifests ------------------------------------------------------------ */

/* Value of a manifest key as text (numbers come back formatted), or NULL. */
static const char *manifest_get(const nl_table *m, const char *key, char *buf)
{
  for (size_t i = 0; i < m->nrows; i++)
    if (m->text[i * 2] && !strcmp(m->text[i * 2], key)) return nl_table_cell_text(m, i, 1, buf);
  return NULL;
}

static nl_status manifest_seeds(const nl_table *m, const char *dir, int *seeds, nl_error *err)
{
  char buf[32];
  const char *s = manifest_get(m, "seeds", buf);
  char *end;
  long n = s ? strtol(s, &end, 10) : 0;
  if (!s || *end || n < 1) return nl_fail(err, NL_EFORMAT, "%s/manifest.tsv: no valid 'seeds' line", dir);
  *seeds = (int)n;
  return NL_OK;
}

/* The run must be the same run: seed, seeds, quick and every param line. */
static void check_manifests(check_ctx *c, const nl_table *ref, const nl_table *new)
{
  static const char *keys[] = {"experiment", "seed", "seeds", "quick"};
  for (int k = 0; k < 4; k++) {
    char ba[32], bb[32];
    const char *a = manifest_get(ref, keys[k], ba), *b = manifest_get(new, keys[k], bb);
    c->s->values++;
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
      if (side == 0) c->s->values++;
      if (!found) drift(c, "manifest.tsv", "-", "param", side ? "-" : p, side ? p : "-", "exact");
    }
  }
}

/* "CPU same (X)", "CPU other (reference X, this run Y)" or "CPU unknown
 * (...)" for one platform key of the two manifests. Returns 2 for other, 1
 * for unknown, 0 for same: the order the summary names them in. */
static int platform_phrase(const nl_table *ref, const nl_table *new, const char *key,
                           const char *label, char *out, size_t n)
{
  char ba[32], bb[32];
  const char *a = manifest_get(ref, key, ba), *b = manifest_get(new, key, bb);
  if (!a || !b || !strcmp(a, "unknown") || !strcmp(b, "unknown")) {
    snprintf(out, n, "%s unknown (reference: %s, this run: %s)", label, a ? a : "not recorded",
             b ? b : "not recorded");
    return 1;
  }
  if (!strcmp(a, b)) {
    snprintf(out, n, "%s same (%s)", label, a);
    return 0;
  }
  snprintf(out, n, "%s other (reference %s, this run %s)", label, a, b);
  return 2;
}

/* After an experiment with drift: how much, and what the two runs were made
 * on, what differs first (a libm variant or BLAS kernel moves the last bits
 * on one CPU; another CPU or architecture may change either). */
static void check_summary(const check_ctx *c, const nl_table *ref, const nl_table *new)
{
  static const char *keys[][2] = {
    {"cpu", "CPU"}, {"arch", "architecture"}, {"blas_core", "BLAS kernel"}, {"libm", "libm"},
  };
  enum { NKEYS = sizeof keys / sizeof keys[0] };
  char phrase[NKEYS][600], shown[80] = "";
  int rank[NKEYS];
  FILE *out = out_of(c->s);
  if (!c->exp_drifted) return;
  for (int k = 0; k < NKEYS; k++)
    rank[k] = platform_phrase(ref, new, keys[k][0], keys[k][1], phrase[k], sizeof phrase[k]);
  if (!c->s->all && c->exp_drifted > NL_CHECK_SHOWN)
    snprintf(shown, sizeof shown, " (first %d shown; --all for every one)", NL_CHECK_SHOWN);
  fprintf(out, "check: %s: %zu drifted%s; reference vs this run: ", c->exp, c->exp_drifted, shown);
  const char *sep = "";
  for (int want = 2; want >= 0; want--)
    for (int k = 0; k < NKEYS; k++) {
      if (rank[k] != want) continue;
      fprintf(out, "%s%s", sep, phrase[k]);
      sep = ", ";
    }
  fputc('\n', out);
}

/* Every rule of checks.tsv names a table of the reference folder: a rule
 * for a table that is not there would silently check nothing. */
static nl_status check_rule_tables(const check_ctx *c, const char *ref_dir, char **tables, size_t n,
                                   nl_error *err)
{
  for (size_t i = 0; c->rules && i < c->rules->nrows; i++) {
    char **row = c->rules->text + i * c->rules->ncols;
    size_t k = 0;
    while (k < n && (!row[0] || strcmp(row[0], tables[k])))
      k++;
    if (k == n)
      return nl_fail(err, NL_EFORMAT, "%s/checks.tsv:%zu: rule '%s' for %s column %s: %s has no "
                     "table %s", ref_dir, i + 2, row[2] ? row[2] : "", row[0] ? row[0] : "",
                     row[1] ? row[1] : "", ref_dir, row[0] ? row[0] : "(empty)");
  }
  return NL_OK;
}

/* The first reference made on another architecture or libm, kept for the
 * totals line: whether or not anything drifted, the user learns that the
 * comparison crossed machines. */
static void note_elsewhere(nl_harness_check_state *s, const nl_table *ref, const nl_table *new)
{
  static const char *keys[][2] = {{"arch", "architecture"}, {"libm", "libm"}};
  if (s->elsewhere[0]) return;
  for (int k = 0; k < 2; k++) {
    char phrase[600];
    if (platform_phrase(ref, new, keys[k][0], keys[k][1], phrase, sizeof phrase) != 2) continue;
    size_t used = strlen(s->elsewhere);
    snprintf(s->elsewhere + used, sizeof s->elsewhere - used, "%s%s", used ? ", " : "", phrase);
  }
}

/* A table the new run wrote that the reference folder lacks is drift too: a
 * committed table deleted by hand (or never committed) would otherwise
 * compare nothing and pass, while the same table missing from the new run
 * fails. What the run wrote is its manifest's "output" lines, not the
 * folder's files: a folder reused from the test suite holds the tests' own
 * tables beside the run's. */
static void check_unreferenced(check_ctx *c, const nl_table *mnew, char **ref_tables, size_t nref)
{
  for (size_t i = 0; i < mnew->nrows; i++) {
    const char *key = mnew->text[i * 2], *f = mnew->text[i * 2 + 1];
    size_t len = f ? strlen(f) : 0;
    if (!key || strcmp(key, "output") || len < 5 || strcmp(f + len - 4, ".tsv") ||
        !strcmp(f, "manifest.tsv") || !strcmp(f, "checks.tsv"))
      continue;
    size_t k = 0;
    while (k < nref && strcmp(ref_tables[k], f)) k++;
    if (k < nref) continue;
    c->s->tables++;
    drift(c, f, "-", "-", "missing", "table", "exact");
  }
}

/* The manifests, the rules and every committed table, in name order. */
static nl_status check_folders(check_ctx *c, const char *ref_dir, const char *new_dir, nl_table *mref,
                               nl_table *mnew, nl_error *err)
{
  char buf[32];
  const char *exp = manifest_get(mref, "experiment", buf);
  nl_status st;
  c->exp = exp ? exp : ref_dir;
  snprintf(c->s->last, sizeof c->s->last, "%s", c->exp);
  if ((st = manifest_seeds(mref, ref_dir, &c->n_ref, err)) || (st = manifest_seeds(mnew, new_dir, &c->n_new, err)) ||
      (st = check_read(ref_dir, "checks.tsv", 0, &c->rules, err)))
    return st;
  if (c->rules && c->rules->ncols != 3)
    return nl_fail(err, NL_EFORMAT, "%s/checks.tsv: wanted columns table, column, rule", ref_dir);
  check_manifests(c, mref, mnew);
  size_t n;
  char **tables = nl_harness_tables(ref_dir, &n, err);
  if (!tables) return NL_EIO;
  st = check_rule_tables(c, ref_dir, tables, n, err);
  for (size_t i = 0; i < n && !st; i++) st = check_table(c, ref_dir, new_dir, tables[i], err);
  if (!st) check_unreferenced(c, mnew, tables, n);
  for (size_t i = 0; i < n; i++) free(tables[i]);
  free(tables);
  if (!st) check_summary(c, mref, mnew);
  if (!st) note_elsewhere(c->s, mref, mnew);
  return st;
}

nl_status nl_harness_check_experiment(nl_harness_check_state *s, const char *ref_dir, const char *new_dir, nl_error *err)
{
  check_ctx c = {.s = s};
  nl_table *mref = NULL, *mnew = NULL;
  nl_status st = check_read(ref_dir, "manifest.tsv", 1, &mref, err);
  if (!st) st = check_read(new_dir, "manifest.tsv", 1, &mnew, err);
  if (!st) st = check_folders(&c, ref_dir, new_dir, mref, mnew, err);
  s->experiments++;
  nl_table_free(c.rules);
  nl_table_free(mref); nl_table_free(mnew);
  return st;
}

void nl_harness_check_totals(const nl_harness_check_state *s)
{
  const char *sep = s->elsewhere[0] ? "; reference made elsewhere: " : "";
  if (s->experiments == 1)
    fprintf(out_of(s), "check: %s: %zu tables, %zu values compared, %zu drifted%s%s\n", s->last,
            s->tables, s->values, s->drifted, sep, s->elsewhere);
  else
    fprintf(out_of(s), "check: %zu experiments, %zu tables, %zu values compared, %zu drifted%s%s\n",
            s->experiments, s->tables, s->values, s->drifted, sep, s->elsewhere);
}
