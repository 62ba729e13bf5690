#!/usr/bin/env bash
# bench.tsv as scripts/noiselab bench writes it from bench_noise's printout:
#  - each "fn2:" line is one row with peer fastnoise2: our rate, FastNoise2's,
#    and the ratio recomputed from them (> 1: ours faster);
#  - the stb rows keep their peers, and a printout without FastNoise2
#    ("# FastNoise2: not built") has no fastnoise2 row;
#  - bench_stats's linkage_scale lines give rows per n against n = 1000,
#    CPU and user CPU;
#  - bench_noise --fastnoise2 with a library that does not load is one line
#    naming it, exit 2, before any timing.
# Args: NOISELAB_SCRIPT BENCH_NOISE OUTDIR.
set -euo pipefail
nl="$1" bn="$2" out="$3"
rm -rf "$out"; mkdir -p "$out/with" "$out/without"
fail() { echo "cli_bench_table: $*"; exit 1; }

# The lines bench_noise prints (column widths as its printf makes them).
table='noise                               Msample/s     cpu ms    wall ms   vs stb
stb_perlin_noise3                        58.8      17.83      44.73     1.00
nl_noise_perm3_row (improved 3D)        986.5       1.06       2.70    16.77'
fn2='# FastNoise2 (/x/libFastNoise.so), SIMD level AVX512, float32, same points and rounds; ours in double, level avx512
ours vs FastNoise2                                 ours        FN2    ratio
fn2: nl_noise_perm3_row (improved 3D)             986.5      451.2     2.19   (Perlin 3D, grid rows)
fn2: nl_noise_grad2_points, random                227.8      788.4     0.29   (Perlin 2D, random points)'
printf '#!/bin/sh\ncat <<"END"\n%s\n%s\nEND\n' "$table" "$fn2" >"$out/with/bench_noise"
printf '#!/bin/sh\ncat <<"END"\n%s\n# FastNoise2: not built\nEND\n' "$table" >"$out/without/bench_noise"
chmod +x "$out/with/bench_noise" "$out/without/bench_noise"

for w in with without; do
  bash -c 'source "$1"; run_benchmarks "$2" "$3"' _ "$nl" "$out/$w" "$out/$w.out" >/dev/null 2>&1 \
    || fail "$w: run_benchmarks failed"
done
tsv="$out/with.out/bench.tsv"
row() { awk -F'\t' -v m="$1" -v p="$2" '$2 == m && $5 == p {print $4 "|" $6 "|" $7}' "$3"; }
[ "$(row 'nl_noise_perm3_row (improved 3D)' fastnoise2 "$tsv")" = "986.5|451.2|2.19" ] \
  || fail "3D rows against FastNoise2: $(row 'nl_noise_perm3_row (improved 3D)' fastnoise2 "$tsv")"
[ "$(row 'nl_noise_grad2_points, random' fastnoise2 "$tsv")" = "227.8|788.4|0.289" ] \
  || fail "2D points against FastNoise2: $(row 'nl_noise_grad2_points, random' fastnoise2 "$tsv")"
[ "$(row 'nl_noise_perm3_row (improved 3D)' stb_perlin_noise3 "$tsv")" = "986.5|58.8|16.8" ] \
  || fail "3D rows against stb: $(row 'nl_noise_perm3_row (improved 3D)' stb_perlin_noise3 "$tsv")"
[ "$(awk -F'\t' 'NR > 1 && $5 != "stb_perlin_noise3"' "$tsv" | wc -l)" = 2 ] \
  || fail "rows other than stb's and the two fn2 lines: $(cat "$tsv")"
tsv="$out/without.out/bench.tsv"
[ "$(awk -F'\t' '$5 == "fastnoise2"' "$tsv" | wc -l)" = 0 ] || fail "a fastnoise2 row without FastNoise2"
[ "$(row 'nl_noise_perm3_row (improved 3D)' stb_perlin_noise3 "$tsv")" = "986.5|58.8|16.8" ] \
  || fail "without FastNoise2, 3D rows against stb: $(cat "$tsv")"

# bench_stats's growth figure: each n against n = 1000, as a cost.
mkdir -p "$out/scale"
printf '#!/bin/sh\ncat <<"END"\n%s\n%s\nEND\n' \
  'linkage_scale C complete n=1000 d=81: 0.021 s CPU (0.178 s wall) a call, 24 calls, 21.27 ns CPU per n^2 (user 16.97 + system 4.39), 1.00x that at n=1000 (load 11.88 12.00 11.00)' \
  'linkage_scale C complete n=20000 d=81: 9.216 s CPU (48.822 s wall) a call, 1 call, 23.04 ns CPU per n^2 (user 17.67 + system 5.38), 1.08x that at n=1000 (load 12.22 12.00 11.00)' \
  >"$out/scale/bench_stats"
chmod +x "$out/scale/bench_stats"
bash -c 'source "$1"; run_benchmarks "$2" "$3"' _ "$nl" "$out/scale" "$out/scale.out" >/dev/null 2>&1 \
  || fail "scale: run_benchmarks failed"
[ "$(row 'complete linkage CPU per n^2, n = 20000, 81 dims' 'the same at n = 1000' "$out/scale.out/bench.tsv")" \
  = "23.04|21.27|0.923" ] || fail "linkage growth row: $(cat "$out/scale.out/bench.tsv")"
[ "$(row 'complete linkage user CPU per n^2, n = 20000, 81 dims' 'the same at n = 1000' "$out/scale.out/bench.tsv")" \
  = "17.67|16.97|0.96" ] || fail "linkage user growth row: $(cat "$out/scale.out/bench.tsv")"

rc=0
err="$("$bn" --fastnoise2 "$out/no such library.so" 2>&1 >/dev/null)" || rc=$?
{ [ "$rc" = 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" = 1 ] &&
  [[ "$err" == "bench_noise: --fastnoise2 $out/no such library.so: "* ]]; } \
  || fail "bench_noise --fastnoise2 missing: rc=$rc: $err"
echo "cli_bench_table: ok"
