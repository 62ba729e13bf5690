/* C2's own-statistic table (c2.h): each objective's statistic under it and
 * under the other objectives, so that "the KS objective has the lower E_KS"
 * sits beside "the Kuiper objective has the lower V" - its control. */
#include "c2.h"

nl_table *c2_own_alloc(void)
{
  const char *cols[] = { "pattern", "statistic", "objective", "seeds", "value", "value_sd" };
  return nl_table_alloc(sizeof cols / sizeof *cols, cols);
}

size_t c2_own_add(nl_table *own, const nl_table *sum, size_t row, const char *pattern,
                  const char *objective, const char *statistic)
{
  char sd[64];
  snprintf(sd, sizeof sd, "%s_sd", statistic);
  nl_table_append(own, "sssddd", pattern, statistic, objective, nl_table_value(sum, row, "seeds"),
                  nl_table_value(sum, row, statistic), nl_table_value(sum, row, sd));
  return own->nrows - 1;
}
