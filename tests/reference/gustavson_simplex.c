/* gustavson_simplex.c - see gustavson_simplex.h. Line for line his
 * noise(xin, yin) and noise(xin, yin, zin); comments in capitals are his. */
#include "reference/gustavson_simplex.h"

#include <math.h>

static const int grad3[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},
  {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

static int fastfloor(double x)
{
  int xi = (int)x;
  return x < xi ? xi - 1 : xi;
}

static double dot2(const int *g, double x, double y) { return g[0] * x + g[1] * y; }
static double dot3(const int *g, double x, double y, double z)
{
  return g[0] * x + g[1] * y + g[2] * z;
}

double gustavson_noise2(const unsigned char *perm, double xin, double yin)
{
  double n0, n1, n2;   /* NOISE CONTRIBUTIONS FROM THE THREE CORNERS */
  /* SKEW THE INPUT SPACE TO DETERMINE WHICH SIMPLEX CELL WE'RE IN */
  const double F2 = 0.5 * (sqrt(3.0) - 1.0);
  double s = (xin + yin) * F2;
  int i = fastfloor(xin + s);
  int j = fastfloor(yin + s);
  const double G2 = (3.0 - sqrt(3.0)) / 6.0;
  double t = (i + j) * G2;
  double X0 = i - t;   /* UNSKEW THE CELL ORIGIN BACK TO (X,Y) SPACE */
  double Y0 = j - t;
  double x0 = xin - X0;   /* THE X,Y DISTANCES FROM THE CELL ORIGIN */
  double y0 = yin - Y0;
  int i1, j1;   /* OFFSETS FOR SECOND (MIDDLE) CORNER OF SIMPLEX IN (I,J) COORDS */
  if (x0 > y0) {
    i1 = 1;
    j1 = 0;
  } else {
    i1 = 0;
    j1 = 1;
  }
  double x1 = x0 - i1 + G2;
  double y1 = y0 - j1 + G2;
  double x2 = x0 - 1.0 + 2.0 * G2;
  double y2 = y0 - 1.0 + 2.0 * G2;
  int ii = i & 255;
  int jj = j & 255;
  int gi0 = perm[ii + perm[jj]] % 12;
  int gi1 = perm[ii + i1 + perm[jj + j1]] % 12;
  int gi2 = perm[ii + 1 + perm[jj + 1]] % 12;
  double t0 = 0.5 - x0 * x0 - y0 * y0;
  if (t0 < 0)
    n0 = 0.0;
  else {
    t0 *= t0;
    n0 = t0 * t0 * dot2(grad3[gi0], x0, y0);
  }
  double t1 = 0.5 - x1 * x1 - y1 * y1;
  if (t1 < 0)
    n1 = 0.0;
  else {
    t1 *= t1;
    n1 = t1 * t1 * dot2(grad3[gi1], x1, y1);
  }
  double t2 = 0.5 - x2 * x2 - y2 * y2;
  if (t2 < 0)
    n2 = 0.0;
  else {
    t2 *= t2;
    n2 = t2 * t2 * dot2(grad3[gi2], x2, y2);
  }
  return 70.0 * (n0 + n1 + n2);
}

double gustavson_noise3(const unsigned char *perm, double r2, double xin, double yin, double zin)
{
  double n0, n1, n2, n3;
  const double F3 = 1.0 / 3.0;
  double s = (xin + yin + zin) * F3;
  int i = fastfloor(xin + s);
  int j = fastfloor(yin + s);
  int k = fastfloor(zin + s);
  const double G3 = 1.0 / 6.0;
  double t = (i + j + k) * G3;
  double X0 = i - t;
  double Y0 = j - t;
  double Z0 = k - t;
  double x0 = xin - X0;
  double y0 = yin - Y0;
  double z0 = zin - Z0;
  int i1, j1, k1;   /* OFFSETS FOR SECOND CORNER OF SIMPLEX IN (I,J,K) COORDS */
  int i2, j2, k2;   /* OFFSETS FOR THIRD CORNER */
  if (x0 >= y0) {
    if (y0 >= z0) {
      i1 = 1; j1 = 0; k1 = 0; i2 = 1; j2 = 1; k2 = 0;   /* X Y Z ORDER */
    } else if (x0 >= z0) {
      i1 = 1; j1 = 0; k1 = 0; i2 = 1; j2 = 0; k2 = 1;   /* X Z Y ORDER */
    } else {
      i1 = 0; j1 = 0; k1 = 1; i2 = 1; j2 = 0; k2 = 1;   /* Z X Y ORDER */
    }
  } else {
    if (y0 < z0) {
      i1 = 0; j1 = 0; k1 = 1; i2 = 0; j2 = 1; k2 = 1;   /* Z Y X ORDER */
    } else if (x0 < z0) {
      i1 = 0; j1 = 1; k1 = 0; i2 = 0; j2 = 1; k2 = 1;   /* Y Z X ORDER */
    } else {
      i1 = 0; j1 = 1; k1 = 0; i2 = 1; j2 = 1; k2 = 0;   /* Y X Z ORDER */
    }
  }
  double x1 = x0 - i1 + G3;
  double y1 = y0 - j1 + G3;
  double z1 = z0 - k1 + G3;
  double x2 = x0 - i2 + 2.0 * G3;
  double y2 = y0 - j2 + 2.0 * G3;
  double z2 = z0 - k2 + 2.0 * G3;
  double x3 = x0 - 1.0 + 3.0 * G3;
  double y3 = y0 - 1.0 + 3.0 * G3;
  double z3 = z0 - 1.0 + 3.0 * G3;
  int ii = i & 255;
  int jj = j & 255;
  int kk = k & 255;
  int gi0 = perm[ii + perm[jj + perm[kk]]] % 12;
  int gi1 = perm[ii + i1 + perm[jj + j1 + perm[kk + k1]]] % 12;
  int gi2 = perm[ii + i2 + perm[jj + j2 + perm[kk + k2]]] % 12;
  int gi3 = perm[ii + 1 + perm[jj + 1 + perm[kk + 1]]] % 12;
  double t0 = r2 - x0 * x0 - y0 * y0 - z0 * z0;
  if (t0 < 0)
    n0 = 0.0;
  else {
    t0 *= t0;
    n0 = t0 * t0 * dot3(grad3[gi0], x0, y0, z0);
  }
  double t1 = r2 - x1 * x1 - y1 * y1 - z1 * z1;
  if (t1 < 0)
    n1 = 0.0;
  else {
    t1 *= t1;
    n1 = t1 * t1 * dot3(grad3[gi1], x1, y1, z1);
  }
  double t2 = r2 - x2 * x2 - y2 * y2 - z2 * z2;
  if (t2 < 0)
    n2 = 0.0;
  else {
    t2 *= t2;
    n2 = t2 * t2 * dot3(grad3[gi2], x2, y2, z2);
  }
  double t3 = r2 - x3 * x3 - y3 * y3 - z3 * z3;
  if (t3 < 0)
    n3 = 0.0;
  else {
    t3 *= t3;
    n3 = t3 * t3 * dot3(grad3[gi3], x3, y3, z3);
  }
  return 32.0 * (n0 + n1 + n2 + n3);
}
