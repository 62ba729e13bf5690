#!/usr/bin/env bash
# noiselab render: images and tables out, bad input refused with one line
# and exit 2, and no partial file left behind.
set -euo pipefail
render="$1" expect="$2" out="$3"
mkdir -p "$out"
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # byte_reruns
"$render" fbm --octaves 6 --gain 0.5 --lacunarity 2 --size 64 --seed 7 -o "$out/fbm.png"
"$render" turbulence --size 32 -o "$out/t.exr"
SOURCE_DATE_EPOCH=0 "$render" marble --size 32 --bits 16 -o "$out/m.tif"
"$render" noise2 --size 16 --seed 3 -o "$out/n.tsv"
"$expect" "$out/n.tsv" rows=256 'value<=0.70711' 'value>=-0.70711' 'x>0' 'x<4'
"$render" gctbf --terms "F2 - F1 - F1F1" --size 32 --normalize range -o "$out/g.png"
"$render" fbm --basis gctbf --octaves 3 --size 16 -o "$out/gf.tsv"
"$expect" "$out/gf.tsv" rows=256
"$render" wavelet --size 16 --tile 16 -o "$out/w.tsv"
"$expect" "$out/w.tsv" rows=256 'value<=6' 'value>=-6'   # Gaussian-tile values: loose sanity bounds
for f in fbm.png t.exr m.tif g.png; do [ -s "$out/$f" ]; done
# Grey levels: the image's range by default, the analytic bound on request;
# stderr says which, with the values mapped to black and white.
"$render" fbm --size 32 --seed 7 -o "$out/r.png" 2>"$out/r.err"
grep -q "to black..white: the image's range" "$out/r.err"
"$render" fbm --size 32 --seed 7 --normalize bound -o "$out/b.png" 2>"$out/b.err"
grep -q "to black..white: the analytic bound" "$out/b.err"
# -o -: the .tsv on stdout, the same bytes as the file
"$render" noise2 --size 16 --seed 3 -o - >"$out/stdout.tsv" 2>/dev/null
cmp "$out/stdout.tsv" "$out/n.tsv"
# .npy: numpy's header (a multiple of 64 bytes) and 16 x 16 float64 values
"$render" noise2 --size 16 --seed 3 -o "$out/n.npy" 2>/dev/null
[ "$(head -c 6 "$out/n.npy" | tail -c 5)" = NUMPY ]
[ "$(stat -c %s "$out/n.npy")" = $((128 + 16 * 16 * 8)) ]
head -c 128 "$out/n.npy" | grep -q "'descr': '<f8', 'fortran_order': False, 'shape': (16, 16)"
# the first value, as od prints it, is the table's first (x 0.125, y 0.125)
first="$(od -A n -t f8 -j 128 -N 8 "$out/n.npy" | tr -d ' ')"
awk -F'\t' -v f="$first" 'NR == 2 { d = $3 - f; exit !(d < 1e-12 && d > -1e-12) }' "$out/n.tsv"
# Same seed, same bytes.
"$render" noise2 --size 16 --seed 3 -o "$out/n2.tsv"
cmp "$out/n.tsv" "$out/n2.tsv"
# --threads: the same bytes for 1, 2 and 3 threads (200^2 x 6 octaves is
# above the size where the grid starts threads; turbulence too)
for s in fbm turbulence; do
  "$render" "$s" --size 200 --threads 1 -o "$out/$s-t1.npy" 2>/dev/null
  for t in 2 3; do
    "$render" "$s" --size 200 --threads "$t" -o "$out/$s-t$t.npy" 2>/dev/null
    cmp "$out/$s-t1.npy" "$out/$s-t$t.npy"
  done
done
bad() {   # expected message fragment, then arguments
  local want="$1"; shift
  local err rc=0
  err="$("$render" "$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
    echo "render $*: rc=$rc err='$err' (wanted '$want')"; exit 1
  fi
}
bad "unknown noise" nosuch -o "$out/x.png"
bad "--size: 0 is outside" fbm --size 0 -o "$out/x.png"
bad "--size: 65537 is outside" fbm --size 65537 -o "$out/x.png"
bad "--octaves: 31 is outside" fbm --octaves 31 -o "$out/x.png"
bad "--gain: 'abc' is not a number" fbm --gain abc -o "$out/x.png"
bad "/nonexistent/dir/x.png: directory /nonexistent/dir does not exist" fbm --size 8 -o /nonexistent/dir/x.png
bad "no output file" fbm --size 8
bad "--threads: 0 is outside [1, 64]" fbm --size 8 --threads 0 -o "$out/x.png"
# Memory is held to what is available, not to the total: capped by the
# tool's test hook, and at 65536 (51.5 GB) against the real figure.
NL_MEMAVAILABLE_OVERRIDE=1e8 bad "--size 4000 needs 192 MB of memory; 100 MB is available" \
  fbm --size 4000 -o "$out/x.png"
if [ "$(awk '/^MemAvailable:/ { print $2 }' /proc/meminfo)" -lt 50000000 ]; then
  bad "--size 65536 needs 51.5 GB of memory; " fbm --size 65536 -o "$out/x.png"
fi
# An integer format cannot hold raw 32-bit floats: refused, nothing written.
rm -f "$out/new.png"
bad "new.png: PNG cannot hold 32-bit float; use .exr or .tif" \
  fbm --size 32 --bits 32 -o "$out/new.png"
[ ! -e "$out/new.png" ] || { echo "render --bits 32 to a PNG wrote $out/new.png"; exit 1; }
"$render" fbm --size 32 --bits 32 -o "$out/f32.tif"
# EXR holds half or float samples: 8 bits is refused, not written as half
# and reported as "8-bit float".
rm -f "$out/e8.exr"
bad "e8.exr: EXR holds 16-bit half or 32-bit float, not 8-bit" fbm --size 32 --bits 8 -o "$out/e8.exr"
[ ! -e "$out/e8.exr" ] || { echo "render --bits 8 to an EXR wrote $out/e8.exr"; exit 1; }
bad "must be even" wavelet --tile 9 -o "$out/x.png"
bad "--lambda: -1 must be in (0, 1000]" gctbf --lambda -1 -o "$out/x.png"
bad "F index must be in 1..4" gctbf --terms F5 -o "$out/x.png"
bad "expected a number" gctbf --terms "abc*F1" -o "$out/x.png"
# Lattice coordinates beyond 2^52 (NaN with exit 0 and signed overflow in
# the floor if let through) are refused naming the options.
bad "--lacunarity 10 with --octaves 30: the finest octave's frequency 1e+29" fbm --octaves 30 --lacunarity 10 --size 4 -o "$out/x.tsv"
bad "--lacunarity 10 with --octaves 30" fbm --octaves 30 --lacunarity 10 --size 4 -o "$out/x.png"
bad "--lacunarity 10 with --octaves 30" fbm --basis gctbf --octaves 30 --lacunarity 10 --size 4 -o "$out/x.tsv"
bad "--lacunarity 1e+06 with --octaves 4" fbm --basis wavelet --tile 8 --octaves 4 --lacunarity 1e6 --size 4 -o "$out/x.tsv"
bad "--octaves 30: the finest octave's frequency" fractal --octaves 30 --x0 1e9 --size 4 -o "$out/x.tsv"
bad "--octaves 30: the finest octave's frequency" marble --octaves 30 --y0 -1e9 --size 4 -o "$out/x.png"
# In range, large: finite values only.
"$render" fbm --octaves 12 --lacunarity 10 --gain 1000 --size 8 -o "$out/big.tsv"
if grep -qi 'nan\|inf' "$out/big.tsv"; then echo "big.tsv holds nan or inf"; exit 1; fi
"$render" fbm --basis table --octaves 30 --lacunarity 0.001 --size 8 -o "$out/small.tsv"
if grep -qi 'nan\|inf' "$out/small.tsv"; then echo "small.tsv holds nan or inf"; exit 1; fi
rm -f "$out/big.tsv" "$out/small.tsv"
# A parent that is a file, option names and ranges.
: > "$out/afile"
bad "$out/afile/x.png: parent $out/afile is not a directory" fbm --size 8 -o "$out/afile/x.png"
bad "$out/afile/x.tsv: parent $out/afile is not a directory" fbm --size 8 -o "$out/afile/x.tsv"
bad "--points: -3 is outside [1, 64]" gctbf --points -3 -o "$out/x.png"
bad "--points: 65 is outside [1, 64]" gctbf --points 65 -o "$out/x.png"
bad "--lambda: 0 must be in (0, 1000]" gctbf --lambda 0 -o "$out/x.png"
bad "'': empty file name" fbm --size 8 -o ""
bad "$out: is a directory" fbm --size 8 -o "$out"
bad "names a directory" fbm --size 8 -o "$out/"
bad "--size 65536 as a .tsv needs" fbm --size 65536 -o "$out/x.tsv"   # 463 GB
SOURCE_DATE_EPOCH=yesterday bad "SOURCE_DATE_EPOCH 'yesterday' is not a number" fbm --size 8 -o "$out/x.tif"
rm -f "$out/afile"
# Same seed, same bytes, for every image format (no timestamp).
# Byte reruns (tests/tsv.sh): release build only; the sanitizer build wrote
# each format above.
if byte_reruns; then
  for e in png tif exr; do
    "$render" fbm --octaves 6 --size 64 --seed 11 -o "$out/same1.$e"
    sleep 1   # a written time would now differ
    "$render" fbm --octaves 6 --size 64 --seed 11 -o "$out/same2.$e"
    cmp "$out/same1.$e" "$out/same2.$e"
    rm -f "$out/same1.$e" "$out/same2.$e"
  done
fi
# GNU-style options: --name=VALUE as --name VALUE, -oFILE, prefixes,
# options after the noise or before it; unknown / missing / unwanted values refused.
"$render" --size=16 noise2 --seed=3 -o"$out/n3.tsv"
cmp "$out/n.tsv" "$out/n3.tsv"
"$render" noise2 --si 16 --seed 3 --out="$out/n4.tsv"
cmp "$out/n.tsv" "$out/n4.tsv"
rm -f "$out/n3.tsv" "$out/n4.tsv"
bad "--bogus: unknown option" fbm --bogus=3 -o "$out/x.png"
bad "--size: missing value" fbm -o "$out/x.png" --size
bad "--reference: takes no value" improved --reference=yes -o "$out/x.png"
bad "--s: ambiguous option (--size, --seed, --stripes)" fbm --s 3 -o "$out/x.png"
bad "--size: 'x' is not" fbm --size=x -o "$out/x.png"
# SOURCE_DATE_EPOCH, when set, is the time written (m.tif above).
grep -aq '1970:01:01 00:00:00' "$out/m.tif"
[ ! -e "$out/x.png" ]
[ ! -e "$out/x.tsv" ]
[ ! -e "$out/x.tif" ]
[ -z "$(find "$out" -mindepth 1 -maxdepth 1 -name '.*')" ]   # no temporary files left
