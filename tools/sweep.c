/* noiselab sweep - the command line of a parameter sweep: scripts/sweep.sh
 * calls `prepare` (check and write the sweep folder), `status` and `merge`;
 * `expand` and `plan` show a spec's values and a plan's tasks. The engine is
 * src/sweep (nl_sweep.h); usage() below is `scripts/noiselab sweep --help`.
 * Errors: one line on stderr, exit 2.
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"
#include "sweep/nl_sweep.h"

#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

/* One line on stderr, exit 2: input quoted in it is escaped (nl_message). */
#define die(...) nl_tool_die("noiselab sweep: ", __VA_ARGS__)

static void check(nl_status s, const nl_error *err)
{
  if (s)
    die("%s", err->msg);
}

static long whole(const char *opt, const char *s, long lo, long hi)
{
  long v;
  nl_error err;
  check(nl_parse_long(opt, s, lo, hi, &v, &err), &err);
  return v;
}

/* nl_opt with the sweep's exit: an option error is one line, exit 2. */
static int next_opt(nl_opt_parser *p, const char *context)
{
  nl_error err;
  int k = nl_opt_next(p, &err);
  if (k == NL_OPT_ERROR)
    die("%s%s%s", context, err.msg, *context ? "" : " (scripts/noiselab sweep --help)");
  return k;
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

static int plan_main(int argc, char **argv)
{
  nl_sweep_plan pl = {.seed = 1, .seeds = 1, .task_seeds = 1};
  nl_error err;
  pl.p = nl_xcalloc((size_t)argc, sizeof *pl.p);
  static const nl_opt_spec spec[] = {{"experiment", 0, 1}, {"out", 0, 1}, {"seed", 0, 1},
                                     {"seeds", 0, 1}, {"task-seeds", 0, 1}, {"quick", 0, 1},
                                     {"images", 0, 1}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_opt_begin(&op, argc, argv, 0, spec);   /* first 0: argv[-1] is the subcommand word */
  for (int k; (k = next_opt(&op, "plan: ")) != NL_OPT_END;) {
    const char *a = op.name, *v = op.value[0];
    switch (k) {
    case NL_OPT_POSITIONAL: check(nl_sweep_expand(v, &pl.p[pl.np++], &err), &err); break;
    case 0: pl.experiment = v; break;
    case 1: pl.out = v; break;
    case 2: pl.seed = whole(a, v, 0, 4294967295L); break;
    case 3: pl.seeds = whole(a, v, 1, 100000); break;
    case 4: pl.task_seeds = whole(a, v, 1, 10000); break;
    case 5: pl.quick = whole(a, v, 0, 1); break;
    case 6: pl.images = whole(a, v, 0, 1); break;
    }
  }
  nl_opt_end(&op);
  if (!pl.experiment)
    die("plan: --experiment missing");
  if (pl.np == 0)
    die("no --param NAME=SPEC given");
  nl_table *def, *tasks;
  check(nl_sweep_plan_make(&pl, &def, &tasks, &err), &err);
  if (pl.out)
    check(nl_sweep_plan_write(&pl, def, tasks, &err), &err);
  else
    nl_sweep_table_print(tasks, stdout);
  return 0;
}

/* Checks everything, writes the sweep folder and, for --emit, says how to
 * run it (nl_sweep_prepare); else prints "DIR<TAB>JOBS" for scripts/sweep.sh. */
static int prepare_main(int argc, char **argv)
{
  nl_sweep_plan pl = {.seed = 1, .seeds = 1, .task_seeds = 1};
  nl_sweep_prepare_opts o = {.root = ".", .emit = "", .mem = "2G", .time = "01:00:00", .cpus = 1};
  long jobs = sysconf(_SC_NPROCESSORS_ONLN);
  const char **specs = nl_xcalloc((size_t)argc + 1, sizeof *specs);
  int nspec = 0;
  enum { P_EXPERIMENT, P_EXE, P_ROOT, P_PARAM, P_SEEDS, P_SEED, P_TASK_SEEDS, P_OUT, P_JOBS,
         P_EMIT, P_CPUS, P_MEM, P_TIME, P_QUICK, P_IMAGES, P_HELP };
  static const nl_opt_spec spec[] = {
    [P_EXPERIMENT] = {"experiment", 0, 1}, [P_EXE] = {"exe", 0, 1}, [P_ROOT] = {"root", 0, 1},
    [P_PARAM] = {"param", 0, 1}, [P_SEEDS] = {"seeds", 0, 1}, [P_SEED] = {"seed", 0, 1},
    [P_TASK_SEEDS] = {"task-seeds", 0, 1}, [P_OUT] = {"out", 0, 1}, [P_JOBS] = {"jobs", 0, 1},
    [P_EMIT] = {"emit", 0, 1}, [P_CPUS] = {"cpus", 0, 1}, [P_MEM] = {"mem", 0, 1},
    [P_TIME] = {"time", 0, 1}, [P_QUICK] = {"quick", 0, 0}, [P_IMAGES] = {"images", 0, 0},
    [P_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_opt_begin(&op, argc, argv, 0, spec);
  for (int k; (k = next_opt(&op, "")) != NL_OPT_END;) {
    const char *a = op.name, *v = op.value[0];
    switch (k) {
    case NL_OPT_POSITIONAL:
      die("one experiment per sweep, first ('%s', '%s')", pl.experiment ? pl.experiment : "", v);
    case P_QUICK: pl.quick = 1; break;
    case P_IMAGES: pl.images = 1; break;
    case P_HELP: usage(stdout); exit(0);
    case P_EXPERIMENT: pl.experiment = v; break;
    case P_EXE: o.exe = v; break;
    case P_ROOT: o.root = v; break;
    case P_PARAM: specs[nspec++] = v; break;
    case P_SEEDS: pl.seeds = whole(a, v, 1, 100000); break;
    case P_SEED: pl.seed = whole(a, v, 0, 4294967295L); break;
    case P_TASK_SEEDS: pl.task_seeds = whole(a, v, 1, 10000); break;
    case P_OUT: o.out = v; break;
    case P_EMIT: o.emit = v; break;
    case P_MEM: o.mem = v; break;
    case P_TIME: o.time = v; break;
    case P_JOBS: case P_CPUS:
      if (v[0] < '1' || v[0] > '9' || v[strspn(v, "0123456789")])
        die("%s: '%s' is not a positive integer", a, v);
      *(k == P_JOBS ? &jobs : &o.cpus) = whole(a, v, 1, 100000);
      break;
    }
  }
  nl_opt_end(&op);
  if (!pl.experiment || !o.exe)
    die("prepare: --experiment and --exe are needed");
  if (nspec == 0)
    die("no --param NAME=SPEC given");
  char *dir;
  nl_error err;
  check(nl_sweep_prepare(&pl, specs, nspec, &o, &dir, stderr, &err), &err);
  if (!*o.emit)
    printf("%s\t%ld\n", dir, jobs < 1 ? 1 : jobs);
  return 0;
}

static int merge_main(int argc, char **argv)
{
  const char *dir = NULL;
  nl_sweep_merge_opts o = {0};
  static const nl_opt_spec spec[] = {{"table", 0, 1}, {"y", 0, 1}, {"x", 0, 1}, {NULL, 0, 0}};
  nl_opt_parser op;
  nl_error err;
  nl_opt_begin(&op, argc, argv, 0, spec);
  for (int k; (k = next_opt(&op, "merge: ")) != NL_OPT_END;) {
    const char *v = op.value[0];
    if (k == 0)
      o.table = v;
    else if (k == 1)
      o.y = v;
    else if (k == 2)
      o.x = v;
    else if (dir)
      die("merge: one folder only ('%s')", v);
    else
      dir = v;
  }
  nl_opt_end(&op);
  if (!dir)
    die("merge: which sweep folder?");
  check(nl_sweep_merge_all(dir, &o, stdout, stderr, &err), &err);
  return 0;
}

/* ---- GNU parallel's shell for the tasks (PARALLEL_SHELL, scripts/sweep.sh)
 *
 * parallel starts each task in a process group of its own, so a SIGKILL of
 * the sweep's group (the shell, its lock watchdog and parallel) reached no
 * task: they ran on, orphaned, writing into the sweep folder. As parallel's
 * shell, `noiselab-sweep -c LINE` asks the kernel for SIGTERM when parallel
 * dies (PR_SET_PDEATHSIG), runs LINE with /bin/sh in a process group of its
 * own and passes SIGTERM, SIGINT and SIGHUP on to that whole group (the
 * experiment then removes its temporaries). */
static volatile sig_atomic_t task_group, task_signal;

static void task_forward(int sig)
{
  task_signal = sig;
  if (task_group > 0)
    kill(-(pid_t)task_group, sig);
}

static int shell_main(const char *line)
{
  static const int sigs[] = {SIGTERM, SIGINT, SIGHUP};
  pid_t parent = getppid();
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = task_forward;
  sigemptyset(&sa.sa_mask);
  for (int k = 0; k < 3; k++)
    sigaction(sigs[k], &sa, NULL);
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  /* parallel gone before the request: no signal will come. parallel names
   * itself in PARALLEL_PID; a parent that differs was replaced by a reaper. */
  const char *pp = getenv("PARALLEL_PID");
  if (getppid() != parent || (pp && atol(pp) != (long)parent))
    return 128 + SIGTERM;
  pid_t child = fork();
  if (child < 0)
    die("-c: cannot start /bin/sh: %s", strerror(errno));
  if (child == 0) {
    setpgid(0, 0);
    sa.sa_handler = SIG_DFL;
    for (int k = 0; k < 3; k++)
      sigaction(sigs[k], &sa, NULL);
    execl("/bin/sh", "sh", "-c", line, (char *)NULL);
    _exit(127);
  }
  setpgid(child, child);   /* both sides: whichever runs first */
  task_group = child;
  if (task_signal)   /* a signal that came before the group was known */
    kill(-child, task_signal);
  int st;
  while (waitpid(child, &st, 0) < 0)
    if (errno != EINTR)
      return 1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

int main(int argc, char **argv)
{
  nl_tool_start("noiselab sweep");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  nl_error err;
  if (argc == 3 && !strcmp(argv[1], "-c"))
    return shell_main(argv[2]);
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    printf("usage: noiselab-sweep expand NAME=SPEC\n"
           "       noiselab-sweep plan --experiment E [--seed S] [--seeds N] [--task-seeds K]\n"
           "                           [--quick 0|1] [--images 0|1] [--out DIR] NAME=SPEC...\n"
           "       noiselab-sweep prepare --experiment E --exe PATH [--root DIR] [sweep options]\n"
           "       noiselab-sweep status DIR [pending|failures]\n"
           "       noiselab-sweep merge DIR [--table T] [--y COL[,COL2]] [--x NAME]\n"
           "       noiselab-sweep usage\n"
           "       noiselab-sweep -c LINE   (GNU parallel's shell for the tasks)\n"
           "(the engine behind scripts/noiselab sweep; see scripts/sweep.sh)\n");
    return argc < 2 ? 2 : 0;
  }
  const char *cmd = argv[1];
  if (!strcmp(cmd, "expand")) {
    nl_sweep_param p;
    if (argc != 3)
      die("expand: wanted one NAME=SPEC");
    check(nl_sweep_expand(argv[2], &p, &err), &err);
    for (size_t i = 0; i < p.n; i++)
      printf("%s\n", p.values[i]);
    nl_sweep_param_free(&p);
    return 0;
  }
  if (!strcmp(cmd, "status")) {
    size_t failed = 0;
    if (argc < 3 || argc > 4)
      die("status: wanted DIR [pending|failures]");
    check(nl_sweep_status(argv[2], argc > 3 ? argv[3] : "", stdout, stderr, &failed, &err), &err);
    return failed ? 1 : 0;
  }
  if (!strcmp(cmd, "usage")) {
    usage(stdout);
    return 0;
  }
  if (!strcmp(cmd, "plan"))
    return plan_main(argc - 2, argv + 2);
  if (!strcmp(cmd, "prepare"))
    return prepare_main(argc - 2, argv + 2);
  if (!strcmp(cmd, "merge"))
    return merge_main(argc - 2, argv + 2);
  die("unknown command '%s' (expand, plan, prepare, status, merge, usage)", cmd);
}
