/* A sweep's merge (nl_sweep.h): the finished tasks' tables into one table
 * each, and their summaries over seeds per parameter point and row. */
#include "sweep/nl_sweep.h"
#include "harness/nl_harness.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static nl_status read_in(const char *dir, const char *file, nl_table **t, nl_error *err)
{
  char *p = nl_path_join(dir, file);
  nl_status s = nl_table_read(p, NL_TABLE_TEXT, t, err);
  free(p);
  return s;
}

/* The param rows of the definition name the parameters (scale "list" until
 * a scale row says otherwise); the seeds row their seeds per point. */
static void read_definition(nl_sweep_merge *m, const nl_table *def)
{
  char kb[32], vb[32];
  for (size_t r = 0; r < def->nrows; r++) {
    const char *k = nl_table_cell_text(def, r, 0, kb), *v = nl_table_cell_text(def, r, 1, vb);
    const char *eq = strchr(v, '=');
    if (!strcmp(k, "seeds"))
      m->seeds = atol(v);
    if (strcmp(k, "param") || !eq)
      continue;
    m->pname = nl_xrealloc(m->pname, (size_t)(m->np + 1) * sizeof *m->pname);
    m->pscale = nl_xrealloc(m->pscale, (size_t)(m->np + 1) * sizeof *m->pscale);
    m->pname[m->np] = nl_xstrdup(v);
    m->pname[m->np][eq - v] = '\0';
    m->pscale[m->np++] = nl_xstrdup("list");
  }
  for (size_t r = 0; r < def->nrows; r++) {
    const char *k = nl_table_cell_text(def, r, 0, kb), *v = nl_table_cell_text(def, r, 1, vb);
    const char *eq = strchr(v, '=');
    if (strcmp(k, "scale") || !eq)
      continue;
    for (int p = 0; p < m->np; p++)
      if (!strncmp(v, m->pname[p], (size_t)(eq - v)) && !m->pname[p][eq - v]) {
        free(m->pscale[p]);
        m->pscale[p] = nl_xstrdup(eq + 1);
      }
  }
}

nl_status nl_sweep_merge_open(const char *dir, nl_sweep_merge *m, FILE *log, nl_error *err)
{
  nl_table *def;
  memset(m, 0, sizeof *m);
  m->dir = dir;
  nl_status s = read_in(dir, "sweep.tsv", &def, err);
  if (s || (s = read_in(dir, "tasks.tsv", &m->tasks, err)))
    return s;
  read_definition(m, def);
  nl_table_free(def);
  if (m->np == 0 || m->seeds < 1 || m->tasks->ncols != (size_t)m->np + 3)
    return nl_fail(err, NL_EFORMAT, "%s/sweep.tsv: not a sweep definition matching tasks.tsv", dir);
  m->done = nl_xcalloc(m->tasks->nrows + 1, sizeof *m->done);
  for (size_t r = 0; r < m->tasks->nrows; r++) {
    char buf[32];
    if (nl_sweep_task_finished(dir, nl_table_cell_text(m->tasks, r, 1, buf)))
      m->done[m->ndone++] = r;
  }
  if (m->ndone == 0)
    return nl_fail(err, NL_EINVAL, "%s: no task has finished yet (no tasks/*/manifest.tsv)", dir);
  if (m->ndone < m->tasks->nrows)
    fprintf(log, "noiselab sweep: merging %zu of %zu tasks (the others are not finished)\n",
            m->ndone, m->tasks->nrows);
  return NL_OK;
}

void nl_sweep_merge_free(nl_sweep_merge *m)
{
  for (int k = 0; k < m->np; k++) {
    free(m->pname[k]);
    free(m->pscale[k]);
  }
  free(m->pname);
  free(m->pscale);
  free(m->done);
  nl_table_free(m->tasks);
  memset(m, 0, sizeof *m);
}

static nl_status task_table(const nl_sweep_merge *m, size_t k, const char *file, nl_table **t,
                            nl_error *err)
{
  char buf[32], *dir = nl_path_join(m->dir, nl_table_cell_text(m->tasks, m->done[k], 1, buf));
  nl_status s = read_in(dir, file, t, err);
  free(dir);
  return s;
}

/* Appends a row of cells taken from text (NULL: the number). */
static void append_cells(nl_table *t, const double *num, char *const *text)
{
  nl_table_append_doubles(t, num);
  for (size_t c = 0; c < t->ncols; c++)
    if (text[c])
      t->text[(t->nrows - 1) * t->ncols + c] = nl_xstrdup(text[c]);
}

/* The merged table's columns: the parameters, seed, then the task's own,
 * renamed task_NAME where they clash with the leading ones. */
static nl_table *merged_alloc(const nl_sweep_merge *m, const nl_table *first)
{
  size_t lead = (size_t)m->np + 1, nc = lead + first->ncols;
  const char **names = nl_xcalloc(nc, sizeof *names);
  char **renamed = nl_xcalloc(nc, sizeof *renamed);
  for (int k = 0; k < m->np; k++)
    names[k] = m->pname[k];
  names[m->np] = "seed";
  for (size_t c = 0; c < first->ncols; c++) {
    const char *n = first->names[c];
    int clash = !strcmp(n, "seed");
    for (int k = 0; k < m->np; k++)
      clash |= !strcmp(n, m->pname[k]);
    if (clash) {
      renamed[lead + c] = nl_xmalloc(strlen(n) + 6);
      sprintf(renamed[lead + c], "task_%s", n);
    }
    names[lead + c] = clash ? renamed[lead + c] : n;
  }
  nl_table *out = nl_table_alloc(nc, names);
  for (size_t c = 0; c < nc; c++)
    free(renamed[c]);
  free(renamed);
  free(names);
  return out;
}

nl_status nl_sweep_merge_rows(const nl_sweep_merge *m, const char *file, nl_table **merged,
                              nl_table **first, size_t **point_of, size_t **row_of, nl_error *err)
{
  *merged = NULL;
  *point_of = *row_of = NULL;
  nl_status s = task_table(m, 0, file, first, err);
  if (s)
    return s;
  nl_table *out = merged_alloc(m, *first);
  size_t lead = (size_t)m->np + 1, nc = out->ncols;
  double *num = nl_xmalloc(nc * sizeof *num);
  char **text = nl_xcalloc(nc, sizeof *text);
  for (size_t k = 0; k < m->ndone && !s; k++) {
    nl_table *t = *first;
    if (k && (s = task_table(m, k, file, &t, err)))
      break;
    if (t->ncols != (*first)->ncols)
      s = nl_fail(err, NL_EFORMAT, "%s: task %zu's %s has other columns than the first task's",
                  m->dir, m->done[k], file);
    for (size_t c = 0; c < lead; c++)   /* the parameters (task columns 3...) and the seed (2) */
      num[c] = nl_table_get(m->tasks, m->done[k], c == (size_t)m->np ? 2 : c + 3);
    for (size_t r = 0; r < t->nrows && !s; r++) {
      for (size_t c = 0; c < t->ncols; c++) {
        num[lead + c] = nl_table_get(t, r, c);
        text[lead + c] = t->text[r * t->ncols + c];
      }
      append_cells(out, num, text);
      *point_of = nl_xrealloc(*point_of, out->nrows * sizeof **point_of);
      *row_of = nl_xrealloc(*row_of, out->nrows * sizeof **row_of);
      (*point_of)[out->nrows - 1] = m->done[k] / (size_t)m->seeds;   /* point-major, seeds inner */
      (*row_of)[out->nrows - 1] = r;
    }
    if (k)
      nl_table_free(t);
  }
  free(num);
  free(text);
  if (s) {
    nl_table_free(out);
    return s;
  }
  *merged = out;
  return NL_OK;
}

/* ---- the summary: groups of merged rows by (point, row) ------------------ */

/* Group of every merged row, numbered in the order of their first rows, by
 * open addressing on (point, row): one pass, so a sweep of a million rows
 * merges in seconds. Returns the number of groups. */
static size_t group_rows(const size_t *point_of, const size_t *row_of, size_t n, size_t *group,
                         size_t *first_row)
{
  size_t cap = 16;
  while (cap < 2 * n)
    cap *= 2;
  size_t *slot = nl_xmalloc(cap * sizeof *slot), ngroups = 0;
  for (size_t i = 0; i < cap; i++)
    slot[i] = SIZE_MAX;   /* empty; else a group number */
  for (size_t r = 0; r < n; r++) {
    uint64_t h = (uint64_t)point_of[r] * 0x9E3779B97F4A7C15u ^ (uint64_t)row_of[r];
    h *= 0xBF58476D1CE4E5B9u;
    size_t i = (size_t)(h >> 17) & (cap - 1);
    for (;; i = (i + 1) & (cap - 1)) {
      size_t g = slot[i];
      if (g == SIZE_MAX) {
        slot[i] = ngroups;
        first_row[ngroups] = r;
        group[r] = ngroups++;
        break;
      }
      if (point_of[first_row[g]] == point_of[r] && row_of[first_row[g]] == row_of[r]) {
        group[r] = g;
        break;
      }
    }
  }
  free(slot);
  return ngroups;
}

/* Columns of the first task's table that hold text (labels), by its first row. */
/* A column is text when any row of the first task's table holds text in it
 * (a verdict's ours_sd is "-" on rows without a spread, a number on others):
 * the summary then carries the group's first cell, not a mean. */
static int is_text_col(const nl_table *first, size_t c)
{
  for (size_t r = 0; r < first->nrows; r++)
    if (first->text[r * first->ncols + c]) return 1;
  return 0;
}

static nl_table *summary_alloc(const nl_sweep_merge *m, const nl_table *merged,
                               const nl_table *first)
{
  size_t lead = (size_t)m->np + 1, tc = first->ncols, nc = (size_t)m->np + 2, j = 0;
  for (size_t c = 0; c < tc; c++)
    nc += is_text_col(first, c) ? 1 : 2;
  const char **names = nl_xcalloc(nc, sizeof *names);
  char **owned = nl_xcalloc(nc, sizeof *owned);
  for (int k = 0; k < m->np; k++)
    names[j++] = m->pname[k];
  names[j++] = "row";
  for (size_t c = 0; c < tc; c++)
    if (is_text_col(first, c))
      names[j++] = merged->names[lead + c];
  names[j++] = "n";
  for (size_t c = 0; c < tc; c++) {
    if (is_text_col(first, c))
      continue;
    const char *b = merged->names[lead + c];
    owned[j] = nl_xmalloc(strlen(b) + 8);
    sprintf(owned[j], "%s_mean", b);
    names[j] = owned[j];
    j++;
    owned[j] = nl_xmalloc(strlen(b) + 8);
    sprintf(owned[j], "%s_spread", b);
    names[j] = owned[j];
    j++;
  }
  nl_table *s = nl_table_alloc(nc, names);
  for (size_t c = 0; c < nc; c++)
    free(owned[c]);
  free(owned);
  free(names);
  return s;
}

nl_status nl_sweep_merge_summary(const nl_sweep_merge *m, const nl_table *merged,
                                 const nl_table *first, const size_t *point_of,
                                 const size_t *row_of, nl_table **summary, nl_error *err)
{
  size_t lead = (size_t)m->np + 1, tc = first->ncols, n = merged->nrows;
  size_t *group = nl_xmalloc((n + 1) * sizeof *group);
  size_t *first_row = nl_xmalloc((n + 1) * sizeof *first_row);
  size_t ng = group_rows(point_of, row_of, n, group, first_row);
  /* The rows of each group in merged order: a counting sort by group. */
  size_t *start = nl_xcalloc(ng + 1, sizeof *start), *rows = nl_xmalloc((n + 1) * sizeof *rows);
  for (size_t r = 0; r < n; r++)
    start[group[r] + 1]++;
  for (size_t g = 0; g < ng; g++)
    start[g + 1] += start[g];
  size_t *fill = nl_xmalloc((ng + 1) * sizeof *fill);
  memcpy(fill, start, (ng + 1) * sizeof *fill);
  for (size_t r = 0; r < n; r++)
    rows[fill[group[r]]++] = r;
  nl_table *s = summary_alloc(m, merged, first);
  size_t nc = s->ncols;
  double *num = nl_xmalloc(nc * sizeof *num), *vals = nl_xmalloc((n + 1) * sizeof *vals);
  char **text = nl_xcalloc(nc, sizeof *text);
  char (*numtext)[32] = nl_xmalloc(nc * sizeof *numtext);   /* numbers in text columns */
  nl_status st = NL_OK;
  for (size_t g = 0; g < ng && !st; g++) {
    size_t r0 = first_row[g], col = 0, cnt = start[g + 1] - start[g];
    const size_t *gr = rows + start[g];
    memset(text, 0, nc * sizeof *text);
    for (int k = 0; k < m->np; k++)
      num[col++] = nl_table_get(merged, r0, (size_t)k);
    num[col++] = (double)row_of[r0] + 1;
    for (size_t c = 0; c < tc; c++)
      if (is_text_col(first, c)) {
        text[col] = merged->text[r0 * merged->ncols + lead + c];
        if (!text[col]) {
          nl_table_format_double(numtext[col], nl_table_get(merged, r0, lead + c));
          text[col] = numtext[col];
        }
        num[col++] = NAN;
      }
    num[col++] = (double)cnt;
    for (size_t c = 0; c < tc && !st; c++) {
      if (is_text_col(first, c))
        continue;
      for (size_t q = 0; q < cnt && !st; q++) {
        if (merged->text[gr[q] * merged->ncols + lead + c])
          st = nl_fail(err, NL_EFORMAT, "%s: column %s holds text and numbers", m->dir,
                       merged->names[lead + c]);
        vals[q] = nl_table_get(merged, gr[q], lead + c);
      }
      num[col++] = gsl_stats_mean(vals, 1, cnt);
      num[col++] = cnt > 1 ? gsl_stats_sd(vals, 1, cnt) : 0;
    }
    if (!st)
      append_cells(s, num, text);
  }
  free(group);
  free(first_row);
  free(start);
  free(rows);
  free(fill);
  free(num);
  free(vals);
  free(text);
  free(numtext);
  if (st) {
    nl_table_free(s);
    s = NULL;
  }
  *summary = s;
  return st;
}

/* ---- the whole merge ------------------------------------------------------ */

static nl_status write_in(const char *dir, const char *file, const nl_table *t, nl_error *err)
{
  char *p = nl_path_join(dir, file);
  nl_status s = nl_table_write(t, p, err);
  free(p);
  return s;
}

/* merged/FILE, its summary, and the plot when FILE is the one to draw. */
static nl_status merge_one(const nl_sweep_merge *m, const nl_sweep_merge_opts *o, const char *file,
                           const char *plot, const char *outdir, FILE *out, FILE *log,
                           nl_error *err)
{
  nl_table *first = NULL, *merged = NULL, *sum = NULL;
  size_t *point_of = NULL, *row_of = NULL;
  char name[300];
  snprintf(name, sizeof name, "%.*s_summary.tsv", (int)(strlen(file) - 4), file);
  nl_status s = nl_sweep_merge_rows(m, file, &merged, &first, &point_of, &row_of, err);
  if (!s)
    s = nl_sweep_merge_summary(m, merged, first, point_of, row_of, &sum, err);
  if (!s)
    s = write_in(outdir, file, merged, err);
  if (!s)
    s = write_in(outdir, name, sum, err);
  if (!s && !strcmp(file, plot))
    s = nl_sweep_plot(m, o, file, first, sum, outdir, out, log, err);
  nl_table_free(merged);
  nl_table_free(sum);
  nl_table_free(first);
  free(point_of);
  free(row_of);
  return s;
}

nl_status nl_sweep_merge_all(const char *dir, const nl_sweep_merge_opts *o, FILE *out, FILE *log,
                             nl_error *err)
{
  nl_sweep_merge m;
  nl_status s = nl_sweep_merge_open(dir, &m, log, err);
  size_t nt = 0;
  char **tables = NULL, *outdir = nl_path_join(dir, "merged");
  if (!s) {
    char buf[32], *task = nl_path_join(dir, nl_table_cell_text(m.tasks, m.done[0], 1, buf));
    if (!(tables = nl_harness_tables(task, &nt, err)))
      s = NL_EIO;
    free(task);
  }
  if (!s && nt == 0)
    s = nl_fail(err, NL_EINVAL, "%s: the tasks wrote no tables", dir);
  if (!s)
    s = nl_mkdir_p(outdir, err);
  const char *plot = o->table ? o->table : nt ? tables[0] : "";
  int found = 0;
  for (size_t i = 0; i < nt; i++)
    found |= !strcmp(tables[i], plot);
  if (!s && !found)
    s = nl_fail(err, NL_EINVAL, "--table %s: the tasks wrote no such table", plot);
  for (size_t i = 0; i < nt && !s; i++)
    s = merge_one(&m, o, tables[i], plot, outdir, out, log, err);
  if (!s)
    fprintf(log, "noiselab sweep: merged %zu table%s of %zu tasks into %s\n", nt,
            nt == 1 ? "" : "s", m.ndone, outdir);
  for (size_t i = 0; i < nt; i++)
    free(tables[i]);
  free(tables);
  free(outdir);
  nl_sweep_merge_free(&m);
  return s;
}
