/* nl_noise_alt.h - other lattice gradient noises that "Perlin noise" may
 * have meant in 2009 (Arnerin 2009 sec. 5.2.2 says only "the Perlin noise
 * function", evaluated in a GPU shader); A3 measures the bandwidth of each.
 *
 * One table-driven 3D gradient noise, with the gradient of a lattice point
 * looked up as g[p[p[p[X] + Y] + Z]] (X, Y, Z = cell & 255):
 *   - improved 2002: g[h] = Perlin's edge gradient grad3[h & 15] (length
 *     sqrt 2), so with the quintic fade and double evaluation it is
 *     nl_noise_perm3_eval up to rounding (tested);
 *   - classic 1985 (Perlin 1985, "An image synthesizer"): random unit
 *     gradients (points uniform in the unit ball, normalised) and the cubic
 *     fade 3t^2 - 2t^3 of his reference code;
 *   - a genuinely 1D gradient noise (Perlin's reference noise1): gradients
 *     uniform in [-1, 1], value lerp(fade(t), g0 t, g1 (t - 1)); y, z ignored.
 *   - simplex noise in 3D as Gustavson published it for GPUs ("Simplex noise
 *     demystified", 2005): the skewed simplex lattice, the kernel
 *     max(0, r2 - |d|^2)^4 (g . d) around each of the 4 corners, gradient
 *     grad3[perm[i + perm[j + perm[k]]] % 12], times 32; r2 = 0.6 as
 *     published (its kernel reaches past the corners' cells, so the value
 *     jumps where a corner leaves the simplex), r2 = 0.5 the continuous one;
 *     and his 2D simplex noise (triangles, kernel (0.5 - |d|^2)^4, times 70).
 * Either fade can be chosen for the lattice noises. nl_noise_alt_gpu8() rounds the
 * gradients as an RGBA8 texture stores them, (g + 1)/2 * 255 to the nearest
 * byte, and switches to float32 evaluation (a 2009 GPU's shader precision).
 *
 *   nl_noise_alt t;
 *   nl_noise_alt_classic(&t, &perm, seed);        // 1985 noise on perm's table
 *   double v = nl_noise_alt_eval(&t, x, y, z);
 */
#ifndef NL_NOISE_ALT_H
#define NL_NOISE_ALT_H

#include "noise/nl_noise.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  unsigned char p[512];   /* permutation of 0..255, doubled */
  double g[256][3];       /* gradient per hash value */
  int quintic;            /* 1: 6t^5 - 15t^4 + 10t^3 (2002); 0: 3t^2 - 2t^3 (1985) */
  int line1;              /* 1: 1D gradient noise of x alone, gradient g[h][0] */
  int f32;                /* 1: evaluate in float32 (lattice noises; simplex stays double) */
  double simplex_r2;      /* > 0: simplex noise with this kernel radius^2 */
  int plane;              /* 1: 2D (simplex) noise of x, y; z ignored */
} nl_noise_alt;

/* Perlin 2002's gradients on p's permutation. */
void nl_noise_alt_improved(nl_noise_alt *t, const nl_noise_perm3 *p, int quintic);
/* Perlin 1985: p's permutation, unit gradients from stream ("noise.alt.classic", 0) of seed, cubic fade. */
void nl_noise_alt_classic(nl_noise_alt *t, const nl_noise_perm3 *p, unsigned long seed);
/* 1D gradient noise: p's permutation, gradients uniform in [-1, 1] from stream ("noise.alt.line1", 0). */
void nl_noise_alt_line1(nl_noise_alt *t, const nl_noise_perm3 *p, unsigned long seed, int quintic);
/* Gustavson's 3D simplex noise on p's permutation, kernel radius^2 r2. */
void nl_noise_alt_simplex(nl_noise_alt *t, const nl_noise_perm3 *p, double r2);
/* Gustavson's 2D simplex noise (r2 = 0.5, scale 70) of x, y on p's permutation. */
void nl_noise_alt_simplex2(nl_noise_alt *t, const nl_noise_perm3 *p);
/* Gradients through an RGBA8 texture, evaluation in float32. */
void nl_noise_alt_gpu8(nl_noise_alt *t);
double nl_noise_alt_eval(const nl_noise_alt *t, double x, double y, double z);

#ifdef __cplusplus
}
#endif

#endif
