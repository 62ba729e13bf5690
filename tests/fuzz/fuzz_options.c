/* libFuzzer target: the experiments' option parser, nl_harness_parse
 * (src/harness/nl_harness.h). The input is split at NUL bytes into argv[1..];
 * every argv must either parse into options within their documented ranges
 * or fail with a one-line message, never exit, and leave nothing to free on
 * failure. */
#include "harness/nl_harness.h"
#include "nl_fuzz.h"

#define NL_FUZZ_MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  char *buf = malloc(size + 1);
  memcpy(buf, data, size);
  buf[size] = '\0';
  char *argv[NL_FUZZ_MAX_ARGS + 2];
  int argc = 0;
  argv[argc++] = "fuzz_options";
  for (size_t i = 0; i <= size && argc <= NL_FUZZ_MAX_ARGS; ) {
    argv[argc++] = buf + i;
    i += strlen(buf + i) + 1;
  }
  argv[argc] = NULL;
  nl_harness_options o;
  nl_error err = {{0}};
  nl_status st = nl_harness_parse(&o, argc, argv, &err);
  nl_fuzz_check_error(st, &err);
  if (st == NL_OK) {
    if (o.seeds != -1 && (o.seeds < 1 || o.seeds > 10000)) { fprintf(stderr, "nl_fuzz: seeds %d\n", o.seeds); abort(); }
    if (o.seed > 4294967295UL) { fprintf(stderr, "nl_fuzz: seed %lu\n", o.seed); abort(); }
    if (o.out && !*o.out) { fprintf(stderr, "nl_fuzz: empty --out accepted\n"); abort(); }
    for (int k = 0; k < o.nset; k++)
      if (!o.set_key[k][0] || !o.set_val[k]) { fprintf(stderr, "nl_fuzz: empty --set name\n"); abort(); }
    nl_harness_options_free(&o);
  }
  free(buf);
  return 0;
}
