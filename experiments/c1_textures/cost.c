/* C1's timing table: what one full optimisation costs per (texture,
 * pattern, formula). Times are machine-dependent, so the regression check
 * ignores them. */
#include "c1.h"
#include "harness/nl_harness.h"

#include <math.h>

nl_table *c1_cost_alloc(void)
{
  const char *cols[] = { "case", "seeds", "moves", "cpu_s", "cpu_s_sd", "moves_per_s" };
  return nl_table_alloc(6, cols);
}

void c1_cost_report(nl_harness *r, const nl_table *t)
{
  nl_harness_write_table(r, t, "timing.tsv");
  const char *times[] = { "cpu_s", "cpu_s_sd", "moves_per_s" };   /* never compared */
  for (int i = 0; i < 3; i++) nl_harness_check(r, "timing.tsv", times[i], "ignore");
  nl_harness_report_table(r, t,
                          "Timing: cost of one optimisation per row (thread CPU time, so other "
                          "work on the machine does not inflate it; the machine is in "
                          "manifest.tsv)",
                          4);
  double lo = INFINITY, hi = 0, rlo = INFINITY, rhi = 0;
  for (size_t q = 0; q < t->nrows; q++) {
    double c = nl_table_value(t, q, "cpu_s");
    double m = nl_table_value(t, q, "moves_per_s");
    lo = fmin(lo, c);
    hi = fmax(hi, c);
    rlo = fmin(rlo, m);
    rhi = fmax(rhi, m);
  }
  if (t->nrows)
    nl_harness_text(r,
                    "Timing: one full multi-level optimisation takes %.3g..%.3g s of CPU over the "
                    "%zu rows, at %.3g..%.3g M annealing moves per CPU second (set-up and the "
                    "per-temperature re-sums included; `build/bench/bench_cheng` times the thesis "
                    "setting alone). C6 sets a reproduction's time per table against one "
                    "optimisation's.\n",
                    lo, hi, t->nrows, rlo / 1e6, rhi / 1e6);
}
