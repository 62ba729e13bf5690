#!/usr/bin/env bash
# Quick A4: F_sup above 1, and normalising by it cuts the energy above the
# Nyquist frequency of 2 samples per unit at least threefold. The stored
# value's energy above Nyquist in units of T: noise(x) above T, the
# paper's Nnoise below it (quick: 2.9 T, 0.15 T), p-values in [0, 1]; the
# two energy verdicts are independent and the figure's row qualitative.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/aliasing.tsv" rows=2 'f_sup>=1' 'f_sup<3' 'aliased_fraction>0' image:normalised.png
tsv_awk 'NR==2{a=n("aliased_fraction")} NR==3{b=n("aliased_fraction")} END{exit !(b * 3 < a)}' "$out/aliasing.tsv"
"$expect" "$out/aliased_energy.tsv" rows=3 'energy_over_t>0' 'energy_over_t_sd>0' 'p_below>=0' \
  'p_below<=1' 'p_above>=0' 'p_above<=1' 'divisor>=1' 'seeds==3'
tsv_awk 'NR==2{a=n("energy_over_t")} NR==4{b=n("energy_over_t"); d=n("divisor")}
         END{exit !(a > 1 && b < 1 && d == 1.7460938)}' "$out/aliased_energy.tsv"
tsv_awk 'NR > 1 { k[v("kind")]++
                  if (v("kind") == "independent" && v("source") !~ /^aliased_energy.tsv/) bad = 1 }
         END { exit !(!bad && k["independent"] == 2 && k["qualitative"] == 1 && NR == 4) }' \
  "$out/verdicts.tsv"
set +e
refused "$exp" --quick --out "$out/bad" --set rate=0
