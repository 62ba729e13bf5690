#include "table/nl_table.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *dir;

static char *write_file(const char *name, const char *content)
{
  char *p = nl_path_join(dir, name);
  FILE *f = fopen(p, "w");
  fputs(content, f);
  fclose(f);
  return p;
}

static int read_fails_with(const char *content, const char *needle, int flags)
{
  char *p = write_file("bad.tsv", content);
  nl_table *t = NULL;
  nl_error err = {{0}};
  nl_status s = nl_table_read(p, flags, &t, &err);
  int ok = s != NL_OK && t == NULL && strstr(err.msg, needle) != NULL;
  if (!ok) fprintf(stderr, "  content %.20s: got '%s'\n", content, err.msg);
  free(p);
  return ok;
}

NL_TEST(round_trip_is_exact)
{
  const char *cols[] = {"label", "x", "y"};
  nl_table *t = nl_table_alloc(3, cols);
  double xs[] = {0.1, 1.0 / 3.0, -2.5e-300, 123456789.123456789, 0};
  for (int i = 0; i < 5; i++) nl_table_append(t, "sdi", "row", xs[i], i);
  char *p = nl_path_join(dir, "rt.tsv");
  nl_error err;
  NL_CHECK(nl_table_write(t, p, &err) == NL_OK);
  nl_table *u = NULL;
  NL_CHECK(nl_table_read(p, NL_TABLE_TEXT, &u, &err) == NL_OK);
  NL_CHECK(u && u->nrows == 5 && u->ncols == 3);
  for (int i = 0; u && i < 5; i++) {
    NL_CHECK(nl_table_get(u, i, 1) == xs[i]);   /* bit-exact */
    NL_CHECK(nl_table_get(u, i, 2) == i);
    NL_CHECK(strcmp(u->text[i * 3], "row") == 0);
  }
  NL_CHECK(u && nl_table_column(u, "y") == 2 && nl_table_column(u, "z") == -1);
  nl_table_free(t); nl_table_free(u); free(p);
}

NL_TEST(rejects_bad_input_with_line)
{
  NL_CHECK(read_fails_with("", "no data rows", 0));
  NL_CHECK(read_fails_with("a\tb\n", "no data rows", 0));
  NL_CHECK(read_fails_with("a\tb\n1\t2\n3\n", "bad.tsv:3: 1 fields", 0));
  NL_CHECK(read_fails_with("a\tb\n1\t2\n3\tx\n", "bad.tsv:3: column 'b' holds 'x'", 0));
  NL_CHECK(read_fails_with("a\tb\n1\tnan\n", "bad.tsv:2: column 'b' holds 'nan' (NaN", 0));
  NL_CHECK(read_fails_with("a\tb\ninf\t1\n", "(NaN or infinite)", NL_TABLE_TEXT));
  NL_CHECK(read_fails_with("a\tb\n1e999\t1\n", "bad.tsv:2: column 'a' holds '1e999', which is beyond the double range", 0));
}

/* A cell is a decimal number: one that underflows to 0 (1e-400, which
 * strtod and numpy read as 0.0) is refused, as is hexadecimal (0x10 read as
 * 16, 0x1p-2 as 0.25), with its line and column; a subnormal (1e-310) is a
 * number, kept to the bit. The same reader takes options (nl_parse_double). */
NL_TEST(underflow_and_hex_refused_subnormals_kept)
{
  NL_CHECK(read_fails_with("a\tb\n1\t2\n3\t1e-400\n", "bad.tsv:3: column 'b' holds '1e-400', which underflows to 0", 0));
  NL_CHECK(read_fails_with("a\tb\n1\t-2e-324\n", "bad.tsv:2: column 'b' holds '-2e-324', which underflows to 0", NL_TABLE_TEXT));
  NL_CHECK(read_fails_with("a\tb\n0x10\t2\n", "bad.tsv:2: column 'a' holds '0x10', which is hexadecimal", 0));
  NL_CHECK(read_fails_with("0x1p-2 1\n", "bad.tsv:1: column 'c1' holds '0x1p-2', which is hexadecimal", NL_TABLE_WHITESPACE | NL_TABLE_HEADER_AUTO));
  char *p = write_file("small.tsv", "a\tb\n1e-310\t0e-400\n4.9406564584124654e-324 \t-0\n");
  nl_table *t = NULL;
  nl_error err;
  NL_CHECK(nl_table_read(p, 0, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 2 && nl_table_get(t, 0, 0) == 1e-310 && nl_table_get(t, 0, 1) == 0.0);
  NL_CHECK(t && nl_table_get(t, 1, 0) == 4.9406564584124654e-324 && nl_table_get(t, 1, 1) == 0.0);
  nl_table_free(t);
  free(p);
  /* in a text table a hexadecimal word is text, like a commit id */
  p = write_file("labels.tsv", "name\tv\n0x1f\t1\n");
  t = NULL;
  NL_CHECK(nl_table_read(p, NL_TABLE_TEXT, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 1 && t->text[0] && !strcmp(t->text[0], "0x1f"));
  nl_table_free(t);
  free(p);
}

/* A word that reads as a number beyond the double range is text where text
 * is allowed: a manifest's commit id 7395e8327457 (7395 x 10^8327457) made
 * every regression check of that commit "bad input". */
NL_TEST(out_of_range_number_is_text_in_text_tables)
{
  char *p = write_file("manifest.tsv", "key\tvalue\ncommit\t7395e8327457\nseed\t1\nbig\t1e999\n");
  nl_table *t = NULL;
  nl_error err;
  NL_CHECK(nl_table_read(p, NL_TABLE_TEXT, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 3 && t->text[1] && !strcmp(t->text[1], "7395e8327457"));
  NL_CHECK(t && !t->text[3] && nl_table_get(t, 1, 1) == 1);
  NL_CHECK(t && t->text[5] && !strcmp(t->text[5], "1e999"));
  nl_table_free(t);
  free(p);
}

/* A byte-order mark is skipped, so the first row stays data (or the first
 * column keeps its name); a first line of numbers that are not finite is
 * data and refused, not taken for a header with one row fewer. */
NL_TEST(bom_and_non_finite_first_line)
{
  char *p = write_file("bom.tsv", "\xEF\xBB\xBF" "0.5\n0.25\n0.75\n");
  nl_table *t = NULL;
  nl_error err;
  NL_CHECK(nl_table_read(p, NL_TABLE_HEADER_AUTO, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 3 && nl_table_get(t, 0, 0) == 0.5);
  nl_table_free(t);
  t = NULL;
  free(p);
  p = write_file("bomh.tsv", "\xEF\xBB\xBF" "x\ty\n1\t2\n");
  NL_CHECK(nl_table_read(p, 0, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 1 && nl_table_column(t, "x") == 0);
  nl_table_free(t);
  free(p);
  NL_CHECK(read_fails_with("inf\n1\n2\n", "bad.tsv:1: column 'c1' holds 'inf'",
                           NL_TABLE_HEADER_AUTO));
  NL_CHECK(read_fails_with("1\t1e999\n1\t2\n", "bad.tsv:1:", NL_TABLE_HEADER_AUTO));
}

NL_TEST(missing_file_names_it)
{
  nl_table *t;
  nl_error err;
  NL_CHECK(nl_table_read("/nonexistent/x.tsv", 0, &t, &err) == NL_EIO);
  NL_CHECK(strstr(err.msg, "/nonexistent/x.tsv: cannot open") != NULL);
}

NL_TEST(optional_header_and_whitespace)
{
  char *p = write_file("ws.txt", "# comment\n 1.5  2\n3 4e1\n");
  nl_table *t = NULL;
  nl_error err;
  NL_CHECK(nl_table_read(p, NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE, &t, &err) == NL_OK);
  NL_CHECK(t && t->nrows == 2 && nl_table_get(t, 1, 1) == 40.0);
  nl_table_free(t); free(p);
}

NL_TEST(failed_write_keeps_old_file)
{
  char *p = write_file("keep.tsv", "old\n");
  const char *cols[] = {"a"};
  nl_table *t = nl_table_alloc(1, cols);
  nl_table_append(t, "d", 1.0);
  nl_error err;
  NL_CHECK(nl_table_write(t, "/nonexistent/dir/x.tsv", &err) == NL_EIO);
  NL_CHECK(strstr(err.msg, "/nonexistent/dir/x.tsv") != NULL);
  FILE *f = fopen(p, "r");
  char buf[16] = {0};
  NL_CHECK(f && fgets(buf, sizeof buf, f) && strcmp(buf, "old\n") == 0);
  if (f) fclose(f);
  nl_table_free(t); free(p);
}

static char *write_bytes(const char *name, const char *content, size_t n)
{
  char *p = nl_path_join(dir, name);
  FILE *f = fopen(p, "wb");
  fwrite(content, 1, n, f);
  fclose(f);
  return p;
}

static int bytes_fail_with(const char *content, size_t n, const char *needle, int flags)
{
  char *p = write_bytes("nul.tsv", content, n);
  nl_table *t = NULL;
  nl_error err = {{0}};
  int ok = nl_table_read(p, flags, &t, &err) == NL_EFORMAT && t == NULL && strstr(err.msg, needle);
  if (!ok) fprintf(stderr, "  got '%s' (wanted '%s')\n", err.msg, needle);
  free(p);
  return ok;
}

/* A NUL byte inside a cell once read as a truncated number (13.6). */
NL_TEST(nul_byte_is_rejected_with_its_column)
{
  NL_CHECK(bytes_fail_with("a\tb\n1\t2\n3\t4\0005\n", 13, "nul.tsv:3: NUL byte in column 2", 0));
  NL_CHECK(bytes_fail_with("1\0002 3\n", 6, "nul.tsv:1: NUL byte in column 1", NL_TABLE_WHITESPACE | NL_TABLE_HEADER_AUTO));
  NL_CHECK(bytes_fail_with("1 2\n3  \0004\n", 10, "nul.tsv:2: NUL byte in column 2", NL_TABLE_WHITESPACE | NL_TABLE_HEADER_AUTO));
  NL_CHECK(bytes_fail_with("x\n\000\n", 4, "nul.tsv:2: NUL byte in column 1", 0));
}

/* /dev/zero is one endless line: refused at the limit, not read forever
 * (13.7); a long but bounded line is still fine. */
NL_TEST(line_length_is_bounded)
{
  nl_table *t = NULL;
  nl_error err = {{0}};
  NL_CHECK(nl_table_read("/dev/zero", NL_TABLE_WHITESPACE, &t, &err) == NL_EFORMAT && t == NULL);
  NL_CHECK(strcmp(err.msg, "/dev/zero:1: line longer than 1048576 bytes") == 0);
  size_t n = NL_TABLE_MAX_LINE + 10;
  char *big = malloc(n + 1);
  memset(big, '1', n);
  big[n] = '\n';
  NL_CHECK(bytes_fail_with(big, n + 1, "nul.tsv:1: line longer than 1048576 bytes", 0));
  /* exactly at the limit: a (long) header and a row read */
  memset(big, 'a', NL_TABLE_MAX_LINE);
  memcpy(big + NL_TABLE_MAX_LINE, "\n1\n", 3);
  char *p = write_bytes("long.tsv", big, NL_TABLE_MAX_LINE + 3);
  NL_CHECK(nl_table_read(p, 0, &t, &err) == NL_OK && t && t->nrows == 1);
  nl_table_free(t);
  free(big); free(p);
}

NL_TEST(columns_by_name_and_nan_refused)
{
  const char *cols[] = {"k", "mean", "label"};
  nl_table *t = nl_table_alloc(3, cols);
  nl_table_append(t, "ids", 1, 0.25, "a");
  nl_table_append(t, "ids", 2, 0.5, "b");
  NL_CHECK(nl_table_value(t, 1, "mean") == 0.5);
  NL_CHECK(nl_table_column_must(t, "label") == 2);
  nl_table_set(t, 0, "mean", 0.75);
  NL_CHECK(nl_table_get(t, 0, 1) == 0.75);
  char buf[32];
  NL_CHECK(strcmp(nl_table_cell_text(t, 1, 2, buf), "b") == 0);
  NL_CHECK(strcmp(nl_table_cell_text(t, 1, 1, buf), "0.5") == 0);
  /* the writer refuses what the reader rejects, and writes nothing */
  nl_table_set(t, 1, "mean", NAN);
  char *p = nl_path_join(dir, "nan.tsv");
  nl_error err = {{0}};
  NL_CHECK(nl_table_write(t, p, &err) == NL_EINVAL);
  NL_CHECK(strstr(err.msg, "column 'mean' row 2") != NULL);
  NL_CHECK(access(p, F_OK) != 0);
  free(p);
  nl_table_free(t);
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
