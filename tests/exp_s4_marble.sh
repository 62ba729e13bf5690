#!/usr/bin/env bash
# Quick S4: u in [0, 1] with the arcsine law's mean 1/2 and sd 1/(2 sqrt 2).
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # NOIMG
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/distribution.tsv" rows=4 'u_mean~0.5:0.05' 'u_sd~0.35355:0.02' image:panels.png
"$expect" "$out/u_density.tsv" rows=20 'u>0' 'u<1'
