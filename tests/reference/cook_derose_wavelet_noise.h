/* cook_derose_wavelet_noise.h - Cook & DeRose's wavelet noise appendix, as a
 * test oracle.
 *
 * A transcription of the C code in the appendix of R. L. Cook and T. DeRose,
 * "Wavelet Noise", SIGGRAPH 2005: Mod, Downsample, Upsample,
 * GenerateNoiseTile and WNoise. It shares no code and no table with
 * src/wavelet (its own copy of the analysis filter, as printed, with the
 * asymmetric 0.003546), so a wrong tap, axis, stride or offset on either
 * side shows as a difference.
 *
 * What is not the printed code, and why:
 *  - step 1's white noise is the caller's (the tile arrives filled), so the
 *    oracle and the library can start from the same numbers;
 *  - the downsampling loop runs k <= 2i + ARAD as printed, which reads
 *    a[ARAD], one past the 32 coefficients; the oracle's array has a 33rd
 *    entry 0 there, so the loop is printed one and its value is defined;
 *  - the tile is n^dim: dim 3 is the appendix; dim 2 runs the same loops
 *    without the z axis (the appendix has no 2D tile);
 *  - literal_shift 1 is the appendix's odd-shift loop (its copy is the
 *    shifted tile transposed, iz fastest), 0 the same loop writing
 *    temp1[ix + iy n + iz n^2] (the shifted tile itself);
 *  - WNoise takes p as doubles and weighs in double (the appendix: float),
 *    so that evaluation can be compared at the library's precision.
 * The tile is built in float as printed.
 *
 *   float *tile = white noise, n^3 values;
 *   cd_generate_tile(tile, n, 3, 1);
 *   double v = cd_wnoise(tile, n, 3, (double[3]){3.7, 1.2, -4});
 */
#ifndef COOK_DEROSE_WAVELET_NOISE_H
#define COOK_DEROSE_WAVELET_NOISE_H

/* Steps 2-4 in place on noise[n^dim] (n even, x fastest). */
void cd_generate_tile(float *noise, int n, int dim, int literal_shift);

/* Quadratic B-spline evaluation (WNoise); dim 2 reads p[0], p[1]. */
double cd_wnoise(const float *tile, int n, int dim, const double *p);

#endif
