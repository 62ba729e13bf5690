/* embed LIBNOISELAB.so - the installed library in a program that has
 * its own signal handlers: it opens libnoiselab with dlopen, as a Python
 * session or a plugin host does, makes it write a PNG and a TIFF (the
 * second loads the OpenImageIO module), evaluate noise and run a KS test,
 * and checks that its handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE are
 * still its own and that a SIGINT reaches its handler and leaves it
 * running. Exit 0, or 1 naming what changed. */
#include "image/nl_image.h"
#include "image/nl_image_config.h"
#include "noise/nl_noise.h"
#include "stats/nl_stats.h"

#include <dlfcn.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t got;
static void mine(int sig) { got = sig; }

/* The library's own copy of each call, looked up in the opened object (the
 * headers give the types; this program links no noiselab code). */
#define SYM(name) __typeof__(name) *p_##name = (__typeof__(name) *)(void (*)(void))dlsym(lib, #name); \
  if (!p_##name) { fprintf(stderr, "embed: %s missing: %s\n", #name, dlerror()); return 1; }

int main(int argc, char **argv)
{
  if (argc != 2) { fprintf(stderr, "usage: embed LIBNOISELAB.so\n"); return 2; }
  char dir[] = "/tmp/noiselab_embed.XXXXXX";
  if (!mkdtemp(dir)) { perror("embed: mkdtemp"); return 2; }
  const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
  struct sigaction sa, before[4], after[4];
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = mine;
  sigemptyset(&sa.sa_mask);
  for (int i = 0; i < 4; i++)
    if (sigaction(sigs[i], &sa, NULL) || sigaction(sigs[i], NULL, &before[i])) return 2;
  void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!lib) { fprintf(stderr, "embed: %s\n", dlerror()); return 1; }
  SYM(nl_image_alloc)
  SYM(nl_image_free)
  SYM(nl_image_write)
  SYM(nl_noise_perm3_reference)
  SYM(nl_noise_perm3_row)
  SYM(nl_stats_ks_test_uniform)
  nl_image *im = p_nl_image_alloc(16, 8, 3);
  nl_noise_perm3 perm;
  nl_stats_ks_result ks;
  double row[128];
  p_nl_noise_perm3_reference(&perm);
  p_nl_noise_perm3_row(&perm, 0.25, 0.1, 0.5, 0.5, 128, row);
  for (int i = 0; i < 16 * 8 * 3; i++) im->data[i] = (float)(0.5 + 0.4 * row[i % 128]);
  char path[4096];
  nl_error err;
  const char *names[2] = {"embed.png", "embed.tif"};
  /* a build without image support (-Dimages=disabled, the arm64 check)
   * writes no image */
  for (int k = 0; k < (NL_OIIO_BUILT ? 2 : 0); k++) {
    snprintf(path, sizeof path, "%s/%s", dir, names[k]);
    int s = p_nl_image_write(im, path, 8, &err);
    unlink(path);
    if (s) { fprintf(stderr, "embed: %s\n", err.msg); rmdir(dir); return 1; }
  }
  rmdir(dir);
  for (int i = 0; i < 128; i++) row[i] = 0.5 + 0.5 * row[i];
  if (p_nl_stats_ks_test_uniform(row, 128, 0.0, 1.0, &ks, &err)) {
    fprintf(stderr, "embed: %s\n", err.msg);
    return 1;
  }
  p_nl_image_free(im);
  int bad = 0;
  for (int i = 0; i < 4; i++) {
    sigaction(sigs[i], NULL, &after[i]);
    if (after[i].sa_handler != mine || after[i].sa_flags != before[i].sa_flags) {
      fprintf(stderr, "embed: the library replaced the handler of signal %d\n", sigs[i]);
      bad = 1;
    }
  }
  raise(SIGINT);
  if (got != SIGINT) { fprintf(stderr, "embed: SIGINT did not reach the program's handler\n"); bad = 1; }
  if (!bad) printf("embed: handlers unchanged; KS D = %.6f\n", ks.d);
  return bad;
}
