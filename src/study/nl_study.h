/* nl_study.h - the loops that several experiments share, written once.
 *
 * An experiment's own code lives in its folder (experiments/NAME/); this
 * module holds what two or more experiments or tools need:
 *
 *   nl_study.c            surveys of sums of octaves as panels, spectra and
 *                         distributions (S1-S4, sweeps), montages, radial
 *                         spectra tables, per-channel KS, grouped means
 *   nl_survey.c           the survey over seeds under all of the above
 *   nl_study_cheng.h/.c   what the Cheng experiments C1-C9 share: the run's
 *                         options, runs over seeds into summary tables,
 *                         Welch rows between conditions, controllability text
 *   nl_study_cheng_image.c  control patterns from images, textures as images
 *   nl_study_cheng_repro.c  the thesis's Tables 4.2-4.4 and the original ->
 *                         pool chain that C5 and C6 both use
 *   nl_study_exemplars.h/.c  exemplar folders (L2, the example tool)
 *   nl_study_example.c    synthesis-against-exemplar tables (L3, the example
 *                         tool)
 *   nl_study_lines.h/.c   the sampling lines of the bandwidth (A3, A4)
 *
 * Tested in test_study.c, and through every experiment's quick run.
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
#include "stats/nl_stats.h" /* nl_stats_mean & co.: the summaries over seeds */
#include "table/nl_table.h"
#include "texture/nl_texture.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- surveys: what a sum of octaves looks like, over seeds -------------
 *
 * nl_study_survey_run evaluates a sum of octaves of the chosen basis (a fresh
 * one per seed: seed0, seed0+1, ...) on a window and records, per seed, the
 * value distribution (mean, sd, min, max) and the radially averaged power
 * spectrum (frequency in cycles per unit of the window, power normalised as
 * nl_spectrum_radial), plus the first seed's raster for pictures. Experiments
 * S1-S4 and sweeps use it so the numbers and the picture come from one pass.
 */
/* The basis under the sums: a name of the noise registry (nl_basis.h), such
 * as "improved" or "noise2", built with its default options for each seed. */
typedef const char *nl_study_basis_kind;

/* Points per octave and seed of the axis-aligned gradient fraction: a
 * quarter of the pixels (4096 at quick scale), at most 16384 (standard
 * error 0.0017 per octave and seed), so it costs at most what the raster
 * does. */
#define NL_STUDY_AXIS_POINTS(w, h) \
  ((size_t)(w) * (size_t)(h) / 4 < 16384 ? (size_t)(w) * (size_t)(h) / 4 : 16384)

typedef struct {
  int nseeds, nbins, w, h;
  double bound;                   /* analytic bound of the sum */
  double *mean, *sd, *min, *max;  /* per seed */
  double *axis, *axis_worst;      /* per seed: axis-aligned gradient fraction of
                                     the octaves, pooled and the largest one's */
  double *sd_sep;                 /* per seed: sqrt(sum amp_l^2 var_l), var_l the
                                     variance of octave l alone on the window */
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
 *           their ratio; axis_frac (sd over seeds axis_frac_sd): the
 *           fraction of points whose gradient lies within 2 degrees of the
 *           x or y axis, for each octave alone on its slice (noise(f p) on
 *           the plane z), pooled over the octaves in the picture (amp != 0),
 *           at NL_STUDY_AXIS_POINTS(w, h) points per octave and seed;
 *           axis_frac_worst the largest single octave's (mean over seeds);
 *           axis_frac_iso = 16/360, the value for an isotropic field. The
 *           octaves on lattice planes (z = 0.5) read 1.7 to 2.0 times that
 *           at quick scale, the slice NL_STUDY_SLICE_Z 1.06 to 1.14 times;
 *  spectrum freq (cycles per unit) and one column of seed-averaged radial
 *           power per setting, headed by its label;
 *  panels   the first seed's raster of each setting as a grey image mapped
 *           from [mean - 3 sd, mean + 3 sd] to [0, 1] (each panel its own
 *           contrast; the table carries the amplitudes);
 *  per_seed one row per setting and seed: setting, seed, mean, sd,
 *           sd_sep (the sd of the sum if its octaves were uncorrelated,
 *           each with the variance it has alone on the window), axis_frac
 *           (the statistics a paired comparison between settings needs,
 *           nl_study_sd_law_table).
 * Any output pointer may be NULL. */
typedef struct { const char *label; nl_noise_octaves oct; double gain, lacunarity; } nl_study_setting;
void nl_study_survey_series(nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                            const nl_noise_window *win, unsigned long seed0, int nseeds,
                            nl_table **dist, nl_table **spectrum, nl_image **panels,
                            nl_table **per_seed);

/* Also writes PREFIX_seeds.tsv (per_seed above), returned in *per_seed
 * when not NULL (caller frees). */
nl_table *nl_study_series(nl_harness *r, const char *prefix, const char *title,
                          nl_study_basis_kind kind, const nl_study_setting *settings, int n,
                          const nl_noise_window *win, nl_table **per_seed);

/* The plane z of the 2D slices through 3D improved noise (S1-S4, Q2's and
 * Q4's Perlin panels). An octave of frequency f samples noise on the plane
 * z f; on a lattice plane (z f an integer) only one layer of gradients
 * contributes and a third of them, (+-1, 0, +-1) and (0, +-1, +-1), project
 * onto an axis, so the slice shows straight axis-aligned creases (and z f a
 * half-integer is nearly as bad). z = 64/3 puts z 2^k at a third of a cell,
 * frac(z 2^k) = 1/3 or 2/3, for every k >= -6: every octave of every sum
 * with lacunarity 2^m (0.5, 1, 2, 4, 8) sits as far from the lattice planes
 * as it can while keeping that for all octaves. The surveys measure the
 * result (axis_frac, nl_study_survey_series). */
#define NL_STUDY_SLICE_Z (64.0 / 3.0)

/* The square window of the S experiments from the run's parameters:
 * size (pixels; 512, or 128 with --quick), extent (4 units) and z
 * (NL_STUDY_SLICE_Z). */
nl_noise_window nl_study_window(nl_harness *r);

/* S1 and S2: Shaffer's sums at 1, 2, 3 and 8 octaves (fractal sum, or
 * turbulence when `turbulence`), introduced by one paragraph ("**Slides:**
 * SLIDES **Ours:** the slice z = ... over [0, size)^2, K seeds ...") and
 * surveyed by nl_study_series. Returns the distribution table (caller frees);
 * per_seed as nl_study_series. */
nl_table *nl_study_octave_series(nl_harness *r, const nl_noise_window *win, int turbulence,
                                 const char *slides, const char *prefix, const char *title,
                                 nl_table **per_seed);

/* The slides' law for the sd of a sum of octaves, per row of a distribution
 * table of nl_study_series (columns setting, octaves, gain, lacunarity, sd,
 * sd_sd): octaves of one noise at different frequencies are uncorrelated,
 * so their variances add, sd_law = sd1 sqrt(sum_{j<n} gain^2j), sd1 the sd
 * of the lone first octave; at lacunarity 1 every octave is the same noise
 * and the amplitudes add, sd_law = sd1 sum gain^j. sd1 is setting `ref` of
 * the per-seed table ref_seeds (nl_study_series), seeds the series' own
 * per-seed table: the ratio sd / sd_law is taken seed by seed (the sum and
 * the lone octave share the first octave's noise, so the pairing removes
 * most of the seed-to-seed spread) and averaged. Columns: setting, octaves,
 * gain, lacunarity, sd, sd_sd, sd1 (mean over seeds), sd_law (sd1 times
 * the law's factor), law ("independent" or "identical"), sd_over_law (mean
 * of the per-seed ratios), sd_over_law_se (their standard error),
 * claim_ratio = 1, the law's value of the ratio, and its two factors, each
 * a mean of per-seed ratios with its standard error: sd_over_sep = sd /
 * sd_sep (the octaves' correlation: 1 when uncorrelated) and sep_over_law =
 * sd_sep / sd_law (each octave's variance on the window against the lone
 * first octave's: 1 when sampling treats every octave alike), and seeds,
 * the number of per-seed ratios averaged. Caller frees. */
nl_table *nl_study_sd_law_table(const nl_table *dist, const nl_table *seeds,
                                const nl_table *ref_seeds, const char *ref);
/* The rule that decides the law (S1, S3): sd_over_law equivalent to 1
 * within 5% by two one-sided tests over the seeds, the margin stated in
 * docs/experiments.md (Equivalence margins) before the run. */
#define NL_STUDY_SD_LAW_RULE "equiv rel 0.05 0.05 0.2"
/* The negative control of the law: for each row of a law table (above),
 * the same octaves and gains with every octave at the first one's
 * frequency (lacunarity 1: one noise summed with itself, octaves as
 * correlated as they can be), rendered on win for nseeds seeds from seed0,
 * its sd over sd1 sqrt(sum gain^2j) with sd1 from ref_seeds' setting ref,
 * taken seed by seed. Same row order and column names as the law table
 * (setting, octaves, gain, lacunarity, sd, sd1, sd_law, sd_over_law,
 * sd_over_law_se, claim_ratio, seeds), so a verdict on row i of the law
 * has its control on row i. Caller frees. */
nl_table *nl_study_sd_law_control(nl_study_basis_kind kind, const nl_table *law,
                                  const nl_table *ref_seeds, const char *ref,
                                  const nl_noise_window *win, unsigned long seed0, int nseeds);
/* One paragraph on such a table: the row of independent octaves farthest
 * from the law in standard errors, and its two factors. */
void nl_study_sd_law_text(nl_harness *r, const nl_table *law);

/* Lays panels out in a montage of `cols` columns (nl_image_montage), writes it as
 * FILE in the run's folder (nl_harness_write_image) and frees it: the figure step that
 * most experiments end a loop with. */
void nl_study_montage(nl_harness *r, const nl_image *const *panels, const char *const *labels,
                      int n, int cols, const char *title, const char *file);

/* Radially averaged power (nl_spectrum_radial, size / 2 bins, cycles per
 * pixel) of n square size x size rasters: column "freq" then one column per
 * raster named cols[i]; rows from bin `first` on. */
nl_table *nl_study_radial_table(const double *const *img, const char *const *cols, int n, int size,
                                int first);

/* Two-sample KS distance between the intensities of a and b, per channel
 * (per[0..2]; may be NULL) and their mean over R, G, B (the return): how
 * far a synthesis' histograms are from its exemplar's (sec. 5). */
double nl_study_ks_channels(const nl_image *a, const nl_image *b, double *per);

/* Mean of column `col` over the rows of a per-seed table whose text column
 * `key` reads `value` (0 rows: NaN); with pcol, *below (if not NULL) gets how
 * many of those rows have pcol < alpha: "rejected on k of n seeds". */
double nl_study_mean_where(const nl_table *t, const char *key, const char *value, const char *col,
                           const char *pcol, double alpha, int *below);

/* ---- A photograph against its synthesis (nl_study_example.c) ------------
 *
 * Lagae et al. 2010 sec. 5 on real exemplars: the `example` command
 * (tools/example.c) and L3's photographs judge a synthesis by these rows. */

/* The tables nl_study_example_compare appends to (caller frees). */
nl_table *nl_study_example_band_table(void);
nl_table *nl_study_example_summary_table(void);
/* Compares a synthesis with its photograph ex by luminance: one row per eq. 13
 * band of the photo (bands may be NULL), tagged with `replicate`,
 * to `bands` (power of photo and synthesis, ratio synth/photo, the band's
 * share of the photo's power, checked = share >= min_share) and one row to
 * `sum` (KS of the luminance, mean KS over R, G, B, tail mass beyond 2.5 sd
 * of photo and synthesis, speckle (nl_byexample_speckle), the checked band
 * whose ratio is farthest from 1, and pass = that ratio within
 * [1/max_ratio, max_ratio] and KS < max_ks). rep names the representation.
 * NL_EINVAL, nothing appended, when either image's size is one whose Fourier
 * transform nl_spectrum_check_size refuses (the message names ex by name,
 * syn by rep). */
nl_status nl_study_example_compare(const nl_image *ex, const nl_image *syn, const char *name,
                                   const char *rep, int replicate, double min_share, double max_ratio,
                                   double max_ks, nl_table *bands, nl_table *sum, nl_error *err);

#ifdef __cplusplus
}
#endif

#endif
