/* nl_report.h - the harness around an experiment program: options, seeds,
 * parameters, output folder, manifest and report section.
 *
 * An experiment reads like the paper's method section:
 *
 *   int main(int argc, char **argv) {
 *     nl_run *r = nl_run_begin("s3_fbm", "S3 - fBm gain and lacunarity", argc, argv);
 *     int octaves = nl_run_param_int(r, "octaves", 6, 1, 30);   // --set octaves=8
 *     nl_run_params_done(r);                                    // rejects unknown --set
 *     ... library calls ...
 *     nl_run_table(r, t, "dist.tsv");                           // out/dist.tsv, atomic
 *     nl_report_text(r, "The slides show ...");
 *     nl_report_table(r, t, "Value distribution", 4);
 *     nl_report_figure(r, "spectrum.png", "Radially averaged power spectrum");
 *     return nl_run_end(r);                                     // report.md + manifest.tsv
 *   }
 *
 * Common options, parsed by nl_run_begin (errors: one line, exit 2):
 *   --out DIR    output folder (default results/NAME)
 *   --seed N     base seed (default 1); multi-seed summaries use N, N+1, ...
 *   --seeds K    number of seeds for means and spreads (default 10, quick 3)
 *   --quick      small sizes for tests and CI
 *   --set K=V    an experiment parameter (repeatable), for sweeps
 *   --help
 * The manifest (manifest.tsv: key, value) records the experiment, seed,
 * parameters, commit (NL_COMMIT from the entry script), library versions,
 * wall time and peak memory. It is written last and removed first, so a
 * folder with a manifest is a complete run.
 *
 * Figures named with nl_report_figure are made afterwards by the entry
 * script from scripts/gnuplot/NAME-*.gp, or are images the program wrote.
 * Report links are relative to results/ ("NAME/file.png").
 */
#ifndef NL_REPORT_H
#define NL_REPORT_H

#include "image/nl_image.h"
#include "table/nl_table.h"

typedef struct nl_run nl_run;

nl_run *nl_run_begin(const char *name, const char *title, int argc, char **argv);

unsigned long nl_run_seed(const nl_run *r);   /* base seed */
int nl_run_seeds(const nl_run *r);            /* K seeds: seed .. seed+K-1 */
int nl_run_quick(const nl_run *r);
const char *nl_run_dir(const nl_run *r);

/* Parameter `name` from --set, else def; range-checked; recorded. */
double nl_run_param(nl_run *r, const char *name, double def, double lo, double hi);
long nl_run_param_int(nl_run *r, const char *name, long def, long lo, long hi);
void nl_run_params_done(nl_run *r);
/* Extra manifest line (e.g. "pool_bytes"). */
void nl_run_note(nl_run *r, const char *key, const char *fmt, ...)
  __attribute__((format(printf, 3, 4)));

/* Path inside the output folder; caller frees. */
char *nl_run_path(const nl_run *r, const char *file);
/* Write into the output folder; on failure print the error and exit 1. */
void nl_run_table(nl_run *r, const nl_table *t, const char *file);
void nl_run_image(nl_run *r, const nl_image *im, const char *file);

/* Progress for long runs: "[name] 40% what (3.2 s)" on stderr, one
 * rewritten line on a terminal, at most one plain line a second otherwise. */
void nl_run_progress(nl_run *r, double fraction, const char *what);

/* Prints "name: message" and exits with `code`; the manifest is not written. */
void nl_run_die(nl_run *r, int code, const char *fmt, ...)
  __attribute__((format(printf, 3, 4), noreturn));

/* Report section (Markdown). */
void nl_report_text(nl_run *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void nl_report_table(nl_run *r, const nl_table *t, const char *caption, int digits);
void nl_report_figure(nl_run *r, const char *file, const char *caption);

/* Writes report.md and manifest.tsv, frees r; returns 0 for main(). */
int nl_run_end(nl_run *r);

#endif
