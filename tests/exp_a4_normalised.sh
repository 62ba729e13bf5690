#!/usr/bin/env bash
# Quick A4: F_sup above 1, and normalising by it cuts the energy above the
# Nyquist frequency of 2 samples per unit at least threefold.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/aliasing.tsv" rows=2 'f_sup>=1' 'f_sup<3' 'aliased_fraction>0' image:normalised.png
tsv_awk 'NR==2{a=n("aliased_fraction")} NR==3{b=n("aliased_fraction")} END{exit !(b * 3 < a)}' "$out/aliasing.tsv"
set +e
refused "$exp" --quick --out "$out/bad" --set rate=0
