/* A sweep's plot (nl_sweep.h): a summary's means and spreads against one
 * parameter, one block per legend entry, for scripts/gnuplot/sweep.gp. */
#include "sweep/nl_sweep.h"

#include <stdlib.h>
#include <string.h>

typedef struct { double x, y, e; } nl_sweep_point;

static int by_x(const void *a, const void *b)
{
  double u = ((const nl_sweep_point *)a)->x, v = ((const nl_sweep_point *)b)->x;
  return (u > v) - (u < v);
}

/* What every legend shares: whether the table has several rows per point,
 * and which parameters vary (one held at a single value says nothing). */
typedef struct {
  int several;
  char *varies;   /* np flags */
} nl_sweep_legend;

static nl_sweep_legend legend_of(const nl_sweep_merge *m, const nl_table *s)
{
  nl_sweep_legend l = {0, nl_xcalloc((size_t)m->np + 1, 1)};
  for (size_t q = 0; q < s->nrows; q++) {
    l.several |= nl_table_get(s, q, (size_t)m->np) > 1;
    for (int k = 0; k < m->np; k++)
      l.varies[k] |= nl_table_get(s, q, (size_t)k) != nl_table_get(s, 0, (size_t)k);
  }
  return l;
}

/* The legend of a summary row: its label (first text column, or "row N" when
 * the table has several rows) and the parameters other than x that vary. */
static void group_title(const nl_sweep_merge *m, const nl_sweep_legend *l, const nl_table *s,
                        size_t r, int xi, const char *y, int ny, char *buf, size_t n)
{
  size_t len = 0, lab = (size_t)m->np + 1;
  buf[0] = '\0';
  if (ny > 1)
    len += (size_t)snprintf(buf + len, n - len, "%s ", y);
  if (s->text[r * s->ncols + lab])
    len += (size_t)snprintf(buf + len, n - len, "%s ", s->text[r * s->ncols + lab]);
  else if (l->several)
    len += (size_t)snprintf(buf + len, n - len, "row %g ", nl_table_get(s, r, (size_t)m->np));
  for (int k = 0; k < m->np && len < n; k++) {
    char v[32];
    if (k == xi || !l->varies[k])
      continue;
    nl_table_format_double(v, nl_table_get(s, r, (size_t)k));
    len += (size_t)snprintf(buf + len, n - len, "%s=%s ", m->pname[k], v);
  }
  if (len > 0 && len < n && buf[len - 1] == ' ')
    buf[len - 1] = '\0';
  for (char *c = buf; *c; c++)
    if (*c == '"' || *c == '\t')
      *c = '\'';   /* the block header is a quoted field */
}

#define TITLE_LEN 512

/* Rows ordered by legend, then by row number: each legend's rows together,
 * in table order, so a summary of n rows plots in n log n. */
typedef struct { const char *title; size_t r; } nl_sweep_titled;
static int by_title(const void *a, const void *b)
{
  const nl_sweep_titled *u = a, *v = b;
  int c = strcmp(u->title, v->title);
  return c ? c : (u->r > v->r) - (u->r < v->r);
}

/* Legends (first row, start and end in the order) by their first rows. */
static int by_first(const void *a, const void *b)
{
  size_t u = ((const size_t *)a)[0], v = ((const size_t *)b)[0];
  return (u > v) - (u < v);
}

/* Writes one block per legend entry of y (x, mean, spread), sorted by x, the
 * blocks in the order of their legends' first rows; *blocks gets their
 * number. */
static nl_status plot_blocks(FILE *fp, const nl_sweep_merge *m, const nl_table *s, int xi,
                             const char *y, int ny, int *blocks, nl_error *err)
{
  char mean[160], spread[160];
  snprintf(mean, sizeof mean, "%s_mean", y);
  snprintf(spread, sizeof spread, "%s_spread", y);
  long cm = nl_table_column(s, mean), cs = nl_table_column(s, spread);
  if (cm < 0 || cs < 0)
    return nl_fail(err, NL_EINVAL, "--y %s: not a numeric column of the table", y);
  size_t n = s->nrows, ng = 0;
  nl_sweep_legend l = legend_of(m, s);
  char *titles = nl_xmalloc((n + 1) * TITLE_LEN);
  nl_sweep_titled *order = nl_xmalloc((n + 1) * sizeof *order);
  size_t *span = nl_xmalloc(3 * (n + 1) * sizeof *span);
  for (size_t r = 0; r < n; r++) {
    group_title(m, &l, s, r, xi, y, ny, titles + r * TITLE_LEN, TITLE_LEN);
    order[r] = (nl_sweep_titled){titles + r * TITLE_LEN, r};
  }
  qsort(order, n, sizeof *order, by_title);
  for (size_t i = 0; i < n; i++)
    if (i == 0 || strcmp(order[i].title, order[i - 1].title)) {
      if (ng)
        span[3 * ng - 1] = i;
      span[3 * ng] = order[i].r;
      span[3 * ng + 1] = i;
      ng++;
    }
  if (ng)
    span[3 * ng - 1] = n;
  qsort(span, ng, 3 * sizeof *span, by_first);
  nl_sweep_point *pt = nl_xmalloc((n + 1) * sizeof *pt);
  *blocks = 0;
  for (size_t g = 0; g < ng; g++) {
    size_t k = 0, first = span[3 * g];
    for (size_t i = span[3 * g + 1]; i < span[3 * g + 2]; i++) {
      size_t r = order[i].r;
      pt[k++] = (nl_sweep_point){nl_table_get(s, r, (size_t)xi), nl_table_get(s, r, (size_t)cm),
                                 nl_table_get(s, r, (size_t)cs)};
    }
    qsort(pt, k, sizeof *pt, by_x);
    fprintf(fp, "%sx\t\"%s\"\tspread\n", *blocks ? "\n\n" : "", titles + first * TITLE_LEN);
    for (size_t i = 0; i < k; i++) {
      char a[32], b[32], c[32];
      nl_table_format_double(a, pt[i].x);
      nl_table_format_double(b, pt[i].y);
      nl_table_format_double(c, pt[i].e);
      fprintf(fp, "%s\t%s\t%s\n", a, b, c);
    }
    ++*blocks;
  }
  free(l.varies);
  free(titles);
  free(order);
  free(span);
  free(pt);
  return NL_OK;
}

/* gnuplot single-quoted string: a quote is written twice. */
static void gp_string(FILE *out, const char *key, const char *v)
{
  fprintf(out, "%s='", key);
  for (const char *c = v; *c; c++) {
    if (*c == '\'')
      fputc('\'', out);
    fputc(*c, out);
  }
  fputs("'; ", out);
}

static int is_text_col(const nl_table *first, size_t c)
{
  return first->nrows > 0 && first->text[c] != NULL;
}

/* The first numeric column whose mean moves across the sweep (none moves:
 * the first numeric column; none at all: NULL). */
static const char *default_y(const nl_sweep_merge *m, const nl_table *first, const nl_table *s)
{
  const char *fallback = NULL;
  for (size_t c = 0; c < first->ncols; c++) {
    if (is_text_col(first, c))
      continue;
    int param = 0;
    for (int k = 0; k < m->np; k++)
      param |= !strcmp(first->names[c], m->pname[k]);
    if (param || !strcmp(first->names[c], "seed"))
      continue;
    if (!fallback)
      fallback = first->names[c];
    char mean[160];
    snprintf(mean, sizeof mean, "%s_mean", first->names[c]);
    long cm = nl_table_column(s, mean);
    for (size_t r = 1; cm >= 0 && r < s->nrows; r++)
      if (nl_table_get(s, r, (size_t)cm) != nl_table_get(s, 0, (size_t)cm))
        return first->names[c];
  }
  return fallback;
}

/* plot.dat's blocks for y (and y2 after them, on the right axis). */
static nl_status write_dat(const char *dat, const nl_sweep_merge *m, const nl_table *s, int xi,
                           const char *y, const char *y2, int *n1, int *n2, nl_error *err)
{
  nl_atomic_file af;
  nl_status st = nl_atomic_open(&af, dat, err);
  if (st)
    return st;
  *n2 = 0;
  st = plot_blocks(af.fp, m, s, xi, y, y2 ? 2 : 1, n1, err);
  if (!st && y2) {
    fputs("\n\n", af.fp);
    st = plot_blocks(af.fp, m, s, xi, y2, 2, n2, err);
  }
  if (st) {
    nl_atomic_abort(&af);
    return st;
  }
  return nl_atomic_commit(&af, err);
}

nl_status nl_sweep_plot(const nl_sweep_merge *m, const nl_sweep_merge_opts *o, const char *file,
                        const nl_table *first, const nl_table *s, const char *outdir, FILE *out,
                        FILE *log, nl_error *err)
{
  int xi = 0;
  if (o->x) {
    while (xi < m->np && strcmp(m->pname[xi], o->x))
      xi++;
    if (xi == m->np)
      return nl_fail(err, NL_EINVAL, "--x %s: not a parameter of this sweep", o->x);
  }
  const char *y = o->y ? o->y : default_y(m, first, s);
  if (!y)
    return nl_fail(err, NL_EINVAL, "the table has no numeric column to plot");
  char *ys = nl_xstrdup(y), *y2 = strchr(ys, ',');
  if (y2)
    *y2++ = '\0';
  if (y2 && strchr(y2, ',')) {
    free(ys);
    return nl_fail(err, NL_EINVAL, "--y: at most two columns (the second on the right axis)");
  }
  char *dat = nl_path_join(outdir, "plot.dat"), *png = nl_path_join(outdir, "plot.png");
  int n1, n2;
  nl_status st = write_dat(dat, m, s, xi, ys, y2, &n1, &n2, err);
  if (!st) {
    int logx = !strcmp(m->pscale[xi], "log");
    for (size_t r = 0; r < s->nrows; r++)
      logx &= nl_table_get(s, r, (size_t)xi) > 0;
    char title[512];
    snprintf(title, sizeof title, "%s: %s%s%s over %ld seed%s (mean, error bars: sd over seeds)",
             file, ys, y2 ? " (left), " : "", y2 ? y2 : "", m->seeds, m->seeds > 1 ? "s" : "");
    gp_string(out, "dat", dat);
    gp_string(out, "out", png);
    gp_string(out, "xlabel", m->pname[xi]);
    gp_string(out, "ylabel", ys);
    gp_string(out, "y2label", y2 ? y2 : "");
    gp_string(out, "title", title);
    fprintf(out, "logx=%d; ny1=%d; nblocks=%d\n", logx, n1, n1 + n2);
    fprintf(log, "noiselab sweep: plot: %s of %s against %s%s (choose with --table, --y, --x)\n",
            o->y ? o->y : ys, file, m->pname[xi], logx ? " (log)" : "");
  }
  free(ys);
  free(dat);
  free(png);
  return st;
}
