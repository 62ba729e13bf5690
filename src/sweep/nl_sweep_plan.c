/* A sweep's values and plan (nl_sweep.h): NAME=SPEC to values, the
 * definition and the task list, and the folder that holds them. */
#include "sweep/nl_sweep.h"
#include "sweep/nl_sweep_internal.h"

#include <ctype.h>
#include <dirent.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static nl_status spec_number(const char *arg, const char *s, double *v, nl_error *err)
{
  char *end;
  *v = strtod(s, &end);
  if (end == s || *end || !isfinite(*v))
    return nl_fail(err, NL_EINVAL, "--param %s: '%s' is not a number", arg, s);
  return NL_OK;
}

static void push(nl_sweep_param *p, const char *text)
{
  p->values = nl_xrealloc(p->values, (p->n + 1) * sizeof *p->values);
  p->values[p->n++] = nl_xstrdup(text);
}

/* A:B:N or A:B:logN */
static nl_status expand_range(nl_sweep_param *p, const char *arg, char *spec, nl_error *err)
{
  char *b = strchr(spec, ':'), *n = b ? strchr(b + 1, ':') : NULL;
  if (!b || !n || strchr(n + 1, ':'))
    return nl_fail(err, NL_EINVAL, "--param %s: a range is A:B:N or A:B:logN", arg);
  *b++ = '\0';
  *n++ = '\0';
  int lg = !strncmp(n, "log", 3);
  double lo, hi, cnt;
  if (spec_number(arg, spec, &lo, err) || spec_number(arg, b, &hi, err)
      || spec_number(arg, lg ? n + 3 : n, &cnt, err))
    return NL_EINVAL;
  if (cnt != floor(cnt) || cnt > 100000)
    return nl_fail(err, NL_EINVAL, "--param %s: the count '%s' is not a whole number up to 100000",
                   arg, n);
  if (cnt < 1)
    return nl_fail(err, NL_EINVAL, "--param %s: empty range (%g values)", arg, cnt);
  if (lg && (lo <= 0 || hi <= 0))
    return nl_fail(err, NL_EINVAL, "--param %s: a log range needs positive ends", arg);
  p->scale = nl_xstrdup(lg ? "log" : "lin");
  for (long i = 0; i < (long)cnt; i++) {
    double t = cnt > 1 ? i / (cnt - 1) : 0, v;
    if (i == (long)cnt - 1 && cnt > 1)
      v = hi;   /* the end as written */
    else if (lg)   /* base 10: decades come out exact (pow(10, -4) is 1e-4, exp(log) is not) */
      v = pow(10, log10(lo) + t * (log10(hi) - log10(lo)));
    else
      v = lo + t * (hi - lo);
    char buf[40];
    snprintf(buf, sizeof buf, "%.15g", v);
    push(p, buf);
  }
  return NL_OK;
}

static nl_status expand_list(nl_sweep_param *p, const char *arg, char *spec, nl_error *err)
{
  p->scale = nl_xstrdup("list");
  if (spec[0] == ',' || spec[strlen(spec) - 1] == ',' || strstr(spec, ",,"))
    return nl_fail(err, NL_EINVAL, "--param %s: empty value in the list", arg);
  char *save = NULL;
  for (char *tok = strtok_r(spec, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    double v;
    if (spec_number(arg, tok, &v, err))
      return NL_EINVAL;
    push(p, tok);
  }
  return NL_OK;
}

nl_status nl_sweep_expand(const char *arg, nl_sweep_param *p, nl_error *err)
{
  const char *eq = strchr(arg, '=');
  memset(p, 0, sizeof *p);
  if (!eq || eq == arg)
    return nl_fail(err, NL_EINVAL, "--param '%s' is not NAME=SPEC", arg);
  p->name = nl_xstrdup(arg);
  p->name[eq - arg] = '\0';
  for (const char *c = p->name; *c; c++)
    if (!isalnum((unsigned char)*c) && *c != '_')
      return nl_fail(err, NL_EINVAL, "--param %s: '%s' is not a parameter name", arg, p->name);
  if (!eq[1])
    return nl_fail(err, NL_EINVAL, "--param %s: empty range (no values)", arg);
  char *spec = nl_xstrdup(eq + 1);
  nl_status s = strchr(spec, ':') ? expand_range(p, arg, spec, err)
                                  : expand_list(p, arg, spec, err);
  free(spec);
  return s;
}

void nl_sweep_param_free(nl_sweep_param *p)
{
  for (size_t i = 0; i < p->n; i++)
    free(p->values[i]);
  free(p->values);
  free(p->name);
  free(p->scale);
}

static void append_long(nl_table *d, const char *key, long v)
{
  char buf[64];
  snprintf(buf, sizeof buf, "%ld", v);
  nl_table_append(d, "ss", key, buf);
}

static nl_table *plan_definition(const nl_sweep_plan *pl)
{
  const char *cols[] = {"key", "value"};
  nl_table *d = nl_table_alloc(2, cols);
  char buf[64];
  nl_table_append(d, "ss", "experiment", pl->experiment);
  nl_table_append(d, "ss", "quick", pl->quick ? "yes" : "no");
  nl_table_append(d, "ss", "images", pl->images ? "yes" : "no");
  append_long(d, "seed", pl->seed);
  append_long(d, "seeds", pl->seeds);
  append_long(d, "task_seeds", pl->task_seeds);
  for (int k = 0; k < pl->np; k++) {
    const nl_sweep_param *p = &pl->p[k];
    size_t len = strlen(p->name) + 2;
    for (size_t i = 0; i < p->n; i++)
      len += strlen(p->values[i]) + 1;
    char *v = nl_xmalloc(len), *w = v;
    w += sprintf(w, "%s=", p->name);
    for (size_t i = 0; i < p->n; i++)
      w += sprintf(w, "%s%s", i ? "," : "", p->values[i]);
    nl_table_append(d, "ss", "param", v);
    snprintf(buf, sizeof buf, "%.40s=%s", p->name, p->scale);
    nl_table_append(d, "ss", "scale", buf);
    free(v);
  }
  return d;
}

/* Tasks: points in odometer order (last parameter fastest), seeds innermost. */
static nl_table *plan_tasks(const nl_sweep_plan *pl)
{
  const char **cols = nl_xcalloc((size_t)pl->np + 3, sizeof *cols);
  cols[0] = "task";
  cols[1] = "folder";
  cols[2] = "seed";
  size_t total = (size_t)pl->seeds;
  for (int k = 0; k < pl->np; k++) {
    cols[k + 3] = pl->p[k].name;
    total *= pl->p[k].n;
  }
  nl_table *t = nl_table_alloc((size_t)pl->np + 3, cols);
  int width = 4;
  for (size_t m = total; m >= 10000; m /= 10)
    width++;
  for (size_t id = 0; id < total; id++) {
    char folder[64] = "tasks/", num[32], seed[32];
    size_t rest = id / (size_t)pl->seeds;
    snprintf(num, sizeof num, "%zu", id);
    for (int z = (int)strlen(num); z < width; z++)   /* zero-padded to width digits */
      strcat(folder, "0");
    strcat(folder, num);
    /* Task j runs replicates j K .. j K + K - 1 of the sweep's base seed. */
    long rep = (long)(id % (size_t)pl->seeds) * pl->task_seeds;
    snprintf(seed, sizeof seed, "%lu", nl_seed_replicate((unsigned long)pl->seed, rep));
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

nl_status nl_sweep_plan_make(const nl_sweep_plan *pl, nl_table **def, nl_table **tasks,
                             nl_error *err)
{
  *def = *tasks = NULL;
  for (int a = 0; a < pl->np; a++)
    for (int b = 0; b < a; b++)
      if (!strcmp(pl->p[a].name, pl->p[b].name))
        return nl_fail(err, NL_EINVAL, "--param %s given twice", pl->p[a].name);
  if (pl->seed + (pl->seeds - 1) * pl->task_seeds + pl->task_seeds - 1 > 4294967295L)
    return nl_fail(err, NL_EINVAL, "--seed: seeds run past 2^32 - 1");
  double total = (double)pl->seeds;
  for (int k = 0; k < pl->np; k++)
    total *= (double)pl->p[k].n;
  if (total > 1e6)
    return nl_fail(err, NL_EINVAL, "%.0f tasks: more than a million; split the sweep", total);
  *def = plan_definition(pl);
  *tasks = plan_tasks(pl);
  return NL_OK;
}

char *nl_sweep_slurp(const char *path)
{
  FILE *fp = fopen(path, "rb");
  if (!fp)
    return NULL;
  char *buf = NULL;
  size_t n = 0, cap = 0, got;
  do {
    if (n + 4096 + 1 > cap)
      buf = nl_xrealloc(buf, cap = 2 * cap + 4096 + 1);
    got = fread(buf + n, 1, cap - n - 1, fp);
    n += got;
  } while (got > 0);
  fclose(fp);
  buf[n] = '\0';
  return buf;
}

/* Is the folder missing or empty? */
static int folder_empty(const char *dir)
{
  DIR *d = opendir(dir);
  struct dirent *e;
  int empty = 1;
  while (d && empty && (e = readdir(d)))
    empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..");
  if (d)
    closedir(d);
  return empty;
}

/* Does the folder's sweep.tsv (text old) hold this very definition? */
static nl_status same_sweep(const char *out, const nl_table *def, const char *old, int *same,
                            nl_error *err)
{
  char *tmp = nl_path_join(out, ".sweep.new.tsv");
  nl_status s = nl_table_write(def, tmp, err);
  char *now = s ? NULL : nl_sweep_slurp(tmp);
  remove(tmp);
  *same = now && !strcmp(now, old);
  free(tmp);
  free(now);
  return s;
}

nl_status nl_sweep_plan_write(const nl_sweep_plan *pl, const nl_table *def, const nl_table *tasks,
                              nl_error *err)
{
  char *sweep = nl_path_join(pl->out, "sweep.tsv"), *tpath = nl_path_join(pl->out, "tasks.tsv");
  char *old = nl_sweep_slurp(sweep);
  nl_status s = NL_OK;
  int same = 0;
  if (!old && !folder_empty(pl->out))
    s = nl_fail(err, NL_EINVAL, "%s: the folder holds files but no sweep.tsv; refusing to write "
                "into it", pl->out);
  else if (!old)
    s = nl_mkdir_p(pl->out, err);
  else if (!(s = same_sweep(pl->out, def, old, &same, err)) && !same)
    s = nl_fail(err, NL_EINVAL, "%s holds a different sweep (see its sweep.tsv); choose another "
                "--out", pl->out);
  if (!s)
    s = nl_table_write(tasks, tpath, err);
  if (!s)
    s = nl_table_write(def, sweep, err);   /* last: a folder with sweep.tsv has its tasks.tsv */
  free(old);
  free(sweep);
  free(tpath);
  return s;
}

void nl_sweep_table_print(const nl_table *t, FILE *fp)
{
  for (size_t c = 0; c < t->ncols; c++)
    fprintf(fp, "%s%s", c ? "\t" : "", t->names[c]);
  fputc('\n', fp);
  for (size_t r = 0; r < t->nrows; r++) {
    for (size_t c = 0; c < t->ncols; c++) {
      char buf[32];
      fprintf(fp, "%s%s", c ? "\t" : "", nl_table_cell_text(t, r, c, buf));
    }
    fputc('\n', fp);
  }
}
