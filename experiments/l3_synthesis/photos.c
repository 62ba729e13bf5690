/* photos.c - L3 on photographs (Lagae et al. 2010 sec. 5 on real
 * exemplars): the folder of photographs, their analyses and syntheses over
 * replicates on the run's threads, and the tables of their per-band
 * comparison (nl_study_example_compare). See photos.h. */
#include "photos.h"
#include "structure.h"
#include "base/nl_parallel.h"
#include "study/nl_study_exemplars.h"
#include "stats/nl_stats.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

nl_status l3_photos_dir_parse(int *argc, char **argv, const char **dir, nl_error *err)
{
  return nl_study_dir_option(argc, argv, "--exemplars", "data/exemplars", dir, err);
}

/* The folder's PNGs by nl_study_pngs (one listing for L2 and L3), as names. */
static int list_photos(const char *dir, char (*names)[64], int max, nl_error *err)
{
  char **paths;
  int n;
  if (nl_study_pngs(dir, &paths, &n, err)) {
    nl_fail(err, NL_EIO, "--exemplars %s: cannot open the folder", dir);
    return -1;
  }
  int k = 0;
  for (int i = 0; i < n && k < max; i++) {
    const char *base = strrchr(paths[i], '/') ? strrchr(paths[i], '/') + 1 : paths[i];
    size_t len = strlen(base) - 4; /* ".png" */
    if (len >= 64) continue;
    memcpy(names[k], base, len);
    names[k++][len] = '\0';
  }
  nl_study_paths_free(paths);
  if (!k) nl_fail(err, NL_EIO, "--exemplars %s: no .png photographs", dir);
  return k;
}

int l3_photos_load(const char *dir, char (*names)[64], nl_image **photos, int max, nl_error *err)
{
  int n = list_photos(dir, names, max, err);
  for (int i = 0; i < n; i++) {
    char file[80];
    snprintf(file, sizeof file, "%s.png", names[i]);
    char *path = nl_path_join(dir, file);
    nl_status st = nl_image_read(path, &photos[i], err);
    free(path);
    if (st) {
      while (i--) nl_image_free(photos[i]);
      return -1;
    }
  }
  return n;
}

/* The top-left c x c pixels of im (c <= its size): the montage shows the
 * synthesis at the photo's pixel scale without the full 512^2. */
static nl_image *crop(const nl_image *im, int c)
{
  nl_image *o = nl_image_alloc(c, c, im->channels);
  for (int y = 0; y < c; y++)
    memcpy(o->data + (size_t)y * c * im->channels, im->data + (size_t)y * im->width * im->channels,
           (size_t)c * im->channels * sizeof(float));
  return o;
}

/* One row of photos_mean.tsv: photo i, representation rep over the K
 * replicates just appended to bands and sum (their last rows). */
static void mean_row(nl_table *mt, const nl_table *bands, const nl_table *sum,
                     const nl_image *photo, const char *name, const char *rep, int K,
                     double min_share, double max_ratio, double max_ks)
{
  /* per band: the photo's power and share, the synthesis' power (mean over replicates) */
  double pe[NL_WAVELET_MAX_BANDS] = { 0 };
  double share[NL_WAVELET_MAX_BANDS] = { 0 };
  double ps[NL_WAVELET_MAX_BANDS] = { 0 };
  int nb = 0;
  /* per replicate: KS and speckle; means of the gradient KS and the synthesis' tail */
  double ks[64];
  double sp[64];
  double kg = 0;
  double ts = 0;
  int passes = 0, fail_ks = 0, fail_band = 0;
  for (size_t i = bands->nrows; i-- > 0 && !strcmp(nl_table_text(bands, i, "exemplar"), name) &&
                                !strcmp(nl_table_text(bands, i, "representation"), rep);) {
    int k = (int)nl_table_value(bands, i, "band");
    pe[k] = nl_table_value(bands, i, "power_photo");
    share[k] = nl_table_value(bands, i, "share");
    ps[k] += nl_table_value(bands, i, "power_synth") / K;
    if (k + 1 > nb) nb = k + 1;
  }
  for (int s = 0; s < K && s < 64; s++) {
    size_t i = sum->nrows - (size_t)K + (size_t)s;
    ks[s] = nl_table_value(sum, i, "ks");
    sp[s] = nl_table_value(sum, i, "speckle");
    kg += nl_table_value(sum, i, "ks_grad") / K;
    ts += nl_table_value(sum, i, "tail_synth") / K;
    passes += nl_table_value(sum, i, "pass") > 0;
    fail_ks += !(ks[s] < max_ks);
    double wr = nl_table_value(sum, i, "worst_ratio");
    fail_band += !(wr <= max_ratio && wr >= 1 / max_ratio);
  }
  /* the photo's saturation (max - min) / max of RGB: largest (0 = a grey photo) and 99th percentile
   * (speckle's threshold, nl_byexample_speckle) */
  size_t np = (size_t)photo->width * photo->height;
  double *sv = nl_xmalloc(np * sizeof *sv);
  for (size_t i = 0; i < np; i++)
    sv[i] = nl_byexample_saturation(photo->data + i * photo->channels, photo->channels);
  nl_stats_sort(sv, np);
  double sat = sv[np - 1], sat99 = sv[(size_t)(0.99 * (double)(np - 1))];
  free(sv);
  int wk = -1;
  double w = 1;
  for (int k = 0; k < nb; k++) {
    double ratio = pe[k] > 0 ? ps[k] / pe[k] : 0;
    if (share[k] >= min_share && (wk < 0 || fabs(log(ratio)) > fabs(log(w)))) {
      w = ratio;
      wk = k;
    }
  }
  double km, ksd, sm, ssd;
  nl_stats_mean_sd(ks, K, NL_STATS_SUMMED, &km, &ksd);
  nl_stats_mean_sd(sp, K, NL_STATS_SUMMED, &sm, &ssd);
  size_t last = sum->nrows - 1;
  /* the structure columns (coh_*) are set by structure_cols */
  nl_table_append(mt, "ssdddddddiiiiiiidddddddi", name, rep, km, ksd,
                  nl_table_value(sum, last, "tail_photo"), ts, sm, ssd, w, wk, nb - 1,
                  w <= max_ratio && w >= 1 / max_ratio, passes, K, fail_ks, fail_band, sat, sat99,
                  kg, 0.0, 0.0, 0.0, 0.0, 0);
}

/* The structure columns of mt's last row: the photo's coherence, the K
 * syntheses' (mean, sd), their ratio photo / synthesis and how many
 * replicates keep it within x max_ratio, the tolerance of the band criterion. */
static void structure_cols(nl_table *mt, const l3_structure *photo, const double *coh, int K,
                           double max_ratio)
{
  double m, sd;
  int ok = 0;
  nl_stats_mean_sd(coh, (size_t)K, NL_STATS_SUMMED, &m, &sd);
  for (int s = 0; s < K; s++) {
    double ratio = photo->coherence / coh[s];
    ok += ratio <= max_ratio && ratio >= 1 / max_ratio;
  }
  size_t row = mt->nrows - 1;
  nl_table_set(mt, row, "coh_photo", photo->coherence);
  nl_table_set(mt, row, "coh_synth_mean", m);
  nl_table_set(mt, row, "coh_synth_sd", sd);
  nl_table_set(mt, row, "coh_ratio", photo->coherence / m);
  nl_table_set(mt, row, "structure_passes", ok);
}

/* The rows of src appended to dst (same columns), in order. */
static void append_rows(nl_table *dst, const nl_table *src)
{
  for (size_t q = 0; q < src->nrows; q++) {
    size_t row = nl_table_append_empty(dst);
    for (size_t c = 0; c < src->ncols; c++) {
      const char *tx = src->text ? src->text[q * src->ncols + c] : NULL;
      if (tx)
        nl_table_set_text(dst, row, dst->names[c], tx);
      else
        nl_table_set(dst, row, dst->names[c], src->num[q * src->ncols + c]);
    }
  }
}

enum { NREP = 3, NP = NREP + 1 };

/* The photographs' work on the run's threads (nl_parallel.h): first one
 * analysis per (photo, representation) item (it does not depend on the seed),
 * then one synthesis per (photo, representation, replicate) item into its own
 * row tables and montage slot; the rows go to the shared tables in item order
 * afterwards, so the tables are the same for any thread count. */
typedef struct {
  nl_image **photos;
  char (*names)[64];
  const nl_byexample_hist_kind *kinds;
  const int *cal;
  int K, size;
  unsigned long seed;
  double min_share, max_ratio, max_ks;
  nl_byexample_params *par; /* per (photo, rep) */
  nl_table **bands, **sum;  /* per (photo, rep, replicate) */
  nl_image **crops;         /* per (photo, rep): the first replicate's crop */
  double *coh;              /* per item: the synthesis' coherence (structure.h) */
  nl_status *st, *sst;      /* per (photo, rep): analysis; per item: synthesis */
  nl_error *err, *serr;
} photos_job;

static void analyse_item(void *ctx, size_t q, int thread)
{
  (void)thread;
  photos_job *j = ctx;
  int i = (int)q / NREP, h = (int)q % NREP;
  nl_byexample_options o = { 1, 1, 0, 0, j->kinds[h], j->cal[h] };
  j->st[q] = nl_byexample_analyse(j->photos[i], &o, &j->par[q], &j->err[q]);
}

static void photo_item(void *ctx, size_t q, int thread)
{
  (void)thread;
  photos_job *j = ctx;
  size_t ih = q / (size_t)j->K;
  int i = (int)ih / NREP, h = (int)ih % NREP, s = (int)(q % (size_t)j->K);
  if (j->st[ih]) return; /* its analysis failed: reported in item order */
  nl_image *syn;
  if ((j->sst[q] = nl_byexample_synthesize(&j->par[ih], j->size, j->size,
                                           nl_seed_replicate(j->seed, s), NULL, &syn, &j->serr[q])))
    return;
  j->bands[q] = nl_study_example_band_table();
  j->sum[q] = nl_study_example_summary_table();
  if ((j->sst[q] = nl_study_example_compare(
           j->photos[i], syn, j->names[i],
           j->cal[h] > 0 ? "calibrated" : nl_byexample_hist_name(j->kinds[h]), s, j->min_share,
           j->max_ratio, j->max_ks, j->bands[q], j->sum[q], &j->serr[q]))) {
    nl_image_free(syn);
    return;
  }
  /* the montage shows the first replicate, its top-left 256^2 at most */
  if (!s) j->crops[ih] = crop(syn, j->size < 256 ? j->size : 256);
  /* coherence at the photo's size (its top-left crop), so that photo and synthesis are read over
   * as many pixels */
  int c = j->photos[i]->width < j->photos[i]->height ? j->photos[i]->width : j->photos[i]->height;
  nl_image *sc = crop(syn, c < j->size ? c : j->size);
  l3_structure st;
  l3_structure_measure(sc, &st);
  j->coh[q] = st.coherence;
  nl_image_free(sc);
  nl_image_free(syn);
}

nl_table *l3_photos(nl_harness *r, char (*names)[64], nl_image **photos, int np, int size, int K,
                    unsigned long seed, double min_share, double max_ratio, double max_ks)
{
  nl_table *bands = nl_study_example_band_table();
  nl_table *sum = nl_study_example_summary_table();
  static const char *mcols[] = { "exemplar",     "representation", "ks_mean",
                                 "ks_sd",        "tail_photo",     "tail_synth",
                                 "speckle_mean", "speckle_sd",     "worst_ratio_of_means",
                                 "worst_band",   "coarsest_band",  "bands_ok",
                                 "passes",       "replicates",     "fail_ks",
                                 "fail_band",    "photo_sat_max",  "photo_sat_p99",
                                 "ks_grad_mean", "coh_photo",      "coh_synth_mean",
                                 "coh_synth_sd", "coh_ratio",      "structure_passes" };
  nl_table *mt = nl_table_alloc(24, mcols);
  /* gauss33 and paper10 as the paper synthesises; calibrated = the `example` command's default
   * (gauss33 with the synthesis-time band calibration, nl_byexample.h) */
  const nl_byexample_hist_kind kinds[NREP] = { NL_HIST_GAUSS, NL_HIST_PAPER, NL_HIST_GAUSS };
  const int cal[NREP] = { 0, 0, NL_BYEXAMPLE_CALIBRATE };
  const nl_image **panels = nl_xmalloc((size_t)(NP * np + 1) * sizeof *panels);
  char(*labels)[64] = nl_xmalloc((size_t)(NP * np + 1) * sizeof *labels);
  const char **lab = nl_xmalloc((size_t)(NP * np + 1) * sizeof *lab);
  size_t nih = (size_t)np * NREP; /* (photo, representation) items */
  size_t nitem = nih * (size_t)K; /* (photo, representation, replicate) items */
  photos_job j = { .photos = photos,
                   .names = names,
                   .kinds = kinds,
                   .cal = cal,
                   .K = K,
                   .size = size,
                   .seed = seed,
                   .min_share = min_share,
                   .max_ratio = max_ratio,
                   .max_ks = max_ks };
  j.par = nl_xmalloc(nih * sizeof *j.par);
  j.bands = nl_xcalloc(nitem, sizeof *j.bands);
  j.sum = nl_xcalloc(nitem, sizeof *j.sum);
  j.crops = nl_xcalloc(nih, sizeof *j.crops);
  j.coh = nl_xcalloc(nitem, sizeof *j.coh);
  j.st = nl_xcalloc(nih, sizeof *j.st);
  j.sst = nl_xcalloc(nitem, sizeof *j.sst);
  j.err = nl_xmalloc(nih * sizeof *j.err);
  j.serr = nl_xmalloc(nitem * sizeof *j.serr);
  nl_parallel_for(nih, nl_harness_threads(r), analyse_item, &j);
  nl_parallel_for(nitem, nl_harness_threads(r), photo_item, &j);
  for (int i = 0; i < np; i++) {
    l3_structure photo_st;
    l3_structure_measure(photos[i], &photo_st);
    panels[NP * i] = photos[i];
    snprintf(labels[NP * i], 64, "%s %dx%d", names[i], photos[i]->width, photos[i]->height);
    for (int h = 0; h < NREP; h++) {
      size_t ih = (size_t)i * NREP + (size_t)h;
      const char *rn = cal[h] ? "calibrated" : nl_byexample_hist_name(kinds[h]);
      if (j.st[ih]) nl_harness_die(r, 1, "%s: %s", names[i], j.err[ih].msg);
      for (int s = 0; s < K; s++) {
        size_t q = ih * (size_t)K + (size_t)s;
        if (j.sst[q]) nl_harness_die(r, 1, "%s: %s", names[i], j.serr[q].msg);
        append_rows(bands, j.bands[q]);
        append_rows(sum, j.sum[q]);
        nl_table_free(j.bands[q]);
        nl_table_free(j.sum[q]);
      }
      panels[NP * i + 1 + h] = j.crops[ih];
      snprintf(labels[NP * i + 1 + h], 64, "%s", rn); /* the crop's size is in the title */
      mean_row(mt, bands, sum, photos[i], names[i], rn, K, min_share, max_ratio, max_ks);
      structure_cols(mt, &photo_st, j.coh + ih * (size_t)K, K, max_ratio);
    }
    nl_harness_progress(r, (i + 1.0) / np, names[i]);
  }
  free(j.par);
  free(j.bands);
  free(j.sum);
  free(j.crops);
  free(j.coh);
  free(j.st);
  free(j.sst);
  free(j.err);
  free(j.serr);
  for (int i = 0; i < NP * np; i++) lab[i] = labels[i];
  nl_harness_write_table(r, bands, "photos.tsv");
  nl_harness_write_table(r, sum, "photos_summary.tsv");
  nl_harness_write_table(r, mt, "photos_mean.tsv");
  char title[96];
  snprintf(title, sizeof title, "photographs | synthesis %d x %d (seed %lu), top-left %d x %d",
           size, size, seed, size < 256 ? size : 256, size < 256 ? size : 256);
  nl_study_montage(r, (const nl_image *const *)panels, lab, NP * np, NP, title,
                   "photos_montage.png");
  for (int i = 0; i < np; i++)
    for (int h = 0; h < NREP; h++) nl_image_free((nl_image *)panels[NP * i + 1 + h]);
  free(panels);
  free(labels);
  free(lab);
  nl_table_free(bands);
  nl_table_free(sum);
  return mt;
}
