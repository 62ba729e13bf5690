/* structure.c - L3's structure statistics (structure.h). */
#include "structure.h"
#include "byexample/nl_byexample.h"

#include <math.h>
#include <stdlib.h>

/* One axis of a separable Gaussian blur of src (w x h, clamped at the
 * border) into dst; dx = 1 blurs rows, 0 columns. */
static void blur_axis(const double *src, double *dst, int w, int h, const double *k, int rad,
                      int dx)
{
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      double s = 0;
      for (int j = -rad; j <= rad; j++) {
        int xx = dx ? x + j : x, yy = dx ? y : y + j;
        xx = xx < 0 ? 0 : xx >= w ? w - 1 : xx;
        yy = yy < 0 ? 0 : yy >= h ? h - 1 : yy;
        s += k[j + rad] * src[(size_t)yy * w + xx];
      }
      dst[(size_t)y * w + x] = s;
    }
}

static void blur(double *a, double *tmp, int w, int h)
{
  int rad = (int)ceil(3 * L3_TENSOR_SIGMA);
  double k[64], sum = 0;
  for (int j = -rad; j <= rad; j++)
    sum += k[j + rad] = exp(-0.5 * j * j / (L3_TENSOR_SIGMA * L3_TENSOR_SIGMA));
  for (int j = 0; j <= 2 * rad; j++) k[j] /= sum;
  blur_axis(a, tmp, w, h, k, rad, 1);
  blur_axis(tmp, a, w, h, k, rad, 0);
}

void l3_structure_measure(const nl_image *im, l3_structure *s)
{
  int w = im->width, h = im->height;
  size_t n = (size_t)w * h;
  double *l = malloc(n * sizeof *l);
  double *jxx = calloc(n, sizeof *jxx);
  double *jyy = calloc(n, sizeof *jyy);
  double *jxy = calloc(n, sizeof *jxy);
  double *tmp = malloc(n * sizeof *tmp);
  nl_byexample_luminance(im, l);
  for (int b = 0; b < L3_ORIENT_BINS; b++) s->orient[b] = 0;
  double gsum = 0;
  for (int y = 1; y + 1 < h; y++)
    for (int x = 1; x + 1 < w; x++) {
      size_t i = (size_t)y * w + x;
      double gx = 0.5 * (l[i + 1] - l[i - 1]);
      double gy = 0.5 * (l[i + w] - l[i - w]);
      jxx[i] = gx * gx;
      jyy[i] = gy * gy;
      jxy[i] = gx * gy;
      double g = sqrt(gx * gx + gy * gy);
      if (g <= 0) continue;
      double a = atan2(gy, gx); /* orientation mod pi: an edge and its reverse are one */
      if (a < 0) a += M_PI;
      if (a >= M_PI) a -= M_PI; /* atan2(0, -1) = pi is the orientation 0 */
      int b = (int)(a / M_PI * L3_ORIENT_BINS);
      s->orient[b < L3_ORIENT_BINS ? b : L3_ORIENT_BINS - 1] += g;
      gsum += g;
    }
  for (int b = 0; b < L3_ORIENT_BINS; b++) s->orient[b] = gsum > 0 ? s->orient[b] / gsum : 0;
  blur(jxx, tmp, w, h);
  blur(jyy, tmp, w, h);
  blur(jxy, tmp, w, h);
  double num = 0, den = 0;
  for (int y = 1; y + 1 < h; y++)
    for (int x = 1; x + 1 < w; x++) {
      size_t i = (size_t)y * w + x;
      double d = jxx[i] - jyy[i];
      num += sqrt(d * d + 4 * jxy[i] * jxy[i]); /* lambda1 - lambda2 */
      den += jxx[i] + jyy[i];                   /* lambda1 + lambda2 */
    }
  s->coherence = den > 0 ? num / den : 0;
  free(l);
  free(jxx);
  free(jyy);
  free(jxy);
  free(tmp);
}

double l3_structure_orient_distance(const l3_structure *a, const l3_structure *b)
{
  double d = 0;
  for (int k = 0; k < L3_ORIENT_BINS; k++) d += fabs(a->orient[k] - b->orient[k]);
  return d / 2;
}
