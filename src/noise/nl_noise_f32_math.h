/* nl_noise_f32_math.h - the arithmetic of the float32 noises, written once
 * for the scalar level and every vector level, so that every level performs
 * the same IEEE operations in the same order (the bits agree; fused
 * multiply-adds are correctly rounded, so fmaf() and vfmadd give the same).
 *
 * The including file defines
 *   NLF_T            float, or a GCC vector of floats
 *   NLF_FMA(a,b,c)   a * b + c rounded once
 *   NLF_C(k)         the constant k as an NLF_T
 *   NLF(name)        the name the functions take in that file
 * and includes this header once. Library-internal, never installed.
 *
 * Evaluation order (as the double path's, nl_noise.h, with FMA): per
 * lattice column c the corners are blended along y then z into a line
 * L_c(t) = t GX_c + A_c in the fractional x-coordinate t, and the sample is
 * L_c(t) + fade(t) (L_{c+1}(t - 1) - L_c(t)). A row computes each column's
 * (GX, A) once; a point computes both of its columns; the same operations,
 * so a row and a point give the same bits. */

/* Perlin's quintic 6t^5 - 15t^4 + 10t^3 as t^3 (t (6 t - 15) + 10) */
static inline NLF_T NLF(fade)(NLF_T t)
{
  NLF_T q = NLF_FMA(t, NLF_C(6.0f), NLF_C(-15.0f));
  q = NLF_FMA(t, q, NLF_C(10.0f));
  NLF_T t3 = t * t * t;
  return t3 * q;
}

/* a + t (b - a) */
static inline NLF_T NLF(lerp)(NLF_T t, NLF_T a, NLF_T b) { return NLF_FMA(t, b - a, a); }

/* One column of the 3D noise from its four corners (dy, dz) = 00, 10, 01,
 * 11: the gradients' components gx, gy, gz of each, fy1 = fy - 1,
 * fz1 = fz - 1, v and w the fades of fy and fz. */
static inline void NLF(col3)(const NLF_T gx[4], const NLF_T gy[4], const NLF_T gz[4], NLF_T fy,
                             NLF_T fy1, NLF_T fz, NLF_T fz1, NLF_T v, NLF_T w, NLF_T *GX, NLF_T *A)
{
  *GX = NLF(lerp)(w, NLF(lerp)(v, gx[0], gx[1]), NLF(lerp)(v, gx[2], gx[3]));
  NLF_T a00 = NLF_FMA(gy[0], fy, gz[0] * fz), a10 = NLF_FMA(gy[1], fy1, gz[1] * fz);
  NLF_T a01 = NLF_FMA(gy[2], fy, gz[2] * fz1), a11 = NLF_FMA(gy[3], fy1, gz[3] * fz1);
  *A = NLF(lerp)(w, NLF(lerp)(v, a00, a10), NLF(lerp)(v, a01, a11));
}

/* One column of the 2D noise from its corners dy = 0, 1 (Cheng eq. 3.2). */
static inline void NLF(col2)(NLF_T gx0, NLF_T gy0, NLF_T gx1, NLF_T gy1, NLF_T fy, NLF_T fy1,
                             NLF_T v, NLF_T *GX, NLF_T *A)
{
  *GX = NLF(lerp)(v, gx0, gx1);
  *A = NLF(lerp)(v, gy0 * fy, gy1 * fy1);
}

/* The sample from columns c and c + 1, t the fraction, u = fade(t). */
static inline NLF_T NLF(blend)(NLF_T t, NLF_T u, NLF_T GX0, NLF_T A0, NLF_T GX1, NLF_T A1)
{
  NLF_T l0 = NLF_FMA(t, GX0, A0), l1 = NLF_FMA(t - NLF_C(1.0f), GX1, A1);
  return NLF(lerp)(u, l0, l1);
}
