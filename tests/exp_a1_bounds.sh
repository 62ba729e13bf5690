#!/usr/bin/env bash
# Quick A1: the analytic bound and every incremental interval hold on every
# random point; observed extremes are positive and below the bound. The
# premise |noise| <= 1: the climbs reach at least the largest random point
# and at least 1 (quick: 1.003), never the analytic bound. Eq. 5.4 as
# printed (one absolute value) fails on random points, read as an interval
# it holds, and its control (the remainder bounded by 0) fails; every
# verdict has a control.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name; refused
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/bounds.tsv" rows=8 'over_bound==0' 'over_bound_incremental==0' \
  'max_abs<=bound' 'max_abs>0.5' 'max_noise<=1.2247448713915890' 'S<2' 'S>=1' \
  'over_paper_octave>=0' file:manifest.tsv file:report.md
"$expect" "$out/max_noise.tsv" rows=3 'local_max>=sampled_max' 'local_max>=1' \
  'local_max<1.2247448713915890' 'starts==100' 'candidates==100000'
"$expect" "$out/claims.tsv" rows=9 'ours>=0' 'ours_sd>=0' 'points>0'
"$expect" "$out/printed.tsv" rows=3 'over_printed>0' 'over_dropped>=over_printed' 'over_printed<points'
"$expect" "$out/fractal_climbs.tsv" rows=6 'local_max>=sampled_max' 'local_max<1.2247448713915890'
tsv_awk 'NR > 1 { if (v("verdict") == "" || v("control_verdict") == "-") bad = 1
                  if (v("quantity") ~ /as printed, \|Fnoise/ && v("verdict") != "not reproduced") bad = 1
                  if (v("quantity") ~ /interval/ && v("verdict") != "reproduced") bad = 1 }
         END { exit !(!bad && NR == 5) }' "$out/verdicts.tsv"
# GSL runs on OpenBLAS when the build found it: with gold as the linker,
# --as-needed can drop libopenblas (wanted by libgsl.so, not by the program)
# and GSL falls back to libgslcblas, unnoticed but for C5's and C6's drift.
if [ "${NL_TEST_OPENBLAS:-0}" = 1 ] && ! grep -q $'^blas\tOpenBLAS' "$out/manifest.tsv"; then
  echo "the build links OpenBLAS, but the manifest says: $(grep $'^blas\t' "$out/manifest.tsv")"; exit 1
fi
if byte_reruns; then   # same seed, same tables (tsv.sh: release build only)
  "$exp" --quick --no-images --out "$out/again" >/dev/null
  cmp "$out/bounds.tsv" "$out/again/bounds.tsv"
  cmp "$out/max_noise.tsv" "$out/again/max_noise.tsv"
  cmp "$out/fractal_climbs.tsv" "$out/again/fractal_climbs.tsv"
fi
set +e
refused "$exp" --quick --out "$out/bad" --set octaves=31
[ ! -e "$out/bad/manifest.tsv" ]
