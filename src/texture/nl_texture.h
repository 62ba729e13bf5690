/* nl_texture.h - from noise values to colours: colour ramps, marble,
 * two-colour blends.
 *
 * A ramp maps u to RGB through knots:
 *   - NL_RAMP_LINEAR: knots at increasing positions pos[0..n-1], colours
 *     linearly interpolated, u clamped to [pos[0], pos[n-1]].
 *   - NL_RAMP_SPLINE: Ebert et al.'s spline() of "Texturing & Modeling"
 *     (the ramp Qin & Yang's colour maps use): n >= 4 equally spaced knots,
 *     Catmull-Rom through knots 1..n-2, knots 0 and n-1 only steer the ends;
 *     u in [0, 1] covers the n - 3 segments. pos is ignored.
 *
 *   nl_texture_ramp r = nl_texture_ramp_linear(3, pos, rgb);
 *   nl_image *im = nl_texture_ramp_image(&r, values, w, h, lo, hi);   // lo -> u=0, hi -> u=1
 *
 * Marble (Shaffer's slides, Cheng eq. 4.1 in another form):
 *   u = (1 + sin(y + a * s)) / 2   with s a fractal sum at the point.
 */
#ifndef NL_TEXTURE_H
#define NL_TEXTURE_H

#include "image/nl_image.h"
#include "noise/nl_noise.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NL_RAMP_MAX 32
enum { NL_RAMP_LINEAR = 0, NL_RAMP_SPLINE = 1 };

typedef struct {
  int n, kind;
  double pos[NL_RAMP_MAX];
  float rgb[NL_RAMP_MAX][3];
} nl_texture_ramp;

nl_texture_ramp nl_texture_ramp_linear(int n, const double *pos, const float (*rgb)[3]);
nl_texture_ramp nl_texture_ramp_spline(int n, const float (*rgb)[3]);
void nl_texture_ramp_eval(const nl_texture_ramp *r, double u, float *rgb);
/* RGB image of values mapped by (v - lo) / (hi - lo) through the ramp. */
nl_image *nl_texture_ramp_image(const nl_texture_ramp *r, const double *values, int w, int h, double lo, double hi);

static inline double nl_texture_marble(double y, double a, double s) { return 0.5 * (1.0 + __builtin_sin(y + a * s)); }

/* Shaffer's marble on a window: p.y += a * fractal(p), then
 * u = (1 + sin(omega * p.y)) / 2 (omega = 2 pi stripes per unit).
 * u holds w * h values in [0, 1], rows from y0. */
void nl_texture_marble_grid(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win,
                            double omega, double a, double *u);

/* Built-in ramps: a grey ramp and a white-grey-blue marble ramp. */
nl_texture_ramp nl_texture_ramp_grey(void);
nl_texture_ramp nl_texture_ramp_marble(void);

/* ---- Qin & Yang's colours (sec. 4), on values from cellular/ ----------
 * Here rather than in cellular/ so that the cellular module makes numbers
 * only and never depends on the image module. */
/* Sec. 4.1's 13-knot blue-marble spline ramp (nl_texture_ramp_spline):
 * c1 = c2 = c6 = c7 = c12 = (0.25, 0.25, 0.35), c3 = c4 = c5 = (0.10, 0.10, 0.30),
 * c8 = c9 = (0.05, 0.05, 0.26), c10 = c11 = c13 = (0.03, 0.03, 0.20). */
nl_texture_ramp nl_texture_ramp_cellular_marble(void);
/* RGB image of eq. 7's mix(skycolor, cloudcolor, smoothstep(0, 1, v)). */
nl_image *nl_texture_cloud_colour(const double *v, int w, int h);

/* ---- wood: the solid wood shader of the literature Qin & Yang cite ------
 * Qin & Yang (sec. 4.3, Fig. 6) name only the basis of their RenderMan wood
 * (F1 - F1F1 on the table, F3 - F3F3 on the trunk) and refer to Ebert et al.,
 * "Texturing & Modeling" (1998) for procedural texturing. We read it as the
 * usual solid wood of that literature: rings around a tree axis displaced by
 * the basis, u = frac(ring_freq r + turb g), and the RenderMan wood shader's
 * ring profile and colour mix (Upstill, "The RenderMan Companion", 1990,
 * listing 16.15, whose rings are r += |noise(r)|; frac(r)):
 *   r    = distance from the point p to the tree's axis (axis_p + s axis_d)
 *   u    = frac(ring_freq * r + turb * g)          g: the basis at p
 *   t    = smoothstep(0, 0.8, u) - smoothstep(0.83, 1, u)
 *   rgb  = mix(light, dark, t)
 * t rises slowly over a ring (early to late wood) and falls sharply at its
 * end. */
typedef struct {
  double axis_p[3], axis_d[3];   /* a point of the axis and its direction (any length > 0) */
  double ring_freq, turb;        /* rings per unit of r; basis amplitude in rings */
  float light[3], dark[3];
} nl_texture_wood;
double nl_texture_wood_radius(const nl_texture_wood *w, const double p[3]);
double nl_texture_wood_ring(const nl_texture_wood *w, const double p[3], double g);
/* t of every pixel centre of win (as nl_noise_window), g the basis there (NULL: 0). */
void nl_texture_wood_grid(const nl_texture_wood *w, const nl_noise_window *win, const double *g, double *t);
nl_image *nl_texture_wood_image(const nl_texture_wood *w, const double *t, int width, int height);
/* Dark bands crossed along row `index` (vertical 0) or column `index`
 * (vertical 1) of an image: down-crossings of the line's mean luminance
 * (Rec. 709), with a hysteresis of a tenth of its range. */
int nl_texture_band_count(const nl_image *im, int vertical, int index);

#ifdef __cplusplus
}
#endif

#endif
