/* nl_study.h - the loops that several experiments share, written once.
 *
 * nl_study_series: a row of panels (the slides' (a), (b), ...) of sums of
 * octaves, one per setting, surveyed over the run's seeds. It writes
 *   PREFIX_panels.png        the first seed's raster of each setting, labelled
 *   PREFIX_distribution.tsv  value distribution per setting (nl_study_survey_series)
 *   PREFIX_spectrum.tsv      seed-averaged radial power per setting
 * into the run's folder and adds them to the report; the spectrum figure is
 * PREFIX_spectrum.png, drawn by scripts/gnuplot/NAME-PREFIX_spectrum.gp.
 * Returns the distribution table (caller frees) for the text that
 * interprets it.
 */
#ifndef NL_STUDY_H
#define NL_STUDY_H

#include "byexample/nl_byexample.h"
#include "image/nl_image.h"
#include "noise/nl_noise.h"
#include "harness/nl_harness.h"
#include "table/nl_table.h"
#include "texture/nl_texture.h"

/* ---- surveys: what a sum of octaves looks like, over seeds -------------
 *
 * nl_study_survey_run evaluates a sum of octaves of the chosen basis (a fresh
 * table per seed: seed0, seed0+1, ...) on a window and records, per seed, the
 * value distribution (mean, sd, min, max) and the radially averaged power
 * spectrum (frequency in cycles per unit of the window, power normalised as
 * nl_spectrum_radial), plus the first seed's raster for pictures. Experiments
 * S1-S4 and sweeps use it so the numbers and the picture come from one pass.
 */
typedef enum { NL_BASIS_GRAD2 = 0, NL_BASIS_IMPROVED3 = 1 } nl_study_basis_kind;

typedef struct {
  int nseeds, nbins, w, h;
  double bound;                   /* analytic bound of the sum */
  double *mean, *sd, *min, *max;  /* per seed */
  double *freq;                   /* nbins, cycles per unit */
  double *power;                  /* nseeds * nbins */
  double *first;                  /* w * h values of the first seed */
} nl_study_survey;

nl_study_survey *nl_study_survey_run(nl_study_basis_kind kind, const nl_noise_octaves *o, const nl_noise_window *win,
                                     unsigned long seed0, int nseeds);
void nl_study_survey_free(nl_study_survey *s);

/* A series of surveys, one per setting (the slides' panels (a), (b), ...):
 *  dist     one row per setting: label, octaves, gain, lacunarity (as given
 *           in the setting), then over
 *           seeds the mean and sd of the per-seed mean and sd, the mean
 *           min and max, the largest |value| seen, the analytic bound and
 *           their ratio;
 *  spectrum freq (cycles per unit) and one column of seed-averaged radial
 *           power per setting, headed by its label;
 *  panels   the first seed's raster of each setting as a grey image mapped
 *           from [mean - 3 sd, mean + 3 sd] to [0, 1] (each panel its own
 *           contrast; the table carries the amplitudes).
 * Any output pointer may be NULL. */
typedef struct { const char *label; nl_noise_octaves oct; double gain, lacunarity; } nl_study_setting;
void nl_study_survey_series(nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                            const nl_noise_window *win, unsigned long seed0, int nseeds,
                            nl_table **dist, nl_table **spectrum, nl_image **panels);

nl_table *nl_study_series(nl_harness *r, const char *prefix, const char *title, nl_study_basis_kind kind,
                          const nl_study_setting *settings, int n, const nl_noise_window *win);

/* The square window of the S experiments from the run's parameters:
 * size (pixels; 512, or 128 with --quick), extent (4 units) and z (0.5). */
nl_noise_window nl_study_window(nl_harness *r);

/* Fills settings[i] for octave counts oct[i] of Shaffer's fractal sum (gain
 * 1/2, lacunarity 2), optionally turbulent; labels "(a) 1 octave" are
 * written into labels[i] (32 bytes each). */
void nl_study_octave_settings(const int *oct, int n, int turbulence, nl_study_setting *settings,
                              char (*labels)[32]);

/* S1 and S2: Shaffer's sums at 1, 2, 3 and 8 octaves (fractal sum, or
 * turbulence when `turbulence`), introduced by one paragraph ("**Slides:**
 * SLIDES **Ours:** the slice z = ... over [0, size)^2, K seeds ...") and
 * surveyed by nl_study_series. Returns the distribution table (caller frees). */
nl_table *nl_study_octave_series(nl_harness *r, const nl_noise_window *win, int turbulence, const char *slides,
                                 const char *prefix, const char *title);

/* Lays panels out in a montage of `cols` columns (nl_image_montage), writes it as
 * FILE in the run's folder (nl_harness_write_image) and frees it: the figure step that
 * most experiments end a loop with. */
void nl_study_montage(nl_harness *r, const nl_image *const *panels, const char *const *labels, int n,
                      int cols, const char *title, const char *file);

/* Radially averaged power (nl_spectrum_radial, size / 2 bins, cycles per
 * pixel) of n square size x size rasters: column "freq" then one column per
 * raster named cols[i]; rows from bin `first` on. */
nl_table *nl_study_radial_table(const double *const *img, const char *const *cols, int n, int size,
                                int first);

/* Two-sample KS distance between the intensities of a and b, per channel
 * (per[0..2]; may be NULL) and their mean over R, G, B (the return): how
 * far a synthesis' histograms are from its exemplar's (sec. 5). */
double nl_study_ks_channels(const nl_image *a, const nl_image *b, double *per);

/* Summaries of quantities measured over seeds: thin names for the stats
 * module's (nl_stats.h, "mean, sd and min"). nl_study_mean/_sd round as
 * NL_STATS_RUNNING (GSL's running mean), nl_study_mean_sd as
 * NL_STATS_SUMMED (sums in order); the reference tables were made with both. */
double nl_study_mean(const double *x, int n);
double nl_study_sd(const double *x, int n);
double nl_study_min(const double *x, int n);
void nl_study_mean_sd(const double *v, int n, double *m, double *sd);

/* Mean of column `col` over the rows of a per-seed table whose text column
 * `key` reads `value` (0 rows: NaN); with pcol, *below (if not NULL) gets how
 * many of those rows have pcol < alpha: "rejected on k of n seeds". */
double nl_study_mean_where(const nl_table *t, const char *key, const char *value, const char *col,
                           const char *pcol, double alpha, int *below);

/* ---- L3 on photographs (nl_study_example.c) ------------------------------ */

/* Removes "--exemplars DIR" from argv (before nl_harness_begin sees it) and
 * sets *dir to DIR, or "data/exemplars" (experiments run from the repository
 * root, as with --patterns). */
nl_status nl_study_example_dir_parse(int *argc, char **argv, const char **dir, nl_error *err);
/* The names (without ".png") of dir's PNG files, sorted, at most max; -1 and
 * err when the folder cannot be read, 0 and err when it holds none. */
int nl_study_example_list(const char *dir, char (*names)[64], int max, nl_error *err);
/* The Gaussian self-match of a histogram representation: n N(0, 1) values as
 * the exemplar channel, n fresh N(0, 1) values matched to its histogram
 * (sigma 1, steffen); KS distance between the two samples and the matched
 * values' fraction beyond 2.5 sd of the exemplar (1.24% for a Gaussian). */
void nl_study_example_gauss(size_t n, unsigned long seed, nl_byexample_hist_kind hk, double *ks, double *tail);
/* The tables nl_study_example_photo appends to (caller frees). */
nl_table *nl_study_example_band_table(void);
nl_table *nl_study_example_summary_table(void);
/* Compares a synthesis with its photograph ex by luminance: one row per eq. 13
 * band of the photo (bands may be NULL), tagged with `replicate`,
 * to `bands` (power of photo and synthesis, ratio synth/photo, the band's
 * share of the photo's power, checked = share >= min_share) and one row to
 * `sum` (KS of the luminance, mean KS over R, G, B, tail mass beyond 2.5 sd
 * of photo and synthesis, speckle (nl_byexample_speckle), the checked band
 * whose ratio is farthest from 1, and pass = that ratio within
 * [1/max_ratio, max_ratio] and KS < max_ks). rep names the representation. */
void nl_study_example_compare(const nl_image *ex, const nl_image *syn, const char *name, const char *rep,
                              int replicate, double min_share, double max_ratio, double max_ks, nl_table *bands, nl_table *sum);
/* Analyses a photograph with representation hk (calibrate > 0: with the
 * synthesis-time band calibration of that many rounds, nl_byexample.h; rows
 * named "calibrated"), synthesises size x size (seed) and appends
 * nl_study_example_compare's rows. Returns the synthesis; NULL and err when
 * analysis or synthesis fails. */
nl_image *nl_study_example_photo(const nl_image *ex, const char *name, nl_byexample_hist_kind hk, int calibrate,
                                 int size, unsigned long seed, int replicate, double min_share, double max_ratio,
                                 double max_ks, nl_table *bands, nl_table *sum, nl_error *err);

/* K syntheses of p, size x size, seeds nl_seed_replicate(seed0, s), on up to
 * `threads` threads (nl_parallel_for; seed s writes only its own slots, so the
 * results do not depend on the thread count), each against the exemplar ex:
 * ks[s] = nl_study_ks_channels (per channel in per[3 s .. 3 s + 2]), ce[s] =
 * nl_byexample_correlation_error. Returns seed 0's synthesis (caller frees);
 * NULL and err (the first failing seed's) if a synthesis fails. */
nl_image *nl_study_example_synth_seeds(const nl_byexample_params *p, const nl_byexample_synth_options *so,
                                       const nl_image *ex, int size, int K, unsigned long seed0, int threads,
                                       double *ks, double *per, double *ce, nl_error *err);
/* Reads the first max photographs of nl_study_example_list; -1 and err on the
 * first that does not read (the others freed). */
int nl_study_example_load(const char *dir, char (*names)[64], nl_image **photos, int max, nl_error *err);
/* nl_study_example_gauss for the paper's and the Gaussian-knot representation
 * over K seeds: representation, n, ks_mean/sd, tail_mean/sd, tail_gauss (the
 * Gaussian's own 2 Q(2.5)). Caller frees. */
nl_table *nl_study_example_gauss_table(size_t n, int K, unsigned long seed0, int threads);   /* replicates on `threads` threads */
/* Every photograph through nl_study_example_photo with three representations
 * (gauss33, paper10 as the paper synthesises, and calibrated = gauss33 with
 * NL_EXAMPLE_CALIBRATE rounds, the `example` command's default) and K
 * replicates (nl_seed_replicate(seed, s), the same for all; rows carry the
 * replicate): writes photos.tsv (bands), photos_summary.tsv (one row per
 * replicate), photos_mean.tsv (over replicates: mean KS, tails, speckle, the
 * checked band whose mean power is farthest from the photo's, passes of K,
 * replicates failing by KS and by band, the photo's largest saturation) and
 * the montage photos_montage.png (photo | gauss33 | paper10 | calibrated per
 * row, top-left 256^2 crops); returns the photos_mean table (caller frees).
 * The analyses (one per photo and representation) and the syntheses (one per
 * replicate) run on the harness's threads, rows added in order afterwards:
 * the tables do not depend on the thread count. */
nl_table *nl_study_example_photos(nl_harness *r, char (*names)[64], nl_image **photos, int np, int size,
                                  int K, unsigned long seed, double min_share, double max_ratio, double max_ks);

/* L3's report paragraphs, tables and figures for the Gaussian self-match
 * (gt, K seeds), the procedural `wavelet` exemplar's KS per variant (kt,
 * columns kind, variant, ks_mean) and the photographs (pt,
 * nl_study_example_photos). */
void nl_study_example_report(nl_harness *r, const nl_table *kt, const nl_table *gt, const nl_table *pt, int K, int size,
                             unsigned long seed, double min_share, double max_ratio, double max_ks);

#endif
