/* oracle_chengb - C2, C8 and C9's panels against their captions.
 *
 *   oracle_chengb c2|c8|c9 OUTDIR
 *
 * Each panel's caption names a controlled value of the run's first seed
 * under one setting ("KS term", "fixed, raw 0..1", "c xy str", ...). This
 * recomputes each panel by another path than the experiment: the first
 * seed's optimisation again through the library's one-run call
 * (nl_cheng_run / nl_cheng3_run at nl_seed_replicate(seed, 0), the seed
 * rule of nl_study_cheng_runs and c8_seeds) under the setting the caption
 * names, read from the manifest; then the value at every pixel centre
 * point by point through the noise's point call (nl_noise_grad2_eval_general,
 * nl_noise_grad3_eval), the octaves summed and the control value formed here
 * (nl_cheng.h: c = (1 + V) / 2, (1 + sin(pi V)) / 2, |V|, s sum |Noise_l| /
 * a_l with V = s F_sum, s = 1 / (B sum 1/a_l)), mapped as the caption says
 * (raw: 0..1; "stretched": the value's own 1st..99th percentile) and compared
 * with the PNG's panel to 8 bits. The pattern panels are the pattern's cells
 * (red = D, grey 0.5 without control) nearest-neighbour upscaled. A panel
 * showing another objective's, another seed's or another setting's table
 * fails (grey levels and correlation), and panels whose captions differ
 * must not show one picture. The 2D domain is the unit square at the
 * config's origin, [o, o + 1]^2 (nl_cheng.h, READINGS), sampled at pixel
 * centres as nl_cheng_value_grid's raster; the 3D slices' cube is at the
 * noise's origin. Exit 0 when every panel
 * matches, 1 with one line per mismatch, 2 on a usage or input error.
 */
#include "oracle.h"

#include "base/nl_base.h"
#include "cheng/nl_cheng.h"
#include "cheng/nl_cheng3.h"
#include "noise/nl_noise.h"
#include "study/nl_study_cheng.h"
#include "table/nl_table.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the run's setting --------------------------------------------------- */

typedef struct {
  const nl_table *man;
  const char *dir;
  unsigned long seed;   /* the first seed's run seed */
  char patterns[1024];  /* the run's pattern folder, found from OUTDIR */
  int bad;
} run;

/* The 2D setting of nl_study_cheng_open from the manifest's parameters. */
static nl_cheng_config config_2d(const run *R)
{
  nl_cheng_config c = nl_cheng_config_default();
  c.w1 = oracle_param(R->man, "w1", c.w1);
  c.w2 = oracle_param(R->man, "w2", c.w2);
  c.f1 = oracle_param(R->man, "f1", c.f1);
  c.a1 = oracle_param(R->man, "a1", c.a1);
  c.octaves = (int)oracle_param(R->man, "octaves", c.octaves);
  c.literal = (int)oracle_param(R->man, "literal", 0);
  c.sched.n_temps = (int)oracle_param(R->man, "temps", c.sched.n_temps);
  c.sched.moves_per_var = oracle_param(R->man, "moves_per_var", c.sched.moves_per_var);
  return c;
}

/* The manifest's pattern folder as given, else relative to the results
 * folder's repository (results/NAME, results/quick/NAME). */
static int find_patterns(run *R)
{
  const char *p = oracle_manifest_value(R->man, "patterns");
  if (!p) p = "data/patterns";
  const char *pre[3] = { "", "/../../", "/../../../" };
  for (int i = 0; i < 3; i++) {
    if (i == 0) snprintf(R->patterns, sizeof R->patterns, "%s", p);
    else if (p[0] != '/') snprintf(R->patterns, sizeof R->patterns, "%s%s%s", R->dir, pre[i], p);
    else continue;
    char f[1100];
    snprintf(f, sizeof f, "%s/flower.png", R->patterns);
    FILE *fp = fopen(f, "rb");
    if (fp) { fclose(fp); return 0; }
  }
  fprintf(stderr, "oracle_chengb: no pattern folder %s\n", p);
  return 1;
}

static nl_cheng_pattern *pattern_2d(const run *R, const char *name, int grid)
{
  char f[1100];
  snprintf(f, sizeof f, "%s/%s.png", R->patterns, name);
  nl_image *im;
  nl_cheng_pattern *p = NULL;
  nl_error err;
  if (nl_image_read(f, &im, &err) || nl_study_cheng_pattern_from_image(im, grid, &p, &err)) {
    fprintf(stderr, "oracle_chengb: %s: %s\n", f, err.msg);
    exit(2);
  }
  nl_image_free(im);
  return p;
}

/* ---- what a caption says, by another path -------------------------------- */

/* Pixel centre o + (i + 1/2) / n of the texture's domain. */
static double domain_2d(const nl_cheng_config *c, int i, int n) { return c->origin + (i + 0.5) / n; }

/* c of config c (gains u, NULL: the config's) at the n x n pixel centres. */
static void value_2d(const nl_noise_grad2 *g, const nl_cheng_config *c, const double *u, int n,
                     double *v)
{
  double amp[NL_CHENG_MAX_OCTAVES], f[NL_CHENG_MAX_OCTAVES], asum = 0;
  for (int l = 0; l < c->octaves; l++) {
    amp[l] = exp(u ? u[l] : c->log_gain[l]) / (c->a1 * pow(2, l)); /* eq. 3.10 with gains */
    f[l] = c->f1 * pow(2, l);
    asum += amp[l];
  }
  double s = c->literal ? 1 : 1 / (NL_NOISE2_BOUND * asum);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      double x = domain_2d(c, i, n), y = domain_2d(c, j, n), sum = 0;
      for (int l = 0; l < c->octaves; l++) {
        double nv = nl_noise_grad2_eval_general(g, f[l] * x, f[l] * y);
        sum += amp[l] * (c->con == NL_CHENG_CON_FIRE ? fabs(nv) : nv);
      }
      double V = s * sum, out;
      if (c->literal)
        out = c->con == NL_CHENG_CON_SIN ? sin(V) : c->con == NL_CHENG_CON_ABS ? fabs(V) : V;
      else
        out = c->con == NL_CHENG_CON_SIN   ? 0.5 * (1 + sin(NL_PI * V))
              : c->con == NL_CHENG_CON_ABS ? fabs(V)
              : c->con == NL_CHENG_CON_FIRE ? V
                                            : 0.5 * (1 + V);
      v[(size_t)j * n + i] = out;
    }
}

/* The pattern panel's red: D of the cell under each pixel, 0.5 without control. */
static void pattern_red(const nl_cheng_pattern *p, int n, double *v)
{
  double *cell = malloc((size_t)p->grid * p->grid * sizeof *cell);
  for (int q = 0; q < p->grid * p->grid; q++) cell[q] = 0.5;
  for (size_t i = 0; i < p->n; i++) cell[p->cell[i]] = p->d[i];
  for (int y = 0; y < n; y++)
    for (int x = 0; x < n; x++)
      v[(size_t)y * n + x] = cell[(y * p->grid / n) * p->grid + x * p->grid / n];
  free(cell);
}

/* Panel i of m against v (n x n) mapped by lo..hi, or by its own
 * percentiles when stretch. */
static void check(run *R, const oracle_montage *m, const char *file, int i, const char *label,
                  const double *v, int n, int stretch, double lo, double hi)
{
  if (stretch) oracle_stretch(v, (size_t)n * n, &lo, &hi);
  oracle_result res = oracle_panel_compare(m, i, v, n, n, lo, hi);
  if (res.max_diff > ORACLE_TOL_8BIT || res.corr < 0.999) {
    printf("%s: panel %s is not its caption: max grey difference %.4f at (%d, %d), correlation "
           "%.4f\n",
           file, label, res.max_diff, res.x, res.y, res.corr);
    R->bad++;
  }
}

static int read_montage(run *R, oracle_montage *m, const char *file, int n, int size,
                        const char *const *labels, int cols, const char *title)
{
  int ws[64], hs[64];
  for (int i = 0; i < n; i++) ws[i] = hs[i] = size;
  char path[900];
  snprintf(path, sizeof path, "%s/%s", R->dir, file);
  if (oracle_montage_read(m, path, ws, hs, labels, n, cols, title)) {
    printf("%s: %s\n", file, m->err);
    oracle_montage_free(m);
    R->bad++;
    return 1;
  }
  return 0;
}

/* Panels a..b-1 pairwise different (captions that differ, pictures that differ). */
static void distinct(run *R, const oracle_montage *m, const char *file, const char *const *labels,
                     int a, int b)
{
  for (int i = a; i < b; i++)
    for (int j = i + 1; j < b; j++) {
      double c = oracle_panels_corr(m, i, j);
      if (c > 0.9999) {
        printf("%s: panels %s and %s show one picture (correlation %.5f)\n", file, labels[i],
               labels[j], c);
        R->bad++;
      }
    }
}

static nl_noise_grad2 *first_run(const nl_cheng_config *c, const nl_cheng_pattern *p,
                                 unsigned long seed, nl_cheng_eval *ev)
{
  nl_noise_grad2 *g = NULL;
  nl_error err;
  if (nl_cheng_run(c, p, seed, ev, NULL, &g, &err)) {
    fprintf(stderr, "oracle_chengb: %s\n", err.msg);
    exit(2);
  }
  return g;
}

/* ---- C2: noise_PAT.png, the pattern and the value per objective ---------- */

static void c2(run *R)
{
  const char *pats[2] = { "flower", "x" };
  const nl_cheng_stat objs[4] = { NL_CHENG_STAT_KS, NL_CHENG_STAT_CHISQ, NL_CHENG_STAT_KUIPER,
                                  NL_CHENG_STAT_CHISQ_RAW };
  const char *labels[5] = { "pattern", "KS term", "chi-square term", "Kuiper term",
                            "raw chi-square term" };
  const int size = 192; /* c2's PANEL */
  int grid = (int)oracle_param(R->man, "grid", 64);
  double *v = malloc((size_t)size * size * sizeof *v);
  for (int p = 0; p < 2; p++) {
    char file[64];
    snprintf(file, sizeof file, "noise_%s.png", pats[p]);
    oracle_montage m;
    if (read_montage(R, &m, file, 5, size, labels, 5, pats[p])) continue;
    nl_cheng_pattern *pat = pattern_2d(R, pats[p], grid);
    pattern_red(pat, size, v);
    check(R, &m, file, 0, labels[0], v, size, 0, 0, 1);
    for (int o = 0; o < 4; o++) {
      nl_cheng_config c = config_2d(R);
      c.stat = objs[o];
      nl_cheng_eval ev;
      nl_noise_grad2 *g = first_run(&c, pat, R->seed, &ev);
      value_2d(g, &c, NULL, size, v);
      check(R, &m, file, o + 1, labels[o + 1], v, size, 1, 0, 0);
      nl_noise_grad2_free(g);
    }
    distinct(R, &m, file, labels, 1, 5);
    nl_cheng_pattern_free(pat);
    oracle_montage_free(&m);
  }
  free(v);
}

/* ---- C9: values.png, fixed against optimised amplitudes per case --------- */

static void c9(run *R)
{
  static const struct {
    nl_cheng_con con;
    const char *pattern;
  } cases[6] = { { NL_CHENG_CON_PLAIN, "flower" }, { NL_CHENG_CON_SIN, "rings" },
                 { NL_CHENG_CON_ABS, "disc" },     { NL_CHENG_CON_FIRE, "flower" },
                 { NL_CHENG_CON_PLAIN, "star" },   { NL_CHENG_CON_FIRE, "gradient" } };
  int ncase = (int)oracle_param(R->man, "cases", 6), size = (int)oracle_param(R->man, "size", 192);
  int grid = (int)oracle_param(R->man, "grid", 64);
  double range = oracle_param(R->man, "amp_range", 4);
  char group[6][48];
  const char *labels[30];
  for (int i = 0; i < ncase; i++) {
    nl_cheng_config c = config_2d(R);
    c.con = cases[i].con;
    snprintf(group[i], sizeof group[i], "%s/%s", nl_cheng_con_name(c.con), cases[i].pattern);
    const char *pl[5] = { group[i], "fixed, raw 0..1", "optimised, raw 0..1", "fixed, stretched",
                          "optimised, stretched" };
    for (int k = 0; k < 5; k++) labels[5 * i + k] = pl[k];
  }
  oracle_montage m;
  const char *file = "values.png";
  if (read_montage(R, &m, file, 5 * ncase, size, labels, 5,
                   "C9: fixed vs optimised octave amplitudes (first seed)"))
    return;
  double *v = malloc((size_t)size * size * sizeof *v);
  for (int i = 0; i < ncase; i++) {
    nl_cheng_config cf = config_2d(R);
    cf.con = cases[i].con;
    nl_cheng_config co = cf;
    co.amp_vary = 1;
    co.amp_range = range;
    nl_cheng_pattern *pat = pattern_2d(R, cases[i].pattern, grid);
    nl_cheng_eval ef, eo;
    nl_noise_grad2 *gf = first_run(&cf, pat, R->seed, &ef);
    nl_noise_grad2 *go = first_run(&co, pat, R->seed, &eo);
    int signed_v = cf.literal && (cf.con == NL_CHENG_CON_PLAIN || cf.con == NL_CHENG_CON_SIN);
    const char *const *lab = labels + 5 * i;
    pattern_red(pat, size, v);
    check(R, &m, file, 5 * i, lab[0], v, size, 0, 0, 1);
    value_2d(gf, &cf, NULL, size, v);
    check(R, &m, file, 5 * i + 1, lab[1], v, size, 0, signed_v ? -1 : 0, 1);
    check(R, &m, file, 5 * i + 3, lab[3], v, size, 1, 0, 0);
    value_2d(go, &co, eo.log_gain, size, v);
    check(R, &m, file, 5 * i + 2, lab[2], v, size, 0, signed_v ? -1 : 0, 1);
    check(R, &m, file, 5 * i + 4, lab[4], v, size, 1, 0, 0);
    distinct(R, &m, file, labels, 5 * i + 1, 5 * i + 3);
    distinct(R, &m, file, labels, 5 * i + 3, 5 * i + 5);
    nl_noise_grad2_free(gf);
    nl_noise_grad2_free(go);
    nl_cheng_pattern_free(pat);
  }
  free(v);
  oracle_montage_free(&m);
}

/* ---- C8: slices_PAT.png, slices of the 3D value --------------------------- */

/* c = (1 + V) / 2, V = s sum_l Noise(f_l p) / a_l, s = 1 / (sqrt(3)/2 sum 1/a_l)
 * (nl_cheng3.h), on the slice z = 1/2 (axis 2) or y = 1/2 (axis 1); t NULL:
 * the pattern's D of the cell under the point. */
static void slice_3d(const nl_noise_grad3 *t, const nl_cheng3_config *c,
                     const nl_cheng3_pattern *pat, int axis, int n, double *v)
{
  double asum = 0;
  for (int l = 0; l < c->octaves; l++) asum += 1 / (c->a1 * pow(2, l));
  double s = 1 / (NL_NOISE_GRAD3_BOUND * asum);
  for (int b = 0; b < n; b++)
    for (int a = 0; a < n; a++) {
      double u = (a + 0.5) / n, w = (b + 0.5) / n;
      double p[3] = { u, axis == 2 ? w : 0.5, axis == 2 ? 0.5 : w };
      double out;
      if (!t) {
        int g = pat->grid, k[3];
        for (int d = 0; d < 3; d++) k[d] = (int)fmin(g - 1, floor(p[d] * g));
        out = pat->d[((size_t)k[2] * g + k[1]) * g + k[0]];
      } else {
        double sum = 0;
        for (int l = 0; l < c->octaves; l++) {
          double f = c->f1 * pow(2, l);
          sum += nl_noise_grad3_eval(t, f * p[0], f * p[1], f * p[2]) / (c->a1 * pow(2, l));
        }
        out = 0.5 * (1 + s * sum);
      }
      v[(size_t)b * n + a] = out;
    }
}

static void c8(run *R)
{
  const char *pats[3] = { "torus", "ball", "slab" };
  const char *labels[8] = { "D xy", "c xy", "c xy str", "rand xy", "D xz", "c xz", "c xz str",
                            "rand xz" };
  int size = (int)oracle_param(R->man, "size", 160), grid = (int)oracle_param(R->man, "grid", 16);
  nl_cheng3_config c = nl_cheng3_config_default();
  c.w1 = oracle_param(R->man, "w1", c.w1);
  c.w2 = oracle_param(R->man, "w2", c.w2);
  c.octaves = (int)oracle_param(R->man, "octaves", c.octaves);
  c.f1 = oracle_param(R->man, "f1", c.f1);
  c.sched.n_temps = (int)oracle_param(R->man, "temps", c.sched.n_temps);
  c.sched.moves_per_var = oracle_param(R->man, "moves_per_var", c.sched.moves_per_var);
  double *v = malloc((size_t)size * size * sizeof *v);
  for (int p = 0; p < 3; p++) {
    char file[64], title[128];
    snprintf(file, sizeof file, "slices_%s.png", pats[p]);
    snprintf(title, sizeof title, "C8: %s, slices of the 3D control value (first seed)", pats[p]);
    oracle_montage m;
    if (read_montage(R, &m, file, 8, size, labels, 4, title)) continue;
    nl_cheng3_pattern *pat;
    nl_error err;
    if (nl_cheng3_pattern_shape(pats[p], grid, &pat, &err)) {
      fprintf(stderr, "oracle_chengb: %s\n", err.msg);
      exit(2);
    }
    nl_cheng3_eval ev;
    nl_noise_grad3 *t = NULL, *t0 = nl_noise_grad3_alloc(c.m);
    if (nl_cheng3_run(&c, pat, R->seed, &ev, NULL, NULL, &t, &err)) {
      fprintf(stderr, "oracle_chengb: %s\n", err.msg);
      exit(2);
    }
    nl_noise_grad3_seed(t0, R->seed); /* the run's random start */
    for (int row = 0; row < 2; row++) {
      int axis = row ? 1 : 2, i = 4 * row;
      slice_3d(NULL, &c, pat, axis, size, v);
      check(R, &m, file, i, labels[i], v, size, 0, 0, 1);
      slice_3d(t, &c, pat, axis, size, v);
      check(R, &m, file, i + 1, labels[i + 1], v, size, 0, 0, 1);
      check(R, &m, file, i + 2, labels[i + 2], v, size, 1, 0, 0);
      slice_3d(t0, &c, pat, axis, size, v);
      check(R, &m, file, i + 3, labels[i + 3], v, size, 1, 0, 0);
      distinct(R, &m, file, labels, i + 2, i + 4);
    }
    nl_noise_grad3_free(t);
    nl_noise_grad3_free(t0);
    nl_cheng3_pattern_free(pat);
    oracle_montage_free(&m);
  }
  free(v);
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: oracle_chengb c2|c8|c9 OUTDIR\n");
    return 2;
  }
  run R = { NULL, argv[2], 0, "", 0 };
  nl_table *man = oracle_read_table("oracle_chengb", R.dir, "manifest.tsv");
  if (!man) return 2;
  R.man = man;
  const char *seed_text = oracle_manifest_value(man, "seed");
  R.seed = nl_seed_replicate(seed_text ? strtoul(seed_text, NULL, 10) : 1, 0);
  int rc = 0;
  if (!strcmp(argv[1], "c2")) {
    if (find_patterns(&R)) rc = 2;
    else c2(&R);
  } else if (!strcmp(argv[1], "c9")) {
    if (find_patterns(&R)) rc = 2;
    else c9(&R);
  } else if (!strcmp(argv[1], "c8")) {
    c8(&R);
  } else {
    fprintf(stderr, "oracle_chengb: %s: wanted c2, c8 or c9\n", argv[1]);
    rc = 2;
  }
  nl_table_free(man);
  return rc ? rc : R.bad > 0;
}
