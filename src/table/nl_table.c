#include "table/nl_table.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

nl_table *nl_table_alloc(size_t ncols, const char *const *names)
{
  nl_table *t = nl_xcalloc(1, sizeof *t);
  t->ncols = ncols;
  t->names = nl_xcalloc(ncols, sizeof *t->names);
  for (size_t c = 0; c < ncols; c++)
    t->names[c] = nl_xstrdup(names && names[c] ? names[c] : "");
  return t;
}

void nl_table_free(nl_table *t)
{
  if (!t) return;
  for (size_t c = 0; c < t->ncols; c++) free(t->names[c]);
  if (t->text)
    for (size_t k = 0; k < t->nrows * t->ncols; k++) free(t->text[k]);
  free(t->names); free(t->num); free(t->text); free(t);
}

static size_t grow(nl_table *t)
{
  if (t->nrows == t->cap) {
    size_t cap = t->cap ? 2 * t->cap : 16;
    t->num = nl_xrealloc(t->num, cap * t->ncols * sizeof *t->num);
    t->text = nl_xrealloc(t->text, cap * t->ncols * sizeof *t->text);
    t->cap = cap;
  }
  size_t r = t->nrows++;
  for (size_t c = 0; c < t->ncols; c++) {
    t->num[r * t->ncols + c] = NAN;
    t->text[r * t->ncols + c] = NULL;
  }
  return r;
}

void nl_table_append(nl_table *t, const char *fmt, ...)
{
  if (strlen(fmt) != t->ncols || strspn(fmt, "dis") != t->ncols) {
    fprintf(stderr, "nl_table_append: format \"%s\" does not give one of d, i, s for each of %zu columns (first: %s)\n",
            fmt, t->ncols, t->ncols ? t->names[0] : "-");
    abort();
  }
  size_t r = grow(t);
  va_list ap;
  va_start(ap, fmt);
  for (size_t c = 0; c < t->ncols && fmt[c]; c++) {
    size_t k = r * t->ncols + c;
    switch (fmt[c]) {
    case 'd': t->num[k] = va_arg(ap, double); break;
    case 'i': t->num[k] = (double)va_arg(ap, int); break;
    case 's': t->text[k] = nl_xstrdup(va_arg(ap, const char *)); break;
    default: abort(); /* programming error: bad format character */
    }
  }
  va_end(ap);
}

size_t nl_table_append_empty(nl_table *t) { return grow(t); }

void nl_table_append_doubles(nl_table *t, const double *row)
{
  size_t r = grow(t);
  memcpy(t->num + r * t->ncols, row, t->ncols * sizeof *row);
}

long nl_table_column(const nl_table *t, const char *name)
{
  for (size_t c = 0; c < t->ncols; c++)
    if (strcmp(t->names[c], name) == 0) return (long)c;
  return -1;
}

size_t nl_table_column_must(const nl_table *t, const char *name)
{
  long c = nl_table_column(t, name);
  if (c >= 0) return (size_t)c;
  fprintf(stderr, "nl_table: no column '%s' (columns:", name);
  for (size_t k = 0; k < t->ncols; k++) fprintf(stderr, "%s %s", k ? "," : "", t->names[k]);
  fprintf(stderr, ")\n");
  abort();
}

double nl_table_value(const nl_table *t, size_t r, const char *name)
{
  return nl_table_get(t, r, nl_table_column_must(t, name));
}

void nl_table_set(nl_table *t, size_t r, const char *name, double v)
{
  size_t c = nl_table_column_must(t, name);
  if (t->text) { free(t->text[r * t->ncols + c]); t->text[r * t->ncols + c] = NULL; }
  t->num[r * t->ncols + c] = v;
}

void nl_table_set_text(nl_table *t, size_t r, const char *name, const char *text)
{
  size_t k = r * t->ncols + nl_table_column_must(t, name);
  free(t->text[k]);
  t->text[k] = nl_xstrdup(text);
  t->num[k] = NAN;
}

const char *nl_table_text(const nl_table *t, size_t r, const char *name)
{
  return t->text ? t->text[r * t->ncols + nl_table_column_must(t, name)] : NULL;
}

const char *nl_table_cell_text(const nl_table *t, size_t r, size_t c, char *buf)
{
  size_t k = r * t->ncols + c;
  if (t->text && t->text[k]) return t->text[k];
  nl_table_format_double(buf, t->num[k]);
  return buf;
}

void nl_table_format_double(char *buf, double v)
{
  if (v == 0) { strcpy(buf, v == 0 && signbit(v) ? "-0" : "0"); return; }
  snprintf(buf, 32, "%.15g", v);
  if (strtod(buf, NULL) != v) snprintf(buf, 32, "%.17g", v);
}

/* The rows as the writer writes them, into fp; name is the output's name
 * for messages. Stream errors are left for the caller to check. */
static nl_status table_emit(const nl_table *t, FILE *fp, const char *name, nl_error *err)
{
  for (size_t k = 0; k < t->nrows * t->ncols; k++)
    if (!(t->text && t->text[k]) && !isfinite(t->num[k]))
      return nl_fail(err, NL_EINVAL, "%s: column '%s' row %zu holds %g (NaN or infinite; the reader rejects it)",
                     name, t->names[k % t->ncols], k / t->ncols + 1, t->num[k]);
  for (size_t c = 0; c < t->ncols; c++)
    fprintf(fp, "%s%s", c ? "\t" : "", t->names[c]);
  fputc('\n', fp);
  char buf[32];
  for (size_t r = 0; r < t->nrows; r++) {
    for (size_t c = 0; c < t->ncols; c++)
      fprintf(fp, "%s%s", c ? "\t" : "", nl_table_cell_text(t, r, c, buf));
    fputc('\n', fp);
  }
  return NL_OK;
}

nl_status nl_table_write_to(const nl_table *t, nl_atomic_file *af, nl_error *err)
{
  return table_emit(t, af->fp, af->path, err);
}

nl_status nl_table_print(const nl_table *t, FILE *fp, const char *name, nl_error *err)
{
  nl_status s = table_emit(t, fp, name, err);
  if (s) return s;
  if (fflush(fp) || ferror(fp))
    return nl_fail(err, NL_EIO, "%s: write failed: %s", name, strerror(errno ? errno : EIO));
  return NL_OK;
}

nl_status nl_table_write(const nl_table *t, const char *path, nl_error *err)
{
  nl_atomic_file af;
  nl_status s = nl_atomic_open(&af, path, err);
  if (s) return s;
  s = nl_table_write_to(t, &af, err);
  if (s) {
    nl_atomic_abort(&af);
    return s;
  }
  return nl_atomic_commit(&af, err);
}

/* ---- reading ---------------------------------------------------------- */

/* Splits line in place; returns the number of fields (at most max). */
static size_t split(char *line, int ws, char **f, size_t max)
{
  size_t n = 0;
  char *p = line;
  if (ws == 2) {   /* CSV: commas; blanks and one pair of double quotes around a field dropped */
    for (;;) {
      char *comma = strchr(p, ',');
      if (comma) *comma = '\0';
      while (*p == ' ' || *p == '\t') p++;
      char *e = p + strlen(p);
      while (e > p && (e[-1] == ' ' || e[-1] == '\t')) *--e = '\0';
      if (e - p >= 2 && *p == '"' && e[-1] == '"') { e[-1] = '\0'; p++; }
      if (n < max) f[n] = p;
      n++;
      if (!comma) break;
      p = comma + 1;
    }
    return n;
  }
  if (ws) {
    for (;;) {
      while (*p == ' ' || *p == '\t') p++;
      if (!*p) break;
      if (n < max) f[n] = p;
      n++;
      while (*p && *p != ' ' && *p != '\t') p++;
      if (!*p) break;
      *p++ = '\0';
    }
    return n;
  }
  for (;;) {
    if (n < max) f[n] = p;
    n++;
    char *tab = strchr(p, '\t');
    if (!tab) break;
    *tab = '\0';
    p = tab + 1;
  }
  return n;
}

/* A cell as a number (nl_number_read), trailing spaces allowed (CSV's
 * "1.5 , 2"): they are cut for the read and put back. */
static nl_number_kind cell_number(char *cell, double *v)
{
  size_t n = strlen(cell);
  while (n > 0 && cell[n - 1] == ' ') n--;
  char saved = cell[n];
  cell[n] = '\0';
  nl_number_kind k = n ? nl_number_read(cell, v) : NL_NUMBER_NONE;
  cell[n] = saved;
  return k;
}

static void chomp(char *line)
{
  size_t n = strlen(line);
  while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r')) line[--n] = '\0';
}

static int blank(const char *s)
{
  for (; *s; s++) if (*s != ' ' && *s != '\t') return 0;
  return 1;
}

/* Reads one line (without its '\n') into *line, at most NL_TABLE_MAX_LINE
 * bytes: 1 = a line, 0 = end of file, -1 = longer than the limit (the rest
 * is not read: /dev/zero has no end). *len counts the bytes read, NUL
 * bytes included, so a NUL inside a cell can be told from the line end. */
static int read_line(FILE *fp, char **line, size_t *cap, size_t *len)
{
  size_t n = 0;
  int c;
  while ((c = getc_unlocked(fp)) != EOF && c != '\n') {
    if (n >= NL_TABLE_MAX_LINE) return -1;
    if (n + 2 > *cap) {
      *cap = *cap ? 2 * *cap : 256;
      *line = nl_xrealloc(*line, *cap);
    }
    (*line)[n++] = (char)c;
  }
  if (c == EOF && n == 0) return 0;
  if (!*line) { *cap = 256; *line = nl_xmalloc(*cap); }
  (*line)[n] = '\0';
  *len = n;
  return 1;
}

/* The 1-based column holding byte `pos` of a line (before it is split). */
static size_t column_at(const char *line, size_t pos, int ws)
{
  size_t col = ws ? 0 : 1;
  for (size_t i = 0; i < pos; i++) {
    int sep = line[i] == '\t' || (ws && line[i] == ' ');
    if (!ws) col += sep;
    else if (!sep && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) col++;
  }
  if (ws && (pos == 0 || line[pos - 1] == ' ' || line[pos - 1] == '\t')) col++;   /* the NUL starts a field */
  return col ? col : 1;
}

static nl_status read_rows(FILE *fp, const char *path, int flags, nl_table **out, nl_error *err)
{
  char *line = NULL;
  size_t cap = 0, lineno = 0, fmax = 0, len = 0;
  char **f = NULL;
  nl_table *t = NULL;
  nl_status s = NL_OK;
  int ws = (flags & NL_TABLE_WHITESPACE) != 0, got;
  if (flags & NL_TABLE_CSV) ws = 2;
  while ((got = read_line(fp, &line, &cap, &len)) != 0) {
    lineno++;
    if (got < 0) {
      s = nl_fail(err, NL_EFORMAT, "%s:%zu: line longer than %d bytes", path, lineno, NL_TABLE_MAX_LINE);
      break;
    }
    size_t nul = strlen(line);
    if (nul < len) {
      s = nl_fail(err, NL_EFORMAT, "%s:%zu: NUL byte in column %zu", path, lineno, column_at(line, nul, ws));
      break;
    }
    chomp(line);
    /* A UTF-8 byte-order mark (what some editors and spreadsheets put
     * first) is not part of the first field: left in, it would turn a
     * first row of numbers into a header and rename the first column. */
    if (lineno == 1 && strncmp(line, "\xEF\xBB\xBF", 3) == 0)
      memmove(line, line + 3, strlen(line + 3) + 1);
    if (line[0] == '#' || blank(line)) continue;
    size_t len = strlen(line) + 1;   /* an upper bound on the field count */
    if (len > fmax) { fmax = len; f = nl_xrealloc(f, fmax * sizeof *f); }
    /* NL_TABLE_CSV_AUTO: the first line decides; commas and no tab is CSV. */
    if (!t && (flags & NL_TABLE_CSV_AUTO) && strchr(line, ',') && !strchr(line, '\t')) ws = 2;
    size_t n = split(line, ws, f, fmax);
    if (!t) {
      int header = 1;
      if (flags & NL_TABLE_HEADER_AUTO) {
        /* Fields that parse as numbers, finite or not, make a data row:
         * "inf" or "1e999" first is then refused on line 1 like anywhere
         * else, instead of quietly becoming a header and dropping a row. */
        header = 0;
        double v;
        for (size_t c = 0; c < n; c++) if (cell_number(f[c], &v) == NL_NUMBER_NONE) header = 1;
      }
      char **names = nl_xcalloc(n, sizeof *names);
      char num[32];
      for (size_t c = 0; c < n; c++) {
        if (header) names[c] = f[c];
        else { snprintf(num, sizeof num, "c%zu", c + 1); names[c] = nl_xstrdup(num); }
      }
      t = nl_table_alloc(n, (const char *const *)names);
      if (!header) for (size_t c = 0; c < n; c++) free(names[c]);
      free(names);
      if (header) continue;
    }
    if (n != t->ncols) {
      s = nl_fail(err, NL_EFORMAT, "%s:%zu: %zu fields where the header has %zu", path, lineno, n, t->ncols);
      break;
    }
    if (t->nrows == t->cap && !nl_mem_fits(2.0 * (double)t->cap * (double)t->ncols * (sizeof *t->num + sizeof *t->text))) {
      char b1[32], b2[32];
      s = nl_fail(err, NL_ENOMEM, "%s:%zu: %zu rows of %zu columns would need more than %s; %s is available",
                  path, lineno, t->nrows, t->ncols,
                  nl_format_bytes(b1, 2.0 * (double)t->cap * (double)t->ncols * (sizeof *t->num + sizeof *t->text)),
                  nl_format_bytes(b2, nl_mem_available()));
      break;
    }
    size_t r = grow(t);
    for (size_t c = 0; c < n; c++) {
      double v;
      nl_number_kind k = cell_number(f[c], &v);
      /* Text tables keep what only looks numeric as text: a commit id
       * (7395e8327457 overflows) or a hexadecimal label. */
      int text = (flags & NL_TABLE_TEXT) && (k == NL_NUMBER_NONE || k == NL_NUMBER_OVERFLOW || k == NL_NUMBER_HEX);
      if (k == NL_NUMBER_OK) t->num[r * t->ncols + c] = v;
      else if (k == NL_NUMBER_NONFINITE) {
        s = nl_fail(err, NL_EFORMAT, "%s:%zu: column '%s' holds '%s' (NaN or infinite)", path, lineno, t->names[c], f[c]);
        break;
      } else if (!text && k != NL_NUMBER_NONE) {
        s = nl_fail(err, NL_EFORMAT, "%s:%zu: column '%s' holds '%s', which %s", path, lineno, t->names[c], f[c],
                    nl_number_problem(k));
        break;
      } else if (text) t->text[r * t->ncols + c] = nl_xstrdup(f[c]);
      else {
        s = nl_fail(err, NL_EFORMAT, "%s:%zu: column '%s' holds '%s', not a number%s", path, lineno, t->names[c], f[c],
                    ws != 2 && strchr(f[c], ',') ? " (commas: a CSV file? it is read as tab/blank-separated here)" : "");
        break;
      }
    }
    if (s) break;
  }
  if (!s && ferror(fp)) s = nl_fail(err, NL_EIO, "%s: read error: %s", path, strerror(errno));
  if (!s && (!t || t->nrows == 0)) s = nl_fail(err, NL_EFORMAT, "%s: no data rows", path);
  free(line); free(f);
  if (s) { nl_table_free(t); return s; }
  *out = t;
  return NL_OK;
}

nl_status nl_table_read(const char *path, int flags, nl_table **out, nl_error *err)
{
  *out = NULL;
  int is_stdin = strcmp(path, "-") == 0;
  FILE *fp = is_stdin ? stdin : fopen(path, "r");
  if (!fp) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
  const char *image = is_stdin ? NULL : nl_file_image_kind(fp);
  if (image) {
    fclose(fp);
    return nl_fail(err, NL_EFORMAT, "%s: a %s image, not a table", path, image);
  }
  nl_status s = read_rows(fp, is_stdin ? "<stdin>" : path, flags, out, err);
  if (!is_stdin) fclose(fp);
  return s;
}
