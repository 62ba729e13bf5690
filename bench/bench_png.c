/* bench_png - what a PNG costs: the deflate level the writer uses
 * (NL_PNG_LEVEL, src/image/meson.build) beside every other level, time and
 * file size of a 6-octave fBm at 1024^2 and 4096^2, 8 and 16 bits; and
 * `noiselab render fbm --size 256 -o a.png`, a whole program, in wall time
 * (the median of 5 runs), which is what a user waits for.
 *
 *   build/bench/bench_png [--tsv]
 *
 * Encoding is timed in CPU time of the thread, the best of 3. */
#define _GNU_SOURCE
#include "nl_bench.h"
#include "image/nl_image.h"
#include "image/nl_image_config.h"
#include "image/nl_image_png.h"
#include "noise/nl_noise.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

static int cmp(const void *a, const void *b)
{
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Wall seconds of `render fbm --size 256 -o DIR/a.png`, median of 5. */
static double render_wall(const char *render, const char *dir)
{
  double t[5];
  char out[PATH_MAX];
  snprintf(out, sizeof out, "%s/a.png", dir);
  for (int i = 0; i < 5; i++) {
    double t0 = nl_time_now();
    pid_t pid = fork();
    if (pid == 0) {
      if (!freopen("/dev/null", "w", stderr)) _exit(127);
      execl(render, render, "fbm", "--size", "256", "-o", out, (char *)NULL);
      _exit(127);
    }
    int st = 0;
    if (pid < 0 || waitpid(pid, &st, 0) < 0 || !WIFEXITED(st) || WEXITSTATUS(st)) return -1;
    t[i] = nl_time_now() - t0;
  }
  qsort(t, 5, sizeof *t, cmp);
  return t[2];
}

int main(int argc, char **argv)
{
  int tsv = argc > 1 && !strcmp(argv[1], "--tsv");
  nl_bench_report(stdout, "start");
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  nl_noise_basis b = nl_noise_basis_perm3(&p);
  nl_noise_octaves o = nl_noise_octaves_fbm(6, 0.5, 2);
  printf(tsv ? "size\tbits\tlevel\tcpu_s\tbytes\tused\n"
             : "# PNG of a 6-octave fBm: deflate level, CPU seconds (best of 3), bytes\n");
  const int sizes[2] = {1024, 4096};
  for (int s = 0; s < 2; s++) {
    int n = sizes[s];
    double *v = malloc(sizeof *v * (size_t)n * (size_t)n);
    nl_noise_window w = {0, 0, 0.5, 4, n, n};
    nl_noise_fractal_grid(&b, &o, &w, v);
    nl_image *im = nl_image_from_values(v, n, n, -1, 1);
    free(v);
    for (int bits = 8; bits <= 16; bits += 8)
      for (int lv = 1; lv <= 9; lv++) {
        if (n > 1024 && lv != 1 && lv != NL_PNG_LEVEL && lv != 6 && lv != 9) continue;
        double best = 1e30;
        size_t bytes = 0;
        for (int r = 0; r < 3; r++) {
          unsigned char *d = NULL;
          nl_error err;
          double c0 = nl_bench_cpu_now();
          if (nl_image_png_encode(im, "bench.png", bits, lv, &d, &bytes, &err)) {
            fprintf(stderr, "bench_png: %s\n", err.msg);
            return 1;
          }
          double c = nl_bench_cpu_now() - c0;
          if (c < best) best = c;
          free(d);
        }
        printf(tsv ? "%d\t%d\t%d\t%.4f\t%zu\t%s\n" : "png %5d^2 %2d-bit level %d  %8.4f s  %10zu bytes%s\n",
               n, bits, lv, best, bytes, lv == NL_PNG_LEVEL ? (tsv ? "yes" : "  (used)") : (tsv ? "no" : ""));
      }
    nl_image_free(im);
  }
  /* The render program beside this one: build/bench/../tools. */
  char self[PATH_MAX], render[PATH_MAX + 32], dir[] = "/tmp/noiselab_bench_png.XXXXXX";
  ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
  if (k > 0 && mkdtemp(dir)) {
    self[k] = 0;
    char *slash = strrchr(self, '/');
    if (slash) *slash = 0;
    snprintf(render, sizeof render, "%s/../tools/noiselab-render", self);
    double t = render_wall(render, dir);
    char out[PATH_MAX];
    snprintf(out, sizeof out, "%s/a.png", dir);
    unlink(out);
    rmdir(dir);
    if (t < 0) { fprintf(stderr, "bench_png: %s failed\n", render); return 1; }
    printf(tsv ? "# render\t%.4f\n" : "render fbm --size 256 -o a.png: %.4f s wall (median of 5)\n", t);
  }
  nl_bench_report(stdout, "end");
  return 0;
}
