/* noiselab check - compare an experiment's new tables with its committed
 * ones, column by column, by the rules the experiment declared
 * (nl_harness_check, checks.tsv; see src/harness/nl_harness.h).
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
 * The other manifest lines (commit, versions, cpu, arch, libm, blas*, cflags, started,
 * seconds, cpu_seconds, peak_rss_mb) are never compared.
 *
 * Output: one tab-separated line per drifted value on stdout, under a header
 * line of the column names before the first,
 *   experiment  table  row  column  committed  new  rule[: detail]
 * (row: 1-based data row, with its first text cell as a label), the first
 * 10 of an experiment only unless --all; for an experiment with drift a line
 *   check: EXPERIMENT: D drifted[ (first 10 shown; --all for every one)];
 *     reference vs this run: BLAS kernel other (reference X, this run Y),
 *     CPU same (...), architecture same (...), libm same (...)
 * (the CPU, architecture, BLAS kernel and libm variant: those that differ
 * first, then "unknown" ones a manifest predates, then the same), then
 *   check: E experiments, T tables, V values compared, D drifted
 * ("check: EXPERIMENT: T tables, ..." when one experiment was compared),
 * ending, when a reference was made on another architecture or libm, with
 *   ; reference made elsewhere: architecture other (reference x86_64, this
 *     run aarch64), libm other (reference glibc 2.36 fma, this run ...)
 * A new table that is missing or that the table reader refuses (a NUL byte,
 * a ragged row) is drift, its line naming the reader's complaint; so is a
 * table the new run wrote that the committed folder lacks (one deleted by
 * hand would otherwise compare nothing).
 * Exit 0: no drift; 1: drift; 2: bad input (missing folder or manifest,
 * unreadable committed table, malformed rule, or a rule naming a table or
 * column the committed folder does not have).
 * The engine is the harness's (nl_harness_check_experiment in
 * src/harness/nl_harness.h); this is its command line.
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* One line on stderr; returns check's exit for bad input. Input quoted in
 * the message is escaped (nl_message). */
static int die(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int die(const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fputs("noiselab-check: ", stderr);
  nl_vmessage(stderr, fmt, ap);
  va_end(ap);
  return 2;
}

int main(int argc, char **argv)
{
  nl_tool_start("noiselab-check");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  nl_harness_check_state s = {0};
  nl_error err;
  /* nl_opt (GNU style); the positional words are gathered in argv[1..]. */
  static const nl_opt_spec spec[] = {{"all", 0, 0}, {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser p;
  int w = 1;
  nl_opt_begin(&p, argc, argv, 1, spec);
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    if (k == NL_OPT_ERROR) {
      nl_opt_end(&p);
      return die("%s (see --help)", err.msg);
    }
    if (k == 1) {
      printf("usage: noiselab-check [--all] COMMITTED_DIR NEW_DIR\n"
             "       noiselab-check [--all] COMMITTED_ROOT NEW_ROOT EXPERIMENT...\n\n"
             "Compares every table of the committed run with the new run by the rules of\n"
             "the committed checks.tsv; prints one line per drifted value\n"
             "(experiment, table, row, column, committed, new, rule), the first %d of\n"
             "an experiment (--all: every one), a line per drifted experiment naming\n"
             "the CPU, architecture, BLAS kernel and libm variant of both runs (what\n"
             "differs first), and a summary.\n"
             "Exit 0: no drift, 1: drift, 2: bad input.\n", NL_CHECK_SHOWN);
      nl_opt_end(&p);
      return 0;
    }
    if (k == 0) s.all = 1;
    else argv[w++] = (char *)p.value[0];   /* w never passes the word being read */
  }
  nl_opt_end(&p);
  argc = w;
  if (argc < 3) return die("wanted COMMITTED NEW [EXPERIMENT...] (see --help)");
  if (argc == 3 && nl_harness_check_experiment(&s, argv[1], argv[2], &err))
    return die("%s", err.msg);
  for (int i = 3; i < argc; i++) {
    char *a = nl_path_join(argv[1], argv[i]), *b = nl_path_join(argv[2], argv[i]);
    nl_status st = nl_harness_check_experiment(&s, a, b, &err);
    free(a); free(b);
    if (st) return die("%s", err.msg);
  }
  nl_harness_check_totals(&s);
  return s.drifted ? 1 : 0;
}
