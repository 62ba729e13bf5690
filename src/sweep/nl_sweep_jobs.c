/* A sweep's job files and state (nl_sweep.h): the experiment asked about
 * the swept values, jobs.txt, sweep.slurm, and which tasks have finished. */
#define _GNU_SOURCE   /* open_memstream, popen, realpath */
#include "sweep/nl_sweep.h"
#include "sweep/nl_sweep_internal.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

void nl_sweep_sh_quote(FILE *fp, const char *s)
{
  fputc('\'', fp);
  for (; *s; s++) {
    if (*s == '\'')
      fputs("'\\''", fp);
    else
      fputc(*s, fp);
  }
  fputc('\'', fp);
}

static char *quoted(const char *s)
{
  char *buf = NULL;
  size_t n = 0;
  FILE *fp = open_memstream(&buf, &n);
  nl_sweep_sh_quote(fp, s);
  fclose(fp);
  return buf;
}

const char *nl_sweep_last_line(char *text)
{
  size_t n = strlen(text);
  while (n && text[n - 1] == '\n')
    text[--n] = '\0';
  char *nl = strrchr(text, '\n');
  return nl ? nl + 1 : text;
}

/* Runs a shell command line and returns its exit status (2 if it died), the
 * first `cap` bytes of its output in buf; -1 when it cannot be started. */
static int run_capture(const char *cmd, char *buf, size_t cap)
{
  FILE *fp = popen(cmd, "r");
  size_t n = 0, got;
  if (!fp)
    return -1;
  char tmp[4096];
  while ((got = fread(tmp, 1, sizeof tmp, fp)) > 0)
    for (size_t i = 0; i < got && n + 1 < cap; i++)
      buf[n++] = tmp[i];
  buf[n] = '\0';
  int st = pclose(fp);
  return WIFEXITED(st) ? WEXITSTATUS(st) : 2;
}

/* Is name a line's first field (after the header) of the experiment's
 * --params output? *names gets them all, comma-separated (caller frees). */
static int known_param(const char *out, const char *name, char **names)
{
  char *save = NULL, *copy = nl_xstrdup(out);
  size_t nn = 0;
  int found = 0, first = 1;
  FILE *nf = open_memstream(names, &nn);
  strtok_r(copy, "\n", &save);   /* the header */
  for (char *line = strtok_r(NULL, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
    line[strcspn(line, "\t")] = '\0';
    found |= !strcmp(line, name);
    fprintf(nf, "%s%s", first ? "" : ", ", line);
    first = 0;
  }
  fclose(nf);
  free(copy);
  return found;
}

/* exe --params [--quick] --set NAME=VALUE... with the i-th value of every
 * parameter (a shorter list wraps round). */
static char *dry_run_line(const nl_sweep_plan *pl, const char *qexe, size_t i)
{
  char *cmd = NULL;
  size_t cn = 0;
  FILE *c = open_memstream(&cmd, &cn);
  fprintf(c, "timeout 120 %s --params%s", qexe, pl->quick ? " --quick" : "");
  for (int k = 0; k < pl->np; k++) {
    const nl_sweep_param *p = &pl->p[k];
    const char *v = p->values[i % p->n];
    char *nv = nl_xmalloc(strlen(p->name) + strlen(v) + 2);
    sprintf(nv, "%s=%s", p->name, v);
    fputs(" --set ", c);
    nl_sweep_sh_quote(c, nv);
    free(nv);
  }
  fputs(" 2>&1 >/dev/null", c);
  fclose(c);
  return cmd;
}

/* An experiment's complaint about a value names the option it was given,
 * "--set NAME"; the user typed "--param NAME", so the message says that. */
static nl_status blame_param(nl_error *err, const char *line)
{
  const char *p = strstr(line, "--set ");
  if (!p)
    return nl_fail(err, NL_EINVAL, "%s", line);
  return nl_fail(err, NL_EINVAL, "%.*s--param %s", (int)(p - line), line, p + strlen("--set "));
}

nl_status nl_sweep_probe(const nl_sweep_plan *pl, const char *exe, nl_error *err)
{
  static char out[1 << 16];
  char *qexe = quoted(exe), *cmd = nl_xmalloc(strlen(qexe) + 64);
  nl_status s = NL_OK;
  sprintf(cmd, "timeout 120 %s --params%s 2>&1", qexe, pl->quick ? " --quick" : "");
  int rc = run_capture(cmd, out, sizeof out);
  if (rc < 0)
    s = nl_fail(err, NL_EIO, "cannot run %s", cmd);
  else if (rc)
    s = nl_fail(err, NL_EINVAL, "%s --params failed (exit %d): %s", pl->experiment, rc,
                nl_sweep_last_line(out));
  free(cmd);
  for (int k = 0; !s && k < pl->np; k++) {
    char *names = NULL;
    if (!known_param(out, pl->p[k].name, &names))
      s = nl_fail(err, NL_EINVAL, "--param %s: unknown parameter for %s (valid: %s)", pl->p[k].name,
                  pl->experiment, names);
    free(names);
  }
  size_t max = 0;
  for (int k = 0; k < pl->np; k++)
    max = pl->p[k].n > max ? pl->p[k].n : max;
  for (size_t i = 0; !s && i < max; i++) {
    char *line = dry_run_line(pl, qexe, i);
    rc = run_capture(line, out, sizeof out);
    if (rc < 0)
      s = nl_fail(err, NL_EIO, "cannot run %s", line);
    else if (rc == 2)   /* the experiment's own one-line complaint */
      s = blame_param(err, nl_sweep_last_line(out));
    else if (rc)
      s = nl_fail(err, NL_EINVAL, "dry run of %s failed (exit %d): %s", pl->experiment, rc,
                  nl_sweep_last_line(out));
    free(line);
  }
  free(qexe);
  return s;
}

nl_status nl_sweep_folder(const nl_sweep_plan *pl, const char *out, const char *root, char **dir,
                          nl_error *err)
{
  char *o;
  *dir = NULL;
  /* The folder's name goes into one-line job lines (jobs.txt, GNU parallel
   * reads a job a line) and tab-separated tables: refused, not mangled. */
  for (const unsigned char *c = (const unsigned char *)(out ? out : ""); *c; c++)
    if (*c < 0x20 || *c == 0x7f)
      return nl_fail(err, NL_EINVAL, "--out: '%s': a control character in a sweep folder's name "
                     "(its job lines and tables hold it on one line)", out);
  if (out)
    o = nl_xstrdup(out);
  else {
    size_t len = strlen(root) + strlen(pl->experiment) + 16;
    for (int k = 0; k < pl->np; k++)
      len += strlen(pl->p[k].name) + 1;
    o = nl_xmalloc(len);
    sprintf(o, "%s/sweeps/%s", root, pl->experiment);
    for (int k = 0; k < pl->np; k++) {
      strcat(o, "-");
      strcat(o, pl->p[k].name);
    }
  }
  size_t n = strlen(o);
  while (n > 1 && o[n - 1] == '/')
    o[--n] = '\0';
  char *slash = strrchr(o, '/'), *parent = slash ? nl_xstrdup(o) : nl_xstrdup(".");
  if (slash)
    parent[slash == o ? 1 : slash - o] = '\0';
  char *abs = NULL;
  nl_status s = nl_mkdir_p(parent, err);
  if (!s && !(abs = realpath(parent, NULL)))
    s = nl_fail(err, NL_EIO, "%s: %s", parent, strerror(errno));
  if (!s) {
    const char *base = slash ? slash + 1 : o;
    *dir = nl_xmalloc(strlen(abs) + strlen(base) + 2);
    sprintf(*dir, "%s%s%s", abs, strcmp(abs, "/") ? "/" : "", base);
  }
  free(abs);
  free(parent);
  free(o);
  return s;
}

/* One line of jobs.txt: skips itself when the task has its manifest. */
static void job_line(FILE *fp, const nl_sweep_plan *pl, const nl_table *tasks, size_t r,
                     const char *exe, long cpus, const char *commit)
{
  const char *folder = tasks->text[r * tasks->ncols + 1], *id = strrchr(folder, '/') + 1;
  char *task = nl_path_join(pl->out, folder), *man = nl_path_join(task, "manifest.tsv");
  char *logs = nl_path_join(pl->out, "logs"), *log = nl_xmalloc(strlen(logs) + strlen(id) + 6);
  sprintf(log, "%s/%s.log", logs, id);
  fputs("test -f ", fp);
  nl_sweep_sh_quote(fp, man);
  fprintf(fp, " || OPENBLAS_NUM_THREADS=%ld OMP_NUM_THREADS=%ld NL_COMMIT=", cpus, cpus);
  nl_sweep_sh_quote(fp, commit && *commit ? commit : "unknown");
  fputc(' ', fp);
  nl_sweep_sh_quote(fp, exe);
  fputs(" --out ", fp);
  nl_sweep_sh_quote(fp, task);
  fprintf(fp, " --seed %s --seeds %ld%s%s", tasks->text[r * tasks->ncols + 2], pl->task_seeds,
          pl->quick ? " --quick" : "", pl->images ? "" : " --no-images");
  for (int k = 0; k < pl->np; k++) {
    const char *v = tasks->text[r * tasks->ncols + 3 + (size_t)k];
    char *nv = nl_xmalloc(strlen(pl->p[k].name) + strlen(v) + 2);
    sprintf(nv, "%s=%s", pl->p[k].name, v);
    fputs(" --set ", fp);
    nl_sweep_sh_quote(fp, nv);
    free(nv);
  }
  fputs(" >", fp);
  nl_sweep_sh_quote(fp, log);
  fputs(" 2>&1\n", fp);
  free(task);
  free(man);
  free(logs);
  free(log);
}

nl_status nl_sweep_write_jobs(const nl_sweep_plan *pl, const nl_table *tasks, const char *exe,
                              long cpus, nl_error *err)
{
  char *path = nl_path_join(pl->out, "jobs.txt");
  nl_atomic_file af;
  nl_status s = nl_atomic_open(&af, path, err);
  free(path);
  if (s)
    return s;
  for (size_t r = 0; r < tasks->nrows; r++)
    job_line(af.fp, pl, tasks, r, exe, cpus, getenv("NL_COMMIT"));
  return nl_atomic_commit(&af, err);
}

nl_status nl_sweep_write_slurm(const nl_sweep_plan *pl, size_t ntasks, long cpus, const char *mem,
                               const char *time, nl_error *err)
{
  char *path = nl_path_join(pl->out, "sweep.slurm"), *jobs = nl_path_join(pl->out, "jobs.txt");
  nl_atomic_file af;
  nl_status s = nl_atomic_open(&af, path, err);
  if (!s) {
    FILE *fp = af.fp;
    fputs("#!/bin/bash\n"
          "# Slurm array job for the noiselab sweep in this folder: one array index per\n"
          "# line of jobs.txt (a task). Submit: sbatch ",
          fp);
    nl_sweep_sh_quote(fp, path);
    fprintf(fp,
            "\n# Finished tasks skip themselves, so resubmitting continues a sweep.\n"
            "#SBATCH --job-name=noiselab-%s\n#SBATCH --array=0-%zu\n#SBATCH --ntasks=1\n"
            "#SBATCH --cpus-per-task=%ld\n#SBATCH --mem=%s\n#SBATCH --time=%s\n"
            "#SBATCH --output=\"%s/logs/slurm-%%A_%%a.out\"\n"
            "set -euo pipefail\n"
            "line=\"$(awk -v n=\"$((SLURM_ARRAY_TASK_ID + 1))\" 'NR == n' ",
            pl->experiment, ntasks - 1, cpus, mem, time, pl->out);
    nl_sweep_sh_quote(fp, jobs);
    fputs(")\"\n"
          "[ -n \"$line\" ] || { echo \"no task $SLURM_ARRAY_TASK_ID in jobs.txt\" >&2; exit 2; }\n"
          "exec bash -c \"$line\"\n",
          fp);
    s = nl_atomic_commit(&af, err);
  }
  if (!s && chmod(path, 0755))
    s = nl_fail(err, NL_EIO, "%s: cannot make it executable", path);
  free(path);
  free(jobs);
  return s;
}

int nl_sweep_task_finished(const char *dir, const char *folder)
{
  char *d = nl_path_join(dir, folder), *p = nl_path_join(d, "manifest.tsv");
  struct stat st;
  int ok = stat(p, &st) == 0;
  free(d);
  free(p);
  return ok;
}

/* The failed task's line on log: its seed and parameters, its log's end. */
static void say_failure(FILE *log, const char *dir, const nl_table *tasks, size_t r, const char *id)
{
  char *logs = nl_path_join(dir, "logs"), *path = nl_xmalloc(strlen(logs) + strlen(id) + 6), *text;
  char buf[32];
  sprintf(path, "%s/%s.log", logs, id);
  text = nl_sweep_slurp(path);
  fprintf(log, "sweep: task %s (seed, params:", id);
  for (size_t c = 2; c < tasks->ncols; c++)
    fprintf(log, " %s", nl_table_cell_text(tasks, r, c, buf));
  fprintf(log, ") failed; log: %s: %s\n", path, text ? nl_sweep_last_line(text) : "no log");
  free(text);
  free(path);
  free(logs);
}

nl_status nl_sweep_status(const char *dir, const char *what, FILE *out, FILE *log, size_t *failed,
                          nl_error *err)
{
  int pending = !strcmp(what, "pending"), failures = !strcmp(what, "failures");
  if (*what && !pending && !failures)
    return nl_fail(err, NL_EINVAL, "status: '%s'?", what);
  nl_table *tasks;
  char *tpath = nl_path_join(dir, "tasks.tsv");
  nl_status s = nl_table_read(tpath, NL_TABLE_TEXT, &tasks, err);
  free(tpath);
  if (s)
    return s;
  char *jpath = nl_path_join(dir, "jobs.txt"), *save = NULL;
  char *jobs = pending ? nl_sweep_slurp(jpath) : NULL;
  if (pending && !jobs) {
    s = nl_fail(err, NL_EIO, "%s: cannot read", jpath);
    free(jpath);
    nl_table_free(tasks);
    return s;
  }
  char *line = jobs ? strtok_r(jobs, "\n", &save) : NULL;
  size_t done = 0;
  *failed = 0;
  for (size_t r = 0; r < tasks->nrows; r++, line = jobs ? strtok_r(NULL, "\n", &save) : NULL) {
    char buf[32];
    const char *folder = nl_table_cell_text(tasks, r, 1, buf), *slash = strrchr(folder, '/');
    if (nl_sweep_task_finished(dir, folder)) {
      done++;
      continue;
    }
    if (line && pending)
      fprintf(out, "%s\n", line);
    if (failures) {
      say_failure(log, dir, tasks, r, slash ? slash + 1 : folder);
      ++*failed;
    }
  }
  if (!*what)
    fprintf(out, "%zu %zu\n", tasks->nrows, done);
  free(jobs);
  free(jpath);
  nl_table_free(tasks);
  return NL_OK;
}

static int matches(const char *s, const char *allowed, int need_digit_first)
{
  if (!*s || (need_digit_first && (*s < '1' || *s > '9')))
    return 0;
  for (; *s; s++)
    if (!strchr(allowed, *s))
      return 0;
  return 1;
}

static void say_quoted(FILE *log, const char *before, const char *path, const char *after)
{
  fputs(before, log);
  nl_sweep_sh_quote(log, path);
  fputs(after, log);
}

/* What to do with the written files: how to run them elsewhere. */
static nl_status say_emitted(const nl_sweep_plan *pl, const nl_sweep_prepare_opts *o, size_t ntasks,
                             FILE *log, nl_error *err)
{
  char *jobs = nl_path_join(pl->out, "jobs.txt"), *jl = nl_path_join(pl->out, "joblog");
  char *sl = nl_path_join(pl->out, "sweep.slurm");
  nl_status s = NL_OK;
  if (!strcmp(o->emit, "parallel")) {
    fprintf(log, "sweep: wrote %s/jobs.txt (%zu tasks). Run, e.g. across hosts sharing this "
            "path:\n", pl->out, ntasks);
    say_quoted(log, "  parallel --will-cite --joblog ", jl, " --sshlogin 8/host1,8/host2 < ");
    say_quoted(log, "", jobs, "\n");
  } else if (!strcmp(o->emit, "slurm")
             && !(s = nl_sweep_write_slurm(pl, ntasks, o->cpus, o->mem, o->time, err))) {
    fprintf(log, "sweep: wrote %s/sweep.slurm (%zu array tasks, each %ld cpu, %s, %s). "
            "Submit:\n", pl->out, ntasks, o->cpus, o->mem, o->time);
    say_quoted(log, "  sbatch ", sl, "    # or sbatch --wait; then scripts/noiselab sweep merge ");
    say_quoted(log, "", pl->out, "\n");
  }
  free(jobs);
  free(jl);
  free(sl);
  return s;
}

nl_status nl_sweep_prepare(nl_sweep_plan *pl, const char *const *specs, int nspec,
                           const nl_sweep_prepare_opts *o, char **dir, FILE *log, nl_error *err)
{
  *dir = NULL;
  if (!matches(o->mem, "0123456789KMGT", 1) || strcspn(o->mem, "KMGT") < strlen(o->mem) - 1)
    return nl_fail(err, NL_EINVAL, "--mem: '%s' is not a size like 2G", o->mem);
  if (!matches(o->time, "0123456789:-", 0))
    return nl_fail(err, NL_EINVAL, "--time: '%s' is not a Slurm time like 01:00:00", o->time);
  if (*o->emit && strcmp(o->emit, "parallel") && strcmp(o->emit, "slurm"))
    return nl_fail(err, NL_EINVAL, "--emit: '%s' is neither parallel nor slurm", o->emit);
  if (access(o->exe, X_OK))
    return nl_fail(err, NL_EINVAL, "%s is not built (%s)", pl->experiment, o->exe);
  nl_status s = NL_OK;
  pl->p = nl_xcalloc((size_t)nspec + 1, sizeof *pl->p);
  for (pl->np = 0; pl->np < nspec && !s; pl->np++)
    s = nl_sweep_expand(specs[pl->np], &pl->p[pl->np], err);
  nl_table *def, *tasks;
  if (!s)
    s = nl_sweep_plan_make(pl, &def, &tasks, err);
  if (s)
    return s;
  if (!(s = nl_sweep_probe(pl, o->exe, err)))
    s = nl_sweep_folder(pl, o->out, o->root, dir, err);
  pl->out = *dir;
  if (!s)
    s = nl_sweep_plan_write(pl, def, tasks, err);
  char *logs = *dir ? nl_path_join(*dir, "logs") : NULL;
  char *tdir = *dir ? nl_path_join(*dir, "tasks") : NULL;
  if (!s && !(s = nl_mkdir_p(logs, err)))
    s = nl_mkdir_p(tdir, err);
  if (!s)
    s = nl_sweep_write_jobs(pl, tasks, o->exe, o->cpus, err);
  if (!s)
    s = say_emitted(pl, o, tasks->nrows, log, err);
  free(logs);
  free(tdir);
  nl_table_free(def);
  nl_table_free(tasks);
  return s;
}
