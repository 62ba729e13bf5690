#!/usr/bin/env bash
# Quick S2: turbulence is non-negative and inside its bound.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # NOIMG
exp="$1" expect="$2" out="$3"
"$exp" --quick "${NOIMG[@]}" --out "$out" >/dev/null
"$expect" "$out/turbulence_distribution.tsv" rows=4 'min>=0' 'mean>0' 'max_abs<=bound' \
  image:turbulence_panels.png
"$expect" "$out/turbulence_spectrum.tsv" rows=64
