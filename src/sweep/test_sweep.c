/* Tests of nl_sweep.h: value specs, the plan and its folder, the merge's
 * grouping against a direct count, the summary's means and spreads against
 * sums done here, and the state of a half-finished sweep. */
#define _GNU_SOURCE   /* open_memstream */
#include "sweep/nl_sweep.h"
#include "nl_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *dir;

static int expand_fails_with(const char *arg, const char *needle)
{
  nl_sweep_param p;
  nl_error err = {{0}};
  int ok = nl_sweep_expand(arg, &p, &err) != NL_OK && strstr(err.msg, needle) != NULL;
  if (!ok)
    fprintf(stderr, "  %s: got '%s'\n", arg, err.msg);
  nl_sweep_param_free(&p);
  return ok;
}

NL_TEST(expand_lists_and_ranges)
{
  nl_sweep_param p;
  nl_error err;
  NL_CHECK(nl_sweep_expand("gain=0,0.25,1e-3", &p, &err) == NL_OK);
  NL_CHECK(p.n == 3 && !strcmp(p.values[2], "1e-3") && !strcmp(p.scale, "list"));
  nl_sweep_param_free(&p);
  NL_CHECK(nl_sweep_expand("z=0:1:5", &p, &err) == NL_OK);
  NL_CHECK(p.n == 5 && !strcmp(p.values[1], "0.25") && !strcmp(p.values[4], "1"));
  NL_CHECK(!strcmp(p.scale, "lin"));
  nl_sweep_param_free(&p);
  /* Decades come out exact: 10^-4 .. 10^0, written as %.15g gives 0.001. */
  NL_CHECK(nl_sweep_expand("eps=1e-4:1:log5", &p, &err) == NL_OK);
  NL_CHECK(p.n == 5 && !strcmp(p.values[0], "0.0001") && !strcmp(p.values[1], "0.001"));
  NL_CHECK(!strcmp(p.values[4], "1") && !strcmp(p.scale, "log"));
  nl_sweep_param_free(&p);
  NL_CHECK(expand_fails_with("z=0:1:0", "empty range"));
  NL_CHECK(expand_fails_with("z=", "empty range (no values)"));
  NL_CHECK(expand_fails_with("z=0:1:log5", "a log range needs positive ends"));
  NL_CHECK(expand_fails_with("z=1,,2", "empty value in the list"));
  NL_CHECK(expand_fails_with("z=1,x", "'x' is not a number"));
  NL_CHECK(expand_fails_with("a-b=1", "is not a parameter name"));
  NL_CHECK(expand_fails_with("=1", "is not NAME=SPEC"));
  NL_CHECK(expand_fails_with("z=1:2:2.5", "is not a whole number"));
}

/* A plan of two parameters (2 x 3 values) and 2 seeds, K = 3 seeds a task. */
static void small_plan(nl_sweep_plan *pl, nl_sweep_param *p)
{
  nl_error err;
  nl_sweep_expand("a=1,2", &p[0], &err);
  nl_sweep_expand("b=10:30:3", &p[1], &err);
  *pl = (nl_sweep_plan){.experiment = "x", .seed = 5, .seeds = 2, .task_seeds = 3, .np = 2, .p = p};
}

NL_TEST(plan_is_odometer_order_with_seeds_inner)
{
  nl_sweep_param p[2];
  nl_sweep_plan pl;
  nl_table *def, *tasks;
  nl_error err;
  small_plan(&pl, p);
  NL_CHECK(nl_sweep_plan_make(&pl, &def, &tasks, &err) == NL_OK);
  NL_CHECK(tasks->nrows == 12 && tasks->ncols == 5);
  char buf[32];
  /* Task 7: point 3 = (a 2, b 10), the second seed: replicate 1 * K = 3. */
  NL_CHECK(!strcmp(nl_table_cell_text(tasks, 7, 1, buf), "tasks/0007"));
  NL_CHECK(!strcmp(nl_table_cell_text(tasks, 7, 3, buf), "2"));
  NL_CHECK(!strcmp(nl_table_cell_text(tasks, 7, 4, buf), "10"));
  snprintf(buf, sizeof buf, "%lu", nl_seed_replicate(5, 3));
  NL_CHECK(!strcmp(tasks->text[7 * 5 + 2], buf));
  NL_CHECK(!strcmp(nl_table_text(def, 6, "value"), "a=1,2"));
  NL_CHECK(!strcmp(nl_table_text(def, 9, "value"), "b=lin"));
  nl_table_free(def);
  nl_table_free(tasks);
  nl_sweep_param_free(&p[0]);
  nl_sweep_param_free(&p[1]);
  nl_sweep_expand("a=3", &p[0], &err);
  nl_sweep_expand("a=4", &p[1], &err);
  NL_CHECK(nl_sweep_plan_make(&pl, &def, &tasks, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, "--param a given twice") != NULL);
  nl_sweep_param_free(&p[0]);
  nl_sweep_param_free(&p[1]);
}

NL_TEST(plan_folder_resumes_only_the_same_sweep)
{
  nl_sweep_param p[2];
  nl_sweep_plan pl;
  nl_table *def, *tasks;
  nl_error err;
  small_plan(&pl, p);
  char *out = nl_path_join(dir, "plan");
  pl.out = out;
  nl_sweep_plan_make(&pl, &def, &tasks, &err);
  NL_CHECK(nl_sweep_plan_write(&pl, def, tasks, &err) == NL_OK);
  NL_CHECK(nl_sweep_plan_write(&pl, def, tasks, &err) == NL_OK);
  nl_table_free(def);
  nl_table_free(tasks);
  pl.seeds = 3;
  nl_sweep_plan_make(&pl, &def, &tasks, &err);
  NL_CHECK(nl_sweep_plan_write(&pl, def, tasks, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, "holds a different sweep") != NULL);
  nl_table_free(def);
  nl_table_free(tasks);
  free(out);
  nl_sweep_param_free(&p[0]);
  nl_sweep_param_free(&p[1]);
}

/* A sweep folder whose finished tasks wrote t.tsv: rows labelled "lo" and
 * "hi" with value = f(a, seed, row). Task 1 is left unfinished. */
static double value_of(double a, long seed, int row) { return a * a + 0.1 * seed + row * 7.0; }

static char *fake_sweep(const char *name, int npoints, int nseeds, int nrows)
{
  char *d = nl_path_join(dir, name), spec[64];
  nl_sweep_param p;
  nl_error err;
  snprintf(spec, sizeof spec, "a=1:%d:%d", npoints, npoints);
  nl_sweep_expand(spec, &p, &err);
  nl_sweep_plan pl = {.experiment = "x", .out = d, .seed = 1, .seeds = nseeds, .task_seeds = 1,
                      .np = 1, .p = &p};
  nl_table *def, *tasks;
  NL_CHECK(nl_sweep_plan_make(&pl, &def, &tasks, &err) == NL_OK);
  NL_CHECK(nl_sweep_plan_write(&pl, def, tasks, &err) == NL_OK);
  const char *cols[] = {"label", "value"};
  for (size_t r = 0; r < tasks->nrows; r++) {
    char buf[32], *task = nl_path_join(d, nl_table_cell_text(tasks, r, 1, buf));
    NL_CHECK(nl_mkdir_p(task, &err) == NL_OK);
    nl_table *t = nl_table_alloc(2, cols);
    double a = atof(tasks->text[r * tasks->ncols + 3]);
    long seed = atol(tasks->text[r * tasks->ncols + 2]);
    for (int k = 0; k < nrows; k++)
      nl_table_append(t, "sd", k % 2 ? "hi" : "lo", value_of(a, seed, k));
    char *tp = nl_path_join(task, "t.tsv"), *mp = nl_path_join(task, "manifest.tsv");
    NL_CHECK(nl_table_write(t, tp, &err) == NL_OK);
    if (r != 1)   /* any file: its presence marks the task finished */
      NL_CHECK(nl_table_write(t, mp, &err) == NL_OK);
    nl_table_free(t);
    free(tp);
    free(mp);
    free(task);
  }
  nl_table_free(def);
  nl_table_free(tasks);
  nl_sweep_param_free(&p);
  return d;
}

NL_TEST(merge_groups_rows_by_point_and_row)
{
  enum { NP = 40, NS = 3, NR = 5 };
  char *d = fake_sweep("merge", NP, NS, NR);
  nl_sweep_merge m;
  nl_error err;
  FILE *null = fopen("/dev/null", "w");
  if (nl_sweep_merge_open(d, &m, null, &err)) {
    NL_CHECK(!err.msg[0]);
    fprintf(stderr, "  %s\n", err.msg);
    return;
  }
  NL_CHECK(m.ndone == NP * NS - 1 && m.np == 1 && m.seeds == NS);
  nl_table *merged, *first, *sum;
  size_t *point_of, *row_of;
  NL_CHECK(nl_sweep_merge_rows(&m, "t.tsv", &merged, &first, &point_of, &row_of, &err) == NL_OK);
  NL_CHECK(merged->nrows == (NP * NS - 1) * NR);
  NL_CHECK(!strcmp(merged->names[0], "a") && !strcmp(merged->names[1], "seed"));
  NL_CHECK(nl_sweep_merge_summary(&m, merged, first, point_of, row_of, &sum, &err) == NL_OK);
  NL_CHECK(sum->nrows == NP * NR);
  /* Every group against a direct scan of the merged rows: n, mean, sd. */
  long cn = nl_table_column(sum, "n"), cm = nl_table_column(sum, "value_mean");
  long cs = nl_table_column(sum, "value_spread"), cr = nl_table_column(sum, "row");
  for (size_t g = 0; g < sum->nrows; g++) {
    double a = nl_table_get(sum, g, 0), row = nl_table_get(sum, g, (size_t)cr) - 1;
    double s1 = 0, s2 = 0;
    int n = 0;
    for (size_t r = 0; r < merged->nrows; r++)
      if (nl_table_get(merged, r, 0) == a && (double)row_of[r] == row) {
        double v = nl_table_get(merged, r, 3);
        s1 += v;
        s2 += v * v;
        n++;
      }
    double mean = s1 / n, sd = n > 1 ? sqrt((s2 - n * mean * mean) / (n - 1)) : 0;
    NL_CHECK(nl_table_get(sum, g, (size_t)cn) == n);
    NL_CHECK_NEAR(nl_table_get(sum, g, (size_t)cm), mean, 1e-9 * fabs(mean));
    NL_CHECK_NEAR(nl_table_get(sum, g, (size_t)cs), sd, 1e-6);
    NL_CHECK(!strcmp(sum->text[g * sum->ncols + 2], (int)row % 2 ? "hi" : "lo"));
  }
  /* Point 0 lost its second seed (task 1): n = NS - 1 for its rows. */
  NL_CHECK(nl_table_get(sum, 0, (size_t)cn) == NS - 1 && nl_table_get(sum, NR, (size_t)cn) == NS);
  /* Groups in the order of their first merged rows: point-major, then row. */
  NL_CHECK(nl_table_get(sum, NR + 2, 0) == 2 && nl_table_get(sum, NR + 2, (size_t)cr) == 3);
  nl_table_free(merged);
  nl_table_free(first);
  nl_table_free(sum);
  free(point_of);
  free(row_of);
  nl_sweep_merge_free(&m);
  fclose(null);
  free(d);
}

NL_TEST(merge_all_writes_tables_and_the_plot)
{
  char *d = fake_sweep("all", 3, 2, 2), *p = nl_path_join(d, "merged/t_summary.tsv");
  char *dat = nl_path_join(d, "merged/plot.dat");
  nl_error err;
  FILE *null = fopen("/dev/null", "w");
  nl_sweep_merge_opts o = {.y = "value"};
  NL_CHECK(nl_sweep_merge_all(d, &o, null, null, &err) == NL_OK);
  struct stat st;
  NL_CHECK(stat(p, &st) == 0 && stat(dat, &st) == 0);
  o.y = "nosuch";
  NL_CHECK(nl_sweep_merge_all(d, &o, null, null, &err) != NL_OK);
  NL_CHECK(strstr(err.msg, "--y nosuch: not a numeric column") != NULL);
  fclose(null);
  free(p);
  free(dat);
  free(d);
}

NL_TEST(status_counts_finished_tasks)
{
  char *d = fake_sweep("status", 2, 2, 1), *text = NULL;
  size_t n = 0, failed;
  nl_error err;
  FILE *out = open_memstream(&text, &n), *null = fopen("/dev/null", "w");
  NL_CHECK(nl_sweep_status(d, "", out, null, &failed, &err) == NL_OK);
  NL_CHECK(nl_sweep_status(d, "failures", out, null, &failed, &err) == NL_OK && failed == 1);
  fclose(out);
  NL_CHECK(!strcmp(text, "4 3\n"));
  NL_CHECK(nl_sweep_status(d, "what", stdout, null, &failed, &err) != NL_OK);
  fclose(null);
  free(text);
  free(d);
}

int main(void)
{
  dir = nl_test_tmpdir();
  return nl_test_run();
}
