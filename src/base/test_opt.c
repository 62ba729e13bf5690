/* Tests of the option parser (nl_opt_*): both GNU spellings of a value,
 * prefixes, two-value options, positional words in place, "--", and the
 * one-line messages for unknown, ambiguous, missing and unwanted values. */
#include "base/nl_base.h"
#include "nl_test.h"

#include <string.h>

static const nl_opt_spec spec[] = {
  {"size", 0, 1}, {"seed", 0, 1}, {"seeds", 0, 1}, {"uniform", 0, 2}, {"all", 0, 0},
  {"out", 'o', 1}, {"help", 'h', 0}, {NULL, 0, 0}};

/* Parses words (NULL-ended) and writes "name=v0,v1;" or "+word;" per item
 * into out, or "!message" at the first error. */
static void run(const char **words, char *out, size_t cap)
{
  char *argv[32];
  int argc = 0;
  argv[argc++] = (char *)"prog";
  for (int i = 0; words[i]; i++) argv[argc++] = (char *)words[i];
  argv[argc] = NULL;
  nl_opt_parser p;
  nl_error err;
  nl_opt_begin(&p, argc, argv, 1, spec);
  out[0] = 0;
  for (int k; (k = nl_opt_next(&p, &err)) != NL_OPT_END;) {
    size_t u = strlen(out);
    if (k == NL_OPT_ERROR) { snprintf(out + u, cap - u, "!%s", err.msg); break; }
    if (k == NL_OPT_POSITIONAL) snprintf(out + u, cap - u, "+%s;", p.value[0]);
    else snprintf(out + u, cap - u, "%s=%s,%s;", p.name, p.value[0] ? p.value[0] : "",
                  p.value[1] ? p.value[1] : "");
  }
  nl_opt_end(&p);
}

#define EXPECT(want, ...) do { const char *w_[] = {__VA_ARGS__, NULL}; char o_[512]; \
  run(w_, o_, sizeof o_); if (strcmp(o_, want)) fprintf(stderr, "got '%s'\n", o_); \
  NL_CHECK(strcmp(o_, want) == 0); } while (0)

NL_TEST(values_both_spellings_and_positionals_in_place)
{
  EXPECT("+a;--size=64,;--size=65,;+b;", "a", "--size=64", "--size", "65", "b");
  EXPECT("--size=-3,;", "--size", "-3");                    /* a negative value */
  EXPECT("+-;-o=x.png,;-o=y,;", "-", "-o", "x.png", "-oy"); /* '-' is stdin */
  EXPECT("--uniform=-1,2;+f;", "--uniform", "-1", "2", "f");
  EXPECT("--uniform=0,1;", "--uniform=0", "1");
  EXPECT("--all=,;+--all;+x;", "--all", "--", "--all", "x");
  EXPECT("--seeds=3,;--seed=4,;", "--seeds", "3", "--seed", "4");  /* exact beats prefix */
  EXPECT("--uniform=0,1;", "--un", "0", "1");                      /* unique prefix */
}

NL_TEST(errors_are_one_line_naming_the_option)
{
  EXPECT("!--bogus: unknown option", "--bogus");
  EXPECT("!--bogus: unknown option", "--bogus=3");
  EXPECT("!-x: unknown option", "-x");
  EXPECT("+a;!--size: missing value", "a", "--size");
  EXPECT("!-o: missing value", "-o");
  EXPECT("!--uniform: needs 2 values", "--uniform", "0");
  EXPECT("!--all: takes no value", "--all=1");
  EXPECT("!--s: ambiguous option (--size, --seed, --seeds)", "--s", "1");
}

NL_TEST(a_second_parser_starts_afresh)
{
  EXPECT("--size=1,;", "--size", "1");
  EXPECT("+q;--size=2,;", "q", "--size=2");
}

int main(void) { return nl_test_run(); }
