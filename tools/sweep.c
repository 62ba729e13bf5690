/* noiselab sweep - everything of a parameter sweep but running its tasks:
 * expanding value specs, checking names and values with the experiment
 * (--params), planning the tasks, writing the job lines and the Slurm array
 * script, the sweep's state, and merging the tables. scripts/sweep.sh runs
 * the tasks (GNU parallel here, or prints how to submit them).
 *
 *   noiselab-sweep prepare --experiment E --exe PATH [--root DIR] [sweep options]
 *       what `scripts/noiselab sweep E ...` does before running anything (see
 *       usage below): checks every option, spec, parameter name (against
 *       `PATH --params`) and value (`PATH --params --set ...`, no work done),
 *       writes DIR/sweep.tsv, tasks.tsv and jobs.txt (and sweep.slurm for
 *       --emit slurm), and prints "DIR<TAB>JOBS" when the tasks are to run here.
 *   noiselab-sweep status DIR [pending|failures]
 *       "TOTAL DONE"; the job lines of the unfinished tasks; or a line per
 *       unfinished task with the end of its log on stderr (exit 1 if any).
 *   noiselab-sweep usage
 *
 *   noiselab-sweep expand NAME=SPEC
 *       prints the values, one a line. SPEC: a list 0,0.1,0.5; a linear range
 *       A:B:N (N values from A to B); a log range A:B:logN (N values spaced
 *       evenly in log, A, B > 0). Range values are printed with 15 digits.
 *   noiselab-sweep plan --experiment E --seed S --seeds N --task-seeds K
 *                       --quick 0|1 [--images 0|1] [--out DIR] NAME=SPEC...
 *       the cartesian product of the values times N seeds (S, S+K, ...; each
 *       task runs K seeds of its own, so no two tasks share one). Without
 *       --out: prints tasks.tsv. With it: writes DIR/sweep.tsv (the
 *       definition) and DIR/tasks.tsv, or checks that DIR holds this very
 *       sweep; a folder holding anything else is refused, nothing written.
 *   noiselab-sweep merge DIR [--table T] [--y COL[,COL2]] [--x NAME]
 *       DIR/merged/T for every table T of the finished tasks (parameters and
 *       seed as leading columns), T_summary.tsv (per parameter point and row:
 *       n, then COL_mean and COL_spread, the sd over seeds), and plot.dat, the
 *       blocks scripts/gnuplot/sweep.gp draws; prints the plot's settings as
 *       gnuplot assignments on stdout.
 * Errors: one line on stderr, exit 2.
 */
#define _GNU_SOURCE   /* open_memstream, popen, realpath */
#include "harness/nl_harness.h"
#include "table/nl_table.h"

#include <ctype.h>
#include <errno.h>
#include <sys/wait.h>
#include <unistd.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <dirent.h>
#include <gsl/gsl_statistics_double.h>

typedef struct {
  char *name, *scale;      /* scale: list, lin or log */
  size_t n;
  char **values;           /* text as passed to --set */
} nl_sweep_param;

static void nl_sweep_die(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
static void nl_sweep_die(const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fputs("noiselab sweep: ", stderr);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  exit(2);
}

static double spec_number(const char *arg, const char *s)
{
  char *end;
  double v = strtod(s, &end);
  if (end == s || *end || !isfinite(v)) nl_sweep_die("--param %s: '%s' is not a number", arg, s);
  return v;
}

static void push(nl_sweep_param *p, const char *text)
{
  p->values = nl_xrealloc(p->values, (p->n + 1) * sizeof *p->values);
  p->values[p->n++] = nl_xstrdup(text);
}

/* A:B:N or A:B:logN */
static void expand_range(nl_sweep_param *p, const char *arg, char *spec)
{
  char *b = strchr(spec, ':'), *n = b ? strchr(b + 1, ':') : NULL;
  if (!b || !n || strchr(n + 1, ':')) nl_sweep_die("--param %s: a range is A:B:N or A:B:logN", arg);
  *b++ = '\0'; *n++ = '\0';
  int lg = !strncmp(n, "log", 3);
  double lo = spec_number(arg, spec), hi = spec_number(arg, b), cnt = spec_number(arg, lg ? n + 3 : n);
  if (cnt != floor(cnt) || cnt > 100000) nl_sweep_die("--param %s: the count '%s' is not a whole number up to 100000", arg, n);
  if (cnt < 1) nl_sweep_die("--param %s: empty range (%g values)", arg, cnt);
  if (lg && (lo <= 0 || hi <= 0)) nl_sweep_die("--param %s: a log range needs positive ends", arg);
  p->scale = nl_xstrdup(lg ? "log" : "lin");
  for (long i = 0; i < (long)cnt; i++) {
    double t = cnt > 1 ? i / (cnt - 1) : 0, v;
    if (i == (long)cnt - 1 && cnt > 1) v = hi;    /* the end as written */
    /* base 10: decades come out exact (pow(10, -4) is 1e-4, exp(log) is not) */
    else v = lg ? pow(10, log10(lo) + t * (log10(hi) - log10(lo))) : lo + t * (hi - lo);
    char buf[40];
    snprintf(buf, sizeof buf, "%.15g", v);
    push(p, buf);
  }
}

static void nl_sweep_expand(nl_sweep_param *p, const char *arg)
{
  const char *eq = strchr(arg, '=');
  memset(p, 0, sizeof *p);
  if (!eq || eq == arg) nl_sweep_die("--param '%s' is not NAME=SPEC", arg);
  p->name = nl_xstrdup(arg);
  p->name[eq - arg] = '\0';
  for (const char *c = p->name; *c; c++)
    if (!isalnum((unsigned char)*c) && *c != '_') nl_sweep_die("--param %s: '%s' is not a parameter name", arg, p->name);
  char *spec = nl_xstrdup(eq + 1);
  if (!*spec) nl_sweep_die("--param %s: empty range (no values)", arg);
  if (strchr(spec, ':')) expand_range(p, arg, spec);
  else {
    p->scale = nl_xstrdup("list");
    char *save = NULL;
    if (spec[0] == ',' || spec[strlen(spec) - 1] == ',' || strstr(spec, ",,")) nl_sweep_die("--param %s: empty value in the list", arg);
    for (char *tok = strtok_r(spec, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
      spec_number(arg, tok);
      push(p, tok);
    }
  }
  free(spec);
}

static void param_free(nl_sweep_param *p)
{
  for (size_t i = 0; i < p->n; i++) free(p->values[i]);
  free(p->values); free(p->name); free(p->scale);
}

/* ---- plan ------------------------------------------------------------------ */

typedef struct {
  const char *experiment, *out;
  long seed, seeds, task_seeds, quick;
  long images;   /* 1: --images (each task writes its images); 0: tasks run with --no-images */
  int np;
  nl_sweep_param *p;
} nl_sweep_plan;

static long plan_long(const char *opt, const char *s, long lo, long hi)
{
  long v;
  nl_error err;
  if (nl_parse_long(opt, s, lo, hi, &v, &err)) nl_sweep_die("%s", err.msg);
  return v;
}

static nl_table *plan_definition(const nl_sweep_plan *pl)
{
  const char *cols[] = {"key", "value"};
  nl_table *d = nl_table_alloc(2, cols);
  char buf[64];
  nl_table_append(d, "ss", "experiment", pl->experiment);
  nl_table_append(d, "ss", "quick", pl->quick ? "yes" : "no");
  nl_table_append(d, "ss", "images", pl->images ? "yes" : "no");
  snprintf(buf, sizeof buf, "%ld", pl->seed); nl_table_append(d, "ss", "seed", buf);
  snprintf(buf, sizeof buf, "%ld", pl->seeds); nl_table_append(d, "ss", "seeds", buf);
  snprintf(buf, sizeof buf, "%ld", pl->task_seeds); nl_table_append(d, "ss", "task_seeds", buf);
  for (int k = 0; k < pl->np; k++) {
    size_t len = strlen(pl->p[k].name) + 2;
    for (size_t i = 0; i < pl->p[k].n; i++) len += strlen(pl->p[k].values[i]) + 1;
    char *v = nl_xmalloc(len), *w = v;
    w += sprintf(w, "%s=", pl->p[k].name);
    for (size_t i = 0; i < pl->p[k].n; i++) w += sprintf(w, "%s%s", i ? "," : "", pl->p[k].values[i]);
    nl_table_append(d, "ss", "param", v);
    snprintf(buf, sizeof buf, "%.40s=%s", pl->p[k].name, pl->p[k].scale);
    nl_table_append(d, "ss", "scale", buf);
    free(v);
  }
  return d;
}

/* Tasks: points in odometer order (last parameter fastest), seeds innermost. */
static nl_table *plan_tasks(const nl_sweep_plan *pl)
{
  const char **cols = nl_xcalloc((size_t)pl->np + 3, sizeof *cols);
  cols[0] = "task"; cols[1] = "folder"; cols[2] = "seed";
  size_t total = (size_t)pl->seeds;
  for (int k = 0; k < pl->np; k++) { cols[k + 3] = pl->p[k].name; total *= pl->p[k].n; }
  nl_table *t = nl_table_alloc((size_t)pl->np + 3, cols);
  int width = 4;
  for (size_t m = total; m >= 10000; m /= 10) width++;
  for (size_t id = 0; id < total; id++) {
    char folder[64] = "tasks/", num[32], seed[32];
    size_t rest = id / (size_t)pl->seeds;
    snprintf(num, sizeof num, "%zu", id);
    for (int z = (int)strlen(num); z < width; z++) strcat(folder, "0");
    strcat(folder, num);
    /* Task j runs replicates j K .. j K + K - 1 of the sweep's base seed. */
    snprintf(seed, sizeof seed, "%lu",
             nl_seed_replicate((unsigned long)pl->seed, (long)(id % (size_t)pl->seeds) * pl->task_seeds));
    size_t row = nl_table_append_empty(t);
    nl_table_set(t, row, "task", (double)id);
    nl_table_set_text(t, row, "folder", folder);
    nl_table_set_text(t, row, "seed", seed);
    for (int k = pl->np - 1; k >= 0; k--) {
      nl_table_set_text(t, row, pl->p[k].name, pl->p[k].values[rest % pl->p[k].n]);
      rest /= pl->p[k].n;
    }
  }
  free(cols);
  return t;
}

static char *slurp(const char *path)
{
  FILE *fp = fopen(path, "rb");
  if (!fp) return NULL;
  char *buf = NULL;
  size_t n = 0, cap = 0, got;
  do {
    if (n + 4096 + 1 > cap) buf = nl_xrealloc(buf, cap = 2 * cap + 4096 + 1);
    got = fread(buf + n, 1, cap - n - 1, fp);
    n += got;
  } while (got > 0);
  fclose(fp);
  buf[n] = '\0';
  return buf;
}

static void write_or_die(const nl_table *t, const char *path)
{
  nl_error err;
  if (nl_table_write(t, path, &err)) nl_sweep_die("%s", err.msg);
}

/* A new or empty folder gets the sweep; one holding this sweep is resumed;
 * anything else is refused before a byte is written. */
static void plan_write(const nl_sweep_plan *pl, const nl_table *def, const nl_table *tasks)
{
  nl_error err;
  char *sweep = nl_path_join(pl->out, "sweep.tsv"), *tpath = nl_path_join(pl->out, "tasks.tsv");
  char *old = slurp(sweep);
  if (!old) {
    DIR *d = opendir(pl->out);
    struct dirent *e;
    while (d && (e = readdir(d)))
      if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
        nl_sweep_die("%s: the folder holds files but no sweep.tsv; refusing to write into it", pl->out);
    if (d) closedir(d);
    if (nl_mkdir_p(pl->out, &err)) nl_sweep_die("%s", err.msg);
  } else {
    char *tmp = nl_path_join(pl->out, ".sweep.new.tsv");
    write_or_die(def, tmp);
    char *now = slurp(tmp);
    remove(tmp);
    int same = now && !strcmp(now, old);
    free(tmp); free(now); free(old);
    if (!same) nl_sweep_die("%s holds a different sweep (see its sweep.tsv); choose another --out", pl->out);
  }
  write_or_die(tasks, tpath);
  write_or_die(def, sweep);   /* last: a folder with sweep.tsv has its tasks.tsv */
  free(sweep); free(tpath);
}

static void print_table(const nl_table *t)
{
  for (size_t c = 0; c < t->ncols; c++) printf("%s%s", c ? "\t" : "", t->names[c]);
  putchar('\n');
  for (size_t r = 0; r < t->nrows; r++) {
    for (size_t c = 0; c < t->ncols; c++) {
      char buf[32];
      const char *s = t->text[r * t->ncols + c];
      if (!s) { nl_table_format_double(buf, t->num[r * t->ncols + c]); s = buf; }
      printf("%s%s", c ? "\t" : "", s);
    }
    putchar('\n');
  }
}

/* Names given once, seeds within 32 bits; the definition (sweep.tsv). */
static nl_table *plan_check(const nl_sweep_plan *pl)
{
  for (int a = 0; a < pl->np; a++)
    for (int b = 0; b < a; b++)
      if (!strcmp(pl->p[a].name, pl->p[b].name)) nl_sweep_die("--param %s given twice", pl->p[a].name);
  if (pl->seed + (pl->seeds - 1) * pl->task_seeds + pl->task_seeds - 1 > 4294967295L) nl_sweep_die("--seed: seeds run past 2^32 - 1");
  return plan_definition(pl);
}

/* nl_opt with the sweep's exit: an option error is one line, exit 2. */
static int next_opt(nl_opt_parser *p, const char *context)
{
  nl_error err;
  int k = nl_opt_next(p, &err);
  if (k == NL_OPT_ERROR) nl_sweep_die("%s%s", context, err.msg);
  return k;
}

static int nl_sweep_plan_main(int argc, char **argv)
{
  nl_sweep_plan pl = {.seed = 1, .seeds = 1, .task_seeds = 1};
  pl.p = nl_xcalloc((size_t)argc, sizeof *pl.p);
  static const nl_opt_spec spec[] = {{"experiment", 0, 1}, {"out", 0, 1}, {"seed", 0, 1}, {"seeds", 0, 1},
                                     {"task-seeds", 0, 1}, {"quick", 0, 1}, {"images", 0, 1}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_opt_begin(&op, argc, argv, 0, spec);   /* first 0: argv[-1] is the subcommand word, getopt's argv[0] */
  for (int k; (k = next_opt(&op, "plan: ")) != NL_OPT_END;) {
    const char *a = op.name, *v = op.value[0];
    switch (k) {
    case NL_OPT_POSITIONAL: nl_sweep_expand(&pl.p[pl.np++], v); break;
    case 0: pl.experiment = v; break;
    case 1: pl.out = v; break;
    case 2: pl.seed = plan_long(a, v, 0, 4294967295L); break;
    case 3: pl.seeds = plan_long(a, v, 1, 100000); break;
    case 4: pl.task_seeds = plan_long(a, v, 1, 10000); break;
    case 5: pl.quick = plan_long(a, v, 0, 1); break;
    case 6: pl.images = plan_long(a, v, 0, 1); break;
    }
  }
  nl_opt_end(&op);
  if (!pl.experiment) nl_sweep_die("plan: --experiment missing");
  if (pl.np == 0) nl_sweep_die("no --param NAME=SPEC given");
  nl_table *def = plan_check(&pl), *tasks = plan_tasks(&pl);
  if (tasks->nrows > 1000000) nl_sweep_die("%zu tasks: more than a million; split the sweep", tasks->nrows);
  if (pl.out) plan_write(&pl, def, tasks);
  else print_table(tasks);
  nl_table_free(def); nl_table_free(tasks);
  for (int k = 0; k < pl.np; k++) param_free(&pl.p[k]);
  free(pl.p);
  return 0;
}

/* ---- merge ----------------------------------------------------------------- */

typedef struct {
  const char *dir;
  int np;
  char **pname, **pscale;
  long seeds;
  nl_table *tasks;          /* task, folder, seed, params... */
  size_t ndone, *done;      /* rows of tasks whose folder has a manifest */
} nl_sweep_merge;

static nl_table *read_or_die(const char *dir, const char *file)
{
  char *p = nl_path_join(dir, file);
  nl_table *t;
  nl_error err;
  if (nl_table_read(p, NL_TABLE_TEXT, &t, &err)) nl_sweep_die("%s", err.msg);
  free(p);
  return t;
}

static const char *cell(const nl_table *t, size_t r, size_t c, char *buf)
{
  const char *s = t->text[r * t->ncols + c];
  if (s) return s;
  nl_table_format_double(buf, t->num[r * t->ncols + c]);
  return buf;
}

static int file_exists(const char *dir, const char *a, const char *b)
{
  char *d = nl_path_join(dir, a), *p = nl_path_join(d, b);
  struct stat st;
  int ok = stat(p, &st) == 0;
  free(d); free(p);
  return ok;
}

static void merge_load(nl_sweep_merge *m)
{
  nl_table *def = read_or_die(m->dir, "sweep.tsv");
  m->tasks = read_or_die(m->dir, "tasks.tsv");
  char buf[32];
  for (size_t r = 0; r < def->nrows; r++) {
    const char *k = cell(def, r, 0, buf);
    char vb[32];
    const char *v = cell(def, r, 1, vb), *eq = strchr(v, '=');
    if (!strcmp(k, "seeds")) m->seeds = atol(v);
    if (strcmp(k, "param") || !eq) continue;
    m->pname = nl_xrealloc(m->pname, (size_t)(m->np + 1) * sizeof *m->pname);
    m->pscale = nl_xrealloc(m->pscale, (size_t)(m->np + 1) * sizeof *m->pscale);
    m->pname[m->np] = nl_xstrdup(v);
    m->pname[m->np][eq - v] = '\0';
    m->pscale[m->np++] = nl_xstrdup("list");
  }
  for (size_t r = 0; r < def->nrows; r++) {
    char vb[32];
    const char *v = cell(def, r, 1, vb), *eq = strchr(v, '=');
    if (strcmp(cell(def, r, 0, buf), "scale") || !eq) continue;
    for (int k = 0; k < m->np; k++)
      if (!strncmp(v, m->pname[k], (size_t)(eq - v)) && !m->pname[k][eq - v]) { free(m->pscale[k]); m->pscale[k] = nl_xstrdup(eq + 1); }
  }
  nl_table_free(def);
  if (m->np == 0 || m->seeds < 1 || m->tasks->ncols != (size_t)m->np + 3)
    nl_sweep_die("%s/sweep.tsv: not a sweep definition matching tasks.tsv", m->dir);
  m->done = nl_xcalloc(m->tasks->nrows + 1, sizeof *m->done);
  for (size_t r = 0; r < m->tasks->nrows; r++)
    if (file_exists(m->dir, cell(m->tasks, r, 1, buf), "manifest.tsv")) m->done[m->ndone++] = r;
  if (m->ndone == 0) nl_sweep_die("%s: no task has finished yet (no tasks/*/manifest.tsv)", m->dir);
  if (m->ndone < m->tasks->nrows)
    fprintf(stderr, "noiselab sweep: merging %zu of %zu tasks (the others are not finished)\n", m->ndone, m->tasks->nrows);
}

static char **task_tables(const nl_sweep_merge *m, size_t *n)
{
  char buf[32], *dir = nl_path_join(m->dir, cell(m->tasks, m->done[0], 1, buf));
  nl_error err;
  char **names = nl_harness_tables(dir, n, &err);
  if (!names) nl_sweep_die("%s", err.msg);
  free(dir);
  return names;
}

static nl_table *task_table(const nl_sweep_merge *m, size_t k, const char *file)
{
  char buf[32], *dir = nl_path_join(m->dir, cell(m->tasks, m->done[k], 1, buf));
  nl_table *t = read_or_die(dir, file);
  free(dir);
  return t;
}

/* Appends a row of n cells taken from text (NULL = the number). */
static void append_cells(nl_table *t, const double *num, char *const *text)
{
  nl_table_append_doubles(t, num);
  for (size_t c = 0; c < t->ncols; c++)
    if (text[c]) t->text[(t->nrows - 1) * t->ncols + c] = nl_xstrdup(text[c]);
}

/* merged/FILE: every finished task's rows behind its parameters and seed. */
static nl_table *merge_rows(const nl_sweep_merge *m, const char *file, nl_table **first, size_t **point_of, size_t **row_of)
{
  *first = task_table(m, 0, file);
  size_t lead = (size_t)m->np + 1, nc = lead + (*first)->ncols;
  const char **names = nl_xcalloc(nc, sizeof *names);
  char **renamed = nl_xcalloc(nc, sizeof *renamed);
  for (int k = 0; k < m->np; k++) names[k] = m->pname[k];
  names[m->np] = "seed";
  for (size_t c = 0; c < (*first)->ncols; c++) {
    const char *n = (*first)->names[c];
    int clash = !strcmp(n, "seed");
    for (int k = 0; k < m->np; k++) clash |= !strcmp(n, m->pname[k]);
    if (clash) { renamed[lead + c] = nl_xmalloc(strlen(n) + 6); sprintf(renamed[lead + c], "task_%s", n); }
    names[lead + c] = clash ? renamed[lead + c] : n;
  }
  nl_table *out = nl_table_alloc(nc, names);
  double *num = nl_xmalloc(nc * sizeof *num);
  char **text = nl_xcalloc(nc, sizeof *text);
  for (size_t k = 0; k < m->ndone; k++) {
    nl_table *t = k ? task_table(m, k, file) : *first;
    if (t->ncols != (*first)->ncols) nl_sweep_die("%s: task %zu's %s has other columns than the first task's", m->dir, m->done[k], file);
    for (size_t c = 0; c < lead; c++) num[c] = nl_table_get(m->tasks, m->done[k], c == (size_t)m->np ? 2 : c + 3);
    for (size_t r = 0; r < t->nrows; r++) {
      for (size_t c = 0; c < t->ncols; c++) { num[lead + c] = nl_table_get(t, r, c); text[lead + c] = t->text[r * t->ncols + c]; }
      append_cells(out, num, text);
      *point_of = nl_xrealloc(*point_of, out->nrows * sizeof **point_of);
      *row_of = nl_xrealloc(*row_of, out->nrows * sizeof **row_of);
      (*point_of)[out->nrows - 1] = m->done[k] / (size_t)m->seeds;   /* tasks: point-major, seeds inner */
      (*row_of)[out->nrows - 1] = r;
    }
    if (k) nl_table_free(t);
  }
  for (size_t c = 0; c < nc; c++) free(renamed[c]);
  free(renamed); free(names); free(num); free(text);
  return out;
}

/* Columns of the first task's table that hold text (labels), by its first row. */
static int is_text_col(const nl_table *first, size_t c) { return first->nrows > 0 && first->text[c] != NULL; }

/* FILE_summary.tsv: per parameter point and row of the table, n seeds and
 * the mean and spread (sd over seeds) of every numeric column. */
static nl_table *merge_summary(const nl_sweep_merge *m, const nl_table *merged, const nl_table *first,
                               const size_t *pointof, const size_t *rowof)
{
  size_t lead = (size_t)m->np + 1, tc = first->ncols, nc = (size_t)m->np + 2;
  for (size_t c = 0; c < tc; c++) nc += is_text_col(first, c) ? 1 : 2;
  const char **names = nl_xcalloc(nc, sizeof *names);
  char **owned = nl_xcalloc(nc, sizeof *owned);
  size_t j = 0;
  for (int k = 0; k < m->np; k++) names[j++] = m->pname[k];
  names[j++] = "row";
  for (size_t c = 0; c < tc; c++) if (is_text_col(first, c)) names[j++] = merged->names[lead + c];
  names[j++] = "n";
  for (size_t c = 0; c < tc; c++) {
    if (is_text_col(first, c)) continue;
    const char *b = merged->names[lead + c];
    owned[j] = nl_xmalloc(strlen(b) + 8); sprintf(owned[j], "%s_mean", b); names[j] = owned[j]; j++;
    owned[j] = nl_xmalloc(strlen(b) + 8); sprintf(owned[j], "%s_spread", b); names[j] = owned[j]; j++;
  }
  nl_table *s = nl_table_alloc(nc, names);
  double *num = nl_xmalloc(nc * sizeof *num), *vals = nl_xmalloc((m->ndone + 1) * sizeof *vals);
  char **text = nl_xcalloc(nc, sizeof *text);
  for (size_t r0 = 0; r0 < merged->nrows; r0++) {
    int seen = 0;   /* a (point, row) group starts at its first merged row */
    for (size_t r = 0; r < r0 && !seen; r++) seen = pointof[r] == pointof[r0] && rowof[r] == rowof[r0];
    if (seen) continue;
    memset(text, 0, nc * sizeof *text);
    size_t col = 0, n = 0;
    for (int k = 0; k < m->np; k++) num[col++] = nl_table_get(merged, r0, (size_t)k);
    num[col++] = (double)rowof[r0] + 1;
    for (size_t c = 0; c < tc; c++) if (is_text_col(first, c)) { text[col] = merged->text[r0 * merged->ncols + lead + c]; num[col++] = NAN; }
    for (size_t r = r0; r < merged->nrows; r++) n += pointof[r] == pointof[r0] && rowof[r] == rowof[r0];
    num[col++] = (double)n;
    for (size_t c = 0; c < tc; c++) {
      if (is_text_col(first, c)) continue;
      size_t q = 0;
      for (size_t r = r0; r < merged->nrows; r++) {
        if (pointof[r] != pointof[r0] || rowof[r] != rowof[r0]) continue;
        if (merged->text[r * merged->ncols + lead + c]) nl_sweep_die("%s: column %s holds text and numbers", m->dir, merged->names[lead + c]);
        vals[q++] = nl_table_get(merged, r, lead + c);
      }
      num[col++] = gsl_stats_mean(vals, 1, q);
      num[col++] = q > 1 ? gsl_stats_sd(vals, 1, q) : 0;
    }
    append_cells(s, num, text);
  }
  for (size_t c = 0; c < nc; c++) free(owned[c]);
  free(owned); free(names); free(num); free(vals); free(text);
  return s;
}

/* ---- the plot's data ---------------------------------------------------- */

typedef struct { double x, y, e; } nl_sweep_point;

static int by_x(const void *a, const void *b)
{
  double u = ((const nl_sweep_point *)a)->x, v = ((const nl_sweep_point *)b)->x;
  return (u > v) - (u < v);
}

/* The legend of a summary row: its label (first text column, or "row N" when
 * the table has several rows) and the parameters other than x. */
static void group_title(const nl_sweep_merge *m, const nl_table *s, size_t r, int xi, const char *y, int ny, char *buf, size_t n)
{
  size_t len = 0, lab = (size_t)m->np + 1;
  int several = 0;
  for (size_t q = 0; q < s->nrows; q++) several |= nl_table_get(s, q, (size_t)m->np) > 1;
  buf[0] = '\0';
  if (ny > 1) len += (size_t)snprintf(buf + len, n - len, "%s ", y);
  if (s->text[r * s->ncols + lab]) len += (size_t)snprintf(buf + len, n - len, "%s ", s->text[r * s->ncols + lab]);
  else if (several) len += (size_t)snprintf(buf + len, n - len, "row %g ", nl_table_get(s, r, (size_t)m->np));
  for (int k = 0; k < m->np && len < n; k++) {
    char v[32];
    int varies = 0;   /* a parameter held at one value says nothing here */
    for (size_t q = 0; q < s->nrows; q++) varies |= nl_table_get(s, q, (size_t)k) != nl_table_get(s, 0, (size_t)k);
    if (k == xi || !varies) continue;
    nl_table_format_double(v, nl_table_get(s, r, (size_t)k));
    len += (size_t)snprintf(buf + len, n - len, "%s=%s ", m->pname[k], v);
  }
  if (len > 0 && len < n && buf[len - 1] == ' ') buf[len - 1] = '\0';
  for (char *c = buf; *c; c++) if (*c == '"' || *c == '\t') *c = '\'';   /* the block header is a quoted field */
}

/* Writes one block per legend entry of y (x, mean, spread), sorted by x;
 * returns the number of blocks. */
static int plot_blocks(FILE *fp, const nl_sweep_merge *m, const nl_table *s, int xi, const char *y, int ny)
{
  char mean[160], spread[160];
  snprintf(mean, sizeof mean, "%s_mean", y); snprintf(spread, sizeof spread, "%s_spread", y);
  long cm = nl_table_column(s, mean), cs = nl_table_column(s, spread);
  if (cm < 0 || cs < 0) nl_sweep_die("--y %s: not a numeric column of the table", y);
  int blocks = 0;
  char *done = nl_xcalloc(s->nrows + 1, 1);
  nl_sweep_point *pt = nl_xmalloc((s->nrows + 1) * sizeof *pt);
  for (size_t r0 = 0; r0 < s->nrows; r0++) {
    if (done[r0]) continue;
    char title[512], t2[512];
    size_t n = 0;
    group_title(m, s, r0, xi, y, ny, title, sizeof title);
    for (size_t r = r0; r < s->nrows; r++) {
      group_title(m, s, r, xi, y, ny, t2, sizeof t2);
      if (done[r] || strcmp(title, t2)) continue;
      done[r] = 1;
      pt[n++] = (nl_sweep_point){nl_table_get(s, r, (size_t)xi), nl_table_get(s, r, (size_t)cm), nl_table_get(s, r, (size_t)cs)};
    }
    qsort(pt, n, sizeof *pt, by_x);
    fprintf(fp, "%sx\t\"%s\"\tspread\n", blocks ? "\n\n" : "", title);
    for (size_t i = 0; i < n; i++) {
      char a[32], b[32], c[32];
      nl_table_format_double(a, pt[i].x); nl_table_format_double(b, pt[i].y); nl_table_format_double(c, pt[i].e);
      fprintf(fp, "%s\t%s\t%s\n", a, b, c);
    }
    blocks++;
  }
  free(done); free(pt);
  return blocks;
}

/* gnuplot single-quoted string: a quote is written twice. */
static void gp_string(const char *key, const char *v)
{
  printf("%s='", key);
  for (const char *c = v; *c; c++) { if (*c == '\'') putchar('\''); putchar(*c); }
  printf("'; ");
}

/* The first numeric column whose mean moves across the sweep. */
static const char *default_y(const nl_sweep_merge *m, const nl_table *first, const nl_table *s)
{
  const char *fallback = NULL;
  for (size_t c = 0; c < first->ncols; c++) {
    if (is_text_col(first, c)) continue;
    int param = 0;
    for (int k = 0; k < m->np; k++) param |= !strcmp(first->names[c], m->pname[k]);
    if (param || !strcmp(first->names[c], "seed")) continue;
    if (!fallback) fallback = first->names[c];
    char mean[160];
    snprintf(mean, sizeof mean, "%s_mean", first->names[c]);
    long cm = nl_table_column(s, mean);
    for (size_t r = 1; cm >= 0 && r < s->nrows; r++)
      if (nl_table_get(s, r, (size_t)cm) != nl_table_get(s, 0, (size_t)cm)) return first->names[c];
  }
  if (!fallback) nl_sweep_die("the table has no numeric column to plot");
  return fallback;
}

typedef struct { const char *table, *y, *x; } nl_sweep_merge_opts;

static void merge_plot(const nl_sweep_merge *m, const nl_sweep_merge_opts *o, const char *file,
                       const nl_table *first, const nl_table *s, const char *outdir)
{
  int xi = 0;
  if (o->x) {
    for (xi = 0; xi < m->np && strcmp(m->pname[xi], o->x); xi++) {}
    if (xi == m->np) nl_sweep_die("--x %s: not a parameter of this sweep", o->x);
  }
  char *ys = nl_xstrdup(o->y ? o->y : default_y(m, first, s)), *y2 = strchr(ys, ',');
  if (y2) { *y2++ = '\0'; if (strchr(y2, ',')) nl_sweep_die("--y: at most two columns (the second on the right axis)"); }
  char *dat = nl_path_join(outdir, "plot.dat"), *png = nl_path_join(outdir, "plot.png");
  nl_atomic_file af;
  nl_error err;
  if (nl_atomic_open(&af, dat, &err)) nl_sweep_die("%s", err.msg);
  int n1 = plot_blocks(af.fp, m, s, xi, ys, y2 ? 2 : 1), n2 = 0;
  if (y2) { fputs("\n\n", af.fp); n2 = plot_blocks(af.fp, m, s, xi, y2, 2); }
  if (nl_atomic_commit(&af, &err)) nl_sweep_die("%s", err.msg);
  int logx = !strcmp(m->pscale[xi], "log");
  for (size_t r = 0; r < s->nrows; r++) logx &= nl_table_get(s, r, (size_t)xi) > 0;
  char title[512];
  snprintf(title, sizeof title, "%s: %s%s%s over %ld seed%s (mean, error bars: sd over seeds)", file, ys,
           y2 ? " (left), " : "", y2 ? y2 : "", m->seeds, m->seeds > 1 ? "s" : "");
  gp_string("dat", dat); gp_string("out", png); gp_string("xlabel", m->pname[xi]);
  gp_string("ylabel", ys); gp_string("y2label", y2 ? y2 : ""); gp_string("title", title);
  printf("logx=%d; ny1=%d; nblocks=%d\n", logx, n1, n1 + n2);
  fprintf(stderr, "noiselab sweep: plot: %s of %s against %s%s (choose with --table, --y, --x)\n",
          o->y ? o->y : ys, file, m->pname[xi], logx ? " (log)" : "");
  free(ys); free(dat); free(png);
}

static void write_in(const char *dir, const char *file, const nl_table *t)
{
  char *p = nl_path_join(dir, file);
  write_or_die(t, p);
  free(p);
}

static int nl_sweep_merge_main(int argc, char **argv)
{
  nl_sweep_merge m = {0};
  nl_sweep_merge_opts o = {0};
  static const nl_opt_spec spec[] = {{"table", 0, 1}, {"y", 0, 1}, {"x", 0, 1}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_opt_begin(&op, argc, argv, 0, spec);   /* first 0: argv[-1] is the subcommand word, getopt's argv[0] */
  for (int k; (k = next_opt(&op, "merge: ")) != NL_OPT_END;) {
    const char *v = op.value[0];
    if (k == 0) o.table = v;
    else if (k == 1) o.y = v;
    else if (k == 2) o.x = v;
    else if (m.dir) nl_sweep_die("merge: one folder only ('%s')", v);
    else m.dir = v;
  }
  nl_opt_end(&op);
  if (!m.dir) nl_sweep_die("merge: which sweep folder?");
  merge_load(&m);
  size_t nt;
  char **tables = task_tables(&m, &nt), *outdir = nl_path_join(m.dir, "merged");
  nl_error err;
  if (nt == 0) nl_sweep_die("%s: the tasks wrote no tables", m.dir);
  if (nl_mkdir_p(outdir, &err)) nl_sweep_die("%s", err.msg);
  const char *plot = o.table ? o.table : tables[0];
  int found = 0;
  for (size_t i = 0; i < nt; i++) found |= !strcmp(tables[i], plot);
  if (!found) nl_sweep_die("--table %s: the tasks wrote no such table", plot);
  for (size_t i = 0; i < nt; i++) {
    nl_table *first;
    size_t *pointof = NULL, *rowof = NULL;
    nl_table *merged = merge_rows(&m, tables[i], &first, &pointof, &rowof);
    nl_table *s = merge_summary(&m, merged, first, pointof, rowof);
    char sum[300];
    snprintf(sum, sizeof sum, "%.*s_summary.tsv", (int)(strlen(tables[i]) - 4), tables[i]);
    write_in(outdir, tables[i], merged);
    write_in(outdir, sum, s);
    if (!strcmp(tables[i], plot)) merge_plot(&m, &o, tables[i], first, s, outdir);
    nl_table_free(merged); nl_table_free(s); nl_table_free(first);
    free(pointof); free(rowof); free(tables[i]);
  }
  fprintf(stderr, "noiselab sweep: merged %zu table%s of %zu tasks into %s\n", nt, nt == 1 ? "" : "s", m.ndone, outdir);
  free(tables); free(outdir); free(m.done);
  for (int k = 0; k < m.np; k++) { free(m.pname[k]); free(m.pscale[k]); }
  free(m.pname); free(m.pscale);
  nl_table_free(m.tasks);
  return 0;
}

static void usage(FILE *fp)
{
  fputs("usage: scripts/noiselab sweep EXPERIMENT --param NAME=SPEC... [options]\n"
        "       scripts/noiselab sweep merge DIR [--table T] [--y COL[,COL2]] [--x NAME]\n\n"
        "Runs EXPERIMENT once per point of the cartesian product of the parameters\n"
        "(--set NAME=VALUE) and per seed; every task writes its own folder.\n"
        "  SPEC          a list 0,0.1,0.5; a linear range A:B:N (N values, A to B);\n"
        "                a log range A:B:logN (N values evenly spaced in log; A, B > 0)\n"
        "  --seeds N     seeds per point (default 1): S, S+K, ..., S+(N-1)K\n"
        "  --seed S      first seed (default 1)\n"
        "  --task-seeds K  seeds each task averages over itself (the experiment's\n"
        "                --seeds; default 1), so that no two tasks share a seed\n"
        "  --quick       the experiments' quick sizes\n"
        "  --images      every task writes its images too (default: the tasks run\n"
        "                with --no-images, tables only: no OpenImageIO start-up,\n"
        "                about 0.6 s of CPU, per task)\n"
        "  --out DIR     the sweep folder (default sweeps/EXPERIMENT-NAMES); running\n"
        "                again continues an interrupted sweep, skipping finished tasks\n"
        "  --jobs N      tasks at once on this machine (default: cores)\n"
        "  --emit parallel  write DIR/jobs.txt for GNU parallel (e.g. --sshlogin, with\n"
        "                the folder on a shared file system) instead of running\n"
        "  --emit slurm  write DIR/sweep.slurm, a Slurm array job (one index a task)\n"
        "  --cpus N --mem SIZE --time T\n"
        "                Slurm resources per task (default 1, 2G, 01:00:00)\n"
        "The parameters and their meanings: build/experiments/EXPERIMENT --params.\n"
        "merge: DIR/merged/TABLE (parameters and seed as leading columns) for every\n"
        "table, TABLE_summary.tsv (mean and spread over seeds per point) and\n"
        "plot.png: COL (mean, error bars the sd over seeds) against the first\n"
        "parameter (or --x), one line per row label; a second COL on the right axis.\n"
        "Exit 2 on bad input, 1 when a task failed (its log is named).\n", fp);
}

/* ---- prepare: everything before the tasks run ------------------------------ */

/* POSIX single quotes, so job lines run under any sh (parallel --sshlogin). */
static void sh_quote(FILE *fp, const char *s)
{
  fputc('\'', fp);
  for (; *s; s++) { if (*s == '\'') fputs("'\\''", fp); else fputc(*s, fp); }
  fputc('\'', fp);
}

/* Runs a shell command line and returns its exit status (2 if it died), the
 * first `cap` bytes of its output in buf. */
static int run_capture(const char *cmd, char *buf, size_t cap)
{
  FILE *fp = popen(cmd, "r");
  size_t n = 0, got;
  if (!fp) nl_sweep_die("cannot run %s", cmd);
  char tmp[4096];
  while ((got = fread(tmp, 1, sizeof tmp, fp)) > 0)
    for (size_t i = 0; i < got; i++) if (n + 1 < cap) buf[n++] = tmp[i];
  buf[n] = '\0';
  int st = pclose(fp);
  return WIFEXITED(st) ? WEXITSTATUS(st) : 2;
}

static char *quoted(const char *s)
{
  char *buf = NULL;
  size_t n = 0;
  FILE *fp = open_memstream(&buf, &n);
  sh_quote(fp, s);
  fclose(fp);
  return buf;
}

/* The last non-empty line of text (modified in place). */
static const char *last_line(char *text)
{
  size_t n = strlen(text);
  while (n && text[n - 1] == '\n') text[--n] = '\0';
  char *nl = strrchr(text, '\n');
  return nl ? nl + 1 : text;
}

/* The experiment lists its parameters (--params): every swept name must be
 * one of them, and one --params run per position in the value lists, with
 * those --set values, has the experiment check every value as a run would;
 * none does any work. */
static void probe(const nl_sweep_plan *pl, const char *exe)
{
  static char out[1 << 16];
  char *qexe = quoted(exe), *cmd = NULL;
  size_t cn = 0;
  const char *quick = pl->quick ? " --quick" : "";
  FILE *c = open_memstream(&cmd, &cn);
  fprintf(c, "timeout 120 %s --params%s 2>&1", qexe, quick);
  fclose(c);
  int rc = run_capture(cmd, out, sizeof out);
  free(cmd);
  if (rc) nl_sweep_die("%s --params failed (exit %d): %s", pl->experiment, rc, last_line(out));
  for (int k = 0; k < pl->np; k++) {
    char *save = NULL, *copy = nl_xstrdup(out), *names = NULL;
    size_t nn = 0;
    int found = 0, first = 1;
    FILE *nf = open_memstream(&names, &nn);
    strtok_r(copy, "\n", &save);   /* the header */
    for (char *line = strtok_r(NULL, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
      line[strcspn(line, "\t")] = '\0';
      found |= !strcmp(line, pl->p[k].name);
      fprintf(nf, "%s%s", first ? "" : ", ", line);
      first = 0;
    }
    fclose(nf);
    if (!found) nl_sweep_die("--set %s: unknown parameter for %s (valid: %s)", pl->p[k].name, pl->experiment, names);
    free(names); free(copy);
  }
  size_t max = 0;
  for (int k = 0; k < pl->np; k++) if (pl->p[k].n > max) max = pl->p[k].n;
  for (size_t i = 0; i < max; i++) {
    cmd = NULL; cn = 0;
    c = open_memstream(&cmd, &cn);
    fprintf(c, "timeout 120 %s --params%s", qexe, quick);
    for (int k = 0; k < pl->np; k++) {
      char *nv = nl_xmalloc(strlen(pl->p[k].name) + strlen(pl->p[k].values[i % pl->p[k].n]) + 2);
      sprintf(nv, "%s=%s", pl->p[k].name, pl->p[k].values[i % pl->p[k].n]);
      fputs(" --set ", c); sh_quote(c, nv);
      free(nv);
    }
    fputs(" 2>&1 >/dev/null", c);
    fclose(c);
    rc = run_capture(cmd, out, sizeof out);
    free(cmd);
    if (rc == 2) nl_sweep_die("%s", last_line(out));
    if (rc) nl_sweep_die("dry run of %s failed (exit %d): %s", pl->experiment, rc, last_line(out));
  }
  free(qexe);
}

/* jobs.txt: one self-contained line per task; a finished task (manifest)
 * skips itself. */
static void write_jobs(const nl_sweep_plan *pl, const nl_table *tasks, const char *exe, long cpus)
{
  char *path = nl_path_join(pl->out, "jobs.txt");
  const char *commit = getenv("NL_COMMIT");
  nl_atomic_file af;
  nl_error err;
  if (nl_atomic_open(&af, path, &err)) nl_sweep_die("%s", err.msg);
  FILE *fp = af.fp;
  for (size_t r = 0; r < tasks->nrows; r++) {
    const char *folder = tasks->text[r * tasks->ncols + 1], *id = strrchr(folder, '/') + 1;
    char *task = nl_path_join(pl->out, folder), *man = nl_path_join(task, "manifest.tsv");
    char *logs = nl_path_join(pl->out, "logs"), *log = nl_xmalloc(strlen(logs) + strlen(id) + 6);
    sprintf(log, "%s/%s.log", logs, id);
    fputs("test -f ", fp); sh_quote(fp, man);
    fprintf(fp, " || OPENBLAS_NUM_THREADS=%ld OMP_NUM_THREADS=%ld NL_COMMIT=", cpus, cpus);
    sh_quote(fp, commit && *commit ? commit : "unknown");
    fputc(' ', fp); sh_quote(fp, exe);
    fputs(" --out ", fp); sh_quote(fp, task);
    fprintf(fp, " --seed %s --seeds %ld%s%s", tasks->text[r * tasks->ncols + 2], pl->task_seeds, pl->quick ? " --quick" : "",
            pl->images ? "" : " --no-images");
    for (int k = 0; k < pl->np; k++) {
      const char *v = tasks->text[r * tasks->ncols + 3 + (size_t)k];
      char *nv = nl_xmalloc(strlen(pl->p[k].name) + strlen(v) + 2);
      sprintf(nv, "%s=%s", pl->p[k].name, v);
      fputs(" --set ", fp); sh_quote(fp, nv);
      free(nv);
    }
    fputs(" >", fp); sh_quote(fp, log); fputs(" 2>&1\n", fp);
    free(task); free(man); free(logs); free(log);
  }
  if (nl_atomic_commit(&af, &err)) nl_sweep_die("%s", err.msg);
  free(path);
}

/* sweep.slurm: an array job, one index per line of jobs.txt. */
static void write_slurm(const nl_sweep_plan *pl, size_t ntasks, long cpus, const char *mem, const char *time)
{
  char *path = nl_path_join(pl->out, "sweep.slurm"), *jobs = nl_path_join(pl->out, "jobs.txt");
  nl_atomic_file af;
  nl_error err;
  if (nl_atomic_open(&af, path, &err)) nl_sweep_die("%s", err.msg);
  FILE *fp = af.fp;
  fputs("#!/bin/bash\n"
        "# Slurm array job for the noiselab sweep in this folder: one array index per\n"
        "# line of jobs.txt (a task). Submit: sbatch ", fp);
  sh_quote(fp, path);
  fprintf(fp, "\n# Finished tasks skip themselves, so resubmitting continues a sweep.\n"
              "#SBATCH --job-name=noiselab-%s\n#SBATCH --array=0-%zu\n#SBATCH --ntasks=1\n"
              "#SBATCH --cpus-per-task=%ld\n#SBATCH --mem=%s\n#SBATCH --time=%s\n"
              "#SBATCH --output=\"%s/logs/slurm-%%A_%%a.out\"\n"
              "set -euo pipefail\n"
              "line=\"$(awk -v n=\"$((SLURM_ARRAY_TASK_ID + 1))\" 'NR == n' ",
          pl->experiment, ntasks - 1, cpus, mem, time, pl->out);
  sh_quote(fp, jobs);
  fputs(")\"\n"
        "[ -n \"$line\" ] || { echo \"no task $SLURM_ARRAY_TASK_ID in jobs.txt\" >&2; exit 2; }\n"
        "exec bash -c \"$line\"\n", fp);
  if (nl_atomic_commit(&af, &err)) nl_sweep_die("%s", err.msg);
  if (chmod(path, 0755)) nl_sweep_die("%s: cannot make it executable", path);
  free(path); free(jobs);
}

static int matches(const char *s, const char *allowed, int need_digit_first)
{
  if (!*s || (need_digit_first && (*s < '1' || *s > '9'))) return 0;
  for (; *s; s++) if (!strchr(allowed, *s)) return 0;
  return 1;
}

/* The default folder ROOT/sweeps/EXPERIMENT-NAME..., made absolute (job
 * lines run anywhere); its parent is made. */
static char *sweep_folder(const nl_sweep_plan *pl, const char *out, const char *root)
{
  char *o;
  if (out) o = nl_xstrdup(out);
  else {
    size_t len = strlen(root) + strlen(pl->experiment) + 16;
    for (int k = 0; k < pl->np; k++) len += strlen(pl->p[k].name) + 1;
    o = nl_xmalloc(len);
    sprintf(o, "%s/sweeps/%s", root, pl->experiment);
    for (int k = 0; k < pl->np; k++) { strcat(o, "-"); strcat(o, pl->p[k].name); }
  }
  size_t n = strlen(o);
  while (n > 1 && o[n - 1] == '/') o[--n] = '\0';
  char *slash = strrchr(o, '/'), *parent = slash ? nl_xstrdup(o) : nl_xstrdup(".");
  if (slash) parent[slash == o ? 1 : slash - o] = '\0';
  nl_error err;
  if (nl_mkdir_p(parent, &err)) nl_sweep_die("%s", err.msg);
  char *abs = realpath(parent, NULL);
  if (!abs) nl_sweep_die("%s: %s", parent, strerror(errno));
  const char *base = slash ? slash + 1 : o;
  char *full = nl_xmalloc(strlen(abs) + strlen(base) + 2);
  sprintf(full, "%s%s%s", abs, strcmp(abs, "/") ? "/" : "", base);
  free(abs); free(parent); free(o);
  return full;
}

static void say_quoted(const char *before, const char *path, const char *after)
{
  fputs(before, stderr); sh_quote(stderr, path); fputs(after, stderr);
}

/* noiselab-sweep prepare --experiment E --exe PATH --root DIR [options]
 * NAME=SPEC via --param: checks everything, writes the sweep folder (sweep.tsv,
 * tasks.tsv, jobs.txt, and sweep.slurm for --emit slurm), and prints
 * "DIR<TAB>JOBS" when the tasks are to run here. */
static int nl_sweep_prepare_main(int argc, char **argv)
{
  nl_sweep_plan pl = {.seed = 1, .seeds = 1, .task_seeds = 1};
  const char *exe = NULL, *root = ".", *out = NULL, *emit = "", *mem = "2G", *time = "01:00:00";
  long jobs = sysconf(_SC_NPROCESSORS_ONLN), cpus = 1;
  char **specs = nl_xcalloc((size_t)argc + 1, sizeof *specs);
  int nspec = 0;
  if (jobs < 1) jobs = 1;
  enum { P_EXPERIMENT, P_EXE, P_ROOT, P_PARAM, P_SEEDS, P_SEED, P_TASK_SEEDS, P_OUT, P_JOBS, P_EMIT,
         P_CPUS, P_MEM, P_TIME, P_QUICK, P_IMAGES, P_HELP };
  static const nl_opt_spec spec[] = {
    [P_EXPERIMENT] = {"experiment", 0, 1}, [P_EXE] = {"exe", 0, 1}, [P_ROOT] = {"root", 0, 1},
    [P_PARAM] = {"param", 0, 1}, [P_SEEDS] = {"seeds", 0, 1}, [P_SEED] = {"seed", 0, 1},
    [P_TASK_SEEDS] = {"task-seeds", 0, 1}, [P_OUT] = {"out", 0, 1}, [P_JOBS] = {"jobs", 0, 1},
    [P_EMIT] = {"emit", 0, 1}, [P_CPUS] = {"cpus", 0, 1}, [P_MEM] = {"mem", 0, 1}, [P_TIME] = {"time", 0, 1},
    [P_QUICK] = {"quick", 0, 0}, [P_IMAGES] = {"images", 0, 0}, [P_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_opt_begin(&op, argc, argv, 0, spec);   /* first 0: argv[-1] is the subcommand word, getopt's argv[0] */
  nl_error oerr;
  for (int k; (k = nl_opt_next(&op, &oerr)) != NL_OPT_END;) {
    const char *a = op.name, *v = op.value[0];
    if (k == NL_OPT_ERROR) nl_sweep_die("%s (scripts/noiselab sweep --help)", oerr.msg);
    switch (k) {
    case NL_OPT_POSITIONAL:
      nl_sweep_die("one experiment per sweep, first ('%s', '%s')", pl.experiment ? pl.experiment : "", v);
    case P_QUICK: pl.quick = 1; break;
    case P_IMAGES: pl.images = 1; break;
    case P_HELP: usage(stdout); exit(0);
    case P_EXPERIMENT: pl.experiment = v; break;
    case P_EXE: exe = v; break;
    case P_ROOT: root = v; break;
    case P_PARAM: specs[nspec++] = (char *)v; break;
    case P_SEEDS: pl.seeds = plan_long(a, v, 1, 100000); break;
    case P_SEED: pl.seed = plan_long(a, v, 0, 4294967295L); break;
    case P_TASK_SEEDS: pl.task_seeds = plan_long(a, v, 1, 10000); break;
    case P_OUT: out = v; break;
    case P_EMIT: emit = v; break;
    case P_MEM: mem = v; break;
    case P_TIME: time = v; break;
    case P_JOBS: case P_CPUS: {
      long n;
      char what[64];
      snprintf(what, sizeof what, "%s", a);
      if (!matches(v, "0123456789", 1)) nl_sweep_die("%s: '%s' is not a positive integer", a, v);
      n = plan_long(what, v, 1, 100000);
      if (k == P_JOBS) jobs = n; else cpus = n;
      break;
    }
    }
  }
  nl_opt_end(&op);
  if (!pl.experiment || !exe) nl_sweep_die("prepare: --experiment and --exe are needed");
  if (nspec == 0) nl_sweep_die("no --param NAME=SPEC given");
  size_t ml = strlen(mem);
  if (!matches(mem, "0123456789KMGT", 1) || strcspn(mem, "KMGT") < ml - 1) nl_sweep_die("--mem: '%s' is not a size like 2G", mem);
  if (!matches(time, "0123456789:-", 0)) nl_sweep_die("--time: '%s' is not a Slurm time like 01:00:00", time);
  if (*emit && strcmp(emit, "parallel") && strcmp(emit, "slurm")) nl_sweep_die("--emit: '%s' is neither parallel nor slurm", emit);
  if (access(exe, X_OK)) nl_sweep_die("%s is not built (%s)", pl.experiment, exe);
  pl.p = nl_xcalloc((size_t)nspec, sizeof *pl.p);
  for (int k = 0; k < nspec; k++) nl_sweep_expand(&pl.p[pl.np++], specs[k]);
  nl_table *def = plan_check(&pl), *tasks = plan_tasks(&pl);
  if (tasks->nrows > 1000000) nl_sweep_die("%zu tasks: more than a million; split the sweep", tasks->nrows);
  probe(&pl, exe);
  char *dir = sweep_folder(&pl, out, root);
  pl.out = dir;
  plan_write(&pl, def, tasks);
  nl_error err;
  char *logs = nl_path_join(dir, "logs"), *tdir = nl_path_join(dir, "tasks");
  if (nl_mkdir_p(logs, &err) || nl_mkdir_p(tdir, &err)) nl_sweep_die("%s", err.msg);
  write_jobs(&pl, tasks, exe, cpus);
  char *jobsf = nl_path_join(dir, "jobs.txt"), *jl = nl_path_join(dir, "joblog"), *sl = nl_path_join(dir, "sweep.slurm");
  if (!strcmp(emit, "parallel")) {
    fprintf(stderr, "sweep: wrote %s/jobs.txt (%zu tasks). Run, e.g. across hosts sharing this path:\n", dir, tasks->nrows);
    say_quoted("  parallel --will-cite --joblog ", jl, " --sshlogin 8/host1,8/host2 < ");
    say_quoted("", jobsf, "\n");
  } else if (!strcmp(emit, "slurm")) {
    write_slurm(&pl, tasks->nrows, cpus, mem, time);
    fprintf(stderr, "sweep: wrote %s/sweep.slurm (%zu array tasks, each %ld cpu, %s, %s). Submit:\n", dir,
            tasks->nrows, cpus, mem, time);
    say_quoted("  sbatch ", sl, "    # or sbatch --wait; then scripts/noiselab sweep merge ");
    say_quoted("", dir, "\n");
  } else printf("%s\t%ld\n", dir, jobs);
  nl_table_free(def); nl_table_free(tasks);
  for (int k = 0; k < pl.np; k++) param_free(&pl.p[k]);
  free(pl.p); free(specs); free(dir); free(logs); free(tdir); free(jobsf); free(jl); free(sl);
  return 0;
}

/* ---- the state of a prepared sweep ------------------------------------------ */

/* noiselab-sweep status DIR [pending|failures]: "TOTAL DONE"; the job lines
 * of the unfinished tasks; or one line per unfinished task with the end of
 * its log (exit 1 if there is one). */
static int nl_sweep_status_main(int argc, char **argv)
{
  if (argc < 1 || argc > 2) nl_sweep_die("status: wanted DIR [pending|failures]");
  const char *dir = argv[0], *what = argc > 1 ? argv[1] : "";
  if (*what && strcmp(what, "pending") && strcmp(what, "failures")) nl_sweep_die("status: '%s'?", what);
  nl_table *tasks = read_or_die(dir, "tasks.tsv");
  char *jpath = nl_path_join(dir, "jobs.txt"), *jobs = !strcmp(what, "pending") ? slurp(jpath) : NULL, *save = NULL;
  if (!strcmp(what, "pending") && !jobs) nl_sweep_die("%s: cannot read", jpath);
  char *line = jobs ? strtok_r(jobs, "\n", &save) : NULL;
  size_t done = 0, bad = 0;
  for (size_t r = 0; r < tasks->nrows; r++, line = jobs ? strtok_r(NULL, "\n", &save) : NULL) {
    char buf[32];
    const char *folder = cell(tasks, r, 1, buf), *id = strrchr(folder, '/') ? strrchr(folder, '/') + 1 : folder;
    if (file_exists(dir, folder, "manifest.tsv")) { done++; continue; }
    if (line && !strcmp(what, "pending")) printf("%s\n", line);
    if (strcmp(what, "failures")) continue;
    char *logs = nl_path_join(dir, "logs"), *log = nl_xmalloc(strlen(logs) + strlen(id) + 6), *text;
    sprintf(log, "%s/%s.log", logs, id);
    text = slurp(log);
    fprintf(stderr, "sweep: task %s (seed, params:", id);
    for (size_t c = 2; c < tasks->ncols; c++) fprintf(stderr, " %s", cell(tasks, r, c, buf));
    fprintf(stderr, ") failed; log: %s: %s\n", log, text ? last_line(text) : "no log");
    free(text); free(log); free(logs);
    bad++;
  }
  if (!*what) printf("%zu %zu\n", tasks->nrows, done);
  free(jobs); free(jpath);
  nl_table_free(tasks);
  return bad ? 1 : 0;
}

int main(int argc, char **argv)
{
  nl_harness_program_start();   /* OOM handler; OpenBLAS's idle workers stopped */
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    printf("usage: noiselab-sweep expand NAME=SPEC\n"
           "       noiselab-sweep plan --experiment E [--seed S] [--seeds N] [--task-seeds K]\n"
           "                           [--quick 0|1] [--images 0|1] [--out DIR] NAME=SPEC...\n"
           "       noiselab-sweep prepare --experiment E --exe PATH [--root DIR] [sweep options]\n"
           "       noiselab-sweep status DIR [pending|failures]\n"
           "       noiselab-sweep merge DIR [--table T] [--y COL[,COL2]] [--x NAME]\n"
           "       noiselab-sweep usage\n"
           "(the engine behind scripts/noiselab sweep; see scripts/sweep.sh)\n");
    return argc < 2 ? 2 : 0;
  }
  if (!strcmp(argv[1], "expand")) {
    if (argc != 3) nl_sweep_die("expand: wanted one NAME=SPEC");
    nl_sweep_param p;
    nl_sweep_expand(&p, argv[2]);
    for (size_t i = 0; i < p.n; i++) printf("%s\n", p.values[i]);
    param_free(&p);
    return 0;
  }
  if (!strcmp(argv[1], "plan")) return nl_sweep_plan_main(argc - 2, argv + 2);
  if (!strcmp(argv[1], "prepare")) return nl_sweep_prepare_main(argc - 2, argv + 2);
  if (!strcmp(argv[1], "status")) return nl_sweep_status_main(argc - 2, argv + 2);
  if (!strcmp(argv[1], "usage")) { usage(stdout); return 0; }
  if (!strcmp(argv[1], "merge")) return nl_sweep_merge_main(argc - 2, argv + 2);
  nl_sweep_die("unknown command '%s' (expand, plan, prepare, status, merge, usage)", argv[1]);
}
