#!/usr/bin/env bash
# The installed library as another project uses it:
#  - `meson install --destdir` puts libnoiselab (shared and static), the
#    headers under include/noiselab/ and noiselab.pc in the destdir;
#  - every installed header compiles on its own with pkg-config's --cflags,
#    as C and as C++ (a public header that needs a private, uninstalled one
#    fails here, and so does one whose C a C++ compiler refuses or whose
#    calls lack extern "C": a C++ program calls one through a pointer, which
#    links only with C linkage);
#  - an outside C program, built with `pkg-config --cflags --libs noiselab`,
#    evaluates Perlin's improved noise, writes a table with nl_table, a PNG
#    (the library's own encoder) and a TIFF through the image module; the
#    values are checked by column name,
#    and the module must come from the destdir (found beside the installed
#    library, src/image/nl_image.c), not from the build tree;
#  - the same program linked statically (`pkg-config --static`) gives the
#    same table, and needs no libnoiselab.so.
# Args: BUILD_DIR OUTDIR. The build is installed as it is (--no-rebuild: the
# suite built it) under OUTDIR/dest, and pkg-config is pointed there with
# --define-variable=prefix (every path in noiselab.pc starts at ${prefix}).
set -euo pipefail
build="$(cd "$1" && pwd)" out="$2"
root="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=tests/tsv.sh
. "$root/tests/tsv.sh"
fail() { echo "cli_install: $*"; exit 1; }
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
rm -rf "$out"; mkdir -p "$out"
dest="$out/dest"

meson install -C "$build" --destdir "$dest" --no-rebuild --quiet >"$out/install.log" 2>&1 \
  || { cat "$out/install.log"; fail "meson install failed"; }
# Where it went: noiselab.pc names the prefix; its folder is LIBDIR/pkgconfig.
pcfile="$(find "$dest" -path '*/pkgconfig/noiselab.pc' | head -n 1)"
[ -n "$pcfile" ] || fail "no noiselab.pc installed (installed: $(cd "$dest" && find . -type f | sort | tr '\n' ' '))"
lib="$(dirname "$(dirname "$pcfile")")"
export PKG_CONFIG_PATH="$lib/pkgconfig"
prefix="$(pkg-config --variable=prefix noiselab)"
pc() { pkg-config --define-variable=prefix="$dest$prefix" "$@" noiselab; }
inc="$(pc --variable=includedir)"
for f in "$lib/libnoiselab.so" "$lib/libnoiselab.a" "$lib/noiselab/libnl_oiio.so" \
         "$inc/noiselab/noise/nl_noise.h" "$inc/noiselab/base/nl_base.h"; do
  [ -e "$f" ] || fail "not installed: ${f#"$dest"} (installed: $(cd "$dest" && find . -type f | sort | tr '\n' ' '))"
done
[ ! -e "$inc/noiselab/cheng/nl_cheng_internal.h" ] || fail "a private header was installed: nl_cheng_internal.h"
# The lab (harness, study, sweep: how the noiselab programs run, record and
# end) is not the library: none of its headers installed, none of its
# symbols exported, and the library calls nothing that changes how its host
# process ends (a signal disposition, an exit hook, exit itself).
for m in harness study sweep; do
  [ ! -e "$inc/noiselab/$m" ] || fail "the lab's headers were installed: include/noiselab/$m"
done
lab_syms="$(nm -D --defined-only "$lib/libnoiselab.so" | awk '$3 ~ /^nl_(harness|study|sweep|survey)_/ {print $3}' | head -n 3)"
[ -z "$lab_syms" ] || fail "libnoiselab exports the lab's symbols: $lab_syms"
ends="$(nm -D --undefined-only "$lib/libnoiselab.so" | awk '{sub(/@.*/, "", $2); print $2}' \
        | grep -xE 'exit|_exit|_Exit|quick_exit|atexit|__cxa_atexit|on_exit|signal|sigaction|sigset|bsd_signal' || true)"
[ -z "$ends" ] || fail "libnoiselab calls what ends or signals its host: ${ends//$'\n'/ }"
cflags="$(pc --cflags)" || fail "pkg-config --cflags noiselab failed"
libs="$(pc --libs)" || fail "pkg-config --libs noiselab failed"
slibs="$(pc --static --libs)" || fail "pkg-config --static --libs noiselab failed"
[[ "$cflags" == *"$inc/noiselab"* ]] || fail "--cflags does not point into the destdir: $cflags"
CC="${CC:-cc}" CXX="${CXX:-c++}"

# Every installed header on its own, in C and in C++.
n=0
while IFS= read -r h; do
  # shellcheck disable=SC2086  # pkg-config's flags are words
  printf '#include "%s"\n' "${h#"$inc/noiselab/"}" \
    | "$CC" -std=c11 -fsyntax-only -Wall -Werror $cflags -x c - 2>"$out/header.log" \
    || { cat "$out/header.log"; fail "installed header ${h#"$dest"} does not compile on its own"; }
  # shellcheck disable=SC2086
  printf '#include "%s"\nint main(void) { return 0; }\n' "${h#"$inc/noiselab/"}" \
    | "$CXX" -std=c++17 -fsyntax-only -Wall -Wextra -Werror $cflags -x c++ - 2>"$out/header.log" \
    || { cat "$out/header.log"; fail "installed header ${h#"$dest"} does not compile as C++"; }
  grep -q 'extern "C"' "$h" || fail "installed header ${h#"$dest"} has no extern \"C\" guard"
  n=$((n + 1))
done < <(find "$inc/noiselab" -name '*.h' | sort)
[ "$n" -ge 10 ] || fail "only $n headers installed"

# A C++ program that calls the library (out-of-line calls: C linkage, or the
# link fails) and gets the same value as the inline point call.
cat >"$out/outside.cpp" <<'CPP'
#include <noise/nl_noise.h>
#include <cstdio>
int main()
{
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  double row[1];
  nl_noise_perm3_row(&p, 3.14, 0.1, 42, 7, 1, row);
  std::printf("%.17g %.17g\n", row[0], nl_noise_perm3_eval(&p, 3.14, 42, 7));
  return row[0] == nl_noise_perm3_eval(&p, 3.14, 42, 7) ? 0 : 1;
}
CPP
# shellcheck disable=SC2086
"$CXX" -std=c++17 -Wall -Werror $cflags -o "$out/outside-cpp" "$out/outside.cpp" $libs \
  2>"$out/cxx.log" || { cat "$out/cxx.log"; fail "a C++ program does not build against libnoiselab"; }
LD_LIBRARY_PATH="$lib" "$out/outside-cpp" >"$out/cpp.log" 2>&1 \
  || fail "the C++ program's row and point call differ: $(cat "$out/cpp.log")"

cat >"$out/outside.c" <<'C'
/* An outside program: Perlin's improved noise on a few points, as a table. */
#include <noise/nl_noise.h>
#include <table/nl_table.h>
#include <image/nl_image.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
  if (argc < 2) { fprintf(stderr, "usage: outside TABLE [IMAGE...]\n"); return 2; }
  nl_noise_perm3 p;
  nl_noise_perm3_reference(&p);
  const char *cols[] = {"x", "y", "z", "noise"};
  nl_table *t = nl_table_alloc(4, cols);
  double pts[][3] = {{3.14, 42, 7}, {0, 0, 0}, {1, 2, 3}, {0.5, 0.5, 0.5}};
  for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++)
    nl_table_append(t, "dddd", pts[i][0], pts[i][1], pts[i][2],
                    nl_noise_perm3_eval(&p, pts[i][0], pts[i][1], pts[i][2]));
  double row[64];
  nl_noise_perm3_row(&p, 0.05, 0.1, 1.3, 2.7, 64, row);
  for (int k = 0; k < 64; k++) nl_table_append(t, "dddd", 0.05 + 0.1 * k, 1.3, 2.7, row[k]);
  nl_error err;
  if (nl_table_write(t, argv[1], &err)) { fprintf(stderr, "%s\n", err.msg); return 1; }
  nl_table_free(t);
  if (argc > 2) {
    nl_image *im = nl_image_from_values(row, 8, 8, -1, 1);
    for (int a = 2; a < argc; a++)
      if (nl_image_write(im, argv[a], 8, &err)) { fprintf(stderr, "%s\n", err.msg); return 1; }
    nl_image_free(im);
    FILE *maps = fopen("/proc/self/maps", "r");   /* where the image module came from */
    char line[4096];
    while (maps && fgets(line, sizeof line, maps))
      if (strstr(line, "libnl_oiio.so")) { printf("module %s", strchr(line, '/')); break; }
    if (maps) fclose(maps);
  }
  return 0;
}
C
# shellcheck disable=SC2086  # pkg-config's flags are words
"$CC" -std=c11 -Wall -Werror -o "$out/outside" "$out/outside.c" $cflags $libs 2>"$out/cc.log" \
  || { cat "$out/cc.log"; fail "the outside program does not build with: $cflags $libs"; }
# shellcheck disable=SC2086
"$CC" -std=c11 -Wall -Werror -o "$out/outside-static" "$out/outside.c" $cflags \
  ${slibs/-lnoiselab/-l:libnoiselab.a} 2>"$out/cc.log" \
  || { cat "$out/cc.log"; fail "the outside program does not link statically with: $slibs"; }
# The module is looked up beside the library first: a build-tree module
# would also load, so the test names the one that did.
LD_LIBRARY_PATH="$lib" "$out/outside" "$out/noise.tsv" "$out/noise.png" "$out/noise.tif" \
  >"$out/run.log" 2>&1 \
  || { cat "$out/run.log"; fail "the outside program failed"; }
grep -q "^module $lib/noiselab/libnl_oiio.so\$" "$out/run.log" \
  || fail "image module not taken from the install ($lib/noiselab): $(cat "$out/run.log")"
[ -s "$out/noise.png" ] || fail "no PNG written"
[ -s "$out/noise.tif" ] || fail "no TIFF written"
"$out/outside-static" "$out/noise-static.tsv" || fail "the static program failed"
! grep -q libnoiselab <<<"$(ldd "$out/outside-static" 2>&1)" || fail "the static program needs libnoiselab.so"
cmp -s "$out/noise.tsv" "$out/noise-static.tsv" || fail "shared and static programs wrote different tables"

# The values: Perlin's reference noise(3.14, 42, 7) = 0.13691995878400012
# (his Java code; nl_noise.h: within 1e-15), 0 on lattice points, the row
# within the bound sqrt(2) sqrt(3)/2 and not flat.
tsv_awk '
  FNR > 1 && n("x") == 3.14 && n("y") == 42 { d = n("noise") - 0.13691995878400012; if (d < -1e-15 || d > 1e-15) { print "noise(3.14, 42, 7) = " v("noise"); bad = 1 } ; seen++ }
  FNR > 1 && (v("x") "," v("y") "," v("z") == "0,0,0" || v("x") "," v("y") "," v("z") == "1,2,3") { if (n("noise") != 0) { print "lattice point " v("x") "," v("y") "," v("z") ": " v("noise"); bad = 1 }; seen++ }
  FNR > 1 && n("y") == 1.3 { r++; s += n("noise"); ss += n("noise") ^ 2; if (n("noise") < -1.2247449 || n("noise") > 1.2247449) { print "out of bound: " v("noise"); bad = 1 } }
  END { if (seen != 3 || r != 64) { print "rows: " seen " points, " r " row samples"; exit 1 }
        sd = sqrt(ss / r - (s / r) ^ 2); if (sd < 0.05) { print "row sd " sd ": flat"; exit 1 }
        exit bad }' "$out/noise.tsv" || fail "wrong values in $out/noise.tsv"

# The Python package installed beside the library (when /usr/bin/python3 has
# numpy, which setup installs): it imports from the destdir's site folder and
# gives Perlin's reference value through the installed libnoiselab.so.
pymsg="no numpy: Python package not checked"
if /usr/bin/python3 -c 'import numpy' 2>/dev/null; then
  pyinit="$(find "$dest" -path '*/noiselab/noise.py' | head -n 1)"
  [ -n "$pyinit" ] || fail "Python package not installed (no noiselab/noise.py in $dest)"
  grep -q "^LIBDIR = \"$prefix/" "$(dirname "$pyinit")/_config.py" \
    || fail "the installed package's _config.py does not name the install's LIBDIR"
  # shellcheck disable=SC2016  # Python, not shell
  v="$(cd "$out" && PYTHONPATH="$(dirname "$(dirname "$pyinit")")" \
       NOISELAB_LIBRARY="$lib/libnoiselab.so" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c '
import noiselab, noiselab.noise as nn
assert noiselab.library_path.startswith("'"$lib"'/"), noiselab.library_path
print(repr(float(nn.points(3.14, 42.0, 7.0, reference=True))))')" \
    || fail "the installed Python package does not run"
  [ "$v" = 0.13691995878400012 ] || [ "$v" = 0.1369199587840001 ] \
    || fail "installed Python package: noise(3.14, 42, 7) = $v"
  pymsg="Python package from $(dirname "$pyinit")"
fi
echo "cli_install: ok ($n headers, shared and static, module from $lib/noiselab; $pymsg)"
