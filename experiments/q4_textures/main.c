/* Q4 - Qin & Yang 2000 Fig. 5 and 6 (sec. 4.3): the cloud pattern of eq. 7
 * for Perlin noise and five GCTBF combinations, and the textures of Fig. 6:
 * marble sum (-1)^i F_i + sum (-1)^(i+j) F_i F_j, wood F1 - F1F1 and
 * F3 - F3F3, sky F1F2 + F2F3 and F1, flame F1. */
#include "cellular/nl_cellular.h"
#include "harness/nl_harness.h"
#include "q4.h"
#include "wood.h"
#include "study/nl_study.h"
#include "texture/nl_texture.h"

#include <math.h>
#include <string.h>

/* Fig. 5's combinations are drawn, not named: our reading. */
/* Eq. 7 needs GCTBF around 1/2 to be partly cloudy (1 - 2 GCTBF changes
 * sign there); small ones such as F1F1 or F2 - F1 saturate to cloud. */
static const char *cloud_combos[5] = { "F1", "F2", "F1 + F1F1", "F1 + F1F2", "F1F2 + F2F3" };
static const char *marble =
    "-F1 + F2 - F3 + F4 + F1F1 - F1F2 + F1F3 - F1F4 - F2F1 + F2F2 - F2F3 + F2F4"
    " + F3F1 - F3F2 + F3F3 - F3F4 - F4F1 + F4F2 - F4F3 + F4F4";

enum { CLOUD = NL_GCTBF_CLOUD, FLAME = NL_GCTBF_FLAME, PLAIN = NL_GCTBF_PLAIN };

int main(int argc, char **argv)
{
  q4 q = { 0 };
  q.r = nl_harness_begin("q4_textures", "Q4 - GCTBF cloud, marble, wood and flame textures", argc,
                         argv);
  q.size = (int)nl_harness_param_int(q.r, "size", nl_harness_quick(q.r) ? 96 : 256, 8, 4096,
                                     "side in pixels of the texture images (quick 96)");
  q.octaves = (int)nl_harness_param_int(
      q.r, "octaves", 4, 0, 30,
      "octaves added above the first in the cloud and texture sums (0 = one octave)");
  q.k = nl_harness_param(q.r, "k", 2.0, 1e-3, 1e3,
                         "scale k between successive octaves of the GCTBF cloud "
                         "(Qin & Yang eq. 7)");
  q.rings = nl_harness_param(q.r, "wood_rings", 6.0, 0.1, 100,
                             "wood: rings per unit of distance to the tree's axis");
  q.turb = nl_harness_param(q.r, "wood_turb", 8.0, 0, 1000,
                            "wood: rings added per unit of the basis (its amplitude)");
  nl_harness_params_done(q.r);
  q.seeds = nl_harness_seeds(q.r);
  q.win = (nl_noise_window){ 0, 0, 0.5, 2.0, q.size, q.size };
  const char *cols[] = { "texture", "method", "gctbf", "mean", "sd" };
  q.t = nl_table_alloc(5, cols);

  /* Fig. 5: eq. 7 over Perlin noise and the five combinations. */
  nl_image *clouds[6];
  const char *clabels[6] = { "Perlin" };
  clouds[0] = q4_texture(&q, CLOUD, "cloud Perlin", NULL, NULL, 0, 1);
  for (int k = 0; k < 5; k++) {
    clabels[k + 1] = cloud_combos[k];
    clouds[k + 1] = q4_texture(&q, CLOUD, "cloud", cloud_combos[k], NULL, 0, 1);
  }
  nl_study_montage(q.r, (const nl_image *const *)clouds, clabels, 6, 3, "Fig. 5: eq. 7 clouds",
                   "clouds.png");

  /* Fig. 6: marble, wood (ramp reading, replaced below), sky and flame. */
  const float woodc[2][3] = { { 0.80f, 0.58f, 0.34f }, { 0.38f, 0.20f, 0.08f } };
  const double wpos[2] = { 0.0, 1.0 };
  const float firec[6][3] = { { 0, 0, 0 },           { 0, 0, 0 },           { 0.8f, 0.1f, 0.0f },
                              { 1.0f, 0.55f, 0.0f }, { 1.0f, 0.95f, 0.5f }, { 1.0f, 1.0f, 1.0f } };
  nl_texture_ramp mr = nl_texture_ramp_cellular_marble();
  nl_texture_ramp wr = nl_texture_ramp_linear(2, wpos, woodc);
  nl_texture_ramp fr = nl_texture_ramp_spline(6, firec);
  nl_image *tex[6];
  const char *tlabels[6] = { "marble",          "wood F1 - F1F1", "wood F3 - F3F3",
                             "sky F1F2 + F2F3", "sky F1",         "flame F1" };
  tex[0] = q4_texture(&q, PLAIN, "marble", marble, &mr, 0.0, 1.0);
  tex[1] = q4_texture(&q, PLAIN, "wood", "F1 - F1F1", &wr, 0.0, 0.25);
  tex[2] = q4_texture(&q, PLAIN, "wood", "F3 - F3F3", &wr, 0.0, 0.25);
  tex[3] = q4_texture(&q, CLOUD, "sky", "F1F2 + F2F3", NULL, 0, 1);
  tex[4] = q4_texture(&q, CLOUD, "sky", "F1", NULL, 0, 1);
  tex[5] = q4_texture(&q, FLAME, "flame", "F1", &fr, 0.2, 1.0);

  /* Wood: the usual solid wood shader (nl_texture_wood): the table a plank
   * whose axis runs along x, tilted into the board; the trunk cut across its
   * axis. Dark bands counted across the rings (middle column, row). */
  nl_texture_wood wd[2] = { { .axis_p = { 1.0, 1.0, 0.25 },
                              .axis_d = { 1.0, 0.08, 0.15 },
                              .ring_freq = q.rings,
                              .turb = q.turb },
                            { .axis_p = { 0.9, 1.1, 0.0 },
                              .axis_d = { 0.0, 0.0, 1.0 },
                              .ring_freq = q.rings,
                              .turb = q.turb } };
  q.wood = q4_wood_table();
  nl_image *wim[4];
  for (int i = 0; i < 2; i++) {
    nl_error err;
    memcpy(wd[i].light, woodc[0], sizeof woodc[0]);
    memcpy(wd[i].dark, woodc[1], sizeof woodc[1]);
    if (q4_wood(q.wood, i ? "trunk" : "table", i ? "F3 - F3F3" : "F1 - F1F1", q.k, &q.win, &wd[i],
                &wr, 0.0, 0.25, i == 0, q.size / 2, nl_harness_seed(q.r), q.seeds, &wim[2 * i + 1],
                &wim[2 * i], &err))
      nl_harness_die(q.r, 1, "%s", err.msg);
    nl_image_free(tex[1 + i]);
    tex[1 + i] = nl_image_convert(wim[2 * i + 1], 3);
  }
  const char *wl[4] = { "table: ramp", "table: rings", "trunk: ramp", "trunk: rings" };
  nl_study_montage(q.r, (const nl_image *const *)wim, wl, 4, 4,
                   "Wood: GCTBF through a ramp, and through a wood shader", "wood.png");
  nl_study_montage(q.r, (const nl_image *const *)tex, tlabels, 6, 3, "Fig. 6: GCTBF textures",
                   "textures.png");
  nl_harness_write_table(q.r, q.t, "textures.tsv");
  nl_harness_write_table(q.r, q.wood, "wood.tsv");
  /* Do Fig. 6's wood rings come from the GCTBF? (rings.tsv, the verdicts) */
  nl_table *rings = q4_wood_verdicts(&q);

  q4_report(&q);
  for (int k = 0; k < 6; k++) {
    nl_image_free(clouds[k]);
    nl_image_free(tex[k]);
  }
  for (int k = 0; k < 4; k++) nl_image_free(wim[k]);
  nl_table_free(q.t);
  nl_table_free(q.wood);
  nl_table_free(rings);
  nl_harness_check_measured(q.r, "*", 100); /* measured tolerances (nl_harness.h) */
  return nl_harness_end(q.r);
}
