/* nl_sweep.h - a parameter sweep of an experiment, everything but running
 * its tasks: value specs, the plan, the job files, the state, the merge.
 *
 * A sweep runs one experiment at every point of the cartesian product of a
 * few parameters (--set NAME=VALUE), N seeds per point. Its folder holds
 *   sweep.tsv    the definition (key, value): experiment, quick, images, seed,
 *                seeds, task_seeds, then a param and a scale row per parameter
 *   tasks.tsv    one row per task: task, folder, seed, then the parameters
 *   jobs.txt     one self-contained shell line per task (GNU parallel, Slurm)
 *   sweep.slurm  an array job, one index per line of jobs.txt (optional)
 *   tasks/NNNN/  each task's run folder; its manifest.tsv marks it finished
 *   merged/      what nl_sweep_merge writes
 * Tasks are numbered in odometer order (last parameter fastest) with the
 * seeds innermost, so task j belongs to point j / seeds. Task j runs K seeds
 * of its own (--task-seeds K): nl_seed_replicate(seed, (j mod seeds) K), so
 * no two tasks of a point share a seed.
 *
 * Every call that can fail returns an nl_status and leaves a one-line
 * message in err; scripts/sweep.sh runs the tasks (tools/sweep.c is the
 * command line).
 */
#ifndef NL_SWEEP_H
#define NL_SWEEP_H

#include "base/nl_base.h"
#include "table/nl_table.h"

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- values: NAME=SPEC (nl_sweep_plan.c) -------------------------------
 *
 * SPEC is a list 0,0.1,0.5 (each a number, kept as written); a linear range
 * A:B:N (N values from A to B); or a log range A:B:logN (N values evenly
 * spaced in log10, A, B > 0). Range values are printed with 15 digits and
 * the last one is B as written, so 1e-4:1:log5 gives exact decades. */
typedef struct {
  char *name, *scale;   /* scale: "list", "lin" or "log" (the plot's x axis) */
  size_t n;
  char **values;        /* the text passed to --set NAME=VALUE */
} nl_sweep_param;

nl_status nl_sweep_expand(const char *arg, nl_sweep_param *p, nl_error *err);
void nl_sweep_param_free(nl_sweep_param *p);

/* ---- the plan (nl_sweep_plan.c) ---------------------------------------- */
typedef struct {
  const char *experiment, *out;
  long seed, seeds, task_seeds, quick;
  long images;          /* 1: each task writes its images; 0: --no-images */
  int np;
  nl_sweep_param *p;
} nl_sweep_plan;

/* Checks names (each given once) and seeds (within 32 bits) and builds the
 * definition (sweep.tsv) into *def and the tasks (tasks.tsv) into *tasks;
 * more than a million tasks is refused. */
nl_status nl_sweep_plan_make(const nl_sweep_plan *pl, nl_table **def, nl_table **tasks,
                             nl_error *err);
/* Writes def and tasks into pl->out: a new or empty folder gets the sweep,
 * one holding this very sweep is resumed, anything else is refused before
 * a byte is written. sweep.tsv is written last, so a folder with it has its
 * tasks.tsv. */
nl_status nl_sweep_plan_write(const nl_sweep_plan *pl, const nl_table *def, const nl_table *tasks,
                              nl_error *err);
/* A table as TSV on fp, cells as nl_table_write formats them. */
void nl_sweep_table_print(const nl_table *t, FILE *fp);

/* ---- jobs and state (nl_sweep_jobs.c) ----------------------------------- */

/* POSIX single quotes, so a job line runs under any sh. */
void nl_sweep_sh_quote(FILE *fp, const char *s);
/* Asks the experiment (exe --params) whether every swept name is one of its
 * parameters, then runs exe --params --set ... once per position of the
 * value lists so that it checks every value as a run would (no work done).
 * The message is the experiment's own line on a bad value. */
nl_status nl_sweep_probe(const nl_sweep_plan *pl, const char *exe, nl_error *err);
/* The sweep folder: out, or ROOT/sweeps/EXPERIMENT-NAME-..., made absolute
 * (job lines run anywhere), its parent made. *dir is the caller's to free. */
nl_status nl_sweep_folder(const nl_sweep_plan *pl, const char *out, const char *root, char **dir,
                          nl_error *err);
/* jobs.txt in pl->out: one line per task, which skips itself when the
 * task's manifest exists, with cpus BLAS/OpenMP threads and NL_COMMIT from
 * the environment; the task's output goes to logs/NNNN.log. */
nl_status nl_sweep_write_jobs(const nl_sweep_plan *pl, const nl_table *tasks, const char *exe,
                              long cpus, nl_error *err);
/* sweep.slurm in pl->out: an array job of ntasks indices, each running its
 * line of jobs.txt with the given cpus, memory (2G) and time (01:00:00). */
nl_status nl_sweep_write_slurm(const nl_sweep_plan *pl, size_t ntasks, long cpus, const char *mem,
                               const char *time, nl_error *err);

/* Everything before the tasks run: checks the Slurm resources (mem like 2G,
 * time like 01:00:00), emit ("", "parallel" or "slurm") and that exe runs;
 * expands the nspec NAME=SPEC into pl->p (the caller frees each with
 * nl_sweep_param_free, then pl->p), plans, asks the experiment
 * (nl_sweep_probe), writes the folder (out, or nl_sweep_folder's default
 * under root; *dir, the caller frees) with its logs/ and tasks/, jobs.txt,
 * and for emit "slurm" sweep.slurm; for an emit it says on log how to run
 * the tasks elsewhere. pl->out becomes *dir. */
typedef struct {
  const char *exe, *root, *out, *emit, *mem, *time;
  long cpus;
} nl_sweep_prepare_opts;
nl_status nl_sweep_prepare(nl_sweep_plan *pl, const char *const *specs, int nspec,
                           const nl_sweep_prepare_opts *o, char **dir, FILE *log, nl_error *err);

/* The state of a prepared sweep in dir. what "": prints "TOTAL DONE" on out;
 * "pending": prints the job lines of the unfinished tasks on out;
 * "failures": one line per unfinished task with the end of its log on log,
 * and *failed the number of them. */
nl_status nl_sweep_status(const char *dir, const char *what, FILE *out, FILE *log, size_t *failed,
                          nl_error *err);
/* Is the task in dir/folder finished? Its run wrote folder/manifest.tsv,
 * which an experiment writes last. */
int nl_sweep_task_finished(const char *dir, const char *folder);
/* The last non-empty line of text (text is modified in place). */
const char *nl_sweep_last_line(char *text);

/* ---- merge (nl_sweep_merge.c) ------------------------------------------
 *
 * For every table T that the finished tasks wrote, merged/T holds all their
 * rows behind the parameters and the seed (a task column named like one of
 * them becomes task_NAME), and merged/T_summary.tsv one row per parameter
 * point and row of T: the parameters, row (1-based), T's text columns, n
 * (seeds that reached it), then COL_mean and COL_spread (the sd over seeds,
 * GSL's, 0 for one seed) for every numeric column. Rows are grouped by
 * (point, row) in a hash table, in the order of their first merged row. */
typedef struct {
  const char *dir;
  int np;
  char **pname, **pscale;  /* the parameters and their scales */
  long seeds;
  nl_table *tasks;         /* task, folder, seed, params... */
  size_t ndone, *done;     /* rows of tasks whose folder has a manifest */
} nl_sweep_merge;

/* Reads dir's definition and tasks and finds the finished tasks (none is an
 * error; some is said on log). nl_sweep_merge_free releases it. */
nl_status nl_sweep_merge_open(const char *dir, nl_sweep_merge *m, FILE *log, nl_error *err);
void nl_sweep_merge_free(nl_sweep_merge *m);
/* merged/FILE: the rows of every finished task. *first gets the first
 * task's table; point_of[r] and row_of[r] (the caller frees) say which
 * parameter point and which row of its task merged row r came from. */
nl_status nl_sweep_merge_rows(const nl_sweep_merge *m, const char *file, nl_table **merged,
                              nl_table **first, size_t **point_of, size_t **row_of, nl_error *err);
/* FILE_summary.tsv from the merged rows. */
nl_status nl_sweep_merge_summary(const nl_sweep_merge *m, const nl_table *merged,
                                 const nl_table *first, const size_t *point_of,
                                 const size_t *row_of, nl_table **summary, nl_error *err);

/* ---- the plot (nl_sweep_plot.c) -----------------------------------------
 *
 * plot.dat holds one block per legend entry ("x", the title, "spread"; then
 * x, mean, sd sorted by x), the blocks of a second y after the first's, as
 * scripts/gnuplot/sweep.gp draws them. y: COL or COL,COL2 (NULL: the first
 * numeric column whose mean moves across the sweep); x: a parameter (NULL:
 * the first). The plot's settings go to out as gnuplot assignments (dat,
 * out, xlabel, ylabel, y2label, title, logx, ny1, nblocks). */
typedef struct { const char *table, *y, *x; } nl_sweep_merge_opts;
nl_status nl_sweep_plot(const nl_sweep_merge *m, const nl_sweep_merge_opts *o, const char *file,
                        const nl_table *first, const nl_table *summary, const char *outdir,
                        FILE *out, FILE *log, nl_error *err);

/* The whole merge of dir: every table merged and summarised into
 * dir/merged, the plot of o->table (NULL: the first) written. */
nl_status nl_sweep_merge_all(const char *dir, const nl_sweep_merge_opts *o, FILE *out, FILE *log,
                             nl_error *err);

#ifdef __cplusplus
}
#endif

#endif
