#!/usr/bin/env bash
# noiselab render: images and tables out, bad input refused with one line
# and exit 2, and no partial file left behind.
set -euo pipefail
render="$1" expect="$2" out="$3"
mkdir -p "$out"
"$render" fbm --octaves 6 --gain 0.5 --lacunarity 2 --size 64 --seed 7 -o "$out/fbm.png"
"$render" turbulence --size 32 -o "$out/t.exr"
"$render" marble --size 32 --bits 16 -o "$out/m.tif"
"$render" noise2 --size 16 --seed 3 -o "$out/n.tsv"
"$expect" "$out/n.tsv" rows=256 'value<=0.70711' 'value>=-0.70711' 'x>0' 'x<4'
"$render" gctbf --terms "F2 - F1 - F1F1" --size 32 --normalize range -o "$out/g.png"
"$render" fbm --basis gctbf --octaves 3 --size 16 -o "$out/gf.tsv"
"$expect" "$out/gf.tsv" rows=256
"$render" wavelet --size 16 --tile 16 -o "$out/w.tsv"
"$expect" "$out/w.tsv" rows=256 'value<=6' 'value>=-6'   # Gaussian-tile values: loose sanity bounds
for f in fbm.png t.exr m.tif g.png; do [ -s "$out/$f" ]; done
# Same seed, same bytes.
"$render" noise2 --size 16 --seed 3 -o "$out/n2.tsv"
cmp "$out/n.tsv" "$out/n2.tsv"
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
bad "not writable" fbm --size 8 -o /nonexistent/dir/x.png
bad "no output file" fbm --size 8
bad "must be even" wavelet --tile 9 -o "$out/x.png"
bad "lambda must be in" gctbf --lambda -1 -o "$out/x.png"
bad "F index must be in 1..4" gctbf --terms F5 -o "$out/x.png"
bad "expected a number" gctbf --terms "abc*F1" -o "$out/x.png"
[ ! -e "$out/x.png" ]
[ -z "$(ls -A "$out" | grep '^\.' || true)" ]   # no temporary files left
