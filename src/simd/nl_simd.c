/* nl_simd.c - the vector level (nl_simd.h): what the CPU supports, the
 * NL_NOISE_SIMD override, and the level every kernel table is picked by. */
#include "simd/nl_simd.h"
#include "base/nl_base.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const level_names[] = {"scalar", "sse2", "avx2", "avx512"};

const char *nl_simd_name(int level)
{
  return level >= 0 && level <= NL_SIMD_AVX512 ? level_names[level] : "unknown";
}

int nl_simd_from_name(const char *name)
{
  for (int l = 0; l <= NL_SIMD_AVX512; l++)
    if (name && strcmp(name, level_names[l]) == 0) return l;
  return -1;
}

int nl_simd_supported(int level)
{
#if !NL_SIMD_X86
  return level == NL_SIMD_SCALAR;
#else
  switch (level) {
  case NL_SIMD_SCALAR: case NL_SIMD_SSE2: return 1;
  case NL_SIMD_AVX2:
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2");
  case NL_SIMD_AVX512:
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
           __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl") &&
           __builtin_cpu_supports("avx512vbmi") && __builtin_cpu_supports("avx2");
  default: return 0;
  }
#endif
}

int nl_simd_best(void)
{
  int l = NL_SIMD_AVX512;
  while (!nl_simd_supported(l)) l--;
  return l;
}

static int simd_level = -1;   /* -1: not yet resolved */

int nl_simd_get(void)
{
  int l = __atomic_load_n(&simd_level, __ATOMIC_ACQUIRE);
  if (l >= 0) return l;
  l = nl_simd_best();
  const char *env = getenv("NL_NOISE_SIMD");
  if (env && *env && strcmp(env, "auto") != 0) {
    int want = nl_simd_from_name(env);
    if (want < 0)
      nl_message(stderr, "noiselab: NL_NOISE_SIMD=%s is not scalar|sse2|avx2|avx512|auto; using %s",
              env, nl_simd_name(l));
    else if (!nl_simd_supported(want))
      nl_message(stderr, "noiselab: this CPU cannot run NL_NOISE_SIMD=%s; using %s", env,
              nl_simd_name(l));
    else l = want;
  }
  __atomic_store_n(&simd_level, l, __ATOMIC_RELEASE);   /* racing first calls agree */
  return l;
}

nl_status nl_simd_set(int level)
{
  if (level < 0 || level > NL_SIMD_AVX512 || !nl_simd_supported(level)) return NL_EINVAL;
  __atomic_store_n(&simd_level, level, __ATOMIC_RELEASE);
  return NL_OK;
}
