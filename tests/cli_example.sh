#!/usr/bin/env bash
# noiselab example: analyse -> synthesize -> determinism; every input format
# the issue lists; bad inputs give exit 2 and exactly one line on stderr.
# Called as: bash tests/cli_example.sh TOOL EXPECT OUTDIR
set -euo pipefail
tool=$1; out=$3
rm -rf "$out"; mkdir -p "$out"

# Inputs are made by the tool itself from hand-written parameter files (no
# image ships with the repo): grey and RGB, as 16-bit PNG, float EXR, TIFF.
cat > "$out/grey.params" <<P
noiselab-example 1
channels 1
bands 5
tile 64
histogram 1
sigma2 0.275
mean 0.5
matrix 1
hist0 0.1 0.2 0.3 0.4 0.45 0.5 0.55 0.7 0.8 0.9
weights0 0.2 0.5 1 0.7 0.3
P
cat > "$out/rgb.params" <<P
noiselab-example 1
channels 3
bands 5
tile 64
histogram 0
sigma2 0.275
mean 0.5 0.4 0.3
matrix 0.6 0.6 0.52915026221291817 -0.70710678118654757 0.70710678118654757 0 -0.37416573867739417 -0.37416573867739417 0.84852813742385702
hist0 -1 -0.5 -0.3 -0.1 0 0.1 0.2 0.3 0.5 1
hist1 -1 -0.5 -0.3 -0.1 0 0.1 0.2 0.3 0.5 1
hist2 -1 -0.5 -0.3 -0.1 0 0.1 0.2 0.3 0.5 1
weights0 0.1 0.2 0.3 0.2 0.1
weights1 0.05 0.1 0.1 0.1 0.05
weights2 0.02 0.05 0.05 0.02 0.01
P
"$tool" synthesize "$out/grey.params" --size 64 --seed 3 -o "$out/grey16.png"
"$tool" synthesize "$out/grey.params" --size 64 --seed 3 -o "$out/grey.exr"
"$tool" synthesize "$out/rgb.params" --size 80 --height 64 --seed 4 -o "$out/rgb.tif"
"$tool" synthesize "$out/rgb.params" --size 64 --seed 4 -o "$out/rgb16.png"
"$tool" synthesize "$out/rgb.params" --size 64 --seed 4 --solid --z 2.5 -o "$out/solid.png"
# 8-bit grey as PGM, 8-bit RGBA as PNG (python3's zlib), if python3 exists.
{ printf 'P5\n32 32\n255\n'; LC_ALL=C awk 'BEGIN { for (i = 0; i < 1024; i++) printf "%c", (i * 37 + int(i / 32) * 11) % 256 }'; } > "$out/grey8.pgm"
inputs="grey16.png grey.exr rgb.tif rgb16.png grey8.pgm"
if command -v python3 >/dev/null; then
  python3 - "$out/rgba8.png" <<'PY'
import struct, sys, zlib
w = h = 24
rows = b''.join(b'\0' + b''.join(bytes(((x * 9 + y * 5) % 256, (x * y) % 256, (x + 3 * y) % 256, 200)) for x in range(w)) for y in range(h))
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 6, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b'')
open(sys.argv[1], 'wb').write(png)
PY
  inputs="$inputs rgba8.png"
fi
for f in $inputs; do
  "$tool" analyse "$out/$f" -o "$out/$f.params"
  grep -q '^weights0 ' "$out/$f.params"
done
grep -q '^channels 3' "$out/rgb.tif.params"
grep -q '^channels 1' "$out/grey.exr.params"
grep -q '^bands 6' "$out/rgb.tif.params"          # max(80, 64) -> floor(log2 80) = 6

# analyse -> synthesize twice with one seed: identical files; another seed differs.
"$tool" synthesize "$out/rgb.tif.params" --size 96 --seed 11 -o "$out/a.png"
"$tool" synthesize "$out/rgb.tif.params" --size 96 --seed 11 -o "$out/b.png"
"$tool" synthesize "$out/rgb.tif.params" --size 96 --seed 12 -o "$out/c.png"
cmp -s "$out/a.png" "$out/b.png"
! cmp -s "$out/a.png" "$out/c.png"
# morph at t = 0 reproduces the first texture exactly (same seed).
"$tool" analyse "$out/rgb16.png" -o "$out/rgb16.params"
"$tool" morph "$out/rgb.tif.params" "$out/rgb.tif.params" --t 0.3 -o "$out/m.params"
"$tool" morph "$out/rgb.tif.params" "$out/rgb16.png.params" --t 0 --size 96 --seed 11 -o "$out/m0.png"
cmp -s "$out/a.png" "$out/m0.png"

# Bad inputs: exit 2, one line on stderr.
bad() {
  local rc=0
  "$tool" "$@" 2> "$out/err.txt" > /dev/null || rc=$?
  if [ "$rc" -ne 2 ]; then echo "expected exit 2, got $rc: $*" >&2; exit 1; fi
  if [ "$(wc -l < "$out/err.txt")" -ne 1 ]; then echo "expected one line on stderr: $*" >&2; cat "$out/err.txt" >&2; exit 1; fi
}
printf 'P5\n8 8\n255\n%064d' 0 > "$out/tiny.pgm"
bad analyse "$out/tiny.pgm" -o "$out/x.params"
grep -q 'tiny.pgm' "$out/err.txt"
bad analyse "$out/missing.png" -o "$out/x.params"
echo 'not an image' > "$out/junk.png"
bad analyse "$out/junk.png" -o "$out/x.params"
grep -v '^weights1' "$out/rgb.params" > "$out/missing.params"
bad synthesize "$out/missing.params" --size 16 -o "$out/x.png"
grep -q "weights1" "$out/err.txt"
sed 's/^sigma2 .*/sigma2 abc/' "$out/rgb.params" > "$out/nonnum.params"
bad synthesize "$out/nonnum.params" --size 16 -o "$out/x.png"
grep -q "abc" "$out/err.txt"
bad morph "$out/rgb.params" "$out/rgb.tif.params" --t 0.5 -o "$out/x.params"   # 5 vs 6 bands
grep -q "bands" "$out/err.txt"
bad synthesize "$out/rgb.params" --size 0 -o "$out/x.png"
bad synthesize "$out/rgb.params" -o "$out/x.png"
bad morph "$out/rgb.params" "$out/rgb.params" --t 1.5 -o "$out/x.params"
bad frobnicate
test ! -e "$out/x.png" && test ! -e "$out/x.params"
echo "cli_example: ok"
