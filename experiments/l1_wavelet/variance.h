/* variance.h - L1's readings of the 3D band variance (variance.c). */
#ifndef L1_VARIANCE_H
#define L1_VARIANCE_H

#include "study/nl_study.h"

/* The rows of l1_variance_readings, in table order. */
enum {
  L1_VOLUME,          /* volume, 4 samples per unit and axis (ours) */
  L1_MEAN_SUBTRACTED, /* volume, mean subtracted */
  L1_POINTS,          /* random points */
  L1_PLANE_RANDOM,    /* one plane at random z */
  L1_PLANE_Z0,        /* plane z = 0 */
  L1_PLANE_HALF,      /* plane z = 1/2 */
  L1_LATTICE,         /* lattice points (frac 0) */
  L1_LATTICE_HALF,    /* half-integer lattice (frac 1/2) */
  L1_TRANSPOSED,      /* the appendix's transposed odd-shift copy, volume */
  L1_TRANSPOSED_Z0,   /* the same, plane z = 0 */
  L1_MULTIBAND,       /* Cook & DeRose's multiband sum, plane z = 0 */
  L1_DOUBLE_PERIOD,   /* tile of twice the period, random points */
  L1_NREADINGS
};

/* Tiles of period n (3D) seeded seed0 .. (nl_seed_replicate, K seeds); per
 * seed, sigma_N^2 read in the ways the literature's constants could have been
 * measured (the volume mean; mean subtracted; random points; one plane at a
 * random, an integer and a half-integer z; the lattice and the half-integer
 * lattice; the appendix's transposed odd-shift copy, as a volume and at
 * z = 0; Cook & DeRose's multiband sum of 4 bands from one tile without
 * offsets over the sum of weights squared, at z = 0; random points of a tile
 * of period 2n, at most 256). Columns: reading,
 * var3d (mean over seeds), var3d_sd, paper, gap (var3d / paper - 1),
 * gap_in_sd ((var3d - paper) / var3d_sd). NULL for a bad period. */
nl_table *l1_variance_readings(int n, int K, unsigned long seed0, double paper);
/* The readings whose |gap_in_sd| <= nsd, as "reading (var +- sd); ..." in
 * buf (size bytes, truncated at a whole reading); returns how many. */
int l1_readings_within(const nl_table *t, double nsd, char *buf, size_t size);
/* The control of L1's rows: step 1 of the tile alone, i.i.d. N(0, 1)
 * coefficients (the very draws nl_wavelet_tile_seed starts from) with
 * no band-pass (no down-, upsampling, subtraction), the same B-spline
 * evaluation: noise without the wavelet construction. */
void l1_raw_tile_seed(nl_wavelet_tile *t, unsigned long seed);
/* The Kolmogorov distance sup |F_n - Phi| of a tile's values on one period
 * (per_unit samples per unit and axis, 2D tiles; 3D: the plane z = 0.5),
 * standardised by their own mean and sd, from the normal CDF. */
double l1_gauss_distance(const nl_wavelet_tile *t, int per_unit);

/* L1's leakage table from K seeds' nb x nb shares (nl_byexample_band_leakage,
 * share[(s nb + k) nb + j]: band k's power in eq. 13 band j): band, below
 * (mean share in coarser bands), inside (mean), inside_sd, above (finer). */
nl_table *l1_leakage_table(const double *share, int K, int nb);

/* The top-left w x w window of a size x size raster (new array, caller frees). */
double *l1_window(const double *img, int size, int w);

/* The measured band variance beside its exact expectation (expect.h):
 * expected.tsv, rows 2D (period n2, mean m2, sd s2) and 3D (n3, m3, s3)
 * over K seeds at `samples` per unit and axis: dim, period, expected (the
 * same grid), expected_cont (the continuous mean), measured, measured_sd,
 * seeds, z = (measured - expected) / (measured_sd / sqrt K). *period gets
 * expected_period.tsv: period 16, 32, ..., 256, var2d, var3d (the grid) and
 * var2d_cont, var3d_cont. */
nl_table *l1_expected_table(int n2, double m2, double s2, int n3, double m3, double s3, int K,
                            int samples, nl_table **period);

#endif
