/* nl_base.h - status codes, error messages and atomic file output.
 *
 * Every fallible library call returns an nl_status (0 = NL_OK) and, when it
 * fails, leaves a one-line human message in an nl_error the caller passed
 * (or NULL to ignore it). Messages name the input and the problem, e.g.
 *   "data.tsv:12: column 3 is not a number: 'abc'"
 * so that programs can print them unchanged and exit non-zero.
 *
 * Output files are written atomically: nl_atomic_open() creates a hidden
 * temporary file beside the target, nl_atomic_commit() flushes it, checks
 * that every byte reached the disk (stdio's error, fsync, close, and the
 * file's size against what was written: a full disk or a file size limit
 * fails here) and renames it over the target; nl_atomic_abort() removes it.
 * A crash or an error half way never leaves a truncated file under the
 * final name, and never destroys the previous version.
 *
 * What the target is decides how it is written (the file is never replaced
 * by something of another kind):
 *   - missing or a regular file: temporary + rename, as above;
 *   - a symbolic link: followed on purpose; the file it finally names is
 *     written atomically and the link stays (a link to nothing, a directory
 *     or a block device is refused);
 *   - a character device or a FIFO (/dev/null, /dev/stdout, a pipe): opened
 *     and written through, no temporary and no rename;
 *   - anything else (a directory, a socket, a block device): refused.
 *
 * The library installs no signal handler and no exit hook: a program that
 * wants its open temporaries removed when it exits or on a signal calls
 * nl_atomic_unlink_open() from its own hook and handler (the noiselab tools
 * and experiments do, nl_harness_program_start). Without them, or after
 * SIGKILL, a temporary stays until the next write of its target:
 * its name holds its writer's pid, and nl_atomic_open removes the
 * temporaries of its target whose writer is no live process.
 *
 * A command that writes several files writes all or none: it opens every
 * output first (which checks each target), writes each, then calls
 * nl_atomic_commit_all(), which checks every temporary before renaming any.
 */
#ifndef NL_BASE_H
#define NL_BASE_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  NL_OK = 0,
  NL_EINVAL = 1,   /* bad argument or parameter */
  NL_EIO = 2,      /* file cannot be opened, read or written */
  NL_EFORMAT = 3,  /* file content malformed */
  NL_ENOMEM = 4,
  NL_ENUM = 5      /* numerical failure (singular matrix, no convergence) */
} nl_status;

#define NL_ERROR_LEN 512
typedef struct { char msg[NL_ERROR_LEN]; } nl_error;

/* Sets err->msg (if err != NULL) and returns status, for `return nl_fail(...)`.
 * The message stays one line whatever input it echoes: control characters
 * are escaped (a newline as \n, a tab as \t, the others and DEL as \xNN).
 * One too long for NL_ERROR_LEN loses the middle of its longest words (the
 * paths and values it quotes: "/very/lo...ng/name.tsv: directory ... does not
 * exist"), never its end, where the reason is. The arguments may include
 * err->msg itself ("%s: %s", path, err->msg). */
nl_status nl_fail(nl_error *err, nl_status status, const char *fmt, ...)
  __attribute__((format(printf, 3, 4)));

/* Prints one line to f: fmt formatted, control characters escaped as by
 * nl_fail, never cut, then a newline. For what a program says itself with
 * input in it ("noiselab render: wrote FILE", a tool's error line). */
void nl_message(FILE *f, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void nl_vmessage(FILE *f, const char *fmt, va_list ap) __attribute__((format(printf, 2, 0)));

/* Flushes and closes a stream the program wrote without nl_atomic_* (its
 * stdout) and says whether every byte got there: stdio's error flag (a write
 * that failed earlier, its buffer full), the last flush and the close. A
 * program that exits 0 after output lost on a full disk or a closed pipe
 * reports a success it did not have. A stream that was already closed and
 * never written (`prog >&-` with nothing to say) is no failure. `what`
 * names it: "write error on standard output: No space left on device". */
nl_status nl_stream_close(FILE *f, const char *what, nl_error *err);

/* The library's allocation: malloc's contract (NULL on failure; a size of
 * 0 asks for 1 byte, so NULL always means failure; nl_calloc and
 * nl_malloc_array refuse a product that overflows size_t). Memory from them
 * is released with free(). A library call that cannot allocate returns
 * NL_ENOMEM with nl_fail_nomem's message; it never prints, exits or aborts:
 * what happens next is the calling program's choice.
 *
 * A host may watch or refuse allocations: nl_alloc_set_hook(h, ctx) makes
 * every allocation of these four first call h(n, ctx) with the bytes asked
 * for, and fail (as malloc returning NULL) when h returns 0. NULL removes the
 * hook. The hook is the host's process-wide setting, like SQLite's
 * sqlite3_config(SQLITE_CONFIG_MALLOC): set it before any other call, not
 * while library calls run in other threads. The tests set a counting hook
 * that makes the 1st, 2nd, ... allocation of a call fail in turn, to show
 * every path returns NL_ENOMEM and leaks nothing. */
typedef int (*nl_alloc_hook)(size_t n, void *ctx);
void nl_alloc_set_hook(nl_alloc_hook h, void *ctx);
void *nl_malloc(size_t n);
void *nl_calloc(size_t n, size_t size);
void *nl_malloc_array(size_t n, size_t size);
void *nl_realloc(void *p, size_t n);
char *nl_strdup(const char *s);
/* "out of memory allocating N bytes" (what names the caller's object when
 * not NULL: "nl_gmm_fit: out of memory allocating N bytes"); returns
 * NL_ENOMEM, for `return nl_fail_nomem(err, "what", n);`. */
nl_status nl_fail_nomem(nl_error *err, const char *what, size_t n);

/* Allocation that never returns NULL: out-of-memory is not a condition any
 * caller here can recover from. On failure it prints "noiselab: out of
 * memory allocating N bytes", then calls the out-of-memory handler with the
 * size asked for, which decides how the program ends and must not return;
 * with none (NULL, the default) it calls abort(), as GSL's default error
 * handler does. Programs choose their own (the experiment harness installs
 * one that exits 3). nl_set_oom_handler returns the previous handler. */
typedef void (*nl_oom_handler)(size_t n);
nl_oom_handler nl_set_oom_handler(nl_oom_handler h);
void *nl_xmalloc(size_t n);
void *nl_xcalloc(size_t n, size_t size);
void *nl_xrealloc(void *p, size_t n);
char *nl_xstrdup(const char *s);

typedef struct {
  FILE *fp;
  char *path;     /* the name given, used in messages */
  char *tmp;      /* temporary name beside the target; NULL when writing through */
  char *target;   /* the file replaced: path, or what a symbolic link names */
  int slot;       /* 1 + this temporary's place in the exit/signal clean-up list */
} nl_atomic_file;

/* An nl_atomic_file set to zeros is "not opened": commit_all skips it and
 * abort does nothing. */
nl_status nl_atomic_open(nl_atomic_file *af, const char *path, nl_error *err);
/* Flushes, checks and renames; on failure removes the temporary. Either way
 * af is released. */
nl_status nl_atomic_commit(nl_atomic_file *af, nl_error *err);
/* Commits n files together: each is flushed and checked first, and only when
 * all are whole are they renamed in; otherwise none is and all temporaries
 * are removed. Entries never opened (path NULL) are skipped. */
nl_status nl_atomic_commit_all(nl_atomic_file *af, size_t n, nl_error *err);
void nl_atomic_abort(nl_atomic_file *af);
/* Removes the temporaries this process has open (not yet committed or
 * aborted), by unlink() only: async-signal-safe, for a program's exit hook
 * or signal handler (the noiselab programs install both:
 * nl_harness_program_start). */
void nl_atomic_unlink_open(void);
/* Writes n bytes to `path` the same way (open, write, commit). */
nl_status nl_atomic_write(const char *path, const void *data, size_t n, nl_error *err);
/* A temporary path beside `path` keeping its extension (image writers pick
 * the format from it) and the writer's pid: "dir/.name.PID.XXXXXX.png", or
 * "dir/.nl.PID.XXXXXX.png" when
 * the name is too long for that in its folder (NAME_MAX, 255 bytes on most
 * file systems), so that every name the folder accepts can be written.
 * Caller frees. */
char *nl_temp_sibling(const char *path);

/* The image format whose signature opens the file `fp` ("PNG", "OpenEXR",
 * "TIFF", "JPEG", "GIF"), or NULL; reads at most 8 bytes of a regular file
 * and rewinds (NULL for a pipe or device, which are not read). Text readers (tables, parameter files) ask it first so
 * that an image given in a text file's place is named as one, instead of
 * its first NUL byte or garbled line. */
const char *nl_file_image_kind(FILE *fp);

/* Creates a directory and its parents (mkdir -p). An empty name is an
 * error ("'': empty directory name"). */
nl_status nl_mkdir_p(const char *dir, nl_error *err);
/* Checks that nl_atomic_open would accept `path`, without creating
 * anything: its parent exists, is a directory and is writable, and what is
 * at path is one of the kinds above (not a directory, a link to nothing, a
 * socket or a block device; a link's target is checked in its own folder).
 * Fails with a message naming path and the reason ("afile/x.png: parent
 * afile is not a directory"). A character device or FIFO passes whatever
 * its folder (it is written through). Programs call it for every output
 * before their work starts. */
nl_status nl_path_check_writable(const char *path, nl_error *err);

/* A status that must be looked at: ignoring one is a compiler warning (the
 * Fourier transforms' size refusals, spectrum/nl_spectrum.h). */
#define NL_MUST_CHECK __attribute__((warn_unused_result))

/* ---- memory a request needs ---------------------------------------------
 *
 * Places that allocate sizes derived from input (rows of a table, pixels of
 * an image, a distance matrix) check the size against the machine first
 * and refuse with a message naming the input, instead of dying in
 * nl_xmalloc or being killed. */
/* Physical memory of this machine in bytes (sysconf), or 0 if unknown. */
double nl_mem_physical(void);
/* What can be allocated now, in bytes: MemAvailable of /proc/meminfo (free
 * memory and reclaimable caches), else MemTotal, else nl_mem_physical; 0 if
 * unknown. Never more than a cap set by nl_mem_cap. */
double nl_mem_available(void);
/* 1 when `bytes` fits in what is available (nl_mem_available; always when
 * unknown). The one place a request is held to the machine's memory. */
int nl_mem_fits(double bytes);
/* Caps nl_mem_available for this process (0: no cap). A test hook: the
 * render and example tools set it from the environment variable
 * NL_MEMAVAILABLE_OVERRIDE (bytes), so that a refusal is tested at sizes
 * this machine could allocate; the library reads no environment for it. */
void nl_mem_cap(double bytes);
/* "160 GB", "894 MB", "512 kB", "12 bytes" (decimal units) into buf[32]; returns buf. */
const char *nl_format_bytes(char *buf, double bytes);
/* Joins dir and name with one '/'. Caller frees. */
char *nl_path_join(const char *dir, const char *name);

/* How a decimal number in text reads: the one number reader of tables
 * (nl_table_read) and options (nl_parse_double). The whole string is the
 * number; leading blanks are skipped (strtod). */
typedef enum {
  NL_NUMBER_OK,          /* a finite double, subnormals (1e-310) included */
  NL_NUMBER_NONE,        /* not a number */
  NL_NUMBER_NONFINITE,   /* nan, inf, infinity */
  NL_NUMBER_OVERFLOW,    /* beyond the double range: 1e999 (a commit id: 7395e8327457) */
  NL_NUMBER_UNDERFLOW,   /* not zero, but nearer 0 than the least subnormal: 1e-400 */
  NL_NUMBER_HEX          /* hexadecimal (0x10, 0x1p-3): a cell or option is decimal */
} nl_number_kind;
/* *v is set for NL_NUMBER_OK (and holds strtod's value otherwise). */
nl_number_kind nl_number_read(const char *s, double *v);
/* "underflows to 0 (nearer 0 than 4.9e-324)", ... : what is wrong with a
 * kind other than NL_NUMBER_OK, for a message "'S' <problem>". */
const char *nl_number_problem(nl_number_kind k);

/* Parse a whole string as a finite number within [lo, hi]; `what` names the
 * argument in the message ("--octaves: 'x' is not a number"). Subnormals
 * are numbers; a value that underflows to 0 is refused (nl_number_read). */
nl_status nl_parse_double(const char *what, const char *s, double lo, double hi,
                          double *out, nl_error *err);
nl_status nl_parse_long(const char *what, const char *s, long lo, long hi,
                        long *out, nl_error *err);

/* ---- command-line options (GNU style, on getopt_long) -------------------
 *
 * One parser for the tools: `--size 64` and `--size=64`, unique prefixes
 * (`--col 2`), `-o FILE`, `--` ends the options, positional words returned
 * in order where they stand. An option may take 0, 1 or 2 values (the
 * second value is the word after the first: `--uniform 0 1`). The parser
 * never prints or exits: an error is NL_OPT_ERROR with one line in err
 * ("--bogus: unknown option", "--size: missing value", "--all: takes no
 * value", "--s: ambiguous option (--seed, --size)"); the tool adds its name
 * and exits.
 *
 *   static const nl_opt_spec spec[] = {{"size", 0, 1}, {"out", 'o', 1}, {"help", 'h', 0}, {0}};
 *   nl_opt_parser p;
 *   nl_opt_begin(&p, argc, argv, 1, spec);
 *   for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END; ) {
 *     if (k == NL_OPT_ERROR) die(err.msg);
 *     if (k == NL_OPT_POSITIONAL) file = p.value[0]; else ... p.name, p.value[0] ...
 *   }
 *   nl_opt_end(&p);
 *
 * getopt_long keeps global state, so one parser runs at a time. */
typedef struct {
  const char *name;   /* long name without "--", or NULL to end the table */
  char short_name;    /* 'o' for -o, or 0 */
  int nvalues;        /* 0, 1 or 2 */
} nl_opt_spec;

enum { NL_OPT_POSITIONAL = -1, NL_OPT_END = -2, NL_OPT_ERROR = -3 };

typedef struct {
  int argc;
  char **argv;
  const nl_opt_spec *spec;
  void *longopts;        /* struct option[], owned */
  char shorts[128];
  int rest;              /* after "--": index of the next positional word */
  const char *value[2];  /* the values of the option or the positional word */
  char name[64];         /* "--size" (the full name even when abbreviated) or "-o" */
} nl_opt_parser;

/* Starts at argv[first]. */
void nl_opt_begin(nl_opt_parser *p, int argc, char **argv, int first, const nl_opt_spec *spec);
/* Index of the option in spec, NL_OPT_POSITIONAL (p->value[0] is the word),
 * NL_OPT_END, or NL_OPT_ERROR (err holds the message). */
int nl_opt_next(nl_opt_parser *p, nl_error *err);
void nl_opt_end(nl_opt_parser *p);

/* ---- the seed rule -----------------------------------------------------
 *
 * Every random stream in noiselab is derived by one rule from the run seed
 * (--seed) and a stream id: a role name and an index.
 *
 *   unsigned long s = nl_seed_stream(seed, "pool.run", q);   // run q's annealer
 *   gsl_rng_set(rng, s);
 *
 * The derivation is splitmix64 (Steele, Lea & Flood 2014, the seeding
 * generator of Java's SplittableRandom and of numpy's SeedSequence idea):
 * z = mix(seed), z = mix(z ^ fnv1a(role)), z = mix(z ^ index). Distinct
 * (role, index) pairs give unrelated seeds, so roles that must be
 * independent (a noise table and the annealer that walks it, a subsample
 * and k-means++) only need different role names; an index numbers the
 * members of one role (run q of a pool, colour channel c). Results then do
 * not depend on which thread runs which stream.
 *
 * GSL's mt19937 reads the low 32 bits of a seed; a seed whose low 32 bits
 * are 0 means 4357 there, which the rule reaches with probability 2^-32.
 *
 * Replicates: an experiment with --seed N --seeds K makes K independent
 * runs whose run seeds are N, N+1, ..., N+K-1 (nl_seed_replicate), so a
 * sweep can split the K runs across tasks and still merge to the same set.
 * Every stream of replicate k is then derived from its run seed by the rule.
 * No other seed arithmetic appears anywhere in the code. */
unsigned long nl_seed_stream(unsigned long seed, const char *role, unsigned long index);
/* The run seed of replicate k of a run with base seed `base`: base + k. */
unsigned long nl_seed_replicate(unsigned long base, long k);
/* splitmix64's output function (the mixer behind nl_seed_stream). */
unsigned long long nl_seed_mix(unsigned long long x);

/* Wall-clock seconds from a monotonic clock. */
double nl_time_now(void);
/* CPU seconds of the calling thread (CLOCK_THREAD_CPUTIME_ID): a per-item
 * time that other threads of an nl_parallel_for, or other processes,
 * running at once do not add to (they still share caches and memory). */
double nl_time_thread_cpu(void);

#define NL_PI 3.14159265358979323846
#define NL_TWO_PI 6.28318530717958647692

/* An angle reduced to [0, 2 pi): fmod, then + 2 pi for negatives, and 0 for
 * a t just below 0, whose t + 2 pi rounds up to 2 pi itself (so that a
 * gradient table's angles, and KS statistics over them, stay in range). */
double nl_wrap_angle(double t);

/* log |Gamma(x)|, the value of lgamma, without writing lgamma's global
 * signgam (a data race when p-values are computed in threads). */
double nl_lgamma(double x);

#ifdef __cplusplus
}
#endif

#endif
