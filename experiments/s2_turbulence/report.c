/* report.c - S2's report prose: how |noise| folds each octave. */
#include "s2.h"

void s2_report(nl_harness *r)
{
  nl_harness_text(r,
                  "The absolute value folds each octave at its zero set, the dark creases. Folding "
                  "moves power into the DC term (the mean is positive) and into frequencies above "
                  "the octave's band, so even one octave has a broad spectrum, unlike S1.\n");
}
