/* L4 - Lagae et al. 2010 Fig. 10 and 12: frequency-based editing (attenuate
 * the finest bands), solid texture extrapolation (2D weights on 3D wavelet
 * noise) and morphing by interpolating parameters. */
#include "byexample/nl_byexample.h"
#include "harness/nl_harness.h"
#include "editing.h"
#include "l4.h"
#include "verdicts.h"
#include "study/nl_study.h"

#include <math.h>
#include <stdlib.h>

static nl_image *synth(nl_harness *r, const nl_byexample_params *p, int size, unsigned long seed,
                       int solid, double z)
{
  nl_image *im;
  nl_error err;
  nl_byexample_synth_options so = {1, solid, z, NL_SPLINE_STEFFEN};
  if (nl_byexample_synthesize(p, size, size, seed, &so, &im, &err))
    nl_harness_die(r, 1, "%s", err.msg);
  return im;
}

int main(int argc, char **argv)
{
  l4 q = {0};
  q.r = nl_harness_begin("l4_editing",
                         "L4 - Frequency-based editing, solid extrapolation, morphing", argc, argv);
  nl_harness *r = q.r;
  int quick = nl_harness_quick(r);
  q.size = (int)nl_harness_param_fft_size(r, "size", quick ? 128 : 512, 16, 4096,
                                     "side in pixels of the exemplar and the edited textures "
                                     "(quick 128)");
  q.nfine = (int)nl_harness_param_int(r, "edit_bands", 3, 1, 16,
                                      "how many of the finest frequency bands the edit attenuates "
                                      "(Lagae Fig. 10)");
  q.factor = nl_harness_param(r, "edit_factor", 0.25, 0, 10,
                              "factor the attenuated bands' weights are multiplied by (their power "
                              "by its square)");
  nl_harness_params_done(r);
  int size = q.size;
  unsigned long seed = q.seed = nl_harness_seed(r);
  nl_error err;

  /* Fig. 10: exemplar, synthesis, edited synthesis, solid slices. */
  nl_image *ex = nl_byexample_exemplar("granite", size, nl_seed_stream(seed, "l4.exemplar", 0));
  nl_byexample_params p;
  nl_byexample_params pe;
  if (nl_byexample_analyse(ex, NULL, &p, &err)) nl_harness_die(r, 1, "%s", err.msg);
  pe = p;
  nl_byexample_attenuate(&pe, q.nfine, q.factor);
  nl_image *syn = synth(r, &p, size, seed, 0, 0);
  nl_image *ed = synth(r, &pe, size, seed, 0, 0);
  nl_image *s0 = synth(r, &p, size, seed, 1, 0.0);
  nl_image *s1 = synth(r, &p, size, seed, 1, size / 4.0);
  const nl_image *panels[] = {ex, syn, ed, s0, s1};
  const char *labels[] = {"(a) exemplar", "(b) synthesis", "(c) edited", "(d) solid z=0",
                          "(d') z=size/4"};
  nl_study_montage(r, panels, labels, 5, 5, "Fig. 10: editing and solid extrapolation",
                   "editing.png");

  /* Editing acts on the spectrum: luminance band power of (c) over (b) and
   * of the bands removed over (b), with and without histogram matching, and
   * solid slices against the 2D synthesis; K seeds (replicate 0 is the figure's). */
  q.K = nl_harness_seeds(r);
  l4_edit *rep = nl_xcalloc((size_t)q.K, sizeof *rep);
  l4_edit *rep1 = nl_xcalloc((size_t)q.K, sizeof *rep1); /* the control: factor 1 */
  for (int s = 0; s < q.K; s++) {
    unsigned long sk = nl_seed_replicate(seed, s);
    nl_image *exk = nl_byexample_exemplar("granite", size, nl_seed_stream(sk, "l4.exemplar", 0));
    if (l4_edit_replicate(exk, q.nfine, q.factor, sk, &rep[s], &err) ||
        l4_edit_replicate(exk, q.nfine, 1.0, sk, &rep1[s], &err))
      nl_harness_die(r, 1, "%s", err.msg);
    nl_image_free(exk);
    nl_harness_progress(r, (s + 1.0) / q.K, "seeds");
  }
  q.edit = l4_edit_tables(rep, q.K, q.nfine, q.factor, &q.solid, &q.summary);
  nl_harness_write_table(r, q.edit, "editing.tsv");
  nl_harness_write_table(r, q.solid, "solid.tsv");
  nl_harness_write_table(r, q.summary, "editing_summary.tsv");
  size_t n = (size_t)size * size;

  /* Fig. 12: morph clouds -> granite. */
  nl_image *ex2 = nl_byexample_exemplar("clouds", size, nl_seed_stream(seed, "l4.exemplar2", 0));
  nl_byexample_params pc;
  if (nl_byexample_analyse(ex2, NULL, &pc, &err)) nl_harness_die(r, 1, "%s", err.msg);
  const char *mcols[] = {"t", "det", "orth_err", "mean_r", "mean_g", "mean_b"};
  q.morph = nl_table_alloc(6, mcols);
  nl_image *seq[5];
  const char *tl[5] = {"t = 0", "t = 0.25", "t = 0.5", "t = 0.75", "t = 1"};
  for (int i = 0; i < 5; i++) {
    nl_byexample_params m;
    double t = i / 4.0;
    double det;
    double orth;
    if (nl_byexample_morph(&pc, &p, t, &m, &err)) nl_harness_die(r, 1, "%s", err.msg);
    nl_byexample_rotation_error((const double(*)[3])m.matrix, &det, &orth);
    seq[i] = synth(r, &m, size, seed, 0, 0);
    double mean[3] = {0};
    for (size_t j = 0; j < n; j++)
      for (int ch = 0; ch < 3; ch++) mean[ch] += seq[i]->data[3 * j + ch] / (double)n;
    nl_table_append(q.morph, "dddddd", t, det, orth, mean[0], mean[1], mean[2]);
  }
  nl_harness_write_table(r, q.morph, "morph.tsv");
  nl_study_montage(r, (const nl_image *const *)seq, tl, 5, 5,
                   "Fig. 12: morphing clouds into granite", "morph.png");

  q.claims = l4_verdicts(&q, rep, rep1);
  l4_report(&q);
  nl_image *all[] = {ex, syn, ed, s0, s1, ex2};
  for (int i = 0; i < 6; i++) nl_image_free(all[i]);
  for (int i = 0; i < 5; i++) nl_image_free(seq[i]);
  nl_table_free(q.edit);
  nl_table_free(q.solid);
  nl_table_free(q.summary);
  nl_table_free(q.morph);
  nl_table_free(q.claims);
  free(rep);
  free(rep1);
  nl_harness_check_measured(r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(r);
}
