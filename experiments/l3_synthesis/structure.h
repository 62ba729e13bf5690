/* structure.h - L3's structure statistics (structure.c): what band power
 * and histogram leave out. Lagae et al. 2010 model isotropic stochastic
 * textures; their Fig. 9 failures are structured exemplars (joints, stripes).
 * Band power and the histogram cannot see that structure, so the photo
 * criteria of sec. 5 pass a synthesis that has none. These statistics are
 * computed on the luminance (nl_byexample_luminance) by central differences
 * on the interior pixels. */
#ifndef L3_STRUCTURE_H
#define L3_STRUCTURE_H

#include "image/nl_image.h"

#define L3_ORIENT_BINS 12 /* gradient-orientation histogram over [0, pi), 15 degrees a bin */

/* The statistics of one image:
 *   coherence   energy-weighted structure-tensor coherence
 *               sum |lambda1 - lambda2| / sum (lambda1 + lambda2), the tensor
 *               J = G_s * (grad L grad L^T) smoothed by a Gaussian of s =
 *               L3_TENSOR_SIGMA pixels: 0 for isotropic local gradients, 1
 *               where every neighbourhood has one orientation (an edge);
 *   orient      the |grad L|-weighted histogram of the gradient orientation
 *               mod pi in L3_ORIENT_BINS bins (sums to 1). */
#define L3_TENSOR_SIGMA 2.0
typedef struct {
  double coherence;
  double orient[L3_ORIENT_BINS];
} l3_structure;

void l3_structure_measure(const nl_image *im, l3_structure *s);
/* Total-variation distance between two orientation histograms, in [0, 1]. */
double l3_structure_orient_distance(const l3_structure *a, const l3_structure *b);

#endif
