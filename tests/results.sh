#!/usr/bin/env bash
# The committed results/ as a reader finds them: every experiment of the
# build has a complete folder at paper scale and in results/quick, each with
# a verdicts.tsv whose rows carry a valid kind, REPORT.md counts independent
# verdicts, and no manifest was made from a modified tree (+dirty), so the
# commit it names holds the code that made it.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
root="$1" list="$2"
fail() { printf 'results: %s\n' "$*" >&2; exit 1; }
[ -s "$list" ] || fail "no experiment list at $list"
kinds='^(independent|fitted [1-9][0-9]*/[1-9][0-9]*|selected 1/([2-9]|[1-9][0-9]+)|by construction|qualitative)$'
for dir in "$root/results" "$root/results/quick"; do
  [ -f "$dir/REPORT.md" ] || fail "$dir has no REPORT.md"
  grep -qE '^[0-9]+ independent verdicts \(' "$dir/REPORT.md" || fail "$dir/REPORT.md does not count independent verdicts"
  while IFS= read -r e; do
    [ -n "$e" ] || continue
    m="$dir/$e/manifest.tsv" v="$dir/$e/verdicts.tsv"
    [ -f "$m" ] || fail "$dir/$e has no manifest.tsv"
    commit="$(tsv_awk 'v("key") == "commit" { print v("value") }' "$m")"
    [ -n "$commit" ] || fail "$m names no commit"
    case "$commit" in *+dirty) fail "$m was made from a modified tree ($commit)";; esac
    [ -f "$v" ] || fail "$dir/$e has no verdicts.tsv: every experiment decides at least one claim"
    n="$(tsv_awk 'FNR > 1 { cnt++ } END { print cnt + 0 }' "$v")"
    [ "$n" -ge 1 ] || fail "$v has no rows"
    bad="$(tsv_awk -v re="$kinds" 'FNR > 1 && !(v("kind") ~ re) { print NR ": " v("kind") }' "$v" | head -1)"
    [ -z "$bad" ] || fail "$v row $bad: not a kind"
  done <"$list"
done
