/* C2's histograms of the optimised angles (Fig 4.5, 4.6 right). */
#include "c2.h"
#include "stats/nl_stats.h"

#include <gsl/gsl_histogram.h>

nl_table *c2_hist_table(const nl_noise_grad2 *const *tables, const char *const *names, int n,
                        size_t bins)
{
  const char *cols[16];
  cols[0] = "theta";
  for (int i = 0; i < n; i++) cols[i + 1] = names[i];
  nl_table *t = nl_table_alloc((size_t)n + 1, cols);
  gsl_histogram *h[16];
  for (int i = 0; i < n; i++)
    h[i] = nl_stats_histogram_uniform(tables[i]->angle, tables[i]->m, bins, 0, NL_TWO_PI, NULL,
                                      NULL);
  double row[16];
  for (size_t b = 0; b < bins; b++) {
    row[0] = (b + 0.5) * NL_TWO_PI / (double)bins;
    for (int i = 0; i < n; i++) row[i + 1] = h[i]->bin[b];
    nl_table_append_doubles(t, row);
  }
  for (int i = 0; i < n; i++) gsl_histogram_free(h[i]);
  return t;
}
