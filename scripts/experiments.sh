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

# The papers the experiments reproduce, cited once (docs/targets.md "The
# papers, for citation"), keyed by the letter of their experiments' ids:
# letter, short name, citation (authors, year, title, venue), as TSV.
# REPORT.md's per-paper table and sub-headings are made from these lines.
paper_citations() {
  printf '%s\t%s\t%s\n' \
    S "Shaffer" "Eric Shaffer. *Noise-Based Textures: Sums of Noise Functions.* Lecture slides, Production Computer Graphics (undated)." \
    C "Cheng 2009" "Wei-Chien Cheng. *Controllable Stochastic Texture Synthesis Based on Perlin Noise.* Master's thesis, National Chiao Tung University, Hsinchu, 2009." \
    A "Arnerin 2009" "Reynald Arnerin. *A journey in a procedural volume: Optimization and filtering of Perlin noise.* 2009. HAL open archive, inria-00598443." \
    Q "Qin & Yang 2000" "Xuejie Qin (supervisor Herbert Yang). *A Generalized Cellular Texture Basis Function.* Proceedings of the Twelfth Annual Graduate Symposium on Computer Science, University of Saskatchewan, 2000." \
    L "Lagae et al. 2010" "Ares Lagae, Peter Vangorp, Toon Lenaerts, Philip Dutré. *Procedural Isotropic Stochastic Textures by Example.* Computers & Graphics 34(4), 2010."
}

# The table, figure or section of its paper each experiment reproduces
# (docs/targets.md's "paper item"), by id, as TSV: REPORT.md's "paper ->
# program -> output" table is made from these lines and the manifests.
experiment_items() {
  printf '%s\t%s\n' \
    S1 "slides: fractal sum, 1, 2, 3 and 8 octaves" \
    S2 "slides: turbulence, 1, 2, 3 and 8 octaves" \
    S3 "slides: fBm, gain and lacunarity" \
    S4 "slides: marble through a colour ramp" \
    C1 "Fig 4.1-4.4" \
    C2 "Fig 4.5, 4.6" \
    C3 "Fig 4.7" \
    C4 "Table 4.1, Fig 4.8" \
    C5 "sec 3.5, Tables 4.2-4.4" \
    C6 "Fig 4.9-4.14" \
    C7 "Fig 4.15-4.17" \
    C8 "ch. 5 (future work): gradients on the sphere" \
    C9 "ch. 5 (future work): octave amplitudes" \
    A1 "eq. 4.1-4.3, 5.1-5.4" \
    A2 "Table 5.1, Fig 5.1-5.3" \
    A3 "Fig 5.5, Table 5.2" \
    A4 "Fig 5.7" \
    Q1 "sec 3" \
    Q2 "Fig 2" \
    Q3 "Fig 4" \
    Q4 "Fig 5, 6" \
    L1 "sec 3, Fig 2" \
    L2 "sec 4, eq. 12-13, Fig 4" \
    L3 "sec 5, Fig 5-8" \
    L4 "Fig 10, 12"
}
