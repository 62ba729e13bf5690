/* noiselab example - procedural textures by example (Lagae et al. 2010).
 *
 *   noiselab example analyse IMAGE -o PARAMS [--rgb] [--no-histogram] [--paper-histogram]
 *                    [--no-calibration]
 *   noiselab example synthesize PARAMS --size N [--height H] [--seed S]
 *                    [--scale S] [--solid [--z Z]] -o OUT.png|.exr|.tif
 *   noiselab example morph PARAMS1 PARAMS2 --t T -o OUT.params
 *                    (or with --size N [--seed S]: -o OUT.png, the image)
 *   noiselab example compare PHOTO SYNTH -o SUMMARY.tsv [--bands BANDS.tsv]
 * Errors: one line on stderr naming the input and the problem, exit 2.
 * Outputs are written atomically (temporary file, then rename).
 */
#include "harness/nl_harness.h"
#include "nl_tool.h"
#include "byexample/nl_byexample.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Each subcommand's usage and options; `example CMD --help` prints its own,
 * `example --help` all four. */
static const struct { const char *cmd, *usage, *help; } HELP[] = {
  {"analyse",
   "noiselab example analyse IMAGE -o PARAMS [--rgb] [--no-histogram] [--paper-histogram]\n"
   "                        [--no-calibration]\n",
   "  analyse     fit the procedural texture of an exemplar (grey, RGB, RGBA; 8/16-bit or\n"
   "              float; at least 16 x 16 pixels): C^2 + C (Q + B) parameters for C channels,\n"
   "              Q histogram quantiles and B = floor(log2 of the larger side) bands (the\n"
   "              paper's 66 for a 512 x 512 RGB exemplar and its 10 quantiles); analyse\n"
   "              prints the count\n"
   "  --rgb       no PCA colour decorrelation;  --no-histogram  no histogram matching\n"
   "  --paper-histogram  the paper's 10 quantiles at p = j/9 (default: 33 quantiles at\n"
   "              p = Phi(z), z = -4..4 every 1/4 sd, which keep the tails)\n"
   "  --no-calibration  the paper's synthesis: weights by eq. 12, histogram by the expected\n"
   "              sd; default: the file keeps the exemplar's band powers and synthesis\n"
   "              calibrates the band weights to them at its size and seed (4 rounds of\n"
   "              synthesize, rank-match the histogram, measure, correct; nl_byexample.h)\n"},
  {"synthesize",
   "noiselab example synthesize PARAMS --size N [--height H] [--seed S] [--scale S]\n"
   "                        [--solid [--z Z]] -o OUT.png|.exr|.tif\n",
   "  synthesize  evaluate it on an N x H grid (pixels of the exemplar's size times --scale);\n"
   "              --solid uses 3D wavelet noise, the slice at depth --z\n"},
  {"morph",
   "noiselab example morph PARAMS1 PARAMS2 --t T -o OUT.params\n"
   "                        [--size N [--seed S]  (then OUT is an image)]\n",
   "  morph       interpolate two parameter files at t in [0, 1] (matrix by quaternion slerp)\n"},
  {"compare",
   "noiselab example compare PHOTO SYNTH -o SUMMARY.tsv [--bands BANDS.tsv]\n",
   "  compare     luminance of SYNTH against PHOTO: KS distance, tail mass beyond 2.5 sd, colour\n"
   "              speckle, and per eq. 13 band of PHOTO the power ratio (--bands); pass = every\n"
   "              band with >= 2% of the power within x1.3 and KS < 0.03 (L3's criteria); it\n"
   "              does not test structure (edges, shapes: a speckled synthesis can pass), which\n"
   "              ks_grad, the KS distance of gradient magnitudes, reports\n"},
};
enum { NHELP = sizeof HELP / sizeof HELP[0] };

/* cmd NULL: every subcommand; else the one whose name cmd starts (analyze,
 * synthesise are accepted spellings). */
static void usage(FILE *fp, const char *cmd)
{
  int first = 1;
  for (int k = 0; k < NHELP; k++) {
    if (cmd && strncmp(cmd, HELP[k].cmd, 5))
      continue;
    fputs(first ? "usage: " : "       ", fp);
    fputs(HELP[k].usage, fp);
    first = 0;
  }
  for (int k = 0; k < NHELP; k++)
    if (!cmd || !strncmp(cmd, HELP[k].cmd, 5))
      fputs(HELP[k].help, fp);
}

/* One line on stderr, exit 2: input quoted in it is escaped (nl_message). */
#define die(...) nl_tool_die("noiselab example: ", __VA_ARGS__)

static void check(nl_status st, const nl_error *err) { if (st) die("%s", err->msg); }

typedef struct {
  const char *pos[2];
  int npos;
  const char *out, *bands;
  long size, height, seed;
  double t, scale, z;
  int rgb, nohist, paperhist, nocal, solid, have_t, have_size;
  int have_seed, have_height, have_scale, have_z;   /* typed, for the ignored-option warnings */
} args;

static void parse(int argc, char **argv, args *a)
{
  enum { O_OUT, O_BANDS, O_SIZE, O_HEIGHT, O_SEED, O_T, O_SCALE, O_Z, O_RGB, O_NOHIST, O_PAPERHIST, O_NOCAL, O_SOLID, O_HELP };
  static const nl_opt_spec spec[] = {
    [O_OUT] = {"out", 'o', 1}, [O_BANDS] = {"bands", 0, 1}, [O_SIZE] = {"size", 0, 1}, [O_HEIGHT] = {"height", 0, 1},
    [O_SEED] = {"seed", 0, 1}, [O_T] = {"t", 0, 1}, [O_SCALE] = {"scale", 0, 1}, [O_Z] = {"z", 0, 1},
    [O_RGB] = {"rgb", 0, 0}, [O_NOHIST] = {"no-histogram", 0, 0}, [O_PAPERHIST] = {"paper-histogram", 0, 0},
    [O_NOCAL] = {"no-calibration", 0, 0},
    [O_SOLID] = {"solid", 0, 0}, [O_HELP] = {"help", 'h', 0}, {NULL, 0, 0}};
  nl_error err;
  memset(a, 0, sizeof *a);
  a->seed = 1;
  a->scale = 1;
  nl_opt_parser p;
  nl_opt_begin(&p, argc, argv, 2, spec);   /* argv[1] is the subcommand */
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    const char *v = p.value[0];
    switch (k) {
    case NL_OPT_ERROR: die("%s (try --help)", err.msg);
    case NL_OPT_POSITIONAL:
      if (a->npos == 2) die("%s: unexpected argument", v);
      a->pos[a->npos++] = v;
      break;
    case O_OUT: a->out = v; break;
    case O_BANDS: a->bands = v; break;
    case O_SIZE:
      check(nl_parse_long("--size", v, 1, NL_BYEXAMPLE_MAX_SIDE, &a->size, &err), &err);
      a->have_size = 1;
      break;
    case O_HEIGHT:
      check(nl_parse_long("--height", v, 1, NL_BYEXAMPLE_MAX_SIDE, &a->height, &err), &err);
      a->have_height = 1;
      break;
    case O_SEED:
      check(nl_parse_long("--seed", v, 0, 4294967295L, &a->seed, &err), &err);
      a->have_seed = 1;
      break;
    /* --t, --scale and --z: any number here, the range is the library's
     * (nl_byexample_morph_check, nl_byexample_synth_check, below), which
     * the Python binding reaches through the same calls */
    case O_T: check(nl_parse_double("--t", v, -HUGE_VAL, HUGE_VAL, &a->t, &err), &err); a->have_t = 1; break;
    case O_SCALE:
      check(nl_parse_double("--scale", v, -HUGE_VAL, HUGE_VAL, &a->scale, &err), &err);
      a->have_scale = 1;
      break;
    case O_Z:
      check(nl_parse_double("--z", v, -HUGE_VAL, HUGE_VAL, &a->z, &err), &err);
      a->have_z = 1;
      break;
    case O_RGB: a->rgb = 1; break;
    case O_NOHIST: a->nohist = 1; break;
    case O_PAPERHIST: a->paperhist = 1; break;
    case O_NOCAL: a->nocal = 1; break;
    case O_SOLID: a->solid = 1; break;
    case O_HELP: usage(stdout, argv[1]); exit(0);
    }
  }
  nl_opt_end(&p);
  nl_byexample_synth_options so = {a->scale, a->solid, a->z, NL_SPLINE_STEFFEN};
  check(nl_byexample_synth_check(&so, &err), &err);
  if (a->have_t) check(nl_byexample_morph_check(a->t, &err), &err);
  if (!a->out) die("-o OUT is required");
  nl_tool_check_output(a->out, a->pos, a->npos);   /* not an input, not our sources */
  nl_tool_check_output(a->bands, a->pos, a->npos);
  /* a bad output is named before any input is read (an image read starts
   * OpenImageIO: 0.5 s) */
  check(nl_path_check_writable(a->out, &err), &err);
  if (a->bands) check(nl_path_check_writable(a->bands, &err), &err);
}

static void write_image(const nl_image *im, const char *path)
{
  nl_error err;
  check(nl_image_write(im, path, 16, &err), &err);
}

static int analyse(const args *a)
{
  nl_error err;
  nl_image *im;
  if (a->npos != 1) die("analyse takes one IMAGE");
  check(nl_image_read(a->pos[0], &im, &err), &err);
  nl_byexample_options o = {!a->rgb, !a->nohist, 0, 0, a->paperhist ? NL_HIST_PAPER : NL_HIST_GAUSS,
                            a->nocal ? 0 : NL_BYEXAMPLE_CALIBRATE};
  nl_byexample_params p;
  if (nl_byexample_analyse(im, &o, &p, &err)) die("%s: %s", a->pos[0], err.msg);
  check(nl_byexample_params_save(&p, a->out, &err), &err);
  nl_message(stderr, "noiselab example: wrote %s (%d parameters: %d channel%s, %d quantiles, "
             "%d bands)", a->out, nl_byexample_param_count(&p), p.channels,
             p.channels > 1 ? "s" : "", p.nhist, p.nbands);
  nl_image_free(im);
  return 0;
}

/* An option typed but without effect is said, as render does, rather than
 * silently ignored: the user meant something by it. */
static void ignored(const char *opt, const char *why)
{
  fprintf(stderr, "noiselab example: warning: %s ignored: %s\n", opt, why);
}

static void synth_write(const nl_byexample_params *p, const args *a)
{
  nl_error err;
  nl_image *im;
  if (!a->have_size) die("--size N is required");
  if (a->have_z && !a->solid) ignored("--z", "it sets the depth of --solid's slice");
  nl_byexample_synth_options so = {a->scale, a->solid, a->z, NL_SPLINE_STEFFEN};
  check(nl_byexample_synthesize(p, (int)a->size, (int)(a->height ? a->height : a->size),
                                (unsigned long)a->seed, &so, &im, &err), &err);
  write_image(im, a->out);
  nl_image_free(im);
}

static int synthesize(const args *a)
{
  nl_error err;
  nl_byexample_params p;
  if (a->npos != 1) die("synthesize takes one PARAMS file");
  check(nl_byexample_params_load(a->pos[0], &p, &err), &err);
  synth_write(&p, a);
  return 0;
}

static int morph(const args *a)
{
  nl_error err;
  nl_byexample_params p1, p2, m;
  if (a->npos != 2) die("morph takes two PARAMS files");
  if (!a->have_t) die("--t T is required");
  check(nl_byexample_params_load(a->pos[0], &p1, &err), &err);
  check(nl_byexample_params_load(a->pos[1], &p2, &err), &err);
  if (nl_byexample_morph(&p1, &p2, a->t, &m, &err))
    die("%s, %s: %s", a->pos[0], a->pos[1], err.msg);
  if (p1.nbands != p2.nbands)
    nl_message(stderr, "noiselab example: morph: %s has %d bands, %s %d: the result keeps the %d "
               "finest both have", a->pos[0], p1.nbands, a->pos[1], p2.nbands, m.nbands);
  if (a->have_size) {
    synth_write(&m, a);
    return 0;
  }
  const char *const opts[] = {"--seed", "--height", "--scale", "--solid", "--z"};
  const int typed[] = {a->have_seed, a->have_height, a->have_scale, a->solid, a->have_z};
  for (int i = 0; i < 5; i++)
    if (typed[i]) ignored(opts[i], "without --size, morph writes parameters, not an image");
  check(nl_byexample_params_save(&m, a->out, &err), &err);
  return 0;
}

static int compare(const args *a)
{
  nl_error err;
  nl_image *im[2];
  if (a->npos != 2) die("compare takes PHOTO and SYNTH");
  for (int i = 0; i < 2; i++) check(nl_image_read(a->pos[i], &im[i], &err), &err);
  if (im[0]->width < NL_BYEXAMPLE_MIN_SIZE || im[0]->height < NL_BYEXAMPLE_MIN_SIZE)
    die("%s: image is %d x %d pixels, smaller than %d", a->pos[0], im[0]->width, im[0]->height,
        NL_BYEXAMPLE_MIN_SIZE);
  nl_table *bt = nl_study_example_band_table(), *st = nl_study_example_summary_table();
  check(nl_study_example_compare(im[0], im[1], a->pos[0], a->pos[1], 0, 0.02, 1.3, 0.03, bt, st, &err),
        &err);
  /* Both tables or neither: the second path is checked before the first
   * file is replaced. */
  nl_atomic_file af[2] = {{0}, {0}};
  check(nl_atomic_open(&af[0], a->out, &err), &err);
  if (a->bands) check(nl_atomic_open(&af[1], a->bands, &err), &err);
  check(nl_table_write_to(st, &af[0], &err), &err);
  if (a->bands) check(nl_table_write_to(bt, &af[1], &err), &err);
  check(nl_atomic_commit_all(af, 2, &err), &err);
  /* A speckled synthesis can match a photograph's band powers and histogram
   * (a flagstone texture passes without a stone in it): say so each time. */
  nl_message(stderr, "noiselab example: wrote %s: pass %d tests band powers and the histogram, not "
             "structure (edges, shapes); ks_grad %.3g (gradient magnitudes) is reported, not tested",
             a->out, (int)nl_table_value(st, 0, "pass"), nl_table_value(st, 0, "ks_grad"));
  nl_table_free(bt);
  nl_table_free(st);
  nl_image_free(im[0]);
  nl_image_free(im[1]);
  return 0;
}

int main(int argc, char **argv)
{
  nl_tool_start("noiselab example");   /* OOM exit, SIGXFSZ ignored, stdout checked at exit */
  if (argc < 2) { usage(stderr, NULL); return 2; }
  const char *cmd = argv[1];
  if (!strcmp(cmd, "-h") || !strcmp(cmd, "--help")) { usage(stdout, NULL); return 0; }
  args a;
  if (strcmp(cmd, "analyse") && strcmp(cmd, "analyze") && strcmp(cmd, "synthesize") &&
      strcmp(cmd, "synthesise") && strcmp(cmd, "morph") && strcmp(cmd, "compare")) {
    die("unknown command '%s' (analyse, synthesize, morph, compare)", cmd);
  }
  parse(argc, argv, &a);
  if (!strncmp(cmd, "analy", 5)) return analyse(&a);
  if (!strncmp(cmd, "synthes", 7)) return synthesize(&a);
  if (!strcmp(cmd, "compare")) return compare(&a);
  return morph(&a);
}
