# scripts/experiments.sh - sourced by scripts/noiselab and scripts/sweep.sh:
# the experiments of a build and experiment names, and the escaping of their
# messages. Needs BUILD (the build folder) and die (prints its message, exits
# 2) from the script that sources it.
# shellcheck shell=bash

# REPLY = the words given, with control characters escaped as the C tools'
# messages have them (nl_fail: a newline as \n, a tab as \t, the others as
# \xNN): a message that quotes a path or a value the user typed stays one
# line. A message without any costs no loop.
message_line() {
  REPLY="$*"
  [[ "$REPLY" == *[[:cntrl:]]* ]] || return 0
  local s="$REPLY" c i hex
  REPLY=""
  for ((i = 0; i < ${#s}; i++)); do
    c="${s:i:1}"
    case "$c" in
      $'\n') REPLY+='\n' ;;
      $'\t') REPLY+='\t' ;;
      [[:cntrl:]]) printf -v hex '\\x%02x' "'$c"; REPLY+="$hex" ;;
      *) REPLY+="$c" ;;
    esac
  done
}

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
