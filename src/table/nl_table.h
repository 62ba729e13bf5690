/* nl_table.h - tables of numbers (and labels) as TSV files with a header line.
 *
 * Writing:
 *   const char *cols[] = {"gain", "mean", "sd"};
 *   nl_table *t = nl_table_alloc(3, cols);
 *   nl_table_append(t, "ddd", 0.5, m, s);           // 'd' double, 'i' int, 's' text
 *   nl_table_write(t, "out/dist.tsv", &err);         // atomic: temp file + rename
 *   nl_table_free(t);
 * Doubles are written with the fewest of 15 or 17 significant digits that
 * read back to the same bits, so a table is an exact record of the run (the
 * regression check compares them bit for bit).
 *
 * Reading:
 *   nl_table_read(path, flags, &t, &err)
 * Rows are split on tabs (or any run of blanks with NL_TABLE_WHITESPACE, or
 * commas with NL_TABLE_CSV; NL_TABLE_CSV_AUTO takes CSV when the first line
 * has a comma and no tab). A cell holding a comma in a table not read as CSV
 * is refused with a message that says the file looks comma-separated.
 * Rejected with "file:line: reason": an empty file, ragged rows, cells that
 * are not numbers (unless NL_TABLE_TEXT allows text columns), NaN and inf.
 * The first line is a header; with NL_TABLE_HEADER_AUTO it is a header only
 * if one of its fields is not a number (a line of numbers is data, and an
 * "inf" or "nan" in it is refused as on any other line). A UTF-8 byte-order
 * mark at the start of the file is skipped. Lines starting with '#' are comments.
 * Also rejected: a line longer than NL_TABLE_MAX_LINE bytes ("FILE:LINE:
 * line longer than 1048576 bytes"; an endless line such as /dev/zero ends
 * there), a NUL byte ("FILE:LINE: NUL byte in column C"), and a table
 * growing beyond the machine's memory (an endless stream of rows).
 */
#define NL_TABLE_MAX_LINE 1048576
#ifndef NL_TABLE_H
#define NL_TABLE_H

#include "base/nl_base.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nl_table {
  size_t nrows, ncols;
  char **names;      /* ncols column names */
  double *num;       /* nrows * ncols, row-major; NaN in text cells */
  char **text;       /* nrows * ncols; NULL in numeric cells */
  size_t cap;        /* rows allocated */
} nl_table;

enum {
  NL_TABLE_TEXT = 1,         /* reader: allow non-numeric cells */
  NL_TABLE_HEADER_AUTO = 2,  /* reader: header line optional */
  NL_TABLE_WHITESPACE = 4,   /* reader: split on runs of spaces/tabs */
  NL_TABLE_CSV = 8,          /* reader: split on commas (blanks and "quotes" around a field dropped) */
  NL_TABLE_CSV_AUTO = 16     /* reader: CSV if the first line has a comma and no tab */
};

nl_table *nl_table_alloc(size_t ncols, const char *const *names);
void nl_table_free(nl_table *t);

/* Appends one row; fmt has one character per column: 'd' (double),
 * 'i' (int), 's' (const char *). A format whose length is not ncols, or an
 * unknown character, is a programming error: a message and abort(). */
void nl_table_append(nl_table *t, const char *fmt, ...);
/* Appends a row with every cell unset, to be filled by nl_table_set (a wide
 * table built column by column); a cell left unset is NaN, which the writer
 * refuses. Returns the row's index. */
size_t nl_table_append_empty(nl_table *t);
/* Appends a row of ncols doubles. */
void nl_table_append_doubles(nl_table *t, const double *row);

static inline double nl_table_get(const nl_table *t, size_t r, size_t c)
{ return t->num[r * t->ncols + c]; }
/* Column index by name, or -1. */
long nl_table_column(const nl_table *t, const char *name);

/* By name -- the way programs, gnuplot scripts and tests address a table,
 * so that adding a column never shifts what another place reads:
 *   double m = nl_table_value(t, r, "mean");
 *   nl_table_set(t, r, "mean", 0.5);
 * A name the table does not have is a programming error: both print
 * "nl_table: no column 'NAME' (columns: a, b, ...)" and abort(), as GSL's
 * default error handler does. nl_table_value of a text cell is NaN. */
double nl_table_value(const nl_table *t, size_t r, const char *name);
void nl_table_set(nl_table *t, size_t r, const char *name, double v);
void nl_table_set_text(nl_table *t, size_t r, const char *name, const char *text);
/* The text of a cell by column name; NULL for a numeric cell. */
const char *nl_table_text(const nl_table *t, size_t r, const char *name);
/* Like nl_table_column, but aborts (as above) when the name is missing. */
size_t nl_table_column_must(const nl_table *t, const char *name);
/* The cell as the writer writes it: its text, or the double formatted by
 * nl_table_format_double into buf (32 bytes). */
const char *nl_table_cell_text(const nl_table *t, size_t r, size_t c, char *buf);

/* Refuses (NL_EINVAL, nothing written) a NaN or infinite number, which the
 * reader would reject: one rule for both directions. */
nl_status nl_table_write(const nl_table *t, const char *path, nl_error *err);
/* Writes the table into an output opened with nl_atomic_open, without
 * committing it: a command writing several files opens them all first (so
 * a bad path is refused before any is written), then commits them together
 * with nl_atomic_commit_all. On a refusal af is left open for the caller. */
nl_status nl_table_write_to(const nl_table *t, nl_atomic_file *af, nl_error *err);
/* Writes the table to a stream (a command's "-o -", stdout), checking the
 * stream after a flush; `name` names it in messages ("<stdout>"). Nothing
 * is atomic about a stream: a refusal (NaN) comes before the first byte. */
nl_status nl_table_print(const nl_table *t, FILE *fp, const char *name, nl_error *err);
nl_status nl_table_read(const char *path, int flags, nl_table **out, nl_error *err);

/* Formats a double the way the writer does (shortest of %.15g/%.17g that
 * round-trips). buf needs 32 bytes. */
void nl_table_format_double(char *buf, double v);

#ifdef __cplusplus
}
#endif

#endif
