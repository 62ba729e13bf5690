/* direct_dft.h - the discrete Fourier transform by its definition, O(n^2)
 * per output row, as a test oracle for src/spectrum.
 *
 *   F(u, v) = sum_{x, y} img[y w + x] e^{-2 pi i (u x / w + v y / h)}
 *
 * in long double, each angle reduced exactly first: the phase is
 * ((u x mod w) h + (v y mod h) w) / (w h) of a turn, an integer ratio, so
 * cosl/sinl see an angle in [0, 2 pi) with no error grown from large u x.
 * Nothing is shared with the library: no FFT, no GSL, no twiddle table.
 */
#ifndef DIRECT_DFT_H
#define DIRECT_DFT_H

/* F[2 (v w + u) + {0, 1}] = Re, Im of F(u, v); h = 1 is the 1D DFT. */
void direct_dft2(const double *img, int w, int h, long double *F);

#endif
