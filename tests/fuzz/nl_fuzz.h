/* nl_fuzz.h - shared by the libFuzzer targets in tests/fuzz/ (fuzz_NAME.c).
 *
 * The readers under test take a path, so each input is written to a file of
 * this process ($TMPDIR or /tmp, one per extension, removed at exit) and the
 * reader is called on that path. A target is
 *
 *   #include "nl_fuzz.h"
 *   int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
 *   {
 *     const char *path = nl_fuzz_file(data, size, "tsv");
 *     ... call the reader on path, free what it returned ...
 *     return 0;
 *   }
 *
 * A reader that returns an error is fine; a crash, a sanitizer report, a leak,
 * an exit or a hang is a finding. Errors must be one line: nl_fuzz_check_error()
 * aborts (a finding) when a failed call left an empty message or a newline.
 */
#ifndef NL_FUZZ_H
#define NL_FUZZ_H

#include "base/nl_base.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define NL_FUZZ_MAX_EXT 4
static char nl_fuzz_paths[NL_FUZZ_MAX_EXT][512];

static void nl_fuzz_cleanup(void)
{
  for (int i = 0; i < NL_FUZZ_MAX_EXT; i++)
    if (nl_fuzz_paths[i][0]) unlink(nl_fuzz_paths[i]);
}

/* Writes data to this process's file with extension ext; returns its path. */
static const char *nl_fuzz_file(const uint8_t *data, size_t size, const char *ext)
{
  int slot = -1;
  for (int i = 0; i < NL_FUZZ_MAX_EXT && slot < 0; i++) {
    const char *dot = strrchr(nl_fuzz_paths[i], '.');
    if (!nl_fuzz_paths[i][0]) {
      const char *tmp = getenv("TMPDIR");
      snprintf(nl_fuzz_paths[i], sizeof nl_fuzz_paths[i], "%s/nl_fuzz_%ld.%s",
               tmp && *tmp ? tmp : "/tmp", (long)getpid(), ext);
      if (i == 0) atexit(nl_fuzz_cleanup);
      slot = i;
    } else if (dot && !strcmp(dot + 1, ext)) {
      slot = i;
    }
  }
  if (slot < 0) { fprintf(stderr, "nl_fuzz: more than %d extensions\n", NL_FUZZ_MAX_EXT); abort(); }
  FILE *fp = fopen(nl_fuzz_paths[slot], "wb");
  if (!fp || (size && fwrite(data, 1, size, fp) != size) || fclose(fp)) {
    perror(nl_fuzz_paths[slot]);
    abort();
  }
  return nl_fuzz_paths[slot];
}

/* The contract of a failed call: a non-empty one-line message. */
static void nl_fuzz_check_error(nl_status st, const nl_error *err)
{
  if (st == NL_OK) return;
  if (!err->msg[0] || strchr(err->msg, '\n')) {
    fprintf(stderr, "nl_fuzz: status %d with a bad message: '%s'\n", (int)st, err->msg);
    abort();
  }
}

#endif
