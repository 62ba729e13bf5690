/* oracle_cheng - the panels of C1, C3, C4, C6 and C7 against their captions.
 *
 *   oracle_cheng c1|c3|c4|c6|c7 OUTDIR
 *
 * A panel's caption names the controlled value c of a gradient table (Cheng
 * 2009 eq. 3.8, 4.1-4.3: cloud (1 + V) / 2, marble (1 + sin(pi V)) / 2,
 * erosion |V|, fire s sum |Noise_l| / a_l, or the literal formulas V, sin V,
 * |V|, sum |Noise_l| / a_l; V = s sum_l Noise(f_l p) / a_l, s = 1 / (sqrt(2)/2
 * sum 1/a_l), f_l = f1 2^(l-1), a_l = a1 2^(l-1)) over the texture's unit
 * square, pixel centres evaluated at the noise's (o + x, o + y) for the
 * run's origin o, or the control pattern, for the first seed. This reads the
 * tables the run wrote (tables.tsv: k, angle, perm per table), rebuilds each
 * table, and computes every value one point at a time through the noise's
 * point call (nl_noise_grad2_eval_general), the octaves and the control
 * formula summed here, not through nl_cheng_value_grid's rows; the pattern
 * panels from the pattern PNG by a loop over its pixels (the cell means of
 * sec. 3.4.1; $NL_PATTERNS overrides the manifest's folder). Each is mapped
 * as its figure maps it (grey 0..1 raw, grey over the 1st..99th percentile
 * stretched; a texture's red channel: the two colours' blend or the marble
 * ramp over the same stretch) and compared to 8 bits with the panel read
 * back from the PNG. A panel that shows another table, another octave sum or
 * another formula fails (grey levels and correlation). C7's shaded relief is
 * a Lambertian render of the height panel beside it, which is tested; the
 * relief itself is not recomputed here. Exit 0 when every panel matches, 1
 * with one line per mismatch, 2 on bad input.
 */
#include "oracle.h"

#include "base/nl_base.h"
#include "noise/nl_noise.h"
#include "table/nl_table.h"
#include "texture/nl_texture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the model, written out ---------------------------------------------- */

enum { CLOUD, MARBLE, EROSION, FIRE };

typedef struct {
  int con, literal, octaves;
  double f1, a1, origin;
} model;

/* c at texture point (x, y) of table g. */
static double control(const model *md, const nl_noise_grad2 *g, double x, double y)
{
  double sum = 0, inv = 0;
  for (int l = 0; l < md->octaves; l++) {
    double f = md->f1 * ldexp(1.0, l), a = md->a1 * ldexp(1.0, l);
    double v = nl_noise_grad2_eval_general(g, f * (md->origin + x), f * (md->origin + y));
    sum += (md->con == FIRE ? fabs(v) : v) / a;
    inv += 1 / a;
  }
  if (md->literal) return md->con == MARBLE ? sin(sum) : md->con == EROSION ? fabs(sum) : sum;
  double s = 1 / (sqrt(2.0) / 2 * inv);
  if (md->con == FIRE) return s * sum;
  double V = s * sum;
  return md->con == MARBLE ? 0.5 * (1 + sin(M_PI * V)) : md->con == EROSION ? fabs(V) : 0.5 * (1 + V);
}

static double *value_raster(const model *md, const nl_noise_grad2 *g, int n)
{
  double *v = malloc((size_t)n * n * sizeof *v);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) v[(size_t)j * n + i] = control(md, g, (i + 0.5) / n, (j + 0.5) / n);
  return v;
}

/* ---- the run's tables ------------------------------------------------------ */

/* The table whose label columns cols[0..nl-1] hold vals (as text). */
static nl_noise_grad2 *table_of(const nl_table *t, const char *const *cols, const char *const *vals, int nl)
{
  size_t m = 0;
  long ci[8], ck = nl_table_column(t, "k"), ca = nl_table_column(t, "angle"), cp = nl_table_column(t, "perm");
  for (int i = 0; i < nl; i++) if ((ci[i] = nl_table_column(t, cols[i])) < 0) return NULL;
  if (ck < 0 || ca < 0 || cp < 0) return NULL;
  for (int pass = 0; pass < 2; pass++) {
    nl_noise_grad2 *g = pass ? nl_noise_grad2_alloc(m) : NULL;
    size_t found = 0;
    for (size_t r = 0; r < t->nrows; r++) {
      int ok = 1;
      for (int i = 0; i < nl && ok; i++) {
        char buf[64];
        ok = !strcmp(nl_table_cell_text(t, r, (size_t)ci[i], buf), vals[i]);
      }
      if (!ok) continue;
      if (pass) {
        size_t k = (size_t)nl_table_value(t, r, "k");
        g->perm[k] = (unsigned)nl_table_value(t, r, "perm");
        nl_noise_grad2_set_angle(g, k, nl_table_value(t, r, "angle"));
      }
      found++;
    }
    if (!pass) {
      if (!found) return NULL;
      m = found;
    } else return g;
  }
  return NULL;
}

/* ---- the pattern, from its PNG ---------------------------------------------- */

/* The pattern panel of NAME at `grid`, size x size: red = the cell's
 * alpha-weighted mean red, cells of mean alpha < 1/2 grey 0.5 (no
 * control). NULL if the PNG cannot be read. */
static double *pattern_panel(const char *dir, const char *name, int grid, int size)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/%s.png", dir, name);
  nl_image *im;
  nl_error err;
  if (nl_image_read(path, &im, &err)) return NULL;
  int W = im->width, H = im->height, ch = im->channels;
  double *d = malloc((size_t)grid * grid * sizeof *d);
  for (int r = 0; r < grid; r++)
    for (int c = 0; c < grid; c++) {
      int x0 = c * W / grid, x1 = ((c + 1) * W + grid - 1) / grid;
      int y0 = r * H / grid, y1 = ((r + 1) * H + grid - 1) / grid;
      if (x1 <= x0) x1 = x0 + 1;
      if (y1 <= y0) y1 = y0 + 1;
      double sa = 0, sr = 0;
      for (int y = y0; y < y1 && y < H; y++)
        for (int x = x0; x < x1 && x < W; x++) {
          const float *px = im->data + ((size_t)y * W + x) * ch;
          double a = ch == 2 ? px[1] : ch == 4 ? px[3] : 1.0;
          sa += a;
          sr += a * px[0];
        }
      double alpha = sa / ((double)(x1 - x0) * (y1 - y0)), v = sa > 0 ? sr / sa : 0;
      v = v < 0 ? 0 : v > 1 ? 1 : v;
      d[r * grid + c] = alpha < 0.5 ? 0.5 : v;
    }
  nl_image_free(im);
  double *p = malloc((size_t)size * size * sizeof *p);
  for (int y = 0; y < size; y++)
    for (int x = 0; x < size; x++) p[(size_t)y * size + x] = d[(y * grid / size) * grid + x * grid / size];
  free(d);
  return p;
}

/* ---- checking ---------------------------------------------------------------- */

typedef struct {
  const char *dir, *patterns;
  const nl_table *man, *tabs;
  int grid;
  model md;   /* the run's setting (con and literal set per panel) */
} run;

static int report(const char *file, const char *label, oracle_result res)
{
  if (res.max_diff <= ORACLE_TOL_8BIT && res.corr >= 0.999) return 0;
  printf("%s: panel %s is not its caption: max grey difference %.4f at (%d, %d), correlation %.4f\n", file,
         label, res.max_diff, res.x, res.y, res.corr);
  return 1;
}

/* How a panel maps its values: grey over [lo, hi] given, grey over the
 * stretch, or a texture's red channel over the stretch. */
enum { RAW, STRETCH, TEXTURE };

/* The texture's red channel: cloud / erosion / fire blend two colours
 * (sec. 4.1) with alpha = the stretched value; marble maps it through the
 * marble ramp. */
static void texture_red(int con, double *v, size_t n, double lo, double hi)
{
  static const double red[4][2] = { { 0.20, 1.00 }, { 0, 0 }, { 0.22, 0.92 }, { 0.25, 1.00 } };
  nl_texture_ramp ramp = nl_texture_ramp_marble();
  for (size_t q = 0; q < n; q++) {
    double a = (v[q] - lo) / (hi - lo);
    if (con == MARBLE) {
      float rgb[3];
      nl_texture_ramp_eval(&ramp, a, rgb);
      v[q] = rgb[0];
    } else {
      a = a < 0 ? 0 : a > 1 ? 1 : a;
      v[q] = (float)((1 - a) * red[con][0] + a * red[con][1]);
    }
  }
}

/* Panel i of m: table g's value under md, size x size, mapped by `map`. */
static int value_panel(const oracle_montage *m, int i, const char *file, const char *label, const model *md,
                       const nl_noise_grad2 *g, int size, int map)
{
  if (!g) {
    printf("%s: panel %s: no table in tables.tsv\n", file, label);
    return 1;
  }
  double *v = value_raster(md, g, size), lo, hi;
  size_t n = (size_t)size * size;
  if (map == RAW) {
    lo = md->literal && (md->con == CLOUD || md->con == MARBLE) ? -1 : 0;
    hi = 1;
  } else {
    oracle_stretch(v, n, &lo, &hi);
    if (map == TEXTURE) {
      texture_red(md->con, v, n, lo, hi);
      lo = 0;
      hi = 1;
    }
  }
  int bad = report(file, label, oracle_panel_compare(m, i, v, size, size, lo, hi));
  free(v);
  return bad;
}

static int pattern_check(const run *rn, const oracle_montage *m, int i, const char *file, const char *label,
                         const char *name, int size)
{
  double *p = pattern_panel(rn->patterns, name, rn->grid, size);
  if (!p) {
    printf("%s: panel %s: cannot read the pattern %s/%s.png\n", file, label, rn->patterns, name);
    return 1;
  }
  int bad = report(file, label, oracle_panel_compare(m, i, p, size, size, 0, 1));
  free(p);
  return bad;
}

static int open_montage(const run *rn, oracle_montage *m, const char *file, int n, int size,
                        const char *const *labels, int cols, const char *title)
{
  int ws[64], hs[64];
  for (int i = 0; i < n; i++) ws[i] = hs[i] = size;
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", rn->dir, file);
  if (oracle_montage_read(m, path, ws, hs, labels, n, cols, title)) {
    printf("%s: %s\n", file, m->err);
    oracle_montage_free(m);
    return 1;
  }
  return 0;
}

/* ---- the experiments ------------------------------------------------------------ */

static const char *const tex_names[4] = { "cloud", "marble", "erosion", "fire" };

static int c1(const run *rn)
{
  static const char *const pats[4][3] = {
    { "flower", "x", "star" }, { "rings", "spiral", "letter" }, { "disc", "star", "x" }, { "flower", "gradient", "letter" }
  };
  static const char *const eq[4] = { "eq. 3.8", "eq. 4.1", "eq. 4.2", "eq. 4.3" };
  int size = (int)oracle_param(rn->man, "size", 256), bad = 0;
  const char *cols[3] = { "texture", "pattern", "formula" };
  for (int t = 0; t < 4; t++) {
    const char *labels[15];
    for (int j = 0; j < 3; j++) {
      const char *pl[5] = { pats[t][j], "c, raw 0..1", "c, stretched", tex_names[t], "literal c" };
      for (int q = 0; q < 5; q++) labels[5 * j + q] = pl[q];
    }
    char title[96], file[64];
    snprintf(title, sizeof title, "Fig 4.%d: %s (%s)", t + 1, tex_names[t], eq[t]);
    snprintf(file, sizeof file, "%s.png", tex_names[t]);
    oracle_montage m;
    if (open_montage(rn, &m, file, 15, size, labels, 5, title)) { bad++; continue; }
    for (int j = 0; j < 3; j++) {
      const char *vr[3] = { tex_names[t], pats[t][j], "rescaled" }, *vl[3] = { tex_names[t], pats[t][j], "literal" };
      nl_noise_grad2 *g = table_of(rn->tabs, cols, vr, 3), *gl = table_of(rn->tabs, cols, vl, 3);
      model md = rn->md, ml = rn->md;
      md.con = ml.con = t;
      md.literal = 0;
      ml.literal = 1;
      char lab[5][96];
      for (int q = 0; q < 5; q++) snprintf(lab[q], sizeof lab[q], "%s: %s", pats[t][j], labels[5 * j + q]);
      bad += pattern_check(rn, &m, 5 * j, file, lab[0], pats[t][j], size);
      bad += value_panel(&m, 5 * j + 1, file, lab[1], &md, g, size, RAW);
      bad += value_panel(&m, 5 * j + 2, file, lab[2], &md, g, size, STRETCH);
      bad += value_panel(&m, 5 * j + 3, file, lab[3], &md, g, size, TEXTURE);
      bad += value_panel(&m, 5 * j + 4, file, lab[4], &ml, gl, size, STRETCH);
      if (g) nl_noise_grad2_free(g);
      if (gl) nl_noise_grad2_free(gl);
    }
    oracle_montage_free(&m);
  }
  return bad;
}

static int c3(const run *rn)
{
  enum { NF = 4, COLS = NF + 1, PANEL = 160 };
  static const double f1s[NF] = { 2, 4, 6, 8 };
  char lab[2 * COLS][48];
  const char *labels[2 * COLS];
  for (int row = 0; row < 2; row++) snprintf(lab[row * COLS], sizeof lab[0], "pattern");
  for (int i = 0; i < NF; i++) {
    snprintf(lab[1 + i], sizeof lab[0], "(%c) f1=%g", 'a' + i, f1s[i]);
    snprintf(lab[COLS + 1 + i], sizeof lab[0], "(%c) f1=%g cloud", 'a' + i, f1s[i]);
  }
  for (int i = 0; i < 2 * COLS; i++) labels[i] = lab[i];
  const char *file = "panels.png";
  oracle_montage m;
  if (open_montage(rn, &m, file, 2 * COLS, PANEL, labels, COLS, "Fig 4.7: starting frequency f1 (first seed)"))
    return 1;
  int bad = 0;
  for (int row = 0; row < 2; row++) bad += pattern_check(rn, &m, row * COLS, file, labels[row * COLS], "star", PANEL);
  const char *cols[1] = { "f1" };
  for (int i = 0; i < NF; i++) {
    char f[32];
    snprintf(f, sizeof f, "%g", f1s[i]);
    const char *v[1] = { f };
    nl_noise_grad2 *g = table_of(rn->tabs, cols, v, 1);
    model md = rn->md;
    md.con = CLOUD;
    md.literal = 0;
    md.f1 = f1s[i];
    bad += value_panel(&m, 1 + i, file, labels[1 + i], &md, g, PANEL, STRETCH);
    bad += value_panel(&m, COLS + 1 + i, file, labels[COLS + 1 + i], &md, g, PANEL, TEXTURE);
    if (g) nl_noise_grad2_free(g);
  }
  oracle_montage_free(&m);
  return bad;
}

static int c4(const run *rn)
{
  enum { NPAIR = 6, COLS = NPAIR + 1, PANEL = 160 };
  char lab[2 * COLS][32];
  const char *labels[2 * COLS];
  for (int row = 0; row < 2; row++) {
    snprintf(lab[row * COLS], sizeof lab[0], "pattern");
    for (int i = 0; i < NPAIR; i++)
      snprintf(lab[row * COLS + 1 + i], sizeof lab[0], "(%c) %s", 'a' + i, row ? "swapped" : "printed");
  }
  for (int i = 0; i < 2 * COLS; i++) labels[i] = lab[i];
  const char *file = "textures.png";
  oracle_montage m;
  if (open_montage(rn, &m, file, 2 * COLS, PANEL, labels, COLS,
                   "Fig 4.8: controlled value, printed (top) and swapped (bottom) weights"))
    return 1;
  int bad = 0;
  const char *cols[2] = { "reading", "panel" };
  for (int row = 0; row < 2; row++) {
    bad += pattern_check(rn, &m, row * COLS, file, labels[row * COLS], "flower", PANEL);
    for (int i = 0; i < NPAIR; i++) {
      char p[4] = { (char)('a' + i), 0 };
      const char *v[2] = { row ? "swapped" : "printed", p };
      nl_noise_grad2 *g = table_of(rn->tabs, cols, v, 2);
      model md = rn->md;
      md.con = CLOUD;
      md.literal = 0;
      bad += value_panel(&m, row * COLS + 1 + i, file, labels[row * COLS + 1 + i], &md, g, PANEL, RAW);
      if (g) nl_noise_grad2_free(g);
    }
  }
  oracle_montage_free(&m);
  return bad;
}

static int c6(const run *rn)
{
  enum { NSHOW = 8, SIDE = 192 };
  static const char *const tex[3] = { "erosion", "marble", "cloud" };
  static const int con[3] = { EROSION, MARBLE, CLOUD };
  char rp[1024], sp[1024];
  snprintf(rp, sizeof rp, "%s/reproductions.tsv", rn->dir);
  snprintf(sp, sizeof sp, "%s/summary.tsv", rn->dir);
  nl_table *reps = NULL, *sum = NULL;
  nl_error err;
  if (nl_table_read(rp, NL_TABLE_TEXT, &reps, &err) || nl_table_read(sp, NL_TABLE_TEXT, &sum, &err)) {
    printf("c6: %s\n", err.msg);
    nl_table_free(reps);
    return 1;
  }
  int bad = 0;
  const char *cols[2] = { "texture", "table" };
  for (int t = 0; t < 3; t++) {
    /* the captions: E_KS / E_Con of the original and of the first reproductions (swap 1) */
    char lab[NSHOW + 1][80];
    const char *labels[NSHOW + 1];
    for (size_t q = 0; q < sum->nrows; q++)
      if (!strcmp(nl_table_text(sum, q, "texture"), tex[t]) && !strcmp(nl_table_text(sum, q, "kind"), "original"))
        snprintf(lab[0], sizeof lab[0], "orig %.4f / %.0f", nl_table_value(sum, q, "E_ks"),
                 nl_table_value(sum, q, "E_con"));
    int i = 1;
    for (size_t q = 0; q < reps->nrows && i <= NSHOW; q++)
      if (!strcmp(nl_table_text(reps, q, "texture"), tex[t]) && nl_table_value(reps, q, "swap") == 1) {
        snprintf(lab[i], sizeof lab[i], "r%d %.4f / %.0f", i, nl_table_value(reps, q, "E_ks"),
                 nl_table_value(reps, q, "E_con"));
        i++;
      }
    for (int q = 0; q <= NSHOW; q++) labels[q] = lab[q];
    char title[96], file[64];
    snprintf(title, sizeof title, "%s: E_KS / E_Con", tex[t]);
    snprintf(file, sizeof file, "textures_%s.png", tex[t]);
    oracle_montage m;
    if (open_montage(rn, &m, file, NSHOW + 1, SIDE, labels, 3, title)) { bad++; continue; }
    for (int q = 0; q <= NSHOW; q++) {
      char name[16];
      snprintf(name, sizeof name, q ? "r%d" : "original", q);
      const char *v[2] = { tex[t], name };
      nl_noise_grad2 *g = table_of(rn->tabs, cols, v, 2);
      model md = rn->md;
      md.con = con[t];
      md.literal = 0;
      bad += value_panel(&m, q, file, labels[q], &md, g, SIDE, TEXTURE);
      if (g) nl_noise_grad2_free(g);
    }
    oracle_montage_free(&m);
  }
  nl_table_free(reps);
  nl_table_free(sum);
  return bad;
}

static int c7(const run *rn)
{
  enum { NPAT = 3, PANEL = 192 };
  static const char *const names[NPAT] = { "flower", "x", "star" };
  const char *labels[3 * NPAT];
  for (int i = 0; i < NPAT; i++) {
    labels[3 * i] = names[i];
    labels[3 * i + 1] = "height, grey 0..1";
    labels[3 * i + 2] = "shaded relief";
  }
  const char *file = "heightmaps.png";
  oracle_montage m;
  if (open_montage(rn, &m, file, 3 * NPAT, PANEL, labels, 3, "Fig 4.15-4.17: pattern | height | relief")) return 1;
  int bad = 0;
  const char *cols[1] = { "pattern" };
  for (int i = 0; i < NPAT; i++) {
    char lab[64];
    snprintf(lab, sizeof lab, "%s: height", names[i]);
    bad += pattern_check(rn, &m, 3 * i, file, names[i], names[i], PANEL);
    const char *v[1] = { names[i] };
    nl_noise_grad2 *g = table_of(rn->tabs, cols, v, 1);
    model md = rn->md;
    md.con = CLOUD;
    md.literal = 0;
    bad += value_panel(&m, 3 * i + 1, file, lab, &md, g, PANEL, RAW);
    if (g) nl_noise_grad2_free(g);
  }
  oracle_montage_free(&m);
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: oracle_cheng c1|c3|c4|c6|c7 OUTDIR\n");
    return 2;
  }
  run rn = { .dir = argv[2] };
  nl_table *man = oracle_read_table("oracle_cheng", rn.dir, "manifest.tsv");
  nl_table *tabs = man ? oracle_read_table("oracle_cheng", rn.dir, "tables.tsv") : NULL;
  if (!tabs) {
    nl_table_free(man);
    return 2;
  }
  rn.man = man;
  rn.tabs = tabs;
  rn.grid = (int)oracle_param(man, "grid", 64);
  rn.md = (model){ CLOUD, 0, (int)oracle_param(man, "octaves", 4), oracle_param(man, "f1", 8), oracle_param(man, "a1", 4),
                   oracle_param(man, "origin", 0) };
  const char *env = getenv("NL_PATTERNS"), *mpat = oracle_manifest_value(man, "patterns");
  rn.patterns = env && *env ? env : mpat ? mpat : "data/patterns";
  int bad;
  if (!strcmp(argv[1], "c1")) bad = c1(&rn);
  else if (!strcmp(argv[1], "c3")) bad = c3(&rn);
  else if (!strcmp(argv[1], "c4")) bad = c4(&rn);
  else if (!strcmp(argv[1], "c6")) bad = c6(&rn);
  else if (!strcmp(argv[1], "c7")) bad = c7(&rn);
  else {
    fprintf(stderr, "oracle_cheng: %s: wanted c1, c3, c4, c6 or c7\n", argv[1]);
    bad = -1;
  }
  nl_table_free(man);
  nl_table_free(tabs);
  return bad < 0 ? 2 : bad > 0;
}
