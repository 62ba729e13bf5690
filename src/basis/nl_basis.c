/* The noise registry (nl_basis.h): each basis and each sum of octaves named
 * once, with the call that builds or evaluates it. */
#include "basis/nl_basis.h"
#include "texture/nl_texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

nl_basis_options nl_basis_defaults(void)
{
  return (nl_basis_options){.table_size = 512, .lambda = 4, .points = 50,
                            .count = NL_COUNT_INVERSE_CDF, .terms = "F1", .tile = 64};
}

nl_basis_sum_options nl_basis_sum_defaults(void)
{
  return (nl_basis_sum_options){.octaves = 6, .gain = 0.5, .lacunarity = 2, .amplitude = 0.5,
                                .stripes = 1};
}

/* what in [lo, hi] and finite: nl_parse_double's words, so that a value
 * refused here reads as the command line's refusal */
static nl_status in_range(const char *what, double v, double lo, double hi, nl_error *err)
{
  if (!isfinite(v)) return nl_fail(err, NL_EINVAL, "%s: %g is not a finite number", what, v);
  if (!(v >= lo && v <= hi)) return nl_fail(err, NL_EINVAL, "%s: %g is outside [%g, %g]", what, v, lo, hi);
  return NL_OK;
}

nl_status nl_basis_sum_check(const nl_basis_sum_options *o, nl_error *err)
{
  if (o->octaves < 1 || o->octaves > NL_BASIS_MAX_OCTAVES)
    return nl_fail(err, NL_EINVAL, "--octaves: %ld is outside [1, %d]", o->octaves, NL_BASIS_MAX_OCTAVES);
  if (in_range("--gain", o->gain, -1e3, 1e3, err) || in_range("--lacunarity", o->lacunarity, 1e-6, 1e6, err) ||
      in_range("--amplitude", o->amplitude, -1e6, 1e6, err) || in_range("--stripes", o->stripes, 1e-9, 1e9, err))
    return NL_EINVAL;
  return NL_OK;
}

nl_status nl_basis_options_check(const nl_basis_options *o, nl_error *err)
{
  if (o->table_size < 4 || o->table_size > NL_BASIS_MAX_TABLE)
    return nl_fail(err, NL_EINVAL, "--table-size: %ld is outside [4, %d]", o->table_size, NL_BASIS_MAX_TABLE);
  if (o->tile < 8 || o->tile > 256) return nl_fail(err, NL_EINVAL, "--tile: %ld is outside [8, 256]", o->tile);
  if (!isfinite(o->lambda))   /* the parser's words, as the other options' */
    return nl_fail(err, NL_EINVAL, "--lambda: %g is not a finite number", o->lambda);
  if (!(o->lambda > 0 && o->lambda <= 1000))
    return nl_fail(err, NL_EINVAL, "--lambda: %g must be in (0, 1000] (mean feature points per unit cube)",
                   o->lambda);
  if (o->points < 1 || o->points > NL_CELLULAR_MAX_M)
    return nl_fail(err, NL_EINVAL, "--points: %ld is outside [1, %d]", o->points, NL_CELLULAR_MAX_M);
  if (o->count != NL_COUNT_CLOSEST && o->count != NL_COUNT_INVERSE_CDF && o->count != NL_COUNT_CLOSEST_LAST)
    return nl_fail(err, NL_EINVAL, "--count: %d is not a count rule", (int)o->count);
  return NL_OK;
}

nl_status nl_basis_window_check(const nl_noise_window *win, nl_error *err)
{
  if (win->w < 1 || win->w > NL_BASIS_MAX_SIZE || win->h < 1 || win->h > NL_BASIS_MAX_SIZE)
    return nl_fail(err, NL_EINVAL, "--size: %d is outside [1, %d]", win->w < 1 || win->w > NL_BASIS_MAX_SIZE ? win->w : win->h,
                   NL_BASIS_MAX_SIZE);
  if (in_range("--extent", win->size, 1e-9, 1e9, err) || in_range("--x0", win->x0, -1e9, 1e9, err) ||
      in_range("--y0", win->y0, -1e9, 1e9, err) || in_range("--z", win->z, -1e9, 1e9, err))
    return NL_EINVAL;
  return NL_OK;
}

/* ---- the bases ------------------------------------------------------------ */

static nl_status make_grad2(nl_basis *b, const nl_basis_options *o, unsigned long seed,
                            nl_error *err)
{
  if (o->table_size < 4)
    return nl_fail(err, NL_EINVAL, "--table-size: %ld is below 4", o->table_size);
  if (o->table_size > NL_BASIS_MAX_TABLE)
    return nl_fail(err, NL_EINVAL, "--table-size: %ld is outside [4, %d]", o->table_size, NL_BASIS_MAX_TABLE);
  b->grad2 = nl_noise_grad2_alloc((size_t)o->table_size);
  nl_noise_grad2_seed(b->grad2, seed);
  b->noise = nl_noise_basis_grad2(b->grad2);
  return NL_OK;
}

static nl_status make_perm3(nl_basis *b, const nl_basis_options *o, unsigned long seed,
                            nl_error *err)
{
  (void)err;
  if (o->reference)
    nl_noise_perm3_reference(&b->perm3);
  else
    nl_noise_perm3_seed(&b->perm3, seed);
  b->noise = nl_noise_basis_perm3(&b->perm3);
  return NL_OK;
}

static nl_status make_gctbf(nl_basis *b, const nl_basis_options *o, unsigned long seed,
                            nl_error *err)
{
  nl_error e;
  nl_status s = nl_cellular_alloc(o->lambda, (int)o->points, o->count, seed, &b->cell, err);
  if (s)
    return s;
  b->gctbf.cell = b->cell;
  if ((s = nl_cellular_gctbf_parse(o->terms, &b->gctbf.g, &e)))
    return nl_fail(err, s, "--terms: %s", e.msg);
  b->noise = nl_cellular_basis_gctbf(&b->gctbf);
  return NL_OK;
}

static nl_status make_wavelet(nl_basis *b, const nl_basis_options *o, unsigned long seed,
                              nl_error *err)
{
  /* nl_wavelet_tile_alloc's own limit is 512, a 512 MiB tile: render's 256 */
  if (o->tile < 8 || o->tile > 256 || o->tile % 2)
    return nl_fail(err, NL_EINVAL, "--tile: the wavelet tile period must be even and in 8..256, "
                   "not %ld", o->tile);
  b->tile = nl_wavelet_tile_alloc(3, (int)o->tile);
  nl_wavelet_tile_seed(b->tile, seed);
  b->noise = nl_wavelet_basis(b->tile);
  return NL_OK;
}

static const nl_basis_kind kinds[] = {
  {"noise2", "table", "2D gradient-table noise (Cheng 2009 eq. 3.1-3.2)",
   NL_BASIS_READS_TABLE | NL_BASIS_PLANAR, make_grad2},
  {"improved", "improved", "Perlin's improved 3D noise, on the plane z",
   NL_BASIS_READS_REFERENCE, make_perm3},
  {"gctbf", "gctbf", "Qin & Yang's generalized cellular basis sum c_i F_i + c_ij F_i F_j",
   NL_BASIS_READS_CELLS | NL_BASIS_LOOSE_BOUND, make_gctbf},
  {"wavelet", "wavelet", "Cook & DeRose's wavelet noise (3D tile, plane z)", NL_BASIS_READS_TILE,
   make_wavelet},
};

const nl_basis_kind *nl_basis_kinds(size_t *n)
{
  *n = sizeof kinds / sizeof *kinds;
  return kinds;
}

const nl_basis_kind *nl_basis_default(void)
{
  return &kinds[1];
}

const nl_basis_kind *nl_basis_find(const char *name)
{
  for (size_t i = 0; i < sizeof kinds / sizeof *kinds; i++)
    if (!strcmp(name, kinds[i].name) || !strcmp(name, kinds[i].under))
      return &kinds[i];
  return NULL;
}

nl_status nl_basis_make(const char *name, const nl_basis_options *o, unsigned long seed,
                        nl_basis **out, nl_error *err)
{
  const nl_basis_kind *k = nl_basis_find(name);
  nl_basis_options def = nl_basis_defaults();
  *out = NULL;
  if (!k)
    return nl_fail(err, NL_EINVAL, "%s: unknown noise basis", name);
  nl_basis *b = nl_xcalloc(1, sizeof *b);
  b->kind = k;
  nl_status s = k->make(b, o ? o : &def, seed, err);
  if (s) {
    nl_basis_free(b);
    return s;
  }
  *out = b;
  return NL_OK;
}

void nl_basis_free(nl_basis *b)
{
  if (!b)
    return;
  nl_noise_grad2_free(b->grad2);
  nl_cellular_free(b->cell);
  nl_wavelet_tile_free(b->tile);
  free(b);
}

/* ---- the sums ------------------------------------------------------------- */

static nl_noise_octaves one_octave(const nl_basis_sum_options *o)
{
  (void)o;
  return nl_noise_octaves_fbm(1, 1, 1);
}

static nl_noise_octaves fractal(const nl_basis_sum_options *o)
{
  return nl_noise_octaves_fractal((int)o->octaves);
}

static nl_noise_octaves turbulence(const nl_basis_sum_options *o)
{
  nl_noise_octaves oct = nl_noise_octaves_fractal((int)o->octaves);
  oct.turbulence = 1;
  return oct;
}

static nl_noise_octaves fbm(const nl_basis_sum_options *o)
{
  return nl_noise_octaves_fbm((int)o->octaves, o->gain, o->lacunarity);
}

/* The sum itself; its range is the analytic bound, [0, B] for turbulence. */
static void sum_grid(const nl_noise_basis *b, const nl_noise_octaves *oct,
                     const nl_basis_sum_options *o, const nl_noise_window *win, double *v,
                     double *lo, double *hi)
{
  (void)o;
  double B = nl_noise_octaves_bound(oct, b->bound);
  nl_noise_fractal_grid(b, oct, win, v);
  *lo = oct->turbulence ? 0 : -B;
  *hi = B;
}

static void marble_grid(const nl_noise_basis *b, const nl_noise_octaves *oct,
                        const nl_basis_sum_options *o, const nl_noise_window *win, double *v,
                        double *lo, double *hi)
{
  nl_texture_marble_grid(b, oct, win, NL_TWO_PI * o->stripes, o->amplitude, v);
  *lo = 0;
  *hi = 1;
}

const nl_basis_sum nl_basis_single = {"", "", 0, one_octave, sum_grid};

void nl_basis_sum_grid_threads(const nl_basis_sum *s, const nl_noise_basis *b,
                               const nl_noise_octaves *oct, const nl_basis_sum_options *o,
                               const nl_noise_window *win, int nthreads, double *v, double *lo,
                               double *hi)
{
  if (s->grid != sum_grid) {   /* marble: one thread */
    s->grid(b, oct, o, win, v, lo, hi);
    return;
  }
  double B = nl_noise_octaves_bound(oct, b->bound);
  nl_noise_fractal_grid_threads(b, oct, win, nthreads, v);   /* sum_grid's values, by rows */
  *lo = oct->turbulence ? 0 : -B;
  *hi = B;
}

static const nl_basis_sum sums[] = {
  {"fractal", "sum_j noise(2^j p) / 2^j            (Shaffer)", NL_BASIS_SUM_OCTAVES, fractal,
   sum_grid},
  {"turbulence", "sum_j |noise(2^j p)| / 2^j", NL_BASIS_SUM_OCTAVES, turbulence, sum_grid},
  {"fbm", "sum_j gain^j noise(lacunarity^j p)", NL_BASIS_SUM_OCTAVES | NL_BASIS_SUM_FBM, fbm,
   sum_grid},
  {"marble", "(1 + sin(2 pi stripes (y + amplitude fractal(p)))) / 2",
   NL_BASIS_SUM_OCTAVES | NL_BASIS_SUM_MARBLE, fractal, marble_grid},
};

const nl_basis_sum *nl_basis_sums(size_t *n)
{
  *n = sizeof sums / sizeof *sums;
  return sums;
}

const nl_basis_sum *nl_basis_sum_find(const char *name)
{
  for (size_t i = 0; i < sizeof sums / sizeof *sums; i++)
    if (!strcmp(name, sums[i].name))
      return &sums[i];
  return NULL;
}
