# scripts/experiments.sh - sourced by scripts/noiselab and scripts/sweep.sh:
# the experiments of a build and experiment names. Needs BUILD (the build
# folder) and die (prints its message, exits 2) from the script that sources it.
# shellcheck shell=bash

# The experiments of this build, in report order.
experiment_list() { grep -v '^$' "$BUILD/experiments/experiments.txt" || true; }

# S3, s3 or s3_fbm -> s3_fbm
resolve() {
  local want e
  want="$(printf '%s' "$1" | tr '[:upper:]' '[:lower:]')"
  for e in $(experiment_list); do
    if [ "$e" = "$want" ] || [ "${e%%_*}" = "$want" ]; then printf '%s\n' "$e"; return 0; fi
  done
  die "unknown experiment '$1' (scripts/noiselab list shows them)"
}
