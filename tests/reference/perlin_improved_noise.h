/* perlin_improved_noise.h - Ken Perlin's reference improved noise, as a test oracle.
 *
 * A transcription of "JAVA REFERENCE IMPLEMENTATION OF IMPROVED NOISE -
 * COPYRIGHT 2002 KEN PERLIN" (https://mrl.nyu.edu/~perlin/noise/, the code of
 * Perlin 2002, "Improving Noise", SIGGRAPH), with its own copy of the
 * permutation: it shares no code and no table with src/noise, so a wrong
 * entry or a wrong step on either side shows as a difference.
 *
 *   double n = perlin_improved_noise(3.14, 42, 7);   // 0.13691995878400012
 *
 * Java's double arithmetic is IEEE binary64 with round-to-nearest and no
 * fused operations; the C here does the same operations in the same order
 * when compiled with -ffp-contract=off (the project's flag), so it returns
 * the Java program's bits. One difference of domain: Java's (int) cast of
 * floor(x) saturates, C's is undefined outside int's range, so the oracle
 * takes |x|, |y|, |z| < 2^31 only.
 */
#ifndef PERLIN_IMPROVED_NOISE_H
#define PERLIN_IMPROVED_NOISE_H

double perlin_improved_noise(double x, double y, double z);

/* permutation[k], k < 256, of the published table (for the tests that
 * compare it entry by entry). */
int perlin_improved_permutation(int k);

#endif
