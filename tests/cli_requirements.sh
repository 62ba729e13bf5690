#!/usr/bin/env bash
# shellcheck disable=SC2016  # backquotes of Markdown in single quotes
# The run times the README and REPORT.md state come from
# results/requirements.tsv (written by `scripts/noiselab requirements`): the
# README's block between <!-- requirements --> and <!-- /requirements --> is
# what that file renders (or the line saying how to make it when absent); a
# TSV renders its own numbers; reproduce's ETA falls back on its rows when a
# folder has no run.tsv; the command is in the help and refuses arguments.
# (The measurement itself, about 30 min, is not run here.)
# Args: NOISELAB_SCRIPT OUTDIR.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$2"
root="$(cd "$(dirname "$nl")/.." && pwd)"
fail() { echo "cli_requirements: $*"; exit 1; }
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
rm -rf "$out"; mkdir -p "$out"

# shellcheck disable=SC2016  # the inner shell's arguments
lib() { bash -c 'source "$1"; shift; "$@"' _ "$nl" "$@"; }

# The README's block is the committed TSV's rendering.
block="$(awk '/^<!-- requirements -->$/ { s = 1; next } /^<!-- \/requirements -->$/ { s = 0 } s' "$root/README.md")"
[ -n "$block" ] || fail "README.md has no requirements block"
# shellcheck disable=SC2016
want="$(bash -c 'source "$1"; requirements_text "$REQUIREMENTS"' _ "$nl")"
[ "$block" = "$want" ] || fail "README's run times are not results/requirements.tsv's: '$block' against '$want'"
cmp -s <(lib readme_with_requirements "$root/README.md" "$root/results/requirements.tsv") "$root/README.md" \
  || fail "rewriting the README's block changes it"

# A TSV renders its numbers (seconds as min and s, MB rounded) and the machine;
# not the date (the TSV keeps it; a dated line in the README reads as history).
t="$out/req.tsv"
printf 'what\twall_seconds\tcpu_seconds\tpeak_rss_mb\tdisk_mb\tcores\tcpu\tdate\tcommit\n' >"$t"
printf '%s\t%s\t%s\t%s\t%s\t2\tTest CPU\t2030-01-02\tabc123\n' setup 100 150 300.4 200 \
  'reproduce --quick' 400.2 500 600.6 30 reproduce 1800 1000 700 300 test 720 1300 900 1200 \
  'reproduce s4_marble' 12.5 11 158 2 >>"$t"
got="$(lib requirements_text "$t")"
for w in 'measured at commit abc123, 2 cores (Test CPU)' \
         '`scripts/noiselab reproduce` 30 min 0 s wall, 16 min 40 s CPU, 700 MB peak memory (one process), 300 MB of disk' \
         '`scripts/noiselab reproduce --quick` 6 min 40 s wall, 8 min 20 s CPU, 601 MB' \
         '`scripts/noiselab test` 12 min 0 s wall, 21 min 40 s CPU, 900 MB' \
         '`scripts/noiselab setup` 1 min 40 s wall'; do
  [[ "$got" == *"$w"* ]] || fail "requirements_text: no '$w' in: $got"
done
[[ "$got" != *2030-01-02* ]] || fail "requirements_text: a date in: $got"
[[ "$(lib requirements_text "$out/none.tsv")" == *'`scripts/noiselab requirements` measures them'* ]] \
  || fail "no TSV: $(lib requirements_text "$out/none.tsv")"
# The block is replaced, the rest of the README kept.
lib readme_with_requirements "$root/README.md" "$t" >"$out/README.md"
[ "$(grep -c 'measured at commit abc123' "$out/README.md")" = 1 ] || fail "readme_with_requirements: block not replaced"
diff <(grep -v 'measured at commit abc123' "$out/README.md") <(awk '/^<!-- requirements -->$/ { print; s = 1; next }
  /^<!-- \/requirements -->$/ { s = 0 } !s' "$root/README.md") >/dev/null || fail "readme_with_requirements changed other lines"

# previous_seconds: run.tsv when its quick matches, else the TSV's row, else "-".
d="$out/res/s4_marble"; mkdir -p "$d"
# shellcheck disable=SC2016
ps() { bash -c 'source "$1"; REQUIREMENTS="$2"; previous_seconds "$3" "$4"' _ "$nl" "$t" "$@"; }
[ "$(ps "$d" 0)" = 12.5 ] || fail "previous_seconds without run.tsv: $(ps "$d" 0), wanted the TSV's 12.5"
[ "$(ps "$d" 1)" = - ] || fail "previous_seconds --quick, no row: $(ps "$d" 1)"
printf 'key\tvalue\nquick\tno\n' >"$d/manifest.tsv"
printf 'key\tvalue\nseconds\t3.25\n' >"$d/run.tsv"
[ "$(ps "$d" 0)" = 3.25 ] || fail "previous_seconds with run.tsv: $(ps "$d" 0)"

# The command: in the help, and refusing what it does not take.
[[ "$("$nl" help)" == *$'\n  requirements\n'* ]] || fail "help does not list requirements"
[[ "$("$nl" requirements --help)" == *results/requirements.tsv* ]] || fail "requirements --help"
rc=0; "$nl" requirements extra 2>"$out/extra.err" || rc=$?
{ [ "$rc" = 1 ] && grep -q "unexpected argument .extra." "$out/extra.err"; } || fail "requirements extra: exit $rc: $(cat "$out/extra.err")"
grep -qF '| `requirements` |' "$root/README.md" || fail "README's command table has no requirements"
echo "cli_requirements: ok"
