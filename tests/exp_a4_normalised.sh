#!/usr/bin/env bash
# Quick A4: F_sup above 1, and normalising by it cuts the energy above the
# Nyquist frequency of 2 samples per unit at least threefold.
set -euo pipefail
exp="$1" expect="$2" out="$3"
"$exp" --quick --out "$out" 2>/dev/null >/dev/null
"$expect" "$out/aliasing.tsv" rows=2 'f_sup>=1' 'f_sup<3' 'aliased_fraction>0' file:normalised.png
awk -F'\t' 'NR==2{a=$3} NR==3{b=$3} END{exit !(b * 3 < a)}' "$out/aliasing.tsv"
set +e
"$exp" --quick --out "$out/bad" --set rate=0 2>/dev/null; [ $? -eq 2 ] || exit 1
