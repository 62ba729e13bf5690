/* noiselab render - any noise of the library to an image or a table.
 *
 *   noiselab render fbm --octaves 6 --gain 0.5 --lacunarity 2 --size 512 --seed 7 -o fbm.png
 *
 * Images go through OpenImageIO (format from the extension). Integer
 * formats (8/16-bit PNG, TIFF, ...) store the value mapped to [0, 1] by the
 * noise's analytic bound B: (v / B + 1) / 2, or v / B for turbulence, so
 * grey levels mean the same thing at every setting (--normalize range maps
 * min..max instead). Float formats (EXR, or --bits 32) store raw values.
 * A .tsv output holds the raw values as columns x, y, value.
 */
#include "harness/nl_harness.h"
#include "cellular/nl_cellular.h"
#include "noise/nl_noise.h"
#include "table/nl_table.h"
#include "texture/nl_texture.h"
#include "wavelet/nl_wavelet.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *NOISES[] = {"noise2", "improved", "gctbf", "wavelet", "fractal", "turbulence", "fbm", "marble", NULL};

typedef struct {
  const char *noise, *out, *basis, *normalize, *terms, *count;
  long size, octaves, seed, table_size, bits, points, tile;
  double extent, x0, y0, z, gain, lacunarity, amplitude, stripes, lambda;
  int reference;
  int normalize_given;   /* --normalize was given (gctbf's default is range, not bound) */
} options;

static void usage(void)
{
  printf("usage: noiselab render NOISE [options] -o FILE   (options: --name VALUE or --name=VALUE)\n\n"
         "NOISE: noise2      2D gradient-table noise (Cheng 2009 eq. 3.1-3.2)\n"
         "       improved    Perlin's improved 3D noise, on the plane z\n"
         "       gctbf       Qin & Yang's generalized cellular basis sum c_i F_i + c_ij F_i F_j\n"
         "       wavelet     Cook & DeRose's wavelet noise (3D tile, plane z)\n"
         "       fractal     sum_j noise(2^j p) / 2^j            (Shaffer)\n"
         "       turbulence  sum_j |noise(2^j p)| / 2^j\n"
         "       fbm         sum_j gain^j noise(lacunarity^j p)\n"
         "       marble      (1 + sin(2 pi stripes (y + amplitude fractal(p)))) / 2\n\n"
         "  -o FILE              .png .exr .tif ... (OpenImageIO) or .tsv (x, y, value)\n"
         "  --size N             pixels per side, 1..65536 (512)\n"
         "  --extent X           side of the square in noise units (4)\n"
         "  --x0 X --y0 Y --z Z  window origin and plane (0 0 0.5)\n"
         "  --octaves N          1..30 (6)          --gain G (0.5)   --lacunarity L (2)\n"
         "  --amplitude A        marble displacement a (0.5)   --stripes K per unit (1)\n"
         "  --basis improved|table|gctbf|wavelet   noise under the sums (improved)\n"
         "  --tile N             wavelet tile period, even, 8..256 (64)\n"
         "  --terms EXPR         GCTBF, e.g. \"F2 - F1 - F1F1\" or \"0.5*F1 + 2 F1*F2\" (F1)\n"
         "  --lambda L           mean feature points per unit cube, (0, 1000] (4)\n"
         "  --points M           feature points per cube at most, 1..64 (50)\n"
         "  --count inverse|closest  feature-point count rule (inverse: inverse-CDF sampling;\n"
         "                       closest: the paper's 'p(m) closest to r')\n"
         "  --table-size M       gradient-table size for noise2/table, 4..1048576 (512)\n"
         "  --seed S             table seed (1)   --reference  Perlin's own permutation\n"
         "  --bits 8|16|32       image bit depth (8; EXR defaults to 32)\n"
         "  --normalize bound|range   grey mapping for integer formats: the analytic bound, or\n"
         "                       the image's min..max (bound; range for gctbf, whose values\n"
         "                       fill a small part of its bound)\n\n"
         "Pixel (column c, row r) holds the noise at x = x0 + (c + 1/2) extent / size,\n"
         "y = y0 + (r + 1/2) extent / size: row 0 is the top of the image, so y grows\n"
         "downward in the picture (as the .tsv's rows). An option that does not apply to\n"
         "the chosen noise or output format is ignored with a warning.\n");
}

static void fail(const char *msg) { fprintf(stderr, "noiselab render: %s\n", msg); exit(2); }

static void num(const char *opt, const char *val, double lo, double hi, double *out)
{
  nl_error err;
  if (nl_parse_double(opt, val, lo, hi, out, &err)) fail(err.msg);
}

static void integer(const char *opt, const char *val, long lo, long hi, long *out)
{
  nl_error err;
  if (nl_parse_long(opt, val, lo, hi, out, &err)) fail(err.msg);
}

static int one_of(const char *s, const char *const *list)
{
  for (int i = 0; list[i]; i++) if (!strcmp(s, list[i])) return 1;
  return 0;
}

static int ends_with(const char *s, const char *suffix)
{
  size_t a = strlen(s), b = strlen(suffix);
  return a >= b && strcasecmp(s + a - b, suffix) == 0;
}

static void parse(int argc, char **argv, options *o)
{
  *o = (options){.basis = "improved", .normalize = "bound", .terms = "F1", .count = "inverse",
                 .points = 50, .tile = 64, .lambda = 4, .size = 512, .octaves = 6, .seed = 1,
                 .table_size = 512, .bits = 0, .extent = 4, .z = 0.5, .gain = 0.5, .lacunarity = 2,
                 .amplitude = 0.5, .stripes = 1};
  enum { R_OUT, R_SIZE, R_OCTAVES, R_SEED, R_TABLE_SIZE, R_BITS, R_EXTENT, R_X0, R_Y0, R_Z, R_GAIN,
         R_LACUNARITY, R_AMPLITUDE, R_STRIPES, R_BASIS, R_TERMS, R_TILE, R_COUNT, R_LAMBDA, R_POINTS,
         R_NORMALIZE, R_REFERENCE, R_HELP };
  static const nl_opt_spec spec[] = {
    [R_OUT] = {"out", 'o', 1}, [R_SIZE] = {"size", 0, 1}, [R_OCTAVES] = {"octaves", 0, 1},
    [R_SEED] = {"seed", 0, 1}, [R_TABLE_SIZE] = {"table-size", 0, 1}, [R_BITS] = {"bits", 0, 1},
    [R_EXTENT] = {"extent", 0, 1}, [R_X0] = {"x0", 0, 1}, [R_Y0] = {"y0", 0, 1}, [R_Z] = {"z", 0, 1},
    [R_GAIN] = {"gain", 0, 1}, [R_LACUNARITY] = {"lacunarity", 0, 1}, [R_AMPLITUDE] = {"amplitude", 0, 1},
    [R_STRIPES] = {"stripes", 0, 1}, [R_BASIS] = {"basis", 0, 1}, [R_TERMS] = {"terms", 0, 1},
    [R_TILE] = {"tile", 0, 1}, [R_COUNT] = {"count", 0, 1}, [R_LAMBDA] = {"lambda", 0, 1},
    [R_POINTS] = {"points", 0, 1}, [R_NORMALIZE] = {"normalize", 0, 1}, [R_REFERENCE] = {"reference", 0, 0},
    [R_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser p;
  nl_error err;
  int given[R_HELP + 1] = {0};
  nl_opt_begin(&p, argc, argv, 1, spec);
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    const char *a = p.name, *v = p.value[0];
    char m[NL_ERROR_LEN + 32];
    if (k >= 0) given[k] = 1;
    switch (k) {
    case NL_OPT_ERROR: snprintf(m, sizeof m, "%s (see --help)", err.msg); fail(m); break;
    case NL_OPT_POSITIONAL:
      if (o->noise) { snprintf(m, sizeof m, "%s: only one NOISE may be given", v); fail(m); }
      o->noise = v;
      break;
    case R_HELP: usage(); exit(0);
    case R_REFERENCE: o->reference = 1; break;
    case R_OUT: o->out = v; break;
    case R_SIZE: integer(a, v, 1, 65536, &o->size); break;
    case R_OCTAVES: integer(a, v, 1, 30, &o->octaves); break;
    case R_SEED: integer(a, v, 0, 4294967295L, &o->seed); break;
    case R_TABLE_SIZE: integer(a, v, 4, 1048576, &o->table_size); break;
    case R_BITS: integer(a, v, 8, 32, &o->bits); break;
    case R_EXTENT: num(a, v, 1e-9, 1e9, &o->extent); break;
    case R_X0: num(a, v, -1e9, 1e9, &o->x0); break;
    case R_Y0: num(a, v, -1e9, 1e9, &o->y0); break;
    case R_Z: num(a, v, -1e9, 1e9, &o->z); break;
    case R_GAIN: num(a, v, -1e3, 1e3, &o->gain); break;
    case R_LACUNARITY: num(a, v, 1e-6, 1e6, &o->lacunarity); break;
    case R_AMPLITUDE: num(a, v, -1e6, 1e6, &o->amplitude); break;
    case R_STRIPES: num(a, v, 1e-9, 1e9, &o->stripes); break;
    case R_BASIS: o->basis = v; break;
    case R_TERMS: o->terms = v; break;
    case R_TILE: integer(a, v, 8, 256, &o->tile); break;
    case R_COUNT: o->count = v; break;
    case R_LAMBDA:
      num(a, v, -1e9, 1e9, &o->lambda);
      if (!(o->lambda > 0 && o->lambda <= 1000)) {
        snprintf(m, sizeof m, "--lambda: %s must be in (0, 1000] (mean feature points per unit cube)", v);
        fail(m);
      }
      break;
    case R_POINTS: integer(a, v, 1, NL_CELLULAR_MAX_M, &o->points); break;
    case R_NORMALIZE: o->normalize = v; break;
    }
  }
  nl_opt_end(&p);
  char m[512];
  if (!o->noise) fail("no NOISE given (see --help)");
  o->normalize_given = given[R_NORMALIZE];
  if (!given[R_NORMALIZE] && !strcmp(o->noise, "gctbf")) o->normalize = "range";
  /* Options the chosen noise or format does not read: say so, once each. */
  int sums = !strcmp(o->noise, "fractal") || !strcmp(o->noise, "turbulence") || !strcmp(o->noise, "fbm")
             || !strcmp(o->noise, "marble");
  const char *kind = sums ? o->basis : o->noise;
  int is_tsv = o->out && ends_with(o->out, ".tsv");
  struct { int opt, applies; const char *why; } rules[] = {
    {R_OCTAVES, sums, "only the sums (fractal, turbulence, fbm, marble) have octaves"},
    {R_GAIN, !strcmp(o->noise, "fbm"), "only fbm has a gain"},
    {R_LACUNARITY, !strcmp(o->noise, "fbm"), "only fbm has a lacunarity"},
    {R_AMPLITUDE, !strcmp(o->noise, "marble"), "only marble has an amplitude"},
    {R_STRIPES, !strcmp(o->noise, "marble"), "only marble has stripes"},
    {R_BASIS, sums, "a single noise has no basis under it"},
    {R_TERMS, !strcmp(kind, "gctbf"), "only gctbf reads terms"},
    {R_COUNT, !strcmp(kind, "gctbf"), "only gctbf counts feature points"},
    {R_LAMBDA, !strcmp(kind, "gctbf"), "only gctbf has feature points"},
    {R_POINTS, !strcmp(kind, "gctbf"), "only gctbf has feature points"},
    {R_TILE, !strcmp(kind, "wavelet"), "only wavelet noise has a tile"},
    {R_TABLE_SIZE, !strcmp(kind, "noise2") || !strcmp(kind, "table"), "only noise2 (or basis table) has a gradient table"},
    {R_REFERENCE, !strcmp(kind, "improved"), "only improved noise has Perlin's permutation"},
    {R_Z, strcmp(kind, "noise2") && strcmp(kind, "table"), "2D table noise has no plane z"},
    {R_BITS, !is_tsv, "a .tsv holds the values as text"},
    {R_NORMALIZE, !is_tsv, "a .tsv holds the raw values"},
  };
  for (size_t i = 0; i < sizeof rules / sizeof *rules; i++)
    if (given[rules[i].opt] && !rules[i].applies)
      fprintf(stderr, "noiselab render: warning: --%s ignored for %s%s: %s\n", spec[rules[i].opt].name,
              o->noise, is_tsv && (rules[i].opt == R_BITS || rules[i].opt == R_NORMALIZE) ? " to a .tsv" : "", rules[i].why);
  if (given[R_BITS] && o->out && (ends_with(o->out, ".jpg") || ends_with(o->out, ".jpeg")) && o->bits != 8)
  { fprintf(stderr, "noiselab render: warning: --bits %ld: JPEG stores 8 bits; writing 8\n", o->bits); o->bits = 8; }
  if (!one_of(o->noise, NOISES)) { snprintf(m, sizeof m, "%s: unknown noise (noise2, improved, gctbf, wavelet, fractal, turbulence, fbm, marble)", o->noise); fail(m); }
  if (!o->out) fail("-o: no output file given");
  const char *bases[] = {"improved", "table", "gctbf", "wavelet", NULL}, *norms[] = {"bound", "range", NULL};
  const char *counts[] = {"inverse", "closest", NULL};
  if (!one_of(o->basis, bases)) { snprintf(m, sizeof m, "--basis: '%s' is not improved, table, gctbf or wavelet", o->basis); fail(m); }
  if (!one_of(o->count, counts)) { snprintf(m, sizeof m, "--count: '%s' is not inverse or closest", o->count); fail(m); }
  if (!one_of(o->normalize, norms)) { snprintf(m, sizeof m, "--normalize: '%s' is not bound or range", o->normalize); fail(m); }
  if (o->bits && o->bits != 8 && o->bits != 16 && o->bits != 32) { snprintf(m, sizeof m, "--bits: %ld is not 8, 16 or 32", o->bits); fail(m); }
  /* values (double) and the image (float); a .tsv holds 3 columns of a
   * table (number and text slot each) that may be doubled while growing */
  size_t len = strlen(o->out);
  int tsv = len >= 4 && strcasecmp(o->out + len - 4, ".tsv") == 0;
  double bytes = (double)o->size * o->size * (12.0 + (tsv ? 96.0 : 0.0));
  if (!nl_mem_fits(bytes)) {
    char b1[32], b2[32];
    snprintf(m, sizeof m, "--size %ld%s needs %s of memory; this machine has %s", o->size,
             tsv ? " as a .tsv" : "", nl_format_bytes(b1, bytes), nl_format_bytes(b2, nl_mem_physical()));
    fail(m);
  }
}

static void check_writable(const char *path)
{
  nl_error err;
  if (nl_path_check_writable(path, &err)) fail(err.msg);
}

/* The lattice coordinate of the finest octave must stay below 2^52: beyond
 * it doubles have no fractional bits, the noise is 0 or meaningless, and
 * (before the floors were made safe) the cell index overflowed a long. */
static void check_lattice(const options *o, const nl_noise_octaves *oct, const char *kind)
{
  double c = fmax(fmax(fabs(o->x0), fabs(o->x0 + o->extent)), fmax(fabs(o->y0), fabs(o->y0 + o->extent)));
  if (strcmp(kind, "noise2") && strcmp(kind, "table")) c = fmax(c, fabs(o->z));   /* 3D bases */
  double f = 0;
  for (int l = 0; l < oct->n; l++) f = fmax(f, fabs(oct->freq[l]));
  if (f * c < 0x1p52) return;
  char m[600];
  if (!strcmp(o->noise, "fbm"))
    snprintf(m, sizeof m, "--lacunarity %g with --octaves %ld: the finest octave's frequency %g "
             "times the window's largest coordinate %g is %g, beyond 2^52 = 4.5e15 where the "
             "noise lattice has no fractional positions; use fewer octaves or a smaller lacunarity",
             o->lacunarity, o->octaves, f, c, f * c);
  else
    snprintf(m, sizeof m, "--octaves %ld: the finest octave's frequency %g times the window's "
             "largest coordinate %g is %g, beyond 2^52 = 4.5e15 where the noise lattice has no "
             "fractional positions; use fewer octaves or a window nearer the origin",
             o->octaves, f, c, f * c);
  fail(m);
}


/* Evaluates the chosen noise; *lo, *hi are its analytic range. */
static double *evaluate(const options *o, double *lo, double *hi)
{
  nl_noise_window win = {o->x0, o->y0, o->z, o->extent, (int)o->size, (int)o->size};
  nl_noise_grad2 *t = NULL;
  nl_cellular *cell = NULL;
  nl_cellular_gctbf_basis gb;
  nl_noise_perm3 p;
  nl_noise_basis b;
  nl_wavelet_tile *tile = NULL;
  int single = !strcmp(o->noise, "noise2") || !strcmp(o->noise, "improved") || !strcmp(o->noise, "gctbf")
               || !strcmp(o->noise, "wavelet");
  const char *kind = single ? o->noise : o->basis;
  if (!strcmp(kind, "noise2") || !strcmp(kind, "table")) {
    t = nl_noise_grad2_alloc((size_t)o->table_size);
    nl_noise_grad2_seed(t, (unsigned long)o->seed);
    b = nl_noise_basis_grad2(t);
  } else if (!strcmp(kind, "gctbf")) {
    nl_error err;
    nl_cellular_count_rule rule = !strcmp(o->count, "closest") ? NL_COUNT_CLOSEST : NL_COUNT_INVERSE_CDF;
    if (nl_cellular_alloc(o->lambda, (int)o->points, rule, (unsigned long)o->seed, &cell, &err)) fail(err.msg);
    gb.cell = cell;
    if (nl_cellular_gctbf_parse(o->terms, &gb.g, &err)) { char m[600]; snprintf(m, sizeof m, "--terms: %s", err.msg); fail(m); }
    b = nl_cellular_basis_gctbf(&gb);
  } else if (!strcmp(kind, "wavelet")) {
    if (o->tile % 2) fail("--tile: the wavelet tile period must be even");
    tile = nl_wavelet_tile_alloc(3, (int)o->tile);
    nl_wavelet_tile_seed(tile, (unsigned long)o->seed);
    b = nl_wavelet_basis(tile);
  } else {
    if (o->reference) nl_noise_perm3_reference(&p); else nl_noise_perm3_seed(&p, (unsigned long)o->seed);
    b = nl_noise_basis_perm3(&p);
  }
  nl_noise_octaves oct = nl_noise_octaves_fbm(1, 1, 1);
  if (!strcmp(o->noise, "fractal") || !strcmp(o->noise, "marble")) oct = nl_noise_octaves_fractal((int)o->octaves);
  if (!strcmp(o->noise, "turbulence")) { oct = nl_noise_octaves_fractal((int)o->octaves); oct.turbulence = 1; }
  if (!strcmp(o->noise, "fbm")) oct = nl_noise_octaves_fbm((int)o->octaves, o->gain, o->lacunarity);
  check_lattice(o, &oct, kind);
  double *v = nl_xmalloc((size_t)o->size * o->size * sizeof *v);
  double B = nl_noise_octaves_bound(&oct, b.bound);
  if (!strcmp(o->noise, "marble")) { nl_texture_marble_grid(&b, &oct, &win, NL_TWO_PI * o->stripes, o->amplitude, v); *lo = 0; *hi = 1; }
  else { nl_noise_fractal_grid(&b, &oct, &win, v); *lo = oct.turbulence ? 0 : -B; *hi = B; }
  nl_noise_grad2_free(t);
  nl_cellular_free(cell);
  nl_wavelet_tile_free(tile);
  return v;
}

static void write_tsv(const options *o, const double *v)
{
  const char *cols[] = {"x", "y", "value"};
  nl_table *t = nl_table_alloc(3, cols);
  double d = o->extent / o->size;
  for (long r = 0; r < o->size; r++)
    for (long c = 0; c < o->size; c++)
      nl_table_append(t, "ddd", o->x0 + (c + 0.5) * d, o->y0 + (r + 0.5) * d, v[r * o->size + c]);
  nl_error err;
  if (nl_table_write(t, o->out, &err)) fail(err.msg);
  fprintf(stderr, "noiselab render: wrote %s (%ld x %ld values of %s: x, y, value)\n", o->out, o->size, o->size, o->noise);
  nl_table_free(t);
}

static void write_image(const options *o, const double *v, double lo, double hi)
{
  int raw = o->bits == 32 || (ends_with(o->out, ".exr") && o->bits != 16);
  int bits = o->bits ? (int)o->bits : raw ? 32 : 8;
  size_t n = (size_t)o->size * o->size;
  if (!raw && !strcmp(o->normalize, "range")) {
    lo = hi = v[0];
    for (size_t k = 0; k < n; k++) { lo = v[k] < lo ? v[k] : lo; hi = v[k] > hi ? v[k] : hi; }
  }
  nl_image *im = raw ? nl_image_alloc((int)o->size, (int)o->size, 1)
                     : nl_image_from_values(v, (int)o->size, (int)o->size, lo, hi);
  if (raw) for (size_t k = 0; k < n; k++) im->data[k] = (float)v[k];
  nl_error err;
  if (nl_image_write(im, o->out, bits, &err)) fail(err.msg);
  if (raw) fprintf(stderr, "noiselab render: wrote %s (%ld x %ld %s, %d-bit float, raw values)\n", o->out, o->size, o->size, o->noise, bits);
  else fprintf(stderr, "noiselab render: wrote %s (%ld x %ld %s, %d-bit, values [%.4g, %.4g] to black..white: %s)\n", o->out,
               o->size, o->size, o->noise, bits, lo, hi, strcmp(o->normalize, "range") ? "the analytic bound" : "the image's range");
  nl_image_free(im);
}

/* No file is written holding NaN or inf: name the first such pixel. */
static void check_finite(const options *o, const double *v)
{
  size_t n = (size_t)o->size * o->size;
  for (size_t k = 0; k < n; k++)
    if (!isfinite(v[k])) {
      char m[256];
      snprintf(m, sizeof m, "%s: the noise is not finite (%g) at pixel (%zu, %zu); nothing written",
               o->out, v[k], k % (size_t)o->size, k / (size_t)o->size);
      fail(m);
    }
}

int main(int argc, char **argv)
{
  nl_harness_program_start();   /* OOM handler; OpenBLAS's idle workers stopped */
  options o;
  parse(argc, argv, &o);
  check_writable(o.out);
  double lo, hi;
  double *v = evaluate(&o, &lo, &hi);
  check_finite(&o, v);
  if (ends_with(o.out, ".tsv")) write_tsv(&o, v);
  else write_image(&o, v, lo, hi);
  free(v);
  return 0;
}
