/* nl_basis.h - every noise of the library by name, built from (name,
 * options, seed): the one list that the render command and the surveys
 * behind S1-S3 share.
 *
 *   nl_basis_options o = nl_basis_defaults();
 *   o.terms = "F2 - F1";
 *   nl_basis *b;
 *   if (nl_basis_make("gctbf", &o, seed, &b, &err)) ... err.msg names the bad input
 *   const nl_basis_sum *s = nl_basis_sum_find("fbm");       // NULL: not a sum
 *   nl_basis_sum_options so = nl_basis_sum_defaults();
 *   nl_noise_octaves oct = s->octaves(&so);
 *   s->grid(&b->noise, &oct, &so, &win, v, &lo, &hi);       // w * h values, range [lo, hi]
 *   nl_basis_free(b);
 *
 * Two lists. A basis is a noise N(x, y, z) in its own right (nl_noise_basis:
 * rows and a bound |N| <= bound): noise2 (Cheng 2009's 2D gradient table,
 * eq. 3.1-3.2; called "table" under a sum), improved (Perlin 2002), gctbf
 * (Qin & Yang's cellular sum c_i F_i + c_ij F_i F_j, eq. 1) and wavelet
 * (Cook & DeRose 2005). A sum is a sum of octaves of a basis: fractal
 * (sum_j N(2^j p) / 2^j, Shaffer), turbulence (the same over |N|), fbm
 * (sum_j gain^j N(lacunarity^j p)) and marble ((1 + sin(2 pi stripes (y +
 * amplitude fractal(p)))) / 2). A basis on its own is the sum of one octave,
 * nl_basis_single.
 *
 * Each entry says which options it reads (the flags below), so a caller can
 * tell an option that does not apply from one that does. The same (name,
 * options, seed) always gives the same noise: the seed drives the
 * permutation, gradient table, feature points or wavelet tile as the
 * module's own _seed call does.
 */
#ifndef NL_BASIS_H
#define NL_BASIS_H

#include "base/nl_base.h"
#include "cellular/nl_cellular.h"
#include "noise/nl_noise.h"
#include "wavelet/nl_wavelet.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a basis reads of nl_basis_options, and how it lies in space. */
enum {
  NL_BASIS_READS_TABLE = 1 << 0,      /* table_size */
  NL_BASIS_READS_REFERENCE = 1 << 1,  /* reference */
  NL_BASIS_READS_CELLS = 1 << 2,      /* lambda, points, count, terms */
  NL_BASIS_READS_TILE = 1 << 3,       /* tile */
  NL_BASIS_PLANAR = 1 << 4,           /* 2D: ignores z */
  NL_BASIS_LOOSE_BOUND = 1 << 5       /* values fill a small part of its bound */
};

typedef struct {
  long table_size;                /* noise2: gradients in the table (512) */
  int reference;                  /* improved: Perlin's own permutation, not the seed's (0) */
  double lambda;                  /* gctbf: mean feature points per unit cube (4) */
  long points;                    /* gctbf: feature points per cube at most (50) */
  nl_cellular_count_rule count;   /* gctbf: how a cube's count is drawn (inverse CDF) */
  const char *terms;              /* gctbf: the sum, nl_cellular_gctbf_parse ("F1") */
  long tile;                      /* wavelet: tile period, even (64) */
} nl_basis_options;

nl_basis_options nl_basis_defaults(void);

struct nl_basis;
typedef struct {
  const char *name;      /* as a noise of its own */
  const char *under;     /* as the basis under a sum (--basis) */
  const char *summary;   /* one line for a command's help */
  unsigned reads;        /* NL_BASIS_* flags */
  nl_status (*make)(struct nl_basis *b, const nl_basis_options *o, unsigned long seed,
                    nl_error *err);
} nl_basis_kind;

/* The noise and what it points into (a basis owns its tables). */
typedef struct nl_basis {
  nl_noise_basis noise;
  const nl_basis_kind *kind;
  nl_noise_grad2 *grad2;
  nl_noise_perm3 perm3;
  nl_cellular *cell;
  nl_cellular_gctbf_basis gctbf;
  nl_wavelet_tile *tile;
} nl_basis;

/* The entries in their order; *n gets their number. */
const nl_basis_kind *nl_basis_kinds(size_t *n);
/* The basis under a sum when none is named: Perlin's improved noise. */
const nl_basis_kind *nl_basis_default(void);
/* The entry named name (either of its names), or NULL. */
const nl_basis_kind *nl_basis_find(const char *name);
/* Builds the basis name (o NULL: nl_basis_defaults()) for seed. An unknown
 * name, or options it cannot build from, is NL_EINVAL with a message that
 * names the input as the command line spells it ("--tile: ..."). */
nl_status nl_basis_make(const char *name, const nl_basis_options *o, unsigned long seed,
                        nl_basis **out, nl_error *err);
/* The ranges of render's basis options, every field whatever the basis
 * (render refuses --tile 7 for improved noise too, where it is ignored):
 * table_size 4..NL_BASIS_MAX_TABLE, tile 8..256 (even only where a wavelet
 * tile is built), lambda in (0, 1000], points 1..NL_CELLULAR_MAX_M, a known
 * count rule. NL_EINVAL naming the option ("--tile: 7 is outside [8, 256]");
 * the Python binding calls it before nl_basis_make, so that both refuse the
 * same values. nl_basis_make itself checks what the chosen basis reads. */
#define NL_BASIS_MAX_TABLE 1048576
nl_status nl_basis_options_check(const nl_basis_options *o, nl_error *err);
void nl_basis_free(nl_basis *b);

/* ---- sums of octaves ------------------------------------------------------ */

enum {
  NL_BASIS_SUM_OCTAVES = 1 << 0,   /* octaves, and a basis under it */
  NL_BASIS_SUM_FBM = 1 << 1,       /* gain, lacunarity */
  NL_BASIS_SUM_MARBLE = 1 << 2     /* amplitude, stripes */
};

typedef struct {
  long octaves;                /* 6 */
  double gain, lacunarity;     /* fbm: 0.5, 2 */
  double amplitude, stripes;   /* marble: displacement a (0.5), stripes per unit (1) */
} nl_basis_sum_options;

nl_basis_sum_options nl_basis_sum_defaults(void);

/* The values the render command and the Python binding accept, checked in
 * one place: every field of o (whether or not the chosen sum reads it),
 * octaves in 1..NL_BASIS_MAX_OCTAVES, gain in [-1e3, 1e3], lacunarity in
 * [1e-6, 1e6] (0 or a negative one would put every octave at the origin or
 * mirror it), amplitude in [-1e6, 1e6], stripes in [1e-9, 1e9], each finite.
 * NL_EINVAL naming the option as the command line spells it
 * ("--lacunarity: 0 is outside [1e-06, 1e+06]"). */
#define NL_BASIS_MAX_OCTAVES 30
nl_status nl_basis_sum_check(const nl_basis_sum_options *o, nl_error *err);
/* A render window: w and h in 1..NL_BASIS_MAX_SIZE ("--size"), size (the
 * extent) in [1e-9, 1e9], x0, y0 and z in [-1e9, 1e9], each finite. */
#define NL_BASIS_MAX_SIZE 65536
nl_status nl_basis_window_check(const nl_noise_window *win, nl_error *err);

typedef struct {
  const char *name, *summary;
  unsigned reads;   /* NL_BASIS_SUM_* flags */
  nl_noise_octaves (*octaves)(const nl_basis_sum_options *o);
  /* The w * h values of the sum on win; [*lo, *hi] is their analytic range
   * (nl_noise_octaves_bound, or [0, 1] for marble). */
  void (*grid)(const nl_noise_basis *b, const nl_noise_octaves *oct, const nl_basis_sum_options *o,
               const nl_noise_window *win, double *v, double *lo, double *hi);
} nl_basis_sum;

/* A basis on its own: one octave of frequency and amplitude 1. */
extern const nl_basis_sum nl_basis_single;
/* s->grid on nthreads threads (nl_noise_fractal_grid_threads: the same
 * bytes for any count) where s is a plain sum of octaves (the single
 * noise, fractal, turbulence, fbm); other sums (marble) on one thread. */
void nl_basis_sum_grid_threads(const nl_basis_sum *s, const nl_noise_basis *b,
                               const nl_noise_octaves *oct, const nl_basis_sum_options *o,
                               const nl_noise_window *win, int nthreads, double *v, double *lo,
                               double *hi);
const nl_basis_sum *nl_basis_sums(size_t *n);
const nl_basis_sum *nl_basis_sum_find(const char *name);

#ifdef __cplusplus
}
#endif

#endif
