#!/usr/bin/env bash
# Quick A4: F_sup above 1, and normalising by it (measured on the stored
# value, quick 1.25) cuts the fraction of the energy above the
# Nyquist frequency of 2 samples per unit at least twofold. The stored
# value's energy above Nyquist in units of T: noise(x) above T, the
# paper's Nnoise below it (quick: 2.9 T, 0.15 T on the line; 2.6 T, 0.044
# T on the plane), p-values in [0, 1]. The plane's three rows are
# independent, each with a control that fails (the other normalisation);
# the line's two restate F_sup (by construction); the figure's qualitative.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
# every panel against its caption (oracle_al.c), this run and the committed one
panels_oracle al a4 "$out" "$(dirname "$0")/../results/a4_normalised"
"$expect" "$out/aliasing.tsv" rows=2 'f_sup>=1' 'f_sup<3' 'aliased_fraction>0' image:normalised.png
tsv_awk 'NR==2{a=n("aliased_fraction")} NR==3{b=n("aliased_fraction")} END{exit !(b * 2 < a)}' "$out/aliasing.tsv"
"$expect" "$out/aliased_energy.tsv" rows=3 'energy_over_t>0' 'energy_over_t_sd>0' 'p_below>=0' \
  'p_below<=1' 'p_above>=0' 'p_above<=1' 'divisor>=1' 'seeds==3'
tsv_awk 'NR==2{a=n("energy_over_t")} NR==4{b=n("energy_over_t"); d=n("divisor")}
         END{exit !(a > 1 && b < 1 && d == 1.7460938)}' "$out/aliased_energy.tsv"
"$expect" "$out/aliased_energy_2d.tsv" rows=3 'energy_over_t>0' 'p_below>=0' 'p_below<=1' \
  'divisor>=1' 'seeds==3'
tsv_awk 'NR==2{a=n("energy_over_t")} NR==4{b=n("energy_over_t"); d=n("divisor")}
         END{exit !(a > 1 && b < 1 && d == 1.7460938)}' "$out/aliased_energy_2d.tsv"
tsv_awk 'NR > 1 { k[v("kind")]++
                  if (v("kind") == "independent" && (v("source") !~ /^aliased_energy_2d.tsv/ ||
                      v("control_verdict") != "not reproduced")) bad = 1 }
         END { exit !(!bad && k["independent"] == 3 && k["by construction"] == 2 &&
                      k["qualitative"] == 1 && NR == 7) }' "$out/verdicts.tsv"
set +e
refused "$exp" --quick --out "$out/bad" --set rate=0
