#!/usr/bin/env bash
# The Python package installed the two ways docs/python.md gives, each
# imported from another folder with nothing but what the interpreter derives
# (no PYTHONPATH of ours, no NOISELAB_* variable):
#  - `meson install --destdir DEST` of this build (prefix P): the package is
#    in P's site folder as Debian's interpreter reads it (for P = /usr/local
#    or /usr: a folder on its sys.path; for any P: one of
#    site.getsitepackages([P]), what site derives from a prefix), and imports
#    with PYTHONPATH = site.getsitepackages([DEST/P]) alone;
#  - `pip install --no-build-isolation --no-index .` (meson-python builds the
#    wheel from pyproject.toml) into a fresh `python3 -m venv
#    --system-site-packages` (numpy from Debian), then `cd / && V/bin/python
#    -c 'import noiselab.stats; ...'`.
# Each gives Perlin's reference noise(3.14, 42, 7) through the installed
# extension (which holds the library: no libnoiselab.so needed beside it)
# and runs a KS test; the wheel's also reads a PNG through the OpenImageIO
# module it carries (noiselab/noiselab/libnl_oiio.so, where the library's
# code looks first). Skipped (77) without numpy, venv or meson-python.
# Args: SOURCE_DIR BUILD_DIR OUTDIR.
set -euo pipefail
src="$(cd "$1" && pwd)" build="$(cd "$2" && pwd)" out="$3"
fail() { echo "python_install: $*"; exit 1; }
py=/usr/bin/python3
$py -c 'import numpy' 2>/dev/null || { echo "python_install: no numpy: skipped"; exit 77; }
$py -c 'import venv, ensurepip' 2>/dev/null || { echo "python_install: no venv: skipped"; exit 77; }
$py -c 'import mesonpy' 2>/dev/null || { echo "python_install: no meson-python (python3-mesonpy): skipped"; exit 77; }
command -v patchelf >/dev/null || { echo "python_install: no patchelf (meson-python needs it): skipped"; exit 77; }
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\|NOISELAB_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
unset PYTHONPATH PYTHONHOME
rm -rf "$out"; mkdir -p "$out"

# What the installed package must do, from /.
check='
import sys, noiselab, noiselab.noise as nn, noiselab.stats as ns, numpy as np
where = sys.argv[1]
assert noiselab.__file__.startswith(where), (noiselab.__file__, where)
assert noiselab.library_path.startswith(where), noiselab.library_path   # the extension
import noiselab._ext
assert noiselab._ext.__file__.startswith(where), noiselab._ext.__file__
import os
assert os.path.exists(os.path.join(os.path.dirname(noiselab.__file__), "py.typed"))
v = float(nn.points(3.14, 42.0, 7.0, reference=True))
assert abs(v - 0.13691995878400012) < 1e-15, v
f = nn.function("improved", reference=True)
assert float(f(3.14, 42.0, 7.0)) == v
D, p = ns.kstest(np.linspace(0.005, 0.995, 100), "uniform")
assert 0 < D < 0.01 and p > 0.99, (D, p)
if len(sys.argv) > 2:   # an image through the OpenImageIO module the install carries
    import noiselab.byexample as nb
    assert nb.read_image(sys.argv[2]).shape[2] >= 1
    maps = open("/proc/self/maps").read()
    mod = [l.split()[-1] for l in maps.splitlines() if l.endswith("libnl_oiio.so")]
    assert mod and mod[0].startswith(where), mod
print("ok", noiselab.__file__)
'

# 1. meson install into a destdir: the prefix is the build's.
dest="$out/dest"
meson install -C "$build" --destdir "$dest" --no-rebuild --quiet >"$out/install.log" 2>&1 \
  || { cat "$out/install.log"; fail "meson install failed"; }
prefix="$(meson introspect "$build" --buildoptions |
          $py -c 'import json, sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"] == "prefix"))')"
init="$(find "$dest" -path '*/noiselab/__init__.py' | head -n 1)"
[ -n "$init" ] || fail "meson install put no noiselab/__init__.py in $dest"
site="$(dirname "$(dirname "$init")")"
site="${site#"$dest"}"
# shellcheck disable=SC2016  # Python, not shell
$py -c 'import site, sys; sys.exit(sys.argv[2] not in site.getsitepackages([sys.argv[1]]))' \
    "$prefix" "$site" || fail "installed in $site, not a site folder of prefix $prefix"
case "$prefix" in
  /usr|/usr/local)
    $py -c 'import sys; sys.exit(sys.argv[1] not in sys.path)' "$site" \
      || fail "installed in $site, which is not on $py's sys.path" ;;
esac
derived="$($py -c 'import site, sys; print(":".join(site.getsitepackages([sys.argv[1]])))' "$dest$prefix")"
(cd / && PYTHONPATH="$derived" PYTHONDONTWRITEBYTECODE=1 $py -c "$check" "$dest$site") \
  >"$out/meson.log" 2>&1 || { cat "$out/meson.log"; fail "the meson-installed package does not run"; }

# 2. pip install . into a fresh venv (meson-python, offline).
$py -m venv --system-site-packages "$out/venv" >"$out/venv.log" 2>&1 \
  || { cat "$out/venv.log"; fail "python3 -m venv failed"; }
(cd "$src" && "$out/venv/bin/pip" install --no-build-isolation --no-index --no-cache-dir \
   --disable-pip-version-check .) >"$out/pip.log" 2>&1 \
  || { tail -n 40 "$out/pip.log"; fail "pip install . failed (log: $out/pip.log)"; }
vsite="$("$out/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_path("platlib"))')"
png="$(find "$src/data/exemplars" -name '*.png' | sort | head -n 1)"
[ -n "$png" ] || fail "no PNG in $src/data/exemplars to read"
(cd / && PYTHONDONTWRITEBYTECODE=1 "$out/venv/bin/python" -c "$check" "$vsite" "$png") \
  >"$out/pip-run.log" 2>&1 || { cat "$out/pip-run.log"; fail "the pip-installed package does not run"; }
# the wheel holds the package alone: no library, header or program beside it
extra="$(cd "$out/venv" && find . -name 'libnoiselab*' -o -name 'nl_noise.h' -o -name 'noiselab.pc' | head -n 3)"
[ -z "$extra" ] || fail "the wheel installed more than the package: $extra"
# PEP 561: a type checker reads the installed package's hints (py.typed),
# here mypy (Debian's, where installed) run for the venv's interpreter.
typed="mypy not installed: hints not checked"
if $py -c 'import mypy' 2>/dev/null; then
  printf 'import noiselab.noise as nn\nnn.grid("fbm", "64")\n' >"$out/caller.py"
  (cd "$out" && $py -m mypy --no-incremental --cache-dir /dev/null \
     --python-executable "$out/venv/bin/python" caller.py) >"$out/mypy.log" 2>&1 || true
  grep -q 'Argument 2 to "grid" has incompatible type "str"' "$out/mypy.log" \
    || fail "mypy does not read the installed package's hints: $(cat "$out/mypy.log")"
  typed="mypy reads its hints"
fi
echo "python_install: ok (meson install: $site; pip: $vsite; $typed)"
