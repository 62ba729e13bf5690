/* libFuzzer target: the noise-by-example parameter file reader,
 * nl_byexample_params_load (src/byexample/nl_byexample_params.c). Loaded
 * parameters must satisfy the documented limits; they are saved and loaded
 * again and must come back bit for bit. */
#include "byexample/nl_byexample.h"
#include "nl_fuzz.h"

#include <math.h>

static void fail(const char *what)
{
  fprintf(stderr, "nl_fuzz: loaded parameters: %s\n", what);
  abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  const char *path = nl_fuzz_file(data, size, "params");
  nl_byexample_params p, q;
  nl_error err = {{0}};
  nl_status st = nl_byexample_params_load(path, &p, &err);
  nl_fuzz_check_error(st, &err);
  if (st != NL_OK) return 0;
  if (p.channels != 1 && p.channels != 3) fail("channels not 1 or 3");
  if (p.nbands < 1 || p.nbands > NL_WAVELET_MAX_BANDS) fail("bands out of range");
  if (p.tile < 8 || p.tile % 2) fail("tile not even or too small");
  if (!(p.sigma2 > 0) || !isfinite(p.sigma2)) fail("sigma2 not positive and finite");
  for (int c = 0; c < p.channels; c++) {
    for (int j = 0; j < p.nhist; j++)
      if (!isfinite(p.hist[c][j])) fail("histogram value not finite");
    for (int k = 0; k < p.nbands; k++)
      if (!(p.w[c][k] >= 0) || !isfinite(p.w[c][k])) fail("weight negative or not finite");
  }
  /* Round trip: save beside the input, load, compare. */
  const char *out = nl_fuzz_file((const uint8_t *)"", 0, "out");
  if (nl_byexample_params_save(&p, out, &err) || nl_byexample_params_load(out, &q, &err)) {
    fprintf(stderr, "nl_fuzz: round trip: %s\n", err.msg);
    abort();
  }
  if (memcmp(&p, &q, sizeof p)) fail("differ after save and load");
  return 0;
}
