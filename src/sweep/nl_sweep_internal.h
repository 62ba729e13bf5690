/* nl_sweep_internal.h - what the sweep module's files share and no caller
 * needs (not installed). */
#ifndef NL_SWEEP_INTERNAL_H
#define NL_SWEEP_INTERNAL_H

/* The whole file as a string (the caller frees), or NULL if it cannot be
 * opened. */
char *nl_sweep_slurp(const char *path);

#endif
