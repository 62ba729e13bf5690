/* L1's report (report.c): the prose beside summary.tsv, variance_readings.tsv,
 * lattice.tsv and leakage.tsv and the figures' captions. */
#ifndef L1_REPORT_H
#define L1_REPORT_H

#include "harness/nl_harness.h"
#include "table/nl_table.h"
#include "wavelet/nl_wavelet.h"

#define L1_PAPER_SIGMA2_2D 0.265 /* sigma_N^2 in 2D (Lagae et al. eq. 11, citing Cook & DeRose) */
#define L1_CD_SIGMA2_3D    0.210 /* Cook & DeRose's code: plain 3D noise */
#define L1_CD_SIGMA2_PROJ  0.296 /* Cook & DeRose's code: projected noise */

/* The run's setting: tile periods, seeds from seed0, image side, samples per
 * unit and axis of the variance, decades of the spectrum images, side of the
 * window of panels (b) and (d). */
typedef struct {
  int tile, tile3, seeds, size, samples, decades;
  unsigned long seed0;
  int window3;
} l1_setting;

/* st: summary.tsv (2D, 3D, in-band share of band 0); vr: the 3D readings;
 * ft: variance on the shifted lattice (frac 0, 1/8, ..., 1); lt: leakage;
 * xt, pt: expected.tsv and expected_period.tsv (l1_expected_table). */
void l1_report(nl_harness *r, const l1_setting *c, const nl_table *st, const nl_table *vr,
               const nl_table *ft, const nl_table *lt, const nl_table *xt, const nl_table *pt);

/* The per-seed quantities of the claims, of the wavelet noise and of its
 * control (the same coefficients without the band-pass): band variance in
 * 2D and 3D and the Kolmogorov distance to the normal law in 2D. */
typedef struct {
  int seeds;
  const double *v2, *v3, *rv2, *rv3, *ks, *rks;
} l1_per_seed;

/* verdicts.c: writes summary.tsv (the paper's four claims, then the same
 * quantities of the control, in-band shares from leakage tables lt and rlt),
 * declares its equivalence verdicts with their controls and the prose that
 * reads them. Returns summary.tsv for the report. */
nl_table *l1_verdicts(nl_harness *r, const l1_per_seed *ps, const nl_table *lt,
                      const nl_table *rlt);

/* figure.c: noise.png (one band k = band of the 2D tile t2 and a slice of the
 * 3D tile t3, both reseeded with c->seed0, beside their power spectra),
 * radial.tsv and edges.tsv. Returns the side of the window of panels (b)
 * and (d), at most one period of the 3D tile. */
int l1_band_figure(nl_harness *r, nl_wavelet_tile *t2, nl_wavelet_tile *t3, const l1_setting *c,
                   int band);

#endif
