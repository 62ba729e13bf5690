/* nl_abi.c - the table behind nl_abi_sizeof and nl_abi_offsetof: every
 * struct a binding mirrors, with each member the mirror names. */
#include "abi/nl_abi.h"

#include <stddef.h>
#include <string.h>

typedef struct {
  const char *type, *member;   /* member NULL: the type itself */
  size_t offset, size;
} abi_entry;

/* T: the type's size; M: a member's offset and size, member a designator. */
#define T(t) {#t, NULL, 0, sizeof(t)},
#define M(t, m) {#t, #m, offsetof(t, m), sizeof(((t *)0)->m)},
static const abi_entry abi[] = {
  T(nl_error) M(nl_error, msg)
  T(nl_noise_basis) M(nl_noise_basis, row) M(nl_noise_basis, ctx) M(nl_noise_basis, bound)
  T(nl_noise_octaves) M(nl_noise_octaves, n) M(nl_noise_octaves, turbulence)
    M(nl_noise_octaves, freq) M(nl_noise_octaves, amp)
  T(nl_noise_window) M(nl_noise_window, x0) M(nl_noise_window, y0) M(nl_noise_window, z)
    M(nl_noise_window, size) M(nl_noise_window, w) M(nl_noise_window, h)
  T(nl_cellular_gctbf) M(nl_cellular_gctbf, n) M(nl_cellular_gctbf, c) M(nl_cellular_gctbf, cc)
  T(nl_basis) M(nl_basis, noise) M(nl_basis, kind) M(nl_basis, grad2) M(nl_basis, perm3)
    M(nl_basis, cell) M(nl_basis, gctbf.cell) M(nl_basis, gctbf.g) M(nl_basis, tile)
  T(nl_basis_options) M(nl_basis_options, table_size) M(nl_basis_options, reference)
    M(nl_basis_options, lambda) M(nl_basis_options, points) M(nl_basis_options, count)
    M(nl_basis_options, terms) M(nl_basis_options, tile)
  T(nl_basis_sum_options) M(nl_basis_sum_options, octaves) M(nl_basis_sum_options, gain)
    M(nl_basis_sum_options, lacunarity) M(nl_basis_sum_options, amplitude)
    M(nl_basis_sum_options, stripes)
  T(nl_noise_grad2) M(nl_noise_grad2, m) M(nl_noise_grad2, angle) M(nl_noise_grad2, gx)
    M(nl_noise_grad2, gy) M(nl_noise_grad2, perm)
  T(nl_gmm_options) M(nl_gmm_options, covariance) M(nl_gmm_options, tol)
    M(nl_gmm_options, reg_covar) M(nl_gmm_options, max_iter) M(nl_gmm_options, seed)
    M(nl_gmm_options, init_labels) M(nl_gmm_options, threads) M(nl_gmm_options, memo)
    M(nl_gmm_options, workspace)
  T(nl_gmm) M(nl_gmm, k) M(nl_gmm, d) M(nl_gmm, covariance) M(nl_gmm, weights) M(nl_gmm, means)
    M(nl_gmm, covs) M(nl_gmm, chol) M(nl_gmm, prec) M(nl_gmm, n) M(nl_gmm, loglik) M(nl_gmm, aic)
    M(nl_gmm, bic) M(nl_gmm, nparams) M(nl_gmm, iterations) M(nl_gmm, converged)
  T(nl_image) M(nl_image, width) M(nl_image, height) M(nl_image, channels) M(nl_image, data)
  T(nl_byexample_params) M(nl_byexample_params, channels) M(nl_byexample_params, nbands)
    M(nl_byexample_params, tile) M(nl_byexample_params, histogram) M(nl_byexample_params, sigma2)
    M(nl_byexample_params, mean) M(nl_byexample_params, matrix) M(nl_byexample_params, hist_kind)
    M(nl_byexample_params, nhist) M(nl_byexample_params, hist) M(nl_byexample_params, w)
    M(nl_byexample_params, calibrate) M(nl_byexample_params, target) M(nl_byexample_params, corr)
  T(nl_byexample_options) M(nl_byexample_options, decorrelate) M(nl_byexample_options, histogram)
    M(nl_byexample_options, sigma2) M(nl_byexample_options, tile)
    M(nl_byexample_options, hist_kind) M(nl_byexample_options, calibrate)
  T(nl_byexample_synth_options) M(nl_byexample_synth_options, scale)
    M(nl_byexample_synth_options, solid) M(nl_byexample_synth_options, z)
    M(nl_byexample_synth_options, spline)
  T(nl_cheng_schedule) M(nl_cheng_schedule, n_temps) M(nl_cheng_schedule, moves_per_var)
    M(nl_cheng_schedule, t_decades) M(nl_cheng_schedule, p0) M(nl_cheng_schedule, stall)
  T(nl_cheng_config) M(nl_cheng_config, stat) M(nl_cheng_config, con) M(nl_cheng_config, w1)
    M(nl_cheng_config, w2) M(nl_cheng_config, octaves) M(nl_cheng_config, f1)
    M(nl_cheng_config, a1) M(nl_cheng_config, m) M(nl_cheng_config, chisq_bins)
    M(nl_cheng_config, propagate) M(nl_cheng_config, sched) M(nl_cheng_config, literal)
    M(nl_cheng_config, amp_vary) M(nl_cheng_config, amp_range) M(nl_cheng_config, log_gain)
    M(nl_cheng_config, origin)
  T(nl_cheng_eval) M(nl_cheng_eval, e_ks) M(nl_cheng_eval, p_ks) M(nl_cheng_eval, kuiper_v)
    M(nl_cheng_eval, p_kuiper) M(nl_cheng_eval, chi2) M(nl_cheng_eval, p_chi2)
    M(nl_cheng_eval, e_con) M(nl_cheng_eval, e) M(nl_cheng_eval, rms_con)
    M(nl_cheng_eval, roughness) M(nl_cheng_eval, r_pattern) M(nl_cheng_eval, e_con_offset)
    M(nl_cheng_eval, e_con_contrast) M(nl_cheng_eval, e_con_shape) M(nl_cheng_eval, seam_ratio)
    M(nl_cheng_eval, contrast) M(nl_cheng_eval, e_con_const) M(nl_cheng_eval, e_con_random)
    M(nl_cheng_eval, log_gain) M(nl_cheng_eval, moves) M(nl_cheng_eval, cpu_seconds)
  T(nl_cheng_pattern) M(nl_cheng_pattern, grid) M(nl_cheng_pattern, n) M(nl_cheng_pattern, x)
    M(nl_cheng_pattern, y) M(nl_cheng_pattern, d) M(nl_cheng_pattern, cell)
  T(nl_table) M(nl_table, nrows) M(nl_table, ncols) M(nl_table, names) M(nl_table, num)
    M(nl_table, text) M(nl_table, cap)
  T(nl_stats_dist) M(nl_stats_dist, kind) M(nl_stats_dist, loc) M(nl_stats_dist, scale)
    M(nl_stats_dist, shape) M(nl_stats_dist, m) M(nl_stats_dist, x) M(nl_stats_dist, F)
  T(nl_stats_ks_result) M(nl_stats_ks_result, d) M(nl_stats_ks_result, d_plus)
    M(nl_stats_ks_result, d_minus) M(nl_stats_ks_result, p) M(nl_stats_ks_result, n)
    M(nl_stats_ks_result, n2) M(nl_stats_ks_result, method)
  T(nl_stats_kuiper_result) M(nl_stats_kuiper_result, v) M(nl_stats_kuiper_result, d_plus)
    M(nl_stats_kuiper_result, d_minus) M(nl_stats_kuiper_result, p) M(nl_stats_kuiper_result, n)
  T(nl_stats_chisq_result) M(nl_stats_chisq_result, chi2) M(nl_stats_chisq_result, df)
    M(nl_stats_chisq_result, p) M(nl_stats_chisq_result, min_expected)
    M(nl_stats_chisq_result, low_expected) M(nl_stats_chisq_result, n)
    M(nl_stats_chisq_result, k)
};
#undef T
#undef M

static const abi_entry *find(const char *type, const char *member)
{
  for (size_t k = 0; k < sizeof abi / sizeof *abi; k++)
    if (strcmp(abi[k].type, type) == 0 &&
        (member ? abi[k].member && strcmp(abi[k].member, member) == 0 : !abi[k].member))
      return &abi[k];
  return NULL;
}

size_t nl_abi_sizeof(const char *type, const char *member)
{
  const abi_entry *e = type ? find(type, member) : NULL;
  return e ? e->size : 0;
}

long nl_abi_offsetof(const char *type, const char *member)
{
  const abi_entry *e = type && member ? find(type, member) : NULL;
  return e ? (long)e->offset : -1;
}
