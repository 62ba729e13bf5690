/* nl_harness.h - the harness around an experiment program: options, seeds,
 * parameters, output folder, manifest and report section.
 *
 * An experiment reads like the paper's method section:
 *
 *   int main(int argc, char **argv) {
 *     nl_harness *r = nl_harness_begin("s3_fbm", "S3 - fBm gain and lacunarity", argc, argv);
 *     int octaves = nl_harness_param_int(r, "octaves", 6, 1, 30,    // --set octaves=8
 *                                    "octaves summed in the fBm");
 *     nl_harness_params_done(r);             // rejects unknown --set; answers --help, --params
 *     ... library calls ...
 *     nl_harness_write_table(r, t, "dist.tsv");                           // out/dist.tsv, atomic
 *     nl_harness_text(r, "The slides show ...");
 *     nl_harness_report_table(r, t, "Value distribution", 4);
 *     nl_harness_figure(r, "spectrum.png", "Radially averaged power spectrum");
 *     return nl_harness_end(r);                                     // report.md + manifest.tsv
 *   }
 *
 * Common options, parsed by nl_harness_begin through nl_harness_parse (errors: one
 * line, exit 2):
 *   --out DIR    output folder (default results/NAME)
 *   --seed N     base seed (default 1); multi-seed summaries use N, N+1, ...
 *   --seeds K    number of seeds for means and spreads (default 10, quick 3)
 *   --quick      small sizes for tests and CI
 *   --set K=V    an experiment parameter (repeatable), for sweeps
 *   --shard K/N  only the units u with u mod N == K - 1 (nl_harness_units below)
 *   --merge      the run from the shard files of all N shards
 *   --shards DIR where the shard files are (default OUT/.shards)
 *   --units      print each unit's relative cost, one line a unit; exit 0
 *   --params     print the parameters as TSV, a header line then one line
 *                each: name, default, min, max, meaning; exit 0
 *   --help       the usage and the parameters in readable form; exit 0
 * --help and --params are answered at nl_harness_params_done, when every
 * parameter is declared and before any work or output (no file is touched).
 * --set names and values given with them are checked as for a run (exit 2),
 * so `--params --set NAME=VALUE...` validates a sweep point; the list shows
 * the defaults.
 * The manifest (manifest.tsv: key, value) records the experiment, seed,
 * parameters, commit (NL_COMMIT from the entry script), library versions
 * and where it was made: compiler (name and version,
 * "gcc 12.2.0"), cflags
 * (project and user C flags, buildtype, optimisation, sanitizers), cpu
 * (/proc/cpuinfo model name), arch (uname's machine, "x86_64"), libm
 * (glibc's version and, on x86-64, the variant of exp, log, pow, sin... its
 * libm runs as glibc sees the CPU: "glibc 2.36 fma", or "glibc 2.36 avx
 * (CPU's fma turned off)" under GLIBC_TUNABLES=glibc.cpu.hwcaps=-FMA,...),
 * blas (library file; "OpenBLAS (path)" when
 * OpenBLAS is loaded), blas_core, blas_config, blas_threads (OpenBLAS's
 * openblas_get_corename/config/num_threads; "none" without OpenBLAS).
 * The regression check compares none of these, but names cpu, arch, blas_core and libm when it finds drift.
 * When and how long the run took (started, seconds, cpu_seconds,
 * peak_rss_mb) go to run.tsv beside it, a file no "output" line names: they
 * differ on every run, and the manifest is committed with the results.
 * One "output" line per file the run wrote (every path nl_harness_path handed
 * out, and each nl_harness_figure file; a PNG figure the program did not
 * write is drawn by the entry script with an SVG beside it): a run that
 * completes removes the files an earlier run in its folder listed and it did
 * not write (a table the code no longer makes), never a file no run listed.
 * NL_MANIFEST_NAME (a hidden file name, set by the entry script) makes
 * nl_harness_end write the manifest under that name instead; the script renames
 * it to manifest.tsv once the figures are made. It is written last and removed first, so a
 * folder with a manifest is a complete run. Nothing in the output folder is
 * touched before the run writes: the folder is made and the old manifest
 * removed at the first write (nl_harness_write_table, nl_harness_write_image, nl_harness_path,
 * nl_harness_dir or nl_harness_end), after every option and --set value was checked
 * (nl_harness_params_done runs then at the latest), so a rejected run leaves a
 * finished one intact and no empty folder behind. checks.tsv holds the rules the
 * regression check compares the tables by (nl_harness_check below).
 *
 * Figures named with nl_harness_figure are made afterwards by the entry
 * script from scripts/gnuplot/NAME-*.gp, or are images the program wrote.
 * Report links are relative to results/ ("NAME/file.png").
 */
#ifndef NL_HARNESS_H
#define NL_HARNESS_H

#include "image/nl_image.h"
#include "table/nl_table.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nl_harness nl_harness;

/* The common options as parsed, nothing else done (no output, no exit). */
typedef struct {
  char *out;               /* --out, or NULL: results/NAME */
  unsigned long seed;      /* 1 unless --seed */
  int seeds;               /* -1 unless --seeds */
  int quick, help;
  int threads;             /* 0 unless --threads N (1..NL_PARALLEL_MAX) */
  int params;              /* --params */
  int no_images;           /* --no-images */
  int shard_k, shard_n;    /* --shard K/N; 0 0 without */
  int merge;               /* --merge */
  char *shard_dir;         /* --shards DIR, or NULL: OUT/.shards */
  int units;               /* --units */
  int nset;                /* --set NAME=VALUE, in order */
  char **set_key, **set_val;
} nl_harness_options;

/* Parses argv[1..argc-1] into *o. On error *o is empty (nothing to free)
 * and err says "OPTION: problem". nl_harness_options_free releases a parsed *o. */
nl_status nl_harness_parse(nl_harness_options *o, int argc, char **argv, nl_error *err);
void nl_harness_options_free(nl_harness_options *o);

/* The out-of-memory handler of programs (nl_set_oom_handler, nl_base.h):
 * after base's "noiselab: out of memory allocating N bytes", exit 3. nl_harness_begin
 * and the command-line tools install it (nl_harness_program_start, below). */
void nl_harness_oom_exit(size_t n);

/* What every program does first (nl_harness_begin calls it; the tools call
 * it first thing in main): removes the open temporaries (nl_atomic_unlink_open)
 * at exit and on SIGINT, SIGTERM and SIGHUP, then lets the signal do what it
 * did before (an ignored one stays ignored), installs nl_harness_oom_exit
 * and stops OpenBLAS's spinning idle workers (nl_parallel_blas_idle,
 * base/nl_parallel.h). */
void nl_harness_program_start(void);

/* nl_harness_parse; on error prints "NAME: message" and exits 2. --help and
 * --params are remembered and answered by nl_harness_params_done. Touches no file. */
nl_harness *nl_harness_begin(const char *name, const char *title, int argc, char **argv);

unsigned long nl_harness_seed(const nl_harness *r);   /* base seed */
int nl_harness_seeds(const nl_harness *r);            /* K seeds: seed .. seed+K-1 */
int nl_harness_quick(const nl_harness *r);
/* Threads for independent work (--threads N; default nl_parallel_cores()),
 * passed to nl_parallel_for (base/nl_parallel.h) by the experiment's glue;
 * no table depends on it (item i writes slot i from its own stream). */
int nl_harness_threads(const nl_harness *r);
const char *nl_harness_dir(const nl_harness *r);      /* prepares the folder (see above) */
const char *nl_harness_name(const nl_harness *r);     /* "s3_fbm" */

/* Parameter `name` from --set, else def; range-checked; recorded in the
 * manifest. `meaning` is one line saying what the number is (units, the
 * paper's symbol): --params and --help print it. Both strings are borrowed
 * for the run's life (string literals). A bad value: "NAME: --set name: ...",
 * exit 2. */
double nl_harness_param(nl_harness *r, const char *name, double def, double lo, double hi,
                        const char *meaning);
long nl_harness_param_int(nl_harness *r, const char *name, long def, long lo, long hi,
                          const char *meaning);
/* An image side that is Fourier-transformed: nl_harness_param_int, and a
 * side whose square nl_spectrum_check_size refuses (a large prime factor:
 * minutes of O(n^2) transforms) is a bad value like one out of range,
 * "NAME: --set size=1021: 1021 x 1021 pixels: ...", exit 2, before any work
 * (and so for a sweep's --params --set check). */
long nl_harness_param_fft_size(nl_harness *r, const char *name, long def, long lo, long hi,
                               const char *meaning);
/* Every parameter is declared: refuses a --set name none declared (exit 2,
 * one line listing the valid names); then, with --help or --params, prints
 * the list (nl_harness_params_print) and exits 0. Runs at the first write at
 * the latest. */
void nl_harness_params_done(nl_harness *r);

/* A declared parameter (integers have is_int 1 and whole def, lo, hi). */
typedef struct {
  const char *name;
  double def, lo, hi;
  int is_int;
  const char *meaning;
} nl_harness_param_info;
/* The parameters declared so far, in order (owned by r). */
const nl_harness_param_info *nl_harness_params(const nl_harness *r, size_t *n);
/* readable 0: "name\tdefault\tmin\tmax\tmeaning" then one TSV line each
 * (numbers as --set takes them); 1: the --help form. */
void nl_harness_params_print(const nl_harness *r, FILE *fp, int readable);
/* Extra manifest line (e.g. "pool_bytes"). */
void nl_harness_note(nl_harness *r, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 3, 4)));

/* Path inside the output folder; caller frees. */
char *nl_harness_path(const nl_harness *r, const char *file);
/* Write into the output folder; on failure print the error and exit 1.
 * With --no-images (manifest: images no) nl_harness_write_image writes
 * nothing: the image was made, only its file is left out. For runs whose
 * tables are what is wanted (sweep points, a test's rerun that compares
 * tables): a program's first image write starts OpenImageIO, about 0.6 s of
 * CPU (1 s under the sanitizers), often more than a quick run's work. */
void nl_harness_write_table(nl_harness *r, const nl_table *t, const char *file);

/* A column of FILE that is a wall or CPU time: it differs on every run, so
 * nl_harness_write_table leaves it out of FILE (declare it before the
 * write) and puts its cells in times.tsv (table, row, key: the row's first
 * cell, column, value), beside the manifest, not tracked by git and not an
 * output; report tables (nl_harness_report_table, _columns) leave out every
 * column of that name, and no check rule is kept for it. A committed
 * result then does not change when the same commit runs again. Times the
 * paper's claims are about (A2's Table 5.1, C6's real-time claim) stay in
 * their tables. */
void nl_harness_time_column(nl_harness *r, const char *file, const char *column);
void nl_harness_write_image(nl_harness *r, const nl_image *im, const char *file);

/* Progress for long runs: "[name] 40% what (3.2 s)" on stderr. One bar per
 * experiment, never going back: a run made of several stages (a size check,
 * a fit, a sweep, each a loop of its own) declares each with
 * nl_harness_stage, its share [from, to] of the bar; nl_harness_substage
 * splits the current stage into n equal parts (part k for the calls that
 * follow, e.g. one reading of a sweep), and nl_harness_progress's fraction
 * runs over the current part. On a terminal the bar is one rewritten line
 * (ended at 100% or by nl_harness_end); otherwise one plain line per stage
 * (at nl_harness_stage, or, in a run that declares none, when `what`
 * changes), so a log is not flooded. */
void nl_harness_progress(nl_harness *r, double fraction, const char *what);
void nl_harness_stage(nl_harness *r, double from, double to, const char *what);
void nl_harness_substage(nl_harness *r, int k, int n);

/* Prints "name: message" and exits with `code`; the manifest is not written. */
void nl_harness_die(nl_harness *r, int code, const char *fmt, ...)
  __attribute__((format(printf, 3, 4), noreturn));

/* Report section (Markdown). */
void nl_harness_text(nl_harness *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void nl_harness_report_table(nl_harness *r, const nl_table *t, const char *caption, int digits);
void nl_harness_figure(nl_harness *r, const char *file, const char *caption);
/* A wide table told by its story: only `columns` (comma-separated names, in
 * that order) in the report, then a link to the whole table `file` (as
 * written by nl_harness_write_table) naming how many columns it has. A name
 * the table lacks is a bug in the experiment: exit 1. */
void nl_harness_report_columns(nl_harness *r, const nl_table *t, const char *file, const char *columns,
                               const char *caption, int digits);

/* ---- regression rules ------------------------------------------------
 *
 * `scripts/noiselab check` reruns an experiment with the seed of its
 * committed results and compares every table with results/NAME/ (or
 * results/quick/NAME/ with --quick), column by column, by the rule the
 * experiment declares here, beside the table it writes:
 *
 *   nl_harness_write_table(r, dist, "distribution.tsv");
 *   nl_harness_check(r, "distribution.tsv", "mean", "welch mean_sd 1e-3");
 *   nl_harness_check(r, "distribution.tsv", "mean_sd", "ftest 1e-3");
 *   nl_harness_check(r, "spectrum.tsv", "*", "rel 1e-9");
 *
 * nl_harness_end writes the declarations to checks.tsv (table, column, rule),
 * which travels with the results. Rules:
 *   exact          numbers bit-identical, text identical: the default for
 *                  every column not declared (same seed, same program)
 *   abs TOL        |new - committed| <= TOL
 *   rel TOL        |new - committed| <= TOL max(|new|, |committed|): for
 *                  sums whose order a library may change (FFTs, BLAS)
 *   ignore         not compared (timings, work counters)
 *   welch SDCOL A  the column is a mean over the run's n seeds (manifest
 *                  "seeds") and SDCOL, in the same table, the sd of the
 *                  per-seed values: drift when Welch's two-sided t-test
 *                  rejects equal means at level A. Noise passes, shifts fail
 *                  (use for values a change of random stream may move).
 *   ftest A        the column is itself such an sd over n seeds: drift when
 *                  the two-sided F-test rejects equal variances at level A.
 * Statistical rules need n >= 2 on both sides and fall back to exact when
 * both spreads are 0 (a value the seed does not move). Text cells are
 * always compared exactly unless the rule is ignore.
 * column "*" is every column of the table; a named column's rule beats "*",
 * and a later declaration for the same table and column replaces an
 * earlier one. A malformed rule is a bug in the experiment: exit 1.
 */
typedef enum {
  NL_CHECK_EXACT, NL_CHECK_ABS, NL_CHECK_REL, NL_CHECK_IGNORE, NL_CHECK_WELCH, NL_CHECK_FTEST
} nl_harness_rule_kind;

typedef struct {
  nl_harness_rule_kind kind;
  double tol;        /* abs, rel: tolerance; welch, ftest: alpha */
  char sdcol[128];   /* welch: the spread column */
} nl_harness_rule;

void nl_harness_check(nl_harness *r, const char *table, const char *column, const char *rule);
/* The rule declared so far for table/column (a named column beats "*"), or
 * NULL: exact. */
const char *nl_harness_check_rule(const nl_harness *r, const char *table, const char *column);

/* Tolerances from a measurement, for tables whose values pass through a
 * CPU-dependent computation (OpenBLAS picks its kernel per CPU; glibc's libm
 * has FMA variants): bench/blas-spread.sh reruns the experiment under
 * every OpenBLAS kernel this CPU can run, one and two BLAS threads and libm
 * without FMA, and records per table and column the largest spread in
 * data/blas_spread.tsv (for this scale: quick or full). This declares, for
 * each column of `table` that moved, "rel (multiple x its relative spread)",
 * or "abs (multiple x its absolute spread)" when the values are themselves
 * at rounding level (relative spread > 1e-3); columns that did not move
 * stay exact (a scale not measured uses the other scale's spreads, and the
 * report says so). A column that already has a rule other than exact (welch
 * for a mean over seeds, ignore for a timing) keeps it. It adds one line to the report naming the largest spread and
 * the multiple. A table missing from the measurement is an error (exit 1):
 * measure it first. table "*": every table measured for this experiment
 * and scale. NL_BLAS_SPREAD overrides the file's path; NL_MEASURING=1
 * (set by bench/blas-spread.sh) makes it do nothing. */
void nl_harness_check_measured(nl_harness *r, const char *table, double multiple);
/* Parses a rule string as above; "rule 'x': ..." on error. */
nl_status nl_harness_rule_parse(const char *s, nl_harness_rule *rule, nl_error *err);

/* ---- the regression check (nl_harness_check.c) ------------------------
 *
 * Compares a committed run folder with a new one by the committed folder's
 * checks.tsv (the reference says how it may be compared):
 *
 *   nl_harness_check_state s = {0};                 // s.all = 1: every drifted value
 *   if (nl_harness_check_experiment(&s, "results/s3_fbm", "build/check/s3_fbm", &err))
 *     ... bad input: err.msg ...
 *   nl_harness_check_totals(&s);             // "check: s3_fbm: 5 tables, ..."
 *   return s.drifted ? 1 : 0;
 *
 * Every table (nl_harness_tables) of the committed folder is compared cell by
 * cell by its rule; the manifests' experiment, seed, seeds, quick and param
 * lines must match exactly (the others never are). Written to s.out
 * (stdout when NULL), one tab-separated line per drifted value
 *   experiment  table  row  column  committed  new  rule[: detail]
 * (row: 1-based data row, with its first text cell as a label) under a
 * header line of those names before the first, the first
 * NL_CHECK_SHOWN of an experiment unless s.all; after an experiment with
 * drift a line "check: EXP: D drifted[ (first 10 shown; ...)]; reference vs
 * this run: libm other (reference X, this run Y), CPU same (...), ..." naming
 * the CPU, architecture, BLAS kernel and libm variant of both manifests,
 * those that differ first, then those a manifest does not record (unknown),
 * then those that are the same. welch and ftest
 * p-values come from nl_stats_welch_p and nl_stats_ftest_p. Returns NL_OK
 * whether or not there was drift (counted in s), else a one-line message:
 * a missing folder or manifest, an unreadable committed table, a malformed
 * rule or a rule naming a table or column the committed folder does not have
 * (the comparison stops there). A new table that is missing or unreadable is
 * drift ("missing", or "unreadable: " and the table reader's message). */
#define NL_CHECK_SHOWN 10   /* drifted values printed per experiment without `all` */
typedef struct {
  int all;                  /* print every drifted value */
  FILE *out;                /* the report; NULL: stdout */
  size_t experiments, tables, values, drifted;   /* totals so far */
  char last[128];           /* the experiment compared last, for the totals */
  /* The first experiment whose reference was made on another architecture
   * or libm than this run: "architecture other (reference x86_64, this run
   * aarch64), libm other (...)", named by the totals line. */
  char elsewhere[512];
} nl_harness_check_state;
nl_status nl_harness_check_experiment(nl_harness_check_state *s, const char *ref_dir, const char *new_dir,
                                      nl_error *err);
/* "check: E experiments, T tables, V values compared, D drifted" (for one
 * experiment "check: NAME: T tables, ..."), and when a reference was made
 * on another architecture or libm (the manifests' arch and libm lines),
 * "; reference made elsewhere: architecture other (reference x86_64, this
 * run aarch64), libm other (...)": 0 drifted then says the results held
 * across them. */
void nl_harness_check_totals(const nl_harness_check_state *s);

/* The data tables of a run folder: every *.tsv but manifest.tsv,
 * checks.tsv and the times run.tsv and times.tsv (hidden files are
 * temporaries), sorted by name. Caller frees
 * each name and the array (never NULL when the folder is read, even if
 * empty); NULL and a message if the folder cannot be read. */
char **nl_harness_tables(const char *dir, size_t *n, nl_error *err);

/* ---- verdicts: the paper's numbers against ours (nl_harness_verdict.c) -
 *
 * REPORT.md opens with one row per claim of the paper: id, quantity, kind,
 * paper, ours +- sd, verdict, reason. No verdict is typed: the experiment
 * declares the comparison beside the table it wrote, naming the columns that
 * hold the paper's number and ours, the rule that decides, and the kind of
 * reading ours is:
 *
 *   nl_harness_write_table(r, t, "timing.tsv");
 *   nl_harness_verdict(r, "timing.tsv", t, row, "plain/bounded ratio, N = 10",
 *                      "paper_ratio", "eval_ratio", NULL, "factor 1.1 1.5",
 *                      "independent", NULL);
 *
 * Rules, each with two thresholds A <= B: "reproduced" within A, "partly"
 * within B, else "not reproduced":
 *   rel A B     |ours - paper| <= A |paper|            (relative difference)
 *   abs A B     |ours - paper| <= A                    (absolute difference)
 *   factor A B  max(ours/paper, paper/ours) <= A       (ratios, counts; both > 0)
 *   sd A B      |ours - paper| <= A sd (sd_col: the spread over seeds of ours)
 * a claim that two values are equal, close or "very similar", decided by
 * two one-sided tests (TOST) against a margin M fixed before the run from
 * the paper's printed precision or a rule stated in docs/experiments.md
 * (nl_harness_verdict_equiv; never by a failure to reject a difference):
 *   equiv rel M A B   |ours - paper| < M |paper| shown at TOST p <= A
 *                     (reproduced), p <= B (partly)
 *   equiv abs M A B   |ours - paper| < M, likewise
 * and, for a claim decided by a test (nl_harness_verdict_p), on its p-value:
 *   p A B       the claimed effect: reproduced when p <= A, partly when p <= B
 *   fit A B     a claimed law (A >= B): reproduced when p >= A, partly when p >= B
 *
 * Kinds. A reading is fixed before it is compared; the kind says how:
 *   "independent"      the headline: the paper's stated reading, or one chosen
 *                      by a criterion that never looks at the paper's numbers;
 *   "fitted K/M"       K parameters were fitted jointly to M of the paper's
 *                      numbers: "consistent after fit", "partly consistent
 *                      after fit" or "not consistent after fit";
 *   "selected 1/N"     the best of N readings by closeness to the paper: at
 *                      best "consistent after selection" (likewise "partly
 *                      ..." and "not consistent after selection");
 *   "by construction"  the value cannot differ from the paper's by how the
 *                      experiment is set up: verdict "by construction";
 *   "qualitative"      a claim no number decides (nl_harness_verdict_figure):
 *                      verdict "see figure".
 * Only "independent" rows are counted as reproduced at the top of REPORT.md.
 *
 * The reason is generated from the numbers ("4.6% above the paper", "p =
 * 0.003"); the thresholds are the rule's, stated once in its own column.
 * `note` (may be NULL) is appended after a semicolon and must hold no number of the run (it names
 * the reading, e.g. "slope fitted to the paper's ratios"). A malformed rule
 * or kind, a missing column, or sd without sd_col is a bug in the
 * experiment: exit 1. nl_harness_end writes the rows to verdicts.tsv
 * (columns quantity, source, paper, ours, ours_sd, rule, kind, verdict,
 * reason, control, control_ours, control_verdict); the entry script gathers every folder's verdicts.tsv into the
 * table at the top of REPORT.md. The regression check ignores verdicts.tsv:
 * each value in it is a copy of a value compared, by its own rule, in the
 * table it came from. */
typedef enum { NL_VERDICT_REPRODUCED, NL_VERDICT_PARTLY, NL_VERDICT_NOT } nl_harness_outcome;
void nl_harness_verdict(nl_harness *r, const char *file, const nl_table *t, size_t row,
                        const char *quantity, const char *paper_col, const char *ours_col,
                        const char *sd_col, const char *rule, const char *kind, const char *note);
/* One verdict per row of t, quantity "WHAT, LABEL_COL LABEL" (the row's
 * text or number in label_col, e.g. "E_KS, panel a"). */
void nl_harness_verdict_rows(nl_harness *r, const char *file, const nl_table *t, const char *what,
                             const char *label_col, const char *paper_col, const char *ours_col,
                             const char *sd_col, const char *rule, const char *kind,
                             const char *note);
/* A claim of the paper that a value is lower in one condition than in
 * another (rows row_a and row_b of t, column col; sd_col: the sd over the
 * n_col seeds of each row): "reproduced" when ours is lower and Welch's
 * two-sided test rejects equal means at level alpha, "partly" when lower but
 * not significant, else "not reproduced". The paper column holds `claim`
 * (text), ours the two means and sds, the reason the p-value. */
void nl_harness_verdict_less(nl_harness *r, const char *file, const nl_table *t, size_t row_a,
                             size_t row_b, const char *quantity, const char *claim,
                             const char *col, const char *sd_col, const char *n_col,
                             double alpha, const char *kind);
/* A claim decided by a test the experiment ran: the paper column holds
 * `claim` (text), ours the statistic in stat_col and its p-value in p_col
 * (row `row` of t), decided by rule "p A B" or "fit A B" (above). The
 * experiment states in `note` what the test is ("r with the pattern against
 * 100 random tables, one-sided"). */
void nl_harness_verdict_p(nl_harness *r, const char *file, const nl_table *t, size_t row,
                          const char *quantity, const char *claim, const char *stat_col,
                          const char *p_col, const char *rule, const char *kind, const char *note);
/* An equivalence (rule "equiv rel|abs M A B", above): ours in ours_col with
 * its standard error in se_col and n_col the number of seeds it is a mean
 * over (t on n - 1 degrees of freedom; n_col NULL: normal). */
void nl_harness_verdict_equiv(nl_harness *r, const char *file, const nl_table *t, size_t row,
                              const char *quantity, const char *paper_col, const char *ours_col,
                              const char *se_col, const char *n_col, const char *rule, const char *kind,
                              const char *note);
/* The negative control of the verdict declared just before (any of the
 * calls above but nl_harness_verdict_figure): the same rule, with the same
 * paper value and thresholds, run on a baseline without the method (random
 * or unoptimised tables, a flat image, a shuffled pattern, the other
 * objective, noise without the method), named in words by `control`. Its
 * value is row `row` of t (the baseline's own table, or another row of the
 * verdict's) in the columns of the same names the verdict read: ours_col
 * and sd_col, se_col and n_col, stat_col and p_col; for
 * nl_harness_verdict_less, rows row and row_b (nl_harness_verdict_control_less).
 * verdicts.tsv gets control (the words), control_ours and control_verdict
 * ("-" on rows without one). A value outside a factor rule's domain (<= 0)
 * is "not reproduced". An independent row that passes (reproduced or
 * partly) while its control comes out "reproduced" is no evidence for the
 * claim (the rule passes without the method): the harness turns its kind to
 * "by construction" and says why in the reason. A row that fails keeps its
 * "not reproduced" whatever its control says. Calling it with no verdict before, after a figure, or twice
 * for one verdict is a bug in the experiment: exit 1. */
void nl_harness_verdict_control(nl_harness *r, const char *control, const char *file, const nl_table *t,
                                size_t row);
void nl_harness_verdict_control_less(nl_harness *r, const char *control, const char *file,
                                     const nl_table *t, size_t row_a, size_t row_b);
/* A claim no number decides, shown by a figure of the run: kind
 * "qualitative", verdict "see figure", source the figure's file name. */
void nl_harness_verdict_figure(nl_harness *r, const char *quantity, const char *claim,
                               const char *figure, const char *note);
/* The decision alone: outcome and reason (at most `len` bytes) for
 * paper, ours, sd (NAN when there is none) under `rule` (rel, abs, factor,
 * sd; for p and fit, ours is the p-value and paper is ignored). */
nl_status nl_harness_verdict_decide(const char *rule, double paper, double ours, double sd,
                                    nl_harness_outcome *outcome, char *reason, size_t len,
                                    nl_error *err);
/* The same for "equiv rel|abs M A B": ours with standard error se on df
 * degrees of freedom (df < 1: normal). */
nl_status nl_harness_verdict_decide_equiv(const char *rule, double paper, double ours, double se,
                                          double df, nl_harness_outcome *outcome, char *reason,
                                          size_t len, nl_error *err);
/* NL_OK when `kind` is one of the kinds above (K, M, N >= 1). */
nl_status nl_harness_verdict_kind_check(const char *kind, nl_error *err);
/* The word in the verdict column: the outcome capped by the kind
 * ("reproduced", "partly", "not reproduced" for an independent row only;
 * "consistent after fit", "partly consistent after fit", "not consistent
 * after fit", likewise "... after selection"; "by construction", "see
 * figure"). */
const char *nl_harness_verdict_word(nl_harness_outcome outcome, const char *kind);

/* ---- shards: the independent units of an experiment ------------------
 *
 * An experiment whose cost is a set of independent units (replicates,
 * draws, cases, seeds) declares them, computes each one from its own seed
 * (the one seed rule, from the unit's index, never from the shard it runs
 * in), stores what its tables need of it, and builds its tables from the
 * stored values in unit order:
 *
 *   long n = nl_harness_units(r, reps);                // after the parameters
 *   for (long u = 0; u < n; u++) {
 *     if (!nl_harness_unit_mine(r, u)) continue;
 *     nl_harness_unit_begin(r, u);                     // notes go to the unit
 *     ... compute replicate u from nl_seed_replicate(seed, u) ...
 *     nl_harness_unit_put(r, "fit", v, 7);             // doubles, bit-exact
 *     nl_harness_unit_put_table(r, "gmm", t);          // rows of a table
 *     nl_harness_unit_end(r);
 *   }
 *   nl_harness_units_done(r);
 *   for (long u = 0; u < n; u++) {
 *     const double *v = nl_harness_unit_get(r, u, "fit", &len);
 *     nl_harness_unit_get_rows(r, u, "gmm", gmm);       // appended
 *     nl_harness_unit_notes(r, u);                     // its manifest notes
 *   }
 *
 * Without --shard or --merge every unit is mine and the values go through
 * the same store, so one code path makes the tables in all three modes.
 * --shard K/N: unit u is mine when u mod N == K - 1 (round robin: the
 * replicates of every case spread over the shards); nl_harness_units_done
 * writes the stored values to DIR/K-of-N.tsv (DIR: --shards, default
 * OUT/.shards; atomically; first line the run's settings and NL_COMMIT; numbers
 * as C99 hex floats, so NaN and every bit survive) and exits 0, no table,
 * report or manifest written. --merge: no unit is mine; nl_harness_units_done
 * reads DIR/K-of-N.tsv for K = 1..N (N from the files found; a
 * missing shard or one of another unit count is "NAME: --merge: shard K of N
 * missing (PATH)", exit 2); its run.tsv adds shards_cpu_seconds (their sum)
 * and shards_peak_rss_mb (their largest), which each shard file records,
 * and nl_harness_end empties and removes DIR once the
 * manifest is written: the folder is then the unsharded run's, file for
 * file. An experiment that writes before declaring units refuses --shard
 * and --merge (exit 2): it has nothing to shard. Getting a value no unit
 * stored is a bug in the experiment (exit 1). --units: nl_harness_units
 * prints one line a unit, its relative cost (1 unless declared with
 * nl_harness_units_weighted: cost[u], measured, so that a scheduler starts
 * the costly ones first), and exits 0; the experiment's work before it, its
 * parameters and patterns, is all that runs. */
long nl_harness_units(nl_harness *r, long n);
long nl_harness_units_weighted(nl_harness *r, long n, const double *cost);
int nl_harness_unit_mine(const nl_harness *r, long u);
/* 0 normal run, 1 --shard, 2 --merge */
int nl_harness_shard_mode(const nl_harness *r);
void nl_harness_unit_begin(nl_harness *r, long u);
void nl_harness_unit_end(nl_harness *r);
void nl_harness_unit_put(nl_harness *r, const char *key, const double *v, size_t n);
void nl_harness_unit_put_table(nl_harness *r, const char *key, const nl_table *t);
void nl_harness_units_done(nl_harness *r);
/* The values stored under key by unit u (owned by r); exit 1 when none. */
const double *nl_harness_unit_get(nl_harness *r, long u, const char *key, size_t *n);
/* Appends the rows stored under key by unit u to t (same columns). */
void nl_harness_unit_get_rows(nl_harness *r, long u, const char *key, nl_table *t);
/* Adds unit u's notes (nl_harness_note between its begin and end) to the
 * manifest, in the order they were made. */
void nl_harness_unit_notes(nl_harness *r, long u);

/* Writes report.md, checks.tsv, verdicts.tsv (when declared) and manifest.tsv,
 * frees r; returns 0 for main(). */
int nl_harness_end(nl_harness *r);

#ifdef __cplusplus
}
#endif

#endif
