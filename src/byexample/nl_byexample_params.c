/* Parameter files and morphing for nl_byexample (see nl_byexample.h).
 *
 * File format: one "key value..." line per field, '#' comments:
 *   noiselab-example 2
 *   channels 3            bands 9 (one per line)
 *   tile 256
 *   histogram 1
 *   hist_kind 1           0: the paper's 10 quantiles at p = j/9;
 *                         1: 33 quantiles at p = Phi(-4 + j/4) (nl_byexample.h)
 *   sigma2 0.28...
 *   mean m0 m1 m2
 *   matrix (channels^2 values, row-major)
 *   hist0 .. hist{channels-1}        10 or 33 values each (hist_kind), non-decreasing
 *   weights0 .. weights{channels-1}  `bands` values each, >= 0
 * Version 3 (written only when calibrate > 0, nl_byexample.h) adds
 *   calibrate N                      iterations, 1..100
 *   target0 .. target{channels-1}    `bands` eq. 13 band powers each, >= 0
 *   corr01 corr02 corr12             (3 channels) `bands` band correlations each, in [-1, 1]
 * Version 1 files (no hist_kind line) hold the paper's 10 quantiles and
 * still load; version 2 files must say hist_kind; uncalibrated parameters
 * are still written as version 2, so older readers read them.
 * Numbers use the shortest form that reads back to the same bits, so
 * save -> load -> synthesize equals synthesize.
 */
#include "byexample/nl_byexample.h"
#include "table/nl_table.h"

#include <gsl/gsl_cdf.h>

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The histogram's knots and the parameter count belong to the file format
 * (nl_byexample.h); kept here so that a reader of parameter files (the
 * fuzz target fuzz_params) links without the synthesizer. */
const char *nl_byexample_hist_name(nl_byexample_hist_kind kind)
{
  return kind == NL_HIST_GAUSS ? "gauss33" : kind == NL_HIST_PAPER ? "paper10" : "unknown";
}

int nl_byexample_hist_knots(nl_byexample_hist_kind kind, double *x, double *p)
{
  if (kind == NL_HIST_PAPER) {
    for (int j = 0; j < NL_BYEXAMPLE_HIST; j++) {
      if (x) x[j] = (double)j / (NL_BYEXAMPLE_HIST - 1);
      if (p) p[j] = (double)j / (NL_BYEXAMPLE_HIST - 1);
    }
    return NL_BYEXAMPLE_HIST;
  }
  if (kind != NL_HIST_GAUSS) return 0;
  for (int j = 0; j < NL_BYEXAMPLE_HIST_MAX; j++) {
    double z = -4.0 + 0.25 * j;
    if (x) x[j] = z;
    if (p) p[j] = gsl_cdf_ugaussian_P(z);
  }
  return NL_BYEXAMPLE_HIST_MAX;
}

int nl_byexample_param_count(const nl_byexample_params *p)
{
  return p->channels * p->channels + p->channels * (p->nhist + p->nbands);
}

static void put_values(FILE *fp, const char *key, const double *v, int n)
{
  char buf[32];
  fputs(key, fp);
  for (int i = 0; i < n; i++) { nl_table_format_double(buf, v[i]); fprintf(fp, " %s", buf); }
  fputc('\n', fp);
}

/* The first value of p that is NaN or infinite, named, or NULL. */
static const char *non_finite(const nl_byexample_params *p, char *buf, size_t len)
{
  int C = p->channels;
  if (!isfinite(p->sigma2)) { snprintf(buf, len, "sigma2"); return buf; }
  for (int c = 0; c < C; c++) {
    if (!isfinite(p->mean[c])) { snprintf(buf, len, "mean %d", c + 1); return buf; }
    for (int k = 0; k < C; k++)
      if (!isfinite(p->matrix[c][k])) { snprintf(buf, len, "matrix %d,%d", c + 1, k + 1); return buf; }
    for (int k = 0; k < p->nhist && k < NL_BYEXAMPLE_HIST_MAX; k++)
      if (!isfinite(p->hist[c][k])) { snprintf(buf, len, "hist%d %d", c, k + 1); return buf; }
    for (int k = 0; k < p->nbands && k < NL_WAVELET_MAX_BANDS; k++)
      if (!isfinite(p->w[c][k]) || !isfinite(p->target[c][k]) || !isfinite(p->corr[c][k])) { snprintf(buf, len, "weights%d %d", c, k + 1); return buf; }
  }
  return NULL;
}

nl_status nl_byexample_params_save(const nl_byexample_params *p, const char *path, nl_error *err)
{
  /* A file the loader would reject is not written (nothing written). */
  char what[64];
  if (p->channels < 1 || p->channels > 3)
    return nl_fail(err, NL_EINVAL, "%s: %d channels; parameters have 1 or 3", path, p->channels);
  if (p->nhist != nl_byexample_hist_knots(p->hist_kind, NULL, NULL) || !p->nhist)
    return nl_fail(err, NL_EINVAL, "%s: histogram representation %d with %d values; nothing written", path,
                   (int)p->hist_kind, p->nhist);
  if (non_finite(p, what, sizeof what))
    return nl_fail(err, NL_EINVAL, "%s: parameter %s is not finite; nothing written", path, what);
  nl_atomic_file af;
  nl_status st = nl_atomic_open(&af, path, err);
  if (st) return st;
  int C = p->channels;
  fprintf(af.fp, "# procedural texture by example (Lagae et al. 2010), %d parameters in the paper's count\n",
          nl_byexample_param_count(p));
  fprintf(af.fp, "# hist_kind %d = %s: %s\n", (int)p->hist_kind, nl_byexample_hist_name(p->hist_kind),
          p->hist_kind == NL_HIST_PAPER ? "the paper's 10 quantiles at p = j/9, spline in p"
                                        : "33 quantiles at p = Phi(z), z = -4 + j/4, spline in z");
  fprintf(af.fp, "noiselab-example %d\nchannels %d\nbands %d\ntile %d\nhistogram %d\nhist_kind %d\n",
          p->calibrate > 0 ? 3 : 2, C, p->nbands, p->tile, p->histogram, (int)p->hist_kind);
  if (p->calibrate > 0) fprintf(af.fp, "calibrate %d\n", p->calibrate);
  put_values(af.fp, "sigma2", &p->sigma2, 1);
  put_values(af.fp, "mean", p->mean, C);
  double m[9];
  for (int r = 0; r < C; r++)
    for (int c = 0; c < C; c++) m[r * C + c] = p->matrix[r][c];
  put_values(af.fp, "matrix", m, C * C);
  char key[32];
  for (int c = 0; c < C; c++) {
    snprintf(key, sizeof key, "hist%d", c);
    put_values(af.fp, key, p->hist[c], p->nhist);
  }
  for (int c = 0; c < C; c++) {
    snprintf(key, sizeof key, "weights%d", c);
    put_values(af.fp, key, p->w[c], p->nbands);
  }
  for (int c = 0; c < C && p->calibrate > 0; c++) {
    snprintf(key, sizeof key, "target%d", c);
    put_values(af.fp, key, p->target[c], p->nbands);
  }
  static const char *ckey[3] = {"corr01", "corr02", "corr12"};
  for (int q = 0; q < 3 && C == 3 && p->calibrate > 0; q++) put_values(af.fp, ckey[q], p->corr[q], p->nbands);
  return nl_atomic_commit(&af, err);
}

/* ---- loading ------------------------------------------------------------- */

#define MAX_FIELDS 32
#define MAX_VALUES 64
typedef struct {
  char key[32];
  int line, n;
  double v[MAX_VALUES];
} field;

/* Splits one line into a key and numbers; NL_EFORMAT names the bad token. */
/* s with non-printable bytes as '?', cut with "..." to fit buf: messages
 * stay one readable line whatever a file holds. */
static const char *printable(const char *s, char *buf, size_t len)
{
  size_t k = 0;
  for (; s[k] && k + 4 < len; k++) buf[k] = isprint((unsigned char)s[k]) ? s[k] : '?';
  if (s[k]) { memcpy(buf + k, "...", 3); k += 3; }
  buf[k] = '\0';
  return buf;
}

static nl_status parse_line(const char *path, int lineno, char *s, field *f, nl_error *err)
{
  char *tok = strtok(s, " \t\r\n");
  snprintf(f->key, sizeof f->key, "%s", tok);
  f->line = lineno;
  f->n = 0;
  while ((tok = strtok(NULL, " \t\r\n"))) {
    if (f->n == MAX_VALUES)
      return nl_fail(err, NL_EFORMAT, "%s:%d: too many values for '%s'", path, lineno, f->key);
    char *end;
    errno = 0;
    double v = strtod(tok, &end);
    if (*end || end == tok || errno == ERANGE || !isfinite(v)) {
      char t1[48], t2[48];
      return nl_fail(err, NL_EFORMAT, "%s:%d: '%s' of '%s' is not a finite number", path, lineno,
                     printable(tok, t1, sizeof t1), printable(f->key, t2, sizeof t2));
    }
    f->v[f->n++] = v;
  }
  return NL_OK;
}

static nl_status read_fields(const char *path, field *f, int *nf, nl_error *err)
{
  FILE *fp = fopen(path, "r");
  if (!fp) return nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
  const char *image = nl_file_image_kind(fp);
  if (image) {
    fclose(fp);
    return nl_fail(err, NL_EFORMAT, "%s: a %s image, not a parameter file (example analyse makes "
                   "one from an image)", path, image);
  }
  char buf[4096];
  int lineno = 0, c = 0;
  long total = 0;
  nl_status st = NL_OK;
  *nf = 0;
  /* Lines are read whole and bounded: a longer line, a NUL byte or a file
   * beyond 1 MiB (/dev/zero, an endless stream) is an error, not a line
   * silently cut in two or a read that never ends. */
  while (!st && c != EOF) {
    size_t n = 0;
    int nul = 0;
    while ((c = getc(fp)) != EOF && c != '\n') {
      if (++total > (1L << 20)) break;
      if (c == '\0') { nul = 1; break; }
      if (n + 1 >= sizeof buf) break;
      buf[n++] = (char)c;
    }
    if (c == EOF && n == 0) break;
    lineno++;
    if (total > (1L << 20)) { st = nl_fail(err, NL_EFORMAT, "%s: longer than 1 MiB; not a parameter file", path); break; }
    if (nul) { st = nl_fail(err, NL_EFORMAT, "%s:%d: NUL byte", path, lineno); break; }
    if (c != EOF && c != '\n') { st = nl_fail(err, NL_EFORMAT, "%s:%d: line longer than %zu bytes", path, lineno, sizeof buf - 1); break; }
    buf[n] = '\0';
    char *s = buf;
    while (isspace((unsigned char)*s)) s++;
    if (!*s || *s == '#') continue;
    if (*nf == MAX_FIELDS) st = nl_fail(err, NL_EFORMAT, "%s:%d: too many lines", path, lineno);
    else st = parse_line(path, lineno, s, &f[(*nf)++], err);
  }
  if (!st && ferror(fp)) st = nl_fail(err, NL_EIO, "%s: read error: %s", path, strerror(errno));
  fclose(fp);
  return st;
}

/* The values of `key`, which must hold exactly n numbers. */
static nl_status need(const char *path, const field *f, int nf, const char *key, int n,
                      const double **v, nl_error *err)
{
  for (int i = 0; i < nf; i++)
    if (!strcmp(f[i].key, key)) {
      if (f[i].n != n)
        return nl_fail(err, NL_EFORMAT, "%s:%d: '%s' needs %d value%s, has %d", path, f[i].line,
                       key, n, n == 1 ? "" : "s", f[i].n);
      *v = f[i].v;
      return NL_OK;
    }
  return nl_fail(err, NL_EFORMAT, "%s: missing field '%s'", path, key);
}

static nl_status need_int(const char *path, const field *f, int nf, const char *key, int lo,
                          int hi, int *out, nl_error *err)
{
  const double *v = NULL;
  nl_status st = need(path, f, nf, key, 1, &v, err);
  if (st) return st;
  if (v[0] != floor(v[0]) || v[0] < lo || v[0] > hi)
    return nl_fail(err, NL_EFORMAT, "%s: '%s' must be an integer in %d..%d, is %g", path, key,
                   lo, hi, v[0]);
  *out = (int)v[0];
  return NL_OK;
}

static nl_status check_arrays(const char *path, const nl_byexample_params *p, nl_error *err)
{
  if (!(p->sigma2 > 0)) return nl_fail(err, NL_EFORMAT, "%s: 'sigma2' must be positive", path);
  if (p->tile % 2) return nl_fail(err, NL_EFORMAT, "%s: 'tile' must be even", path);
  if (p->channels == 2) return nl_fail(err, NL_EFORMAT, "%s: 'channels' must be 1 or 3", path);
  for (int c = 0; c < p->channels; c++) {
    for (int j = 1; j < p->nhist; j++)
      if (p->hist[c][j] < p->hist[c][j - 1])
        return nl_fail(err, NL_EFORMAT, "%s: 'hist%d' is not non-decreasing", path, c);
    for (int k = 0; k < p->nbands; k++)
      if (p->w[c][k] < 0) return nl_fail(err, NL_EFORMAT, "%s: 'weights%d' has a negative weight", path, c);
    for (int k = 0; k < p->nbands; k++)
      if (!(p->target[c][k] >= 0)) return nl_fail(err, NL_EFORMAT, "%s: 'target%d' has a negative power", path, c);
  }
  return NL_OK;
}

nl_status nl_byexample_params_load(const char *path, nl_byexample_params *p, nl_error *err)
{
  field f[MAX_FIELDS];
  int nf = 0, version;
  const double *v = NULL;
  nl_status st = read_fields(path, f, &nf, err);
  if (st) return st;
  memset(p, 0, sizeof *p);
  if ((st = need_int(path, f, nf, "noiselab-example", 1, 3, &version, err)) ||
      (st = need_int(path, f, nf, "channels", 1, 3, &p->channels, err)) ||
      (st = need_int(path, f, nf, "bands", 1, NL_WAVELET_MAX_BANDS, &p->nbands, err)) ||
      (st = need_int(path, f, nf, "tile", 8, 8192, &p->tile, err)) ||
      (st = need_int(path, f, nf, "histogram", 0, 1, &p->histogram, err)) ||
      (st = need(path, f, nf, "sigma2", 1, &v, err)))
    return st;
  p->sigma2 = v[0];
  int hk = NL_HIST_PAPER;   /* version 1: the paper's reading, the only one then */
  if (version >= 2 && (st = need_int(path, f, nf, "hist_kind", 0, 1, &hk, err))) return st;
  p->hist_kind = (nl_byexample_hist_kind)hk;
  if (version >= 3 && (st = need_int(path, f, nf, "calibrate", 1, 100, &p->calibrate, err))) return st;
  p->nhist = nl_byexample_hist_knots(p->hist_kind, NULL, NULL);
  int C = p->channels;
  if (C != 2) {
    if ((st = need(path, f, nf, "mean", C, &v, err))) return st;
    memcpy(p->mean, v, (size_t)C * sizeof *v);
    if ((st = need(path, f, nf, "matrix", C * C, &v, err))) return st;
    for (int r = 0; r < C; r++)
      for (int c = 0; c < C; c++) p->matrix[r][c] = v[r * C + c];
    char key[32];
    for (int c = 0; c < C; c++) {
      snprintf(key, sizeof key, "hist%d", c);
      if ((st = need(path, f, nf, key, p->nhist, &v, err))) return st;
      memcpy(p->hist[c], v, (size_t)p->nhist * sizeof *v);
      snprintf(key, sizeof key, "weights%d", c);
      if ((st = need(path, f, nf, key, p->nbands, &v, err))) return st;
      memcpy(p->w[c], v, (size_t)p->nbands * sizeof *v);
      if (!p->calibrate) continue;
      snprintf(key, sizeof key, "target%d", c);
      if ((st = need(path, f, nf, key, p->nbands, &v, err))) return st;
      memcpy(p->target[c], v, (size_t)p->nbands * sizeof *v);
    }
    static const char *ckey[3] = {"corr01", "corr02", "corr12"};
    for (int q = 0; q < 3 && C == 3 && p->calibrate; q++) {
      if ((st = need(path, f, nf, ckey[q], p->nbands, &v, err))) return st;
      for (int k = 0; k < p->nbands; k++)
        if (!(fabs(v[k]) <= 1)) return nl_fail(err, NL_EFORMAT, "%s: '%s' has a value outside [-1, 1]", path, ckey[q]);
      memcpy(p->corr[q], v, (size_t)p->nbands * sizeof *v);
    }
  }
  return check_arrays(path, p, err);
}

/* ---- morphing (Fig. 12) ---------------------------------------------------- */

/* Rotation matrix -> unit quaternion (w, x, y, z), Shepperd's branches. */
static void mat_to_quat(const double m[3][3], double q[4])
{
  double tr = m[0][0] + m[1][1] + m[2][2], s;
  if (tr > 0) {
    s = 2 * sqrt(tr + 1);
    q[0] = s / 4; q[1] = (m[2][1] - m[1][2]) / s; q[2] = (m[0][2] - m[2][0]) / s; q[3] = (m[1][0] - m[0][1]) / s;
  } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    s = 2 * sqrt(1 + m[0][0] - m[1][1] - m[2][2]);
    q[0] = (m[2][1] - m[1][2]) / s; q[1] = s / 4; q[2] = (m[0][1] + m[1][0]) / s; q[3] = (m[0][2] + m[2][0]) / s;
  } else if (m[1][1] > m[2][2]) {
    s = 2 * sqrt(1 + m[1][1] - m[0][0] - m[2][2]);
    q[0] = (m[0][2] - m[2][0]) / s; q[1] = (m[0][1] + m[1][0]) / s; q[2] = s / 4; q[3] = (m[1][2] + m[2][1]) / s;
  } else {
    s = 2 * sqrt(1 + m[2][2] - m[0][0] - m[1][1]);
    q[0] = (m[1][0] - m[0][1]) / s; q[1] = (m[0][2] + m[2][0]) / s; q[2] = (m[1][2] + m[2][1]) / s; q[3] = s / 4;
  }
}

static void quat_to_mat(const double q[4], double m[3][3])
{
  double w = q[0], x = q[1], y = q[2], z = q[3];
  m[0][0] = 1 - 2 * (y * y + z * z); m[0][1] = 2 * (x * y - z * w); m[0][2] = 2 * (x * z + y * w);
  m[1][0] = 2 * (x * y + z * w); m[1][1] = 1 - 2 * (x * x + z * z); m[1][2] = 2 * (y * z - x * w);
  m[2][0] = 2 * (x * z - y * w); m[2][1] = 2 * (y * z + x * w); m[2][2] = 1 - 2 * (x * x + y * y);
}

/* Spherical linear interpolation along the shorter arc (q and -q are the
 * same rotation); nearly equal quaternions fall back to normalised lerp. */
static void slerp(const double a[4], const double b0[4], double t, double q[4])
{
  double b[4], dot = 0;
  for (int i = 0; i < 4; i++) dot += a[i] * b0[i];
  for (int i = 0; i < 4; i++) b[i] = dot < 0 ? -b0[i] : b0[i];
  dot = fabs(dot);
  double wa = 1 - t, wb = t;
  if (dot < 0.9995) {
    double th = acos(dot), s = sin(th);
    wa = sin((1 - t) * th) / s;
    wb = sin(t * th) / s;
  }
  double norm = 0;
  for (int i = 0; i < 4; i++) { q[i] = wa * a[i] + wb * b[i]; norm += q[i] * q[i]; }
  for (int i = 0; i < 4; i++) q[i] /= sqrt(norm);
}

nl_status nl_byexample_morph_check(double t, nl_error *err)
{
  if (!isfinite(t)) return nl_fail(err, NL_EINVAL, "--t: %g is not a finite number", t);
  if (!(t >= 0 && t <= 1)) return nl_fail(err, NL_EINVAL, "--t: %g is outside [0, 1]", t);
  return NL_OK;
}

nl_status nl_byexample_morph(const nl_byexample_params *a, const nl_byexample_params *b, double t,
                             nl_byexample_params *out, nl_error *err)
{
  if (nl_byexample_morph_check(t, err)) return NL_EINVAL;
  if (a->channels != b->channels)
    return nl_fail(err, NL_EINVAL, "cannot morph %d channels into %d", a->channels, b->channels);
  if (a->histogram != b->histogram)
    return nl_fail(err, NL_EINVAL, "cannot morph with and without histogram matching");
  if ((a->calibrate > 0) != (b->calibrate > 0))
    return nl_fail(err, NL_EINVAL, "cannot morph calibrated into uncalibrated parameters");
  if (a->hist_kind != b->hist_kind)
    return nl_fail(err, NL_EINVAL, "cannot morph histogram representation %s into %s",
                   nl_byexample_hist_name(a->hist_kind), nl_byexample_hist_name(b->hist_kind));
  nl_byexample_params r = *a;
  r.nbands = a->nbands < b->nbands ? a->nbands : b->nbands;
  for (int c = 0; c < 3; c++)
    for (int k = r.nbands; k < NL_WAVELET_MAX_BANDS; k++)
      r.w[c][k] = r.target[c][k] = r.corr[c][k] = 0;
  r.sigma2 = (1 - t) * a->sigma2 + t * b->sigma2;
  for (int c = 0; c < 3; c++) {
    r.mean[c] = (1 - t) * a->mean[c] + t * b->mean[c];
    for (int j = 0; j < a->nhist; j++) r.hist[c][j] = (1 - t) * a->hist[c][j] + t * b->hist[c][j];
    for (int k = 0; k < r.nbands; k++) r.w[c][k] = (1 - t) * a->w[c][k] + t * b->w[c][k];
    /* targets are powers: interpolated as their square roots, like the weights */
    for (int k = 0; k < r.nbands; k++) {
      double s = (1 - t) * sqrt(a->target[c][k]) + t * sqrt(b->target[c][k]);
      r.target[c][k] = s * s;
      r.corr[c][k] = (1 - t) * a->corr[c][k] + t * b->corr[c][k];   /* a convex mix of definite matrices is definite */
    }
  }
  if (a->channels == 3) {
    double qa[4], qb[4], q[4];
    mat_to_quat(a->matrix, qa);
    mat_to_quat(b->matrix, qb);
    slerp(qa, qb, t, q);
    quat_to_mat(q, r.matrix);
  }
  *out = r;
  return NL_OK;
}
