/* noiselab render - any noise of the library to an image or a table.
 *
 *   noiselab render fbm --octaves 6 --gain 0.5 --lacunarity 2 --size 512 --seed 7 -o fbm.png
 *
 * Images go through OpenImageIO (format from the extension). Integer
 * formats (8/16-bit PNG, TIFF, ...) store the image's min..max mapped to
 * black..white, so that every picture uses the whole grey scale (an fBm's
 * values fill under half of its analytic bound); --normalize bound maps the
 * noise's analytic bound B instead, (v / B + 1) / 2 or v / B for
 * turbulence, so that grey levels mean the same thing at every setting.
 * stderr names the mapping and its values. Float formats (EXR, or --bits
 * 32) store raw values. A .tsv output, or "-o -" (stdout), holds the raw
 * values as columns x, y, value; a .npy (numpy's format, float64, rows by
 * y) the raw values as a size x size array.
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"
#include "basis/nl_basis.h"
#include "table/nl_table.h"
#include "base/nl_parallel.h"

#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The render's options: the noise's own (nl_basis.h) and the picture's. */
typedef struct {
  const char *noise, *out, *basis, *normalize, *count;
  const nl_basis_sum *sum;   /* the chosen sum, or nl_basis_single */
  nl_basis_options bo;
  nl_basis_sum_options so;
  long size, seed, bits, threads;
  double extent, x0, y0, z;
} options;

/* The registry's names joined by sep (the last by `last`): as noises of
 * their own, with the sums, or as --basis spells them, the default first. */
static void names(char *buf, size_t n, int under, const char *sep, const char *last)
{
  size_t nk, ns, len = 0, total;
  const nl_basis_kind *k = nl_basis_kinds(&nk);
  const nl_basis_sum *s = nl_basis_sums(&ns);
  const char *list[16];
  total = 0;
  if (under)
    list[total++] = nl_basis_default()->under;
  for (size_t i = 0; i < nk; i++)
    if (!under || &k[i] != nl_basis_default())
      list[total++] = under ? k[i].under : k[i].name;
  for (size_t i = 0; !under && i < ns; i++)
    list[total++] = s[i].name;
  buf[0] = '\0';
  for (size_t i = 0; i < total && len < n; i++)
    len += (size_t)snprintf(buf + len, n - len, "%s%s", i == 0 ? "" : i + 1 < total ? sep : last,
                            list[i]);
}

static void usage(void)
{
  size_t nk, ns;
  const nl_basis_kind *k = nl_basis_kinds(&nk);
  const nl_basis_sum *s = nl_basis_sums(&ns);
  char bases[128];
  names(bases, sizeof bases, 1, "|", "|");
  printf("usage: noiselab render NOISE [options] -o FILE   "
         "(options: --name VALUE or --name=VALUE)\n\n");
  for (size_t i = 0; i < nk + ns; i++)
    printf("%s%-12s%s\n", i ? "       " : "NOISE: ", i < nk ? k[i].name : s[i - nk].name,
           i < nk ? k[i].summary : s[i - nk].summary);
  printf("\n  -o FILE              .png .exr .tif ... (OpenImageIO), .tsv (x, y, value), - (the\n"
         "                       .tsv on stdout) or .npy (numpy: float64, size x size, rows by y)\n"
         "  --size N             pixels per side, 1..65536 (512)\n"
         "  --extent X           side of the square in noise units (4)\n"
         "  --x0 X --y0 Y --z Z  window origin and plane (0 0 0.5)\n"
         "  --octaves N          1..30 (6)          --gain G (0.5)   --lacunarity L (2)\n"
         "  --amplitude A        marble displacement a (0.5)   --stripes K per unit (1)\n"
         "  --basis %s   noise under the sums (%s)\n"
         "  --tile N             wavelet tile period, even, 8..256 (64)\n"
         "  --terms EXPR         GCTBF, e.g. \"F2 - F1 - F1F1\" or \"0.5*F1 + 2 F1*F2\" (F1)\n"
         "  --lambda L           mean feature points per unit cube, (0, 1000] (4)\n"
         "  --points M           feature points per cube at most, 1..64 (50)\n"
         "  --count inverse|closest|closest-last  feature-point count rule (inverse:\n"
         "                       inverse-CDF sampling; closest: the paper's 'p(m) closest to\n"
         "                       r', the smaller m on ties; closest-last: the larger)\n"
         "  --table-size M       gradient-table size for noise2/table, 4..1048576 (512)\n"
         "  --seed S             table seed (1)   --reference  Perlin's own permutation\n"
         "  --bits 8|16|32       image bit depth (8; EXR defaults to 32)\n"
         "  --threads N          threads for the sums' grids, 1..%d (default: the %d\n"
         "                       processors online); the same values for any count\n"
         "  --normalize range|bound   grey mapping for integer formats: the image's min..max\n"
         "                       (range), or the noise's analytic bound, the same grey for\n"
         "                       the same value at every setting (bound)\n\n"
         "Pixel (column c, row r) holds the noise at x = x0 + (c + 1/2) extent / size,\n"
         "y = y0 + (r + 1/2) extent / size: row 0 is the top of the image, so y grows\n"
         "downward in the picture (as the .tsv's rows). An option that does not apply to\n"
         "the chosen noise or output format is ignored with a warning.\n",
         bases, nl_basis_default()->under, NL_PARALLEL_MAX, nl_parallel_cores());
}

/* One line on stderr, exit 2: input quoted in it is escaped (nl_message). */
#define fail(...) nl_tool_die("noiselab render: ", __VA_ARGS__)

static void num(const char *opt, const char *val, double lo, double hi, double *out)
{
  nl_error err;
  if (nl_parse_double(opt, val, lo, hi, out, &err)) fail("%s", err.msg);
}

static void integer(const char *opt, const char *val, long lo, long hi, long *out)
{
  nl_error err;
  if (nl_parse_long(opt, val, lo, hi, out, &err)) fail("%s", err.msg);
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

/* Outputs that hold the values themselves, not a picture: a table (.tsv or
 * "-", stdout) or a numpy array (.npy). */
static int raw_values(const char *out)
{
  return !strcmp(out, "-") || ends_with(out, ".tsv") || ends_with(out, ".npy");
}

static void parse(int argc, char **argv, options *o)
{
  *o = (options){.basis = nl_basis_default()->under, .normalize = "range", .count = "inverse",
                 .bo = nl_basis_defaults(), .so = nl_basis_sum_defaults(), .size = 512, .seed = 1,
                 .bits = 0, .extent = 4, .z = 0.5, .threads = nl_parallel_cores()};
  enum { R_OUT, R_SIZE, R_OCTAVES, R_SEED, R_TABLE_SIZE, R_BITS, R_EXTENT, R_X0, R_Y0, R_Z, R_GAIN,
         R_LACUNARITY, R_AMPLITUDE, R_STRIPES, R_BASIS, R_TERMS, R_TILE, R_COUNT, R_LAMBDA, R_POINTS,
         R_NORMALIZE, R_REFERENCE, R_THREADS, R_HELP };
  static const nl_opt_spec spec[] = {
    [R_OUT] = {"out", 'o', 1}, [R_SIZE] = {"size", 0, 1}, [R_OCTAVES] = {"octaves", 0, 1},
    [R_SEED] = {"seed", 0, 1}, [R_TABLE_SIZE] = {"table-size", 0, 1}, [R_BITS] = {"bits", 0, 1},
    [R_EXTENT] = {"extent", 0, 1}, [R_X0] = {"x0", 0, 1}, [R_Y0] = {"y0", 0, 1}, [R_Z] = {"z", 0, 1},
    [R_GAIN] = {"gain", 0, 1}, [R_LACUNARITY] = {"lacunarity", 0, 1}, [R_AMPLITUDE] = {"amplitude", 0, 1},
    [R_STRIPES] = {"stripes", 0, 1}, [R_BASIS] = {"basis", 0, 1}, [R_TERMS] = {"terms", 0, 1},
    [R_TILE] = {"tile", 0, 1}, [R_COUNT] = {"count", 0, 1}, [R_LAMBDA] = {"lambda", 0, 1},
    [R_POINTS] = {"points", 0, 1}, [R_NORMALIZE] = {"normalize", 0, 1}, [R_REFERENCE] = {"reference", 0, 0},
    [R_THREADS] = {"threads", 0, 1},
    [R_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser p;
  nl_error err;
  int given[R_HELP + 1] = {0};
  nl_opt_begin(&p, argc, argv, 1, spec);
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    const char *a = p.name, *v = p.value[0];
    if (k >= 0) given[k] = 1;
    switch (k) {
    case NL_OPT_ERROR: fail("%s (see --help)", err.msg);
    case NL_OPT_POSITIONAL:
      if (o->noise) fail("%s: only one NOISE may be given", v);
      o->noise = v;
      break;
    case R_HELP: usage(); exit(0);
    case R_REFERENCE: o->bo.reference = 1; break;
    case R_OUT: o->out = v; break;
    /* the window's, the sum's and the basis's ranges are the library's
     * (nl_basis_window_check, nl_basis_sum_check, nl_basis_options_check,
     * after the loop), which the Python binding calls too */
    case R_SIZE: integer(a, v, INT_MIN, INT_MAX, &o->size); break;
    case R_OCTAVES: integer(a, v, LONG_MIN, LONG_MAX, &o->so.octaves); break;
    case R_SEED: integer(a, v, 0, 4294967295L, &o->seed); break;
    case R_TABLE_SIZE: integer(a, v, LONG_MIN, LONG_MAX, &o->bo.table_size); break;
    case R_BITS: integer(a, v, 8, 32, &o->bits); break;
    case R_EXTENT: num(a, v, -HUGE_VAL, HUGE_VAL, &o->extent); break;
    case R_X0: num(a, v, -HUGE_VAL, HUGE_VAL, &o->x0); break;
    case R_Y0: num(a, v, -HUGE_VAL, HUGE_VAL, &o->y0); break;
    case R_Z: num(a, v, -HUGE_VAL, HUGE_VAL, &o->z); break;
    case R_GAIN: num(a, v, -HUGE_VAL, HUGE_VAL, &o->so.gain); break;
    case R_LACUNARITY: num(a, v, -HUGE_VAL, HUGE_VAL, &o->so.lacunarity); break;
    case R_AMPLITUDE: num(a, v, -HUGE_VAL, HUGE_VAL, &o->so.amplitude); break;
    case R_STRIPES: num(a, v, -HUGE_VAL, HUGE_VAL, &o->so.stripes); break;
    case R_BASIS: o->basis = v; break;
    case R_TERMS: o->bo.terms = v; break;
    case R_TILE: integer(a, v, LONG_MIN, LONG_MAX, &o->bo.tile); break;
    case R_COUNT: o->count = v; break;
    case R_LAMBDA:
      num(a, v, -HUGE_VAL, HUGE_VAL, &o->bo.lambda);
      break;
    case R_POINTS: integer(a, v, LONG_MIN, LONG_MAX, &o->bo.points); break;
    case R_NORMALIZE: o->normalize = v; break;
    case R_THREADS: integer(a, v, 1, NL_PARALLEL_MAX, &o->threads); break;
    }
  }
  nl_opt_end(&p);
  nl_noise_window win = {o->x0, o->y0, o->z, o->extent, (int)o->size, (int)o->size};
  if (nl_basis_window_check(&win, &err) || nl_basis_sum_check(&o->so, &err) ||
      nl_basis_options_check(&o->bo, &err))
    fail("%s", err.msg);
  char list[256];
  if (!o->noise) fail("no NOISE given (see --help)");
  /* The chosen sum (a single noise is the sum of one octave) and basis, as
   * the registry knows them; reads: what each of them takes from options. */
  const nl_basis_sum *sum = nl_basis_sum_find(o->noise);
  const nl_basis_kind *basis = nl_basis_find(sum ? o->basis : o->noise);
  unsigned sr = sum ? sum->reads : 0, br = basis ? basis->reads : 0;
  int known = sum || (basis && !strcmp(o->noise, basis->name));   /* "table": under a sum only */
  o->sum = sum ? sum : &nl_basis_single;
  /* Options the chosen noise or format does not read: say so, once each. */
  int is_tsv = o->out && raw_values(o->out);
  struct { int opt, applies; const char *why; } rules[] = {
    {R_OCTAVES, sr & NL_BASIS_SUM_OCTAVES,
     "only the sums (fractal, turbulence, fbm, marble) have octaves"},
    {R_GAIN, sr & NL_BASIS_SUM_FBM, "only fbm has a gain"},
    {R_LACUNARITY, sr & NL_BASIS_SUM_FBM, "only fbm has a lacunarity"},
    {R_AMPLITUDE, sr & NL_BASIS_SUM_MARBLE, "only marble has an amplitude"},
    {R_STRIPES, sr & NL_BASIS_SUM_MARBLE, "only marble has stripes"},
    {R_BASIS, sr & NL_BASIS_SUM_OCTAVES, "a single noise has no basis under it"},
    {R_TERMS, br & NL_BASIS_READS_CELLS, "only gctbf reads terms"},
    {R_COUNT, br & NL_BASIS_READS_CELLS, "only gctbf counts feature points"},
    {R_LAMBDA, br & NL_BASIS_READS_CELLS, "only gctbf has feature points"},
    {R_POINTS, br & NL_BASIS_READS_CELLS, "only gctbf has feature points"},
    {R_TILE, br & NL_BASIS_READS_TILE, "only wavelet noise has a tile"},
    {R_TABLE_SIZE, br & NL_BASIS_READS_TABLE,
     "only noise2 (or basis table) has a gradient table"},
    {R_REFERENCE, br & NL_BASIS_READS_REFERENCE, "only improved noise has Perlin's permutation"},
    {R_Z, !(br & NL_BASIS_PLANAR), "2D table noise has no plane z"},
    {R_BITS, !is_tsv, "a table or .npy holds the values as they are"},
    {R_NORMALIZE, !is_tsv, "a table or .npy holds the raw values"},
  };
  for (size_t i = 0; i < sizeof rules / sizeof *rules; i++) {
    if (!given[rules[i].opt] || rules[i].applies) continue;
    int format = rules[i].opt == R_BITS || rules[i].opt == R_NORMALIZE;
    nl_message(stderr, "noiselab render: warning: --%s ignored for %s%s: %s",
               spec[rules[i].opt].name, o->noise, is_tsv && format ? " to a table or .npy" : "",
               rules[i].why);
  }
  if (given[R_BITS] && o->out && (ends_with(o->out, ".jpg") || ends_with(o->out, ".jpeg")) && o->bits != 8)
  { fprintf(stderr, "noiselab render: warning: --bits %ld: JPEG stores 8 bits; writing 8\n", o->bits); o->bits = 8; }
  if (!known) {
    names(list, sizeof list, 0, ", ", ", ");
    fail("%s: unknown noise (%s)", o->noise, list);
  }
  if (!o->out) fail("-o: no output file given");
  const char *norms[] = {"bound", "range", NULL};
  const char *counts[] = {"inverse", "closest", "closest-last", NULL};
  const nl_basis_kind *under = nl_basis_find(o->basis);
  if (!under || strcmp(o->basis, under->under)) {
    names(list, sizeof list, 1, ", ", " or ");
    fail("--basis: '%s' is not %s", o->basis, list);
  }
  if (!one_of(o->count, counts)) {
    fail("--count: '%s' is not inverse, closest or closest-last", o->count);
  }
  o->bo.count = !strcmp(o->count, "closest") ? NL_COUNT_CLOSEST
              : !strcmp(o->count, "closest-last") ? NL_COUNT_CLOSEST_LAST : NL_COUNT_INVERSE_CDF;
  if (!one_of(o->normalize, norms)) fail("--normalize: '%s' is not bound or range", o->normalize);
  if (o->bits && o->bits != 8 && o->bits != 16 && o->bits != 32)
    fail("--bits: %ld is not 8, 16 or 32", o->bits);
  nl_error berr;
  if (!raw_values(o->out) && nl_image_check_bits(o->out, (int)o->bits, &berr))
    fail("%s", berr.msg);
  /* values (double) and the image (float); a .tsv holds 3 columns of a
   * table (number and text slot each) that may be doubled while growing */
  int tsv = raw_values(o->out) && !ends_with(o->out, ".npy");
  double bytes = (double)o->size * o->size * (12.0 + (tsv ? 96.0 : 0.0));
  if (!nl_mem_fits(bytes)) {
    char b1[32], b2[32];
    fail("--size %ld%s needs %s of memory; %s is available", o->size, tsv ? " as a .tsv" : "",
         nl_format_bytes(b1, bytes), nl_format_bytes(b2, nl_mem_available()));
  }
}

static void check_writable(const char *path)
{
  nl_error err;
  if (nl_path_check_writable(path, &err)) fail("%s", err.msg);
}

/* The lattice coordinate of the finest octave must stay below 2^52: beyond
 * it doubles have no fractional bits, the noise is 0 or meaningless, and a
 * cell index would overflow a long. */
static void check_lattice(const options *o, const nl_noise_octaves *oct, const nl_basis *b)
{
  double c = fmax(fmax(fabs(o->x0), fabs(o->x0 + o->extent)),
                  fmax(fabs(o->y0), fabs(o->y0 + o->extent)));
  if (!(b->kind->reads & NL_BASIS_PLANAR))
    c = fmax(c, fabs(o->z));   /* 3D bases */
  double f = 0;
  for (int l = 0; l < oct->n; l++)
    f = fmax(f, fabs(oct->freq[l]));
  if (f * c < 0x1p52)
    return;
  if (o->sum->reads & NL_BASIS_SUM_FBM)
    fail("--lacunarity %g with --octaves %ld: the finest octave's frequency %g times the window's "
         "largest coordinate %g is %g, beyond 2^52 = 4.5e15 where the noise lattice has no "
         "fractional positions; use fewer octaves or a smaller lacunarity",
         o->so.lacunarity, o->so.octaves, f, c, f * c);
  fail("--octaves %ld: the finest octave's frequency %g times the window's largest coordinate %g "
       "is %g, beyond 2^52 = 4.5e15 where the noise lattice has no fractional positions; use "
       "fewer octaves or a window nearer the origin",
       o->so.octaves, f, c, f * c);
}

/* Evaluates the chosen noise (nl_basis.h builds it); *lo, *hi are its
 * analytic range. */
static double *evaluate(const options *o, double *lo, double *hi)
{
  nl_noise_window win = {o->x0, o->y0, o->z, o->extent, (int)o->size, (int)o->size};
  const char *kind = o->sum == &nl_basis_single ? o->noise : o->basis;
  nl_basis *b;
  nl_error err;
  if (nl_basis_make(kind, &o->bo, (unsigned long)o->seed, &b, &err))
    fail("%s", err.msg);
  nl_noise_octaves oct = o->sum->octaves(&o->so);
  check_lattice(o, &oct, b);
  double *v = nl_xmalloc((size_t)o->size * o->size * sizeof *v);
  nl_basis_sum_grid_threads(o->sum, &b->noise, &oct, &o->so, &win, (int)o->threads, v, lo, hi);
  nl_basis_free(b);
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
  int out = !strcmp(o->out, "-");
  if (out ? nl_table_print(t, stdout, "<stdout>", &err) : nl_table_write(t, o->out, &err)) {
    if (out) clearerr(stdout);   /* said here with its reason, not again at exit */
    fail("%s", err.msg);
  }
  nl_message(stderr, "noiselab render: wrote %s (%ld x %ld values of %s: x, y, value)",
             out ? "<stdout>" : o->out, o->size, o->size, o->noise);
  nl_table_free(t);
}

/* numpy's .npy, version 1.0: magic, header length (2 bytes, little-endian),
 * a Python dict literal padded with spaces to a multiple of 64 bytes and
 * ended by a newline, then the doubles in C order (row r is y = y0 + ...). */
static void write_npy(const options *o, const double *v)
{
  unsigned one = 1;
  int little = *(unsigned char *)&one == 1;
  char head[128];
  int n = snprintf(head + 10, sizeof head - 10,
                   "{'descr': '%cf8', 'fortran_order': False, 'shape': (%ld, %ld), }",
                   little ? '<' : '>', o->size, o->size);
  int total = (10 + n + 1 + 63) / 64 * 64;   /* magic, length, dict, newline */
  memset(head + 10 + n, ' ', (size_t)(total - 10 - n - 1));
  head[total - 1] = '\n';
  memcpy(head, "\x93NUMPY\x01\x00", 8);
  head[8] = (char)((total - 10) & 0xff);
  head[9] = (char)((total - 10) >> 8);
  nl_atomic_file af;
  nl_error err;
  if (nl_atomic_open(&af, o->out, &err)) fail("%s", err.msg);
  fwrite(head, 1, (size_t)total, af.fp);
  fwrite(v, sizeof *v, (size_t)o->size * (size_t)o->size, af.fp);
  if (nl_atomic_commit(&af, &err)) fail("%s", err.msg);
  nl_message(stderr, "noiselab render: wrote %s (%ld x %ld float64 values of %s, numpy .npy)",
             o->out, o->size, o->size, o->noise);
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
  if (nl_image_write(im, o->out, bits, &err)) fail("%s", err.msg);
  if (raw)
    nl_message(stderr, "noiselab render: wrote %s (%ld x %ld %s, %d-bit float, raw values)", o->out,
               o->size, o->size, o->noise, bits);
  else
    nl_message(stderr, "noiselab render: wrote %s (%ld x %ld %s, %d-bit, values [%.4g, %.4g] to "
               "black..white: %s)", o->out, o->size, o->size, o->noise, bits, lo, hi,
               strcmp(o->normalize, "range") ? "the analytic bound" : "the image's range");
  nl_image_free(im);
}

/* No file is written holding NaN or inf: name the first such pixel. */
static void check_finite(const options *o, const double *v)
{
  size_t n = (size_t)o->size * o->size;
  for (size_t k = 0; k < n; k++)
    if (!isfinite(v[k])) {
      fail("%s: the noise is not finite (%g) at pixel (%zu, %zu); nothing written", o->out, v[k],
           k % (size_t)o->size, k / (size_t)o->size);
    }
}

int main(int argc, char **argv)
{
  nl_tool_start("noiselab render");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  options o;
  parse(argc, argv, &o);
  nl_tool_check_output(o.out, NULL, 0);   /* not the program's own sources */
  if (strcmp(o.out, "-")) check_writable(o.out);
  double lo, hi;
  double *v = evaluate(&o, &lo, &hi);
  check_finite(&o, v);
  if (!strcmp(o.out, "-") || ends_with(o.out, ".tsv")) write_tsv(&o, v);
  else if (ends_with(o.out, ".npy")) write_npy(&o, v);
  else write_image(&o, v, lo, hi);
  free(v);
  return 0;
}
