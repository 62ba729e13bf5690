/* C1's timing table: what one full optimisation costs per (texture,
 * pattern, formula). */
#include "c1.h"
#include "harness/nl_harness.h"


nl_table *c1_cost_alloc(void)
{
  const char *cols[] = { "case", "seeds", "moves", "cpu_s", "cpu_s_sd", "moves_per_s" };
  return nl_table_alloc(6, cols);
}

void c1_cost_report(nl_harness *r, const nl_table *t)
{
  /* The times differ on every run: times.tsv, beside the manifest, not
   * tracked; timing.tsv keeps the moves, which do not. */
  const char *times[] = { "cpu_s", "cpu_s_sd", "moves_per_s" };
  for (int i = 0; i < 3; i++) nl_harness_time_column(r, "timing.tsv", times[i]);
  nl_harness_write_table(r, t, "timing.tsv");
  nl_harness_report_table(r, t, "Cost: annealing moves of one optimisation per row", 4);
  if (t->nrows)
    nl_harness_text(r,
                    "Timing: the thread CPU time of one full multi-level optimisation per row and "
                    "its annealing moves per CPU second (set-up and the per-temperature re-sums "
                    "included) are in times.tsv, beside the manifest (not tracked: they differ on "
                    "every run); `build/bench/bench_cheng` times the thesis setting alone. C6 sets "
                    "a reproduction's time per table against one optimisation's.\n");
}
