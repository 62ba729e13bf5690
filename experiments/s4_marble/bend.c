/* bend.c - S4: how far the noise bends the ramp's stripes. */
#include "bend.h"

double s4_bend_share(const double *u, int w, int h)
{
  double sx = 0, sy = 0;
  for (int y = 0; y < h; y++)
    for (int x = 0; x < w; x++) {
      double v = u[(size_t)y * w + x];
      if (x + 1 < w) {
        double d = u[(size_t)y * w + x + 1] - v;
        sx += d * d;
      }
      if (y + 1 < h) {
        double d = u[(size_t)(y + 1) * w + x] - v;
        sy += d * d;
      }
    }
  return sx + sy > 0 ? sx / (sx + sy) : 0;
}

void s4_marble_rows(const nl_noise_basis *b, const nl_noise_octaves *o, const nl_noise_window *win,
                    double omega, double a, double *u)
{
  nl_noise_fractal_grid(b, o, win, u);
  double dy = win->size / win->h;
  for (int r = 0; r < win->h; r++) {
    double y = win->y0 + (r + 0.5) * dy;
    double *row = u + (size_t)r * win->w, f = row[0];
    for (int c = 0; c < win->w; c++) row[c] = nl_texture_marble(omega * y, omega * a, f);
  }
}
