#include "abi/nl_abi.h"
#include "nl_test.h"

NL_TEST(sizes_and_offsets_are_the_compilers)
{
  NL_CHECK(nl_abi_sizeof("nl_basis", NULL) == sizeof(nl_basis));
  NL_CHECK(nl_abi_sizeof("nl_error", NULL) == sizeof(nl_error));
  NL_CHECK(nl_abi_sizeof("nl_cheng_eval", NULL) == sizeof(nl_cheng_eval));
  NL_CHECK(nl_abi_offsetof("nl_basis", "gctbf.g") == (long)offsetof(nl_basis, gctbf.g));
  NL_CHECK(nl_abi_offsetof("nl_basis_options", "tile") == (long)offsetof(nl_basis_options, tile));
  NL_CHECK(nl_abi_offsetof("nl_gmm", "converged") == (long)offsetof(nl_gmm, converged));
  NL_CHECK(nl_abi_sizeof("nl_basis", "perm3") == sizeof(nl_noise_perm3));
  NL_CHECK(nl_abi_sizeof("nl_noise_basis", "bound") == sizeof(double));
}

NL_TEST(unknown_names)
{
  NL_CHECK(nl_abi_sizeof("nl_nothing", NULL) == 0);
  NL_CHECK(nl_abi_sizeof(NULL, NULL) == 0);
  NL_CHECK(nl_abi_sizeof("nl_basis", "nothing") == 0);
  NL_CHECK(nl_abi_offsetof("nl_basis", "nothing") == -1);
  NL_CHECK(nl_abi_offsetof("nl_nothing", "tile") == -1);
  NL_CHECK(nl_abi_offsetof("nl_basis", NULL) == -1);
}

int main(void) { return nl_test_run(); }
