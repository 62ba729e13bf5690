/* nl_opt.c - GNU-style option parsing for the tools (see nl_base.h).
 *
 * getopt_long in RETURN_IN_ORDER mode (optstring "-:..."): positional words
 * come back as option 1 where they stand, so nothing is permuted and a
 * second value can be taken from argv[optind] without confusing getopt.
 * opterr = 0 and the leading ':' keep getopt silent; the messages are ours. */
#include "base/nl_base.h"

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#define NL_OPT_LONG_BASE 256

void nl_opt_begin(nl_opt_parser *p, int argc, char **argv, int first, const nl_opt_spec *spec)
{
  size_t n = 0;
  while (spec[n].name) n++;
  struct option *lo = nl_xcalloc(n + 1, sizeof *lo);
  memset(p, 0, sizeof *p);
  p->argc = argc;
  p->argv = argv;
  p->spec = spec;
  p->longopts = lo;
  size_t w = 0;
  p->shorts[w++] = '-';
  p->shorts[w++] = ':';
  for (size_t i = 0; i < n; i++) {
    lo[i].name = spec[i].name;
    lo[i].has_arg = spec[i].nvalues ? required_argument : no_argument;
    lo[i].flag = NULL;
    lo[i].val = NL_OPT_LONG_BASE + (int)i;
    if (spec[i].short_name && w + 3 < sizeof p->shorts) {
      p->shorts[w++] = spec[i].short_name;
      if (spec[i].nvalues) p->shorts[w++] = ':';
    }
  }
  p->shorts[w] = 0;
  p->rest = -1;
  /* argv[first - 1] plays argv[0]; optind = 0 makes glibc start afresh. */
  p->argc = argc - (first - 1);
  p->argv = argv + (first - 1);
  optind = 0;
  opterr = 0;
}

void nl_opt_end(nl_opt_parser *p)
{
  free(p->longopts);
  p->longopts = NULL;
}

/* The option word as the user typed it, without "=value". */
static void word_name(nl_opt_parser *p, const char *word)
{
  size_t len = strcspn(word, "=");
  if (len >= sizeof p->name) len = sizeof p->name - 1;
  memcpy(p->name, word, len);
  p->name[len] = 0;
}

static int spec_of_short(const nl_opt_parser *p, int c)
{
  for (int i = 0; p->spec[i].name; i++) if (p->spec[i].short_name == c) return i;
  return -1;
}

/* Why getopt refused the word: unknown, ambiguous, or a value given to a flag. */
static int refuse(nl_opt_parser *p, nl_error *err)
{
  const char *word = optind - 1 < p->argc && optind > 1 ? p->argv[optind - 1] : "";
  if (optopt && optopt < NL_OPT_LONG_BASE && (word[0] != '-' || word[1] != '-')) {
    snprintf(p->name, sizeof p->name, "-%c", optopt);
    nl_fail(err, NL_EINVAL, "%s: unknown option", p->name);
    return NL_OPT_ERROR;
  }
  word_name(p, word);
  if (strncmp(word, "--", 2) == 0) {
    const char *stem = p->name + 2;
    size_t len = strlen(stem);
    char list[256] = "";
    int matches = 0;
    for (int i = 0; p->spec[i].name; i++) {
      if (strcmp(p->spec[i].name, stem) == 0 && p->spec[i].nvalues == 0 && strchr(word, '=')) {
        nl_fail(err, NL_EINVAL, "%s: takes no value", p->name);
        return NL_OPT_ERROR;
      }
      if (len && strncmp(p->spec[i].name, stem, len) == 0) {
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s--%s", matches ? ", " : "", p->spec[i].name);
        matches++;
      }
    }
    if (matches == 1 && strchr(word, '=')) {   /* an abbreviated flag given a value */
      nl_fail(err, NL_EINVAL, "%s: takes no value", p->name);
      return NL_OPT_ERROR;
    }
    if (matches > 1) {
      nl_fail(err, NL_EINVAL, "%s: ambiguous option (%s)", p->name, list);
      return NL_OPT_ERROR;
    }
  }
  nl_fail(err, NL_EINVAL, "%s: unknown option", p->name);
  return NL_OPT_ERROR;
}

int nl_opt_next(nl_opt_parser *p, nl_error *err)
{
  p->value[0] = p->value[1] = NULL;
  p->name[0] = 0;
  if (p->rest >= 0) {
    if (p->rest >= p->argc) return NL_OPT_END;
    p->value[0] = p->argv[p->rest++];
    return NL_OPT_POSITIONAL;
  }
  int longindex = -1;
  optopt = 0;
  int c = getopt_long(p->argc, p->argv, p->shorts, (const struct option *)p->longopts, &longindex);
  if (c == -1) {
    /* "--" or the end: what is left is positional */
    p->rest = optind;
    return nl_opt_next(p, err);
  }
  if (c == 1) { p->value[0] = optarg; return NL_OPT_POSITIONAL; }
  if (c == '?') return refuse(p, err);
  if (c == ':') {
    const char *word = p->argv[optind - 1];
    if (optopt && optopt < NL_OPT_LONG_BASE && word[1] != '-') snprintf(p->name, sizeof p->name, "-%c", optopt);
    else if (optopt >= NL_OPT_LONG_BASE) snprintf(p->name, sizeof p->name, "--%s", p->spec[optopt - NL_OPT_LONG_BASE].name);
    else word_name(p, word);
    nl_fail(err, NL_EINVAL, "%s: missing value", p->name);
    return NL_OPT_ERROR;
  }
  int k = c >= NL_OPT_LONG_BASE ? c - NL_OPT_LONG_BASE : spec_of_short(p, c);
  if (k < 0) return refuse(p, err);
  if (c >= NL_OPT_LONG_BASE) snprintf(p->name, sizeof p->name, "--%s", p->spec[k].name);
  else snprintf(p->name, sizeof p->name, "-%c", c);
  p->value[0] = optarg;
  if (p->spec[k].nvalues == 2) {
    if (optind >= p->argc) {
      nl_fail(err, NL_EINVAL, "%s: needs 2 values", p->name);
      return NL_OPT_ERROR;
    }
    p->value[1] = p->argv[optind++];
  }
  return k;
}
