/* gustavson_simplex.h - Stefan Gustavson's simplex noise, as a test oracle
 * for nl_noise_alt's simplex noises.
 *
 * A transcription of the Java code published with "Simplex noise
 * demystified" (Gustavson 2005; SimplexNoise.java, its 2D and 3D noise):
 * skew, the simplex by the ordering of the offsets, the four (three) corner
 * kernels t^4 (g . d) for t = r2 - |d|^2 > 0, gradients grad3[perm[ii +
 * perm[jj + perm[kk]]] % 12] (2D: the first two components), times 32
 * (70). Two departures: the permutation is the caller's (Gustavson's code
 * carries Perlin's table; the library puts any table there), and r2, his
 * 0.6 in 3D, is a parameter (the library also offers 0.5). fastfloor is
 * the 2012 revision's ((int)x, one less below it), which is floor for
 * |x| < 2^31; the 2005 text's x > 0 ? (int)x : (int)x - 1 puts negative
 * integers one cell too low.
 */
#ifndef GUSTAVSON_SIMPLEX_H
#define GUSTAVSON_SIMPLEX_H

/* perm: 512 entries (a permutation of 0..255, doubled). */
double gustavson_noise3(const unsigned char *perm, double r2, double xin, double yin, double zin);
double gustavson_noise2(const unsigned char *perm, double xin, double yin);

#endif
