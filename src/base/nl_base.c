#include "base/nl_base.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

nl_status nl_fail(nl_error *err, nl_status status, const char *fmt, ...)
{
  if (err) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    /* One line whatever the input echoed in it (a file name or an argument
     * holding a newline or a NUL-truncated byte run): control characters
     * become '?', so a program can print the message as its one line. */
    for (char *c = err->msg; *c; c++)
      if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
  }
  return status;
}

/* NULL: abort() after the message, as GSL's default error handler does. */
static nl_oom_handler oom_handler = NULL;

nl_oom_handler nl_set_oom_handler(nl_oom_handler h)
{
  nl_oom_handler old = oom_handler;
  oom_handler = h;
  return old;
}

/* The message is always the same; the handler only decides how to end. */
static void oom(size_t n)
{
  fprintf(stderr, "noiselab: out of memory allocating %zu bytes\n", n);
  if (oom_handler) oom_handler(n);
  abort();   /* the default, and a handler must not return */
}

void *nl_xmalloc(size_t n)
{
  void *p = malloc(n ? n : 1);
  if (!p) oom(n);
  return p;
}

void *nl_xcalloc(size_t n, size_t size)
{
  void *p = calloc(n ? n : 1, size ? size : 1);
  if (!p) oom(n * size);
  return p;
}

void *nl_xrealloc(void *p, size_t n)
{
  void *q = realloc(p, n ? n : 1);
  if (!q) oom(n);
  return q;
}

char *nl_xstrdup(const char *s)
{
  size_t n = strlen(s) + 1;
  char *d = nl_xmalloc(n);
  memcpy(d, s, n);
  return d;
}

char *nl_path_join(const char *dir, const char *name)
{
  size_t a = strlen(dir), b = strlen(name);
  char *p = nl_xmalloc(a + b + 2);
  memcpy(p, dir, a);
  size_t k = a;
  if (a > 0 && dir[a - 1] != '/') p[k++] = '/';
  memcpy(p + k, name, b + 1);
  return p;
}

char *nl_temp_sibling(const char *path)
{
  const char *slash = strrchr(path, '/');
  const char *base = slash ? slash + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t dirlen = (size_t)(base - path);
  size_t stemlen = dot ? (size_t)(dot - base) : strlen(base);
  const char *ext = dot ? dot : "";
  size_t n = dirlen + 1 + stemlen + 8 + strlen(ext) + 1;
  char *t = nl_xmalloc(n);
  snprintf(t, n, "%.*s.%.*s.XXXXXX%s", (int)dirlen, path, (int)stemlen, base, ext);
  return t;
}

nl_status nl_atomic_open(nl_atomic_file *af, const char *path, nl_error *err)
{
  af->fp = NULL;
  af->path = af->tmp = NULL;
  /* "", "dir/", a directory or a parent that is a file: say so, naming the
   * target, before a temporary file is made. */
  nl_status c = nl_path_check_writable(path, err);
  if (c) return c;
  af->path = nl_xstrdup(path);
  af->tmp = nl_temp_sibling(path);
  const char *dot = strrchr(af->tmp, '.');
  int suffix = (dot && strstr(af->tmp, "XXXXXX") < dot) ? (int)strlen(dot) : 0;
  int fd = mkstemps(af->tmp, suffix);
  if (fd < 0) {
    int e = errno;
    /* The reason, naming the target rather than the temporary name. */
    nl_status s = nl_path_check_writable(path, err);
    if (!s) s = nl_fail(err, NL_EIO, "%s: cannot create: %s", path, strerror(e));
    free(af->path); free(af->tmp);
    af->path = af->tmp = NULL;
    return s;
  }
  /* mkstemp makes 0600 files; results are meant to be shared. */
  fchmod(fd, 0644);
  af->fp = fdopen(fd, "w");
  if (!af->fp) {
    nl_status s = nl_fail(err, NL_EIO, "%s: cannot open: %s", path, strerror(errno));
    close(fd);
    unlink(af->tmp);
    free(af->path); free(af->tmp);
    af->path = af->tmp = NULL;
    return s;
  }
  return NL_OK;
}

nl_status nl_atomic_commit(nl_atomic_file *af, nl_error *err)
{
  int bad = ferror(af->fp);
  if (fclose(af->fp) != 0) bad = 1;
  af->fp = NULL;
  nl_status s = NL_OK;
  if (bad) {
    s = nl_fail(err, NL_EIO, "%s: write failed: %s", af->path, strerror(errno));
    unlink(af->tmp);
  } else if (rename(af->tmp, af->path) != 0) {
    s = nl_fail(err, NL_EIO, "%s: cannot rename into place: %s", af->path, strerror(errno));
    unlink(af->tmp);
  }
  free(af->path); free(af->tmp);
  af->path = af->tmp = NULL;
  return s;
}

void nl_atomic_abort(nl_atomic_file *af)
{
  if (af->fp) fclose(af->fp);
  if (af->tmp) unlink(af->tmp);
  free(af->path); free(af->tmp);
  af->fp = NULL; af->path = af->tmp = NULL;
}

nl_status nl_mkdir_p(const char *dir, nl_error *err)
{
  if (!dir || !*dir) return nl_fail(err, NL_EINVAL, "'': empty directory name");
  char *p = nl_xstrdup(dir);
  for (char *q = p + 1; ; q++) {
    if (*q == '/' || *q == '\0') {
      char c = *q;
      *q = '\0';
      if (mkdir(p, 0755) != 0 && errno != EEXIST) {
        nl_status s;
        if (errno == ENOTDIR) {
          /* name the component that is a file */
          struct stat st;
          char *q2 = p + 1;
          for (;; q2++)
            if (*q2 == '/' || *q2 == '\0') {
              char c2 = *q2;
              *q2 = '\0';
              int file = stat(p, &st) == 0 && !S_ISDIR(st.st_mode);
              if (file || c2 == '\0') break;
              *q2 = c2;
            }
          s = nl_fail(err, NL_EIO, "%s: cannot create directory: %s is not a directory", dir, p);
        } else {
          s = nl_fail(err, NL_EIO, "%s: cannot create directory %s: %s", dir, p, strerror(errno));
        }
        free(p);
        return s;
      }
      *q = c;
      if (c == '\0') break;
    }
  }
  struct stat st;
  nl_status s = NL_OK;
  if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
    s = nl_fail(err, NL_EIO, "%s: not a directory", dir);
  free(p);
  return s;
}

nl_status nl_path_check_writable(const char *path, nl_error *err)
{
  if (!path || !*path) return nl_fail(err, NL_EINVAL, "'': empty file name");
  size_t n = strlen(path);
  if (path[n - 1] == '/') return nl_fail(err, NL_EINVAL, "%s: names a directory, not a file", path);
  const char *slash = strrchr(path, '/');
  char *dir = slash ? nl_xstrdup(path) : nl_xstrdup(".");
  if (slash) dir[slash == path ? 1 : (size_t)(slash - path)] = '\0';
  struct stat st;
  nl_status s = NL_OK;
  if (stat(dir, &st) != 0) {
    if (errno == ENOTDIR)
      s = nl_fail(err, NL_EIO, "%s: a parent of %s is not a directory", path, dir);
    else if (errno == ENOENT)
      s = nl_fail(err, NL_EIO, "%s: directory %s does not exist", path, dir);
    else
      s = nl_fail(err, NL_EIO, "%s: parent %s: %s", path, dir, strerror(errno));
  } else if (!S_ISDIR(st.st_mode)) {
    s = nl_fail(err, NL_EIO, "%s: parent %s is not a directory", path, dir);
  } else if (access(dir, W_OK) != 0) {
    s = nl_fail(err, NL_EIO, "%s: directory %s is not writable: %s", path, dir, strerror(errno));
  } else if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
    s = nl_fail(err, NL_EIO, "%s: is a directory", path);
  }
  free(dir);
  return s;
}

double nl_mem_physical(void)
{
  long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || size <= 0) return 0;
  return (double)pages * (double)size;
}

int nl_mem_fits(double bytes)
{
  double m = nl_mem_physical();
  return m <= 0 || bytes <= m;
}

const char *nl_format_bytes(char *buf, double bytes)
{
  if (bytes >= 1e12) snprintf(buf, 32, "%.3g TB", bytes / 1e12);
  else if (bytes >= 1e9) snprintf(buf, 32, "%.3g GB", bytes / 1e9);
  else if (bytes >= 1e6) snprintf(buf, 32, "%.3g MB", bytes / 1e6);
  else if (bytes >= 1e3) snprintf(buf, 32, "%.3g kB", bytes / 1e3);
  else snprintf(buf, 32, "%.0f bytes", bytes);
  return buf;
}

double nl_time_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double nl_time_thread_cpu(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

nl_status nl_parse_double(const char *what, const char *s, double lo, double hi,
                          double *out, nl_error *err)
{
  if (!s || !*s) return nl_fail(err, NL_EINVAL, "%s: missing value", what);
  char *end;
  errno = 0;
  double v = strtod(s, &end);
  if (*end != '\0' || end == s)
    return nl_fail(err, NL_EINVAL, "%s: '%s' is not a number", what, s);
  if (v != v || errno == ERANGE || v > 1.7976931348623157e308 || v < -1.7976931348623157e308)
    return nl_fail(err, NL_EINVAL, "%s: '%s' is not a finite number", what, s);
  if (v < lo || v > hi)
    return nl_fail(err, NL_EINVAL, "%s: %s is outside [%g, %g]", what, s, lo, hi);
  *out = v;
  return NL_OK;
}

nl_status nl_parse_long(const char *what, const char *s, long lo, long hi,
                        long *out, nl_error *err)
{
  if (!s || !*s) return nl_fail(err, NL_EINVAL, "%s: missing value", what);
  char *end;
  errno = 0;
  long v = strtol(s, &end, 10);
  if (*end != '\0' || end == s)
    return nl_fail(err, NL_EINVAL, "%s: '%s' is not an integer", what, s);
  if (errno == ERANGE || v < lo || v > hi)
    return nl_fail(err, NL_EINVAL, "%s: %s is outside [%ld, %ld]", what, s, lo, hi);
  *out = v;
  return NL_OK;
}

/* splitmix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
 * generators", OOPSLA 2014): the golden-ratio increment, then Stafford's
 * variant 13 finaliser. A bijection on 64 bits, so distinct inputs never
 * collide before the final truncation. */
unsigned long long nl_seed_mix(unsigned long long x)
{
  unsigned long long z = x + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

unsigned long nl_seed_stream(unsigned long seed, const char *role, unsigned long index)
{
  unsigned long long h = 0xcbf29ce484222325ULL;   /* FNV-1a 64 of the role name */
  for (const unsigned char *p = (const unsigned char *)role; *p; p++) {
    h ^= *p;
    h *= 0x100000001b3ULL;
  }
  unsigned long long z = nl_seed_mix((unsigned long long)seed);
  z = nl_seed_mix(z ^ h);
  z = nl_seed_mix(z ^ (unsigned long long)index);
  return (unsigned long)z;
}

unsigned long nl_seed_replicate(unsigned long base, long k)
{
  return base + (unsigned long)k;
}

double nl_wrap_angle(double t)
{
  t = fmod(t, NL_TWO_PI);
  if (t < 0) t += NL_TWO_PI;
  return t >= NL_TWO_PI ? 0.0 : t;
}

double nl_lgamma(double x)
{
  int sign;
  return lgamma_r(x, &sign);
}
