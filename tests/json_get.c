/* json_get - check that standard input is one JSON value (RFC 8259, strict:
 * no NaN, no trailing commas, no bare words but true, false and null) and
 * print the values at the paths given, one line each.
 *
 *   json_get PATH... < FILE.json
 *     PATH is "." (the whole value) or keys and array indices joined by dots:
 *     Z.0.2 is the third number of the first row of Z.
 *     Printed: a number, true, false or null as written; a string's raw
 *     contents; "array N" or "object N" with the number of elements.
 * Exits 1 with one line on stderr when the input is not JSON or a path is
 * missing, 2 on a malformed call. The test scripts' JSON instrument: the
 * suite has no Python and no jq.
 */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
  const char *path;   /* the wanted path, or NULL */
  const char *start, *end;
  int kind;           /* 0 not found, 's' string, 'n' scalar, '[' array, '{' object */
  size_t count;
} want;

static const char *text;

static void fail(const char *p, const char *what)
{
  fprintf(stderr, "json_get: not JSON at byte %ld: %s\n", (long)(p - text), what);
  exit(1);
}

static const char *ws(const char *p)
{
  while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
  return p;
}

static const char *string(const char *p)
{
  if (*p++ != '"') fail(p - 1, "expected a string");
  for (;;) {
    unsigned char c = (unsigned char)*p++;
    if (c == '"') return p;
    if (c < 0x20) fail(p - 1, "control character or end of input in a string");
    if (c == '\\') {
      char e = *p++;
      if (e == 'u') {
        for (int i = 0; i < 4; i++)
          if (!isxdigit((unsigned char)*p++)) fail(p - 1, "bad \\u escape");
      } else if (!strchr("\"\\/bfnrt", e) || !e) {
        fail(p - 1, "bad escape");
      }
    }
  }
}

static const char *number(const char *p)
{
  if (*p == '-') p++;
  if (*p == '0') p++;
  else if (isdigit((unsigned char)*p)) while (isdigit((unsigned char)*p)) p++;
  else fail(p, "expected a value");
  if (*p == '.') {
    p++;
    if (!isdigit((unsigned char)*p)) fail(p, "digits expected after '.'");
    while (isdigit((unsigned char)*p)) p++;
  }
  if (*p == 'e' || *p == 'E') {
    p++;
    if (*p == '+' || *p == '-') p++;
    if (!isdigit((unsigned char)*p)) fail(p, "digits expected in the exponent");
    while (isdigit((unsigned char)*p)) p++;
  }
  return p;
}

/* Does the path's next component equal [k, k + len)? Then *rest is after it. */
static int component(const char *path, const char *k, size_t len, const char **rest)
{
  size_t n = strcspn(path, ".");
  if (n != len || strncmp(path, k, len)) return 0;
  *rest = path[n] ? path + n + 1 : path + n;
  return 1;
}

/* Parses one value at p; path is what is left of the wanted path below this
 * value ("" = this value), or NULL when it is not on the way. */
static const char *value(const char *p, const char *path, want *w)
{
  p = ws(p);
  const char *start = p;
  int kind = 'n';
  size_t count = 0;
  if (*p == '{' || *p == '[') {
    char close = *p == '{' ? '}' : ']';
    kind = *p;
    p = ws(p + 1);
    if (*p != close) {
      for (;;) {
        const char *sub = NULL;
        if (kind == '{') {
          const char *k = ws(p);
          p = ws(string(k));
          if (*p++ != ':') fail(p - 1, "expected ':'");
          if (path && *path) {   /* the key ends before the blanks and the colon */
            const char *e = k + 1;
            while (*e != '"') e += *e == '\\' ? 2 : 1;
            if (!component(path, k + 1, (size_t)(e - k - 1), &sub)) sub = NULL;
          }
        } else if (path && *path) {
          char idx[32];
          snprintf(idx, sizeof idx, "%zu", count);
          if (!component(path, idx, strlen(idx), &sub)) sub = NULL;
        }
        p = ws(value(p, sub, w));
        count++;
        if (*p == ',') { p++; continue; }
        if (*p != close) fail(p, kind == '{' ? "expected ',' or '}'" : "expected ',' or ']'");
        break;
      }
    }
    p++;
  } else if (*p == '"') {
    kind = 's';
    p = string(p);
  } else if (!strncmp(p, "true", 4) || !strncmp(p, "null", 4)) {
    p += 4;
  } else if (!strncmp(p, "false", 5)) {
    p += 5;
  } else {
    p = number(p);
  }
  if (path && !*path) {
    w->start = start;
    w->end = p;
    w->kind = kind;
    w->count = count;
  }
  return p;
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fputs("usage: json_get PATH... < FILE.json\n", stderr);
    return 2;
  }
  size_t cap = 1 << 16, len = 0, got;
  char *buf = malloc(cap);
  while (buf && (got = fread(buf + len, 1, cap - len - 1, stdin)) > 0) {
    len += got;
    if (len + 1 == cap) buf = realloc(buf, cap *= 2);
  }
  if (!buf) return 2;
  buf[len] = 0;
  if (strlen(buf) != len) { fputs("json_get: NUL byte in the input\n", stderr); return 1; }
  text = buf;
  for (int i = 1; i < argc; i++) {
    want w = {0};
    const char *path = strcmp(argv[i], ".") ? argv[i] : "";
    const char *end = ws(value(buf, path, &w));
    if (*end) fail(end, "text after the value");
    if (!w.kind) {
      fprintf(stderr, "json_get: no value at %s\n", argv[i]);
      return 1;
    }
    if (w.kind == '[' || w.kind == '{')
      printf("%s %zu\n", w.kind == '[' ? "array" : "object", w.count);
    else if (w.kind == 's') printf("%.*s\n", (int)(w.end - w.start - 2), w.start + 1);
    else printf("%.*s\n", (int)(w.end - w.start), w.start);
  }
  free(buf);
  return 0;
}
