/* libFuzzer target: the TSV reader, nl_table_read (src/table/nl_table.h).
 * The first byte picks the flags (NL_TABLE_TEXT, _HEADER_AUTO, _WHITESPACE);
 * the rest is the file. A table read must hold finite numbers in its
 * numeric cells (the reader rejects NaN and inf). */
#include "table/nl_table.h"
#include "nl_fuzz.h"

#include <math.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size < 1) return 0;
  int flags = data[0] & (NL_TABLE_TEXT | NL_TABLE_HEADER_AUTO | NL_TABLE_WHITESPACE);
  const char *path = nl_fuzz_file(data + 1, size - 1, "tsv");
  nl_table *t = NULL;
  nl_error err = {{0}};
  nl_status st = nl_table_read(path, flags, &t, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    /* Touch every name and cell: a wrong row or column count shows up
     * under ASan. */
    volatile size_t sum = 0;
    for (size_t c = 0; c < t->ncols; c++) sum += strlen(t->names[c]);
    for (size_t r = 0; r < t->nrows; r++)
      for (size_t c = 0; c < t->ncols; c++) {
        double v = nl_table_get(t, r, c);
        const char *s = t->text ? t->text[r * t->ncols + c] : NULL;
        if (s) sum += strlen(s);
        else if (!isfinite(v)) {
          fprintf(stderr, "nl_fuzz: row %zu column %zu read as %g\n", r, c, v);
          abort();
        }
      }
    (void)sum;
    nl_table_free(t);
  } else if (t) {
    fprintf(stderr, "nl_fuzz: nl_table_read failed but returned a table\n");
    abort();
  }
  return 0;
}
