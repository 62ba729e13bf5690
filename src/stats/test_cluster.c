/* Tests of nl_cluster.h against scipy.cluster.hierarchy 1.10
 * (tests/reference/make_stats_vectors.py: 200 points in 6-D, 5 blobs).
 * Tolerances: merge heights 1e-12 relative (distances are summed in another
 * order than pdist's); merged ids and sizes exact; flat-cluster labels exact
 * (we number clusters in scipy's order; a relabelling would also be a
 * correct answer, but equal labels are the stronger check).
 */
#include "stats/nl_cluster.h"
#include "nl_test.h"
#include "test_vectors.h"

#include <string.h>

static const char *methods[] = {"single", "complete", "average"};

NL_TEST(linkage_matches_scipy)
{
  size_t n, d;
  double *x = vec_matrix("hclust_X.tsv", &n, &d), *Z = nl_xmalloc((n - 1) * 4 * sizeof(double));
  for (int m = 0; m < 3; m++) {
    nl_cluster_linkage_method lm;
    NL_CHECK(nl_cluster_linkage_method_parse(methods[m], &lm, NULL) == NL_OK);
    NL_CHECK(nl_cluster_linkage(x, n, d, lm, Z, NULL) == NL_OK);
    char name[64];
    snprintf(name, sizeof name, "hclust_%s_Z.tsv", methods[m]);
    nl_table *t = vec_read(name);
    NL_CHECK(t->nrows == n - 1);
    int bad = 0;
    for (size_t i = 0; i + 1 < n; i++) {
      bad += Z[4 * i] != nl_table_get(t, i, 0) || Z[4 * i + 1] != nl_table_get(t, i, 1);
      bad += !vec_close(Z[4 * i + 2], nl_table_get(t, i, 2), 1e-12, 0);
      bad += Z[4 * i + 3] != nl_table_get(t, i, 3);
    }
    if (bad) fprintf(stderr, "  %s: %d mismatches\n", methods[m], bad);
    NL_CHECK(bad == 0);
    nl_table_free(t);
  }
  free(x);
  free(Z);
}

NL_TEST(fcluster_matches_scipy)
{
  size_t n, d;
  double *x = vec_matrix("hclust_X.tsv", &n, &d), *Z = nl_xmalloc((n - 1) * 4 * sizeof(double));
  int *lab = nl_xmalloc(n * sizeof(int));
  for (int m = 0; m < 3; m++) {
    nl_cluster_linkage_method lm = (nl_cluster_linkage_method)m;
    nl_cluster_linkage(x, n, d, lm, Z, NULL);
    char name[64];
    snprintf(name, sizeof name, "hclust_%s_labels.tsv", methods[m]);
    nl_table *t = vec_read(name);
    for (size_t c = 0; c < t->ncols; c++) {
      size_t k;
      if (strncmp(t->names[c], "cut_", 4) == 0)
        NL_CHECK(nl_cluster_fcluster_distance(Z, n, atof(t->names[c] + 4), lab, &k, NULL) == NL_OK);
      else
        NL_CHECK(nl_cluster_fcluster_maxclust(Z, n, (size_t)atol(t->names[c] + 9), lab, &k, NULL) == NL_OK);
      int bad = 0, kmax = 0;
      for (size_t i = 0; i < n; i++) {
        bad += lab[i] != (int)nl_table_get(t, i, c);
        kmax = lab[i] > kmax ? lab[i] : kmax;
      }
      if (bad) fprintf(stderr, "  %s %s: %d labels differ\n", methods[m], t->names[c], bad);
      NL_CHECK(bad == 0 && (size_t)kmax == k);
    }
    nl_table_free(t);
  }
  free(x); free(Z); free(lab);
}

NL_TEST(bad_input)
{
  nl_error err;
  double x[] = {0, 1, NAN, 2}, Z[8];
  int lab[3];
  NL_CHECK(nl_cluster_linkage(x, 1, 2, NL_LINKAGE_SINGLE, Z, &err) == NL_EINVAL);
  NL_CHECK(nl_cluster_linkage(x, 2, 2, NL_LINKAGE_SINGLE, Z, &err) == NL_EINVAL);
  double y[] = {0, 1, 3};
  NL_CHECK(nl_cluster_linkage(y, 3, 1, NL_LINKAGE_AVERAGE, Z, &err) == NL_OK);
  NL_CHECK(nl_cluster_fcluster_distance(Z, 3, -1.0, lab, NULL, &err) == NL_EINVAL && strstr(err.msg, ">= 0"));
  NL_CHECK(nl_cluster_fcluster_maxclust(Z, 3, 0, lab, NULL, &err) == NL_EINVAL);
  nl_cluster_linkage_method m;
  NL_CHECK(nl_cluster_linkage_method_parse("median", &m, &err) == NL_EINVAL);
  NL_CHECK(nl_cluster_linkage_method_parse("ward", &m, &err) == NL_OK && m == NL_LINKAGE_WARD);
}

/* Ward on four points of a line, worked by hand: {0,1} and {10,11} merge at
 * sqrt(2 * 0.5) = 1 each (the height is sqrt(2 x the increase in the sum
 * of squares, 1/2)); the last merge joins two pairs whose centres are 10
 * apart: increase 2*2/4 * 100 = 100, height sqrt(200). */
NL_TEST(ward_by_hand)
{
  double x[] = {0, 1, 10, 11}, Z[12];
  nl_error err;
  NL_CHECK(nl_cluster_linkage(x, 4, 1, NL_LINKAGE_WARD, Z, &err) == NL_OK);
  NL_CHECK_NEAR(Z[2], 1.0, 1e-15);
  NL_CHECK_NEAR(Z[6], 1.0, 1e-15);
  NL_CHECK_NEAR(Z[10], sqrt(200.0), 1e-13);
  NL_CHECK(Z[11] == 4.0);
}

/* 3 million rows need ~36 TB of distances: refused at once with the size
 * named, instead of running for minutes (13.7). */
NL_TEST(linkage_refuses_what_the_machine_cannot_hold)
{
  size_t n = 3000000;
  double *x = calloc(n, sizeof *x);
  double *Z = malloc(4 * sizeof *Z);   /* never written: refused first */
  nl_error err = {{0}};
  NL_CHECK(nl_cluster_linkage(x, n, 1, NL_LINKAGE_COMPLETE, Z, &err) == NL_ENOMEM);
  NL_CHECK(strstr(err.msg, "3000000 rows need 36 TB for the distance matrix; this machine has") != NULL);
  if (!strstr(err.msg, "36 TB")) fprintf(stderr, "  %s\n", err.msg);
  free(x); free(Z);
}

int main(void) { return nl_test_run(); }
