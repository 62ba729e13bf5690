/* nl_abi.h - the layout of the library's public structs, by name, for
 * bindings that mirror them instead of compiling against the headers (the
 * Python package's ctypes Structures, python/noiselab/): a mirror checked
 * against these at load time cannot go stale in silence when a struct
 * gains, loses or reorders a member.
 *
 *   nl_abi_sizeof("nl_basis", NULL)              sizeof(nl_basis)
 *   nl_abi_sizeof("nl_basis", "perm3")           sizeof the member perm3
 *   nl_abi_offsetof("nl_basis", "gctbf.cell")    offsetof(nl_basis, gctbf.cell)
 *
 * The structs are those a binding of this repository mirrors (nl_abi.c
 * lists them, with the members the mirrors name); a nested member is named
 * by its designator ("gctbf.g"). Unknown names: 0 and -1. Sizes and
 * offsets together catch a member retyped within its padding.
 */
#ifndef NL_ABI_H
#define NL_ABI_H

#include "base/nl_base.h"
#include "basis/nl_basis.h"
#include "byexample/nl_byexample.h"
#include "cellular/nl_cellular.h"
#include "cheng/nl_cheng.h"
#include "image/nl_image.h"
#include "noise/nl_noise.h"
#include "stats/nl_gmm.h"
#include "stats/nl_stats.h"
#include "table/nl_table.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

size_t nl_abi_sizeof(const char *type, const char *member);
long nl_abi_offsetof(const char *type, const char *member);

#ifdef __cplusplus
}
#endif

#endif
