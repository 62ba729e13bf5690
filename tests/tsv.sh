# shellcheck shell=bash
# tests/tsv.sh - tables by column name for the shell tests (sourced:
#   . "$(dirname "$0")/tsv.sh").
# Tests address a column by its header, never by its position, so that a
# column added to a table shifts no check (as nl_table_value does in C and
# `set datafile columnheaders` in gnuplot).
#
#   tsv_awk [-v NAME=VALUE ...] 'PROGRAM' FILE...
#       awk -F'\t' with, before PROGRAM, a rule that reads the header of
#       each file (FNR == 1) and two functions:
#         col("name")  the column's index in the current file
#         v("name")    the current row's value in that column, as text
#         n("name")    the same as a number
#       A name the file does not have stops awk with exit 2 and a message.
#   tsv_cut FILE NAME      the column NAME of FILE (header included), as cut -f
#   tsv_slopes FILE LO HI  a spectrum's log-log slopes per column (below)
#   verdict_kinds FILE IND QUAL [RULE]  a verdicts.tsv's rows by kind (below)
# shellcheck disable=SC2016  # awk's $ fields, for awk, not for the shell
TSV_AWK_LIB='
FNR == 1 { split("", TSV_COL); for (TSV_I = 1; TSV_I <= NF; TSV_I++) TSV_COL[$TSV_I] = TSV_I }
function col(name) {
  if (!(name in TSV_COL)) { printf "tsv: no column \"%s\" in %s\n", name, FILENAME > "/dev/stderr"; exit 2 }
  return TSV_COL[name]
}
function v(name) { return $(col(name)) "" }
function n(name) { return $(col(name)) + 0 }
'

tsv_awk() {
  local opts=()
  while [ "$#" -gt 1 ] && [ "$1" = -v ]; do opts+=("$1" "$2"); shift 2; done
  local prog="$1"; shift
  awk -F'\t' "${opts[@]}" "$TSV_AWK_LIB$prog" "$@"
}

tsv_cut() {
  tsv_awk -v name="$2" '{ print v(name) }' "$1"
}

# tsv_slopes FILE LO HI: for a spectrum table (a column freq and one power
# column per setting), the least-squares slope of log(power) on log(freq)
# over LO <= freq <= HI, per setting: a table with the settings' names as
# its header and one row of slopes, for expect.
tsv_slopes() {
  tsv_awk -v lo="$2" -v hi="$3" '
    FNR == 1 { k = col("freq"); nf = NF; head = ""
      for (i = 1; i <= NF; i++) if (i != k) head = head (head == "" ? "" : "\t") $i
      next }
    $k >= lo && $k <= hi { x = log($k); m++; sx += x; sxx += x * x
      for (i = 1; i <= nf; i++) if (i != k) { sy[i] += log($i); sxy[i] += x * log($i) } }
    END { if (m < 3) { print "tsv_slopes: " m " rows in [" lo ", " hi "]" > "/dev/stderr"; exit 2 }
      print head; row = ""
      for (i = 1; i <= nf; i++) if (i != k)
        row = row (row == "" ? "" : "\t") (m * sxy[i] - sx * sy[i]) / (m * sxx - sx * sx)
      print row }' "$1"
}

# What the release build runs and the sanitizer build (NL_TEST_SANITIZE, set
# by tests/meson.build) leaves out: work that tests the bytes or the numbers
# of a result, which the sanitizers do not change, once the first run of the
# command has run under them (the test suite's CPU time). One test
# of the build, three names for the three kinds of such work:
unsanitized() { [ "${NL_TEST_SANITIZE:-none}" = none ]; }
# thread_identity: an experiment run again with --threads 1 and compared with
# its --threads 2 run (the order of the arithmetic).
thread_identity() { unsanitized; }
# byte_reruns: a command run a second time only to compare the output's bytes
# with the first run's (same seed later, another seed, another format of the
# same image; every image-writing run starts OpenImageIO, about 0.8 s of CPU
# under the sanitizers).
byte_reruns() { unsanitized; }
# full_scale: a command run at the size its checked numbers were measured at;
# the sanitizer build runs it smaller and checks only that it runs cleanly
# (cli_example's three 512^2 syntheses of the photograph, 9 s of CPU there).
full_scale() { unsanitized; }
# same_on_one_thread EXP OUT ARGS...: EXP's quick run in OUT (made with
# --threads 2 and ARGS) repeated on one thread into OUT.t1, tables only;
# noiselab-check then compares every table and the manifest's parameters
# under the experiment's own rules (timing columns ignored). Work spread
# over threads must not change the arithmetic. A thread-identity rerun:
# release build only.
same_on_one_thread() {
  local exp="$1" out="$2"
  shift 2
  thread_identity || return 0
  "$exp" --quick --no-images --threads 1 --out "$out.t1" "$@" >/dev/null \
    && "$(dirname "$exp")/../tools/noiselab-check" "$out" "$out.t1" >/dev/null
}
# NOIMG: the options of an experiment's first run, an array ("${NOIMG[@]}").
# The sanitizer build's runs make every image (under the sanitizers) but
# write none (--no-images; the image writer runs under them in test_image,
# cli_render and cli_example): the first image write starts OpenImageIO,
# about 0.85 s of CPU there, more than most quick runs. Reruns that compare
# tables pass --no-images in both builds. expect's image:NAME checks an image
# only when the run's manifest says it wrote images.
# shellcheck disable=SC2034  # read by the scripts that source this file
if unsanitized; then NOIMG=(); else NOIMG=(--no-images); fi

# refused CMD...: CMD must refuse its input as the guide says bad input is
# refused: exit 2 with a one-line message on stderr. On anything else it
# says what happened (exit code and CMD's stderr), so that a CI log shows
# why, and returns 1.
refused() {
  local err rc=0
  err="$("$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [ -z "$err" ]; then
    printf 'expected exit 2 and one line on stderr from: %s\ngot exit %d and:\n%s\n' "$*" "$rc" "$err" >&2
    return 1
  fi
}

# verdict_kinds FILE IND QUAL [RULE]: FILE (a verdicts.tsv) holds exactly IND
# independent and QUAL qualitative rows and nothing else; each qualitative
# row says "see figure", each independent row carries one of the three
# verdicts and, when RULE is given, that rule.
verdict_kinds() {
  tsv_awk -v ind="$2" -v qual="$3" -v rule="${4:-}" 'FNR > 1 { k[v("kind")]++
      if (v("kind") == "qualitative" && v("verdict") != "see figure") { print "bad: " $0; exit 1 }
      if (v("kind") == "independent" && ((rule != "" && v("rule") != rule) \
          || v("verdict") !~ /^(reproduced|partly|not reproduced)$/)) { print "bad: " $0; exit 1 } }
    END { if (k["independent"] != ind || k["qualitative"] != qual || NR - 1 != ind + qual) {
        printf "verdicts: %d independent, %d qualitative, %d rows\n", k["independent"],
          k["qualitative"], NR - 1; exit 1 } }' "$1"
}

# panels_oracle FAMILY ID DIR...: the figures of each run folder DIR against
# their captions, by tests/oracle_FAMILY (oracle.h) built beside expect;
# a folder whose manifest says it wrote no images is skipped. ID names the
# experiment to the oracle (s1, c4...). Fails with the oracle's lines.
panels_oracle() {
  local family="$1" id="$2" d
  shift 2
  for d in "$@"; do
    grep -q $'^images\tyes$' "$d/manifest.tsv" || continue
    # shellcheck disable=SC2154  # expect: the tests' instrument, set by the sourcing script
    "$(dirname "$expect")/oracle_$family" "$id" "$d" || { echo "panels of $d differ from their captions"; return 1; }
  done
}
