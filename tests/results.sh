#!/usr/bin/env bash
# The committed results/ as a reader finds them: every experiment of the
# build has a complete folder at paper scale and in results/quick, each with
# a verdicts.tsv whose rows carry a valid kind, REPORT.md counts independent
# verdicts, and no manifest was made from a modified tree (+dirty), so the
# commit it names holds the code that made it. Every number of a quick table
# that the regression check compares has a measured spread over the CPU
# configurations in data/blas_spread.tsv (bench/blas-spread.sh --quick): a
# table or column added since the last measurement would be compared exactly
# and drift under another OpenBLAS kernel or libm variant.
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

# Every experiment has a claims inventory (experiments/NAME/claims.tsv):
# every claim names the verdict row that decides it (its quantity, in both
# the paper-scale and the quick verdicts.tsv) or says why none does. Every
# independent row has a negative control: the same rule run on a baseline
# without the method, never itself "reproduced" beside a row that passes
# (the harness would have made the row "by construction").
while IFS= read -r e; do
  [ -n "$e" ] || continue
  inv="$root/experiments/$e/claims.tsv"
  [ -f "$inv" ] || fail "$e has no claims inventory experiments/$e/claims.tsv"
  head -1 "$inv" | grep -qx $'id\tclaim\twhere\tdecided_by\twhy_not' ||
    fail "$inv: header is not id, claim, where, decided_by, why_not"
  for dir in "$root/results" "$root/results/quick"; do
    v="$dir/$e/verdicts.tsv"
    bad="$(awk -F'\t' '
      FNR == 1 { split("", c); for (i = 1; i <= NF; i++) c[$i] = i; next }
      FILENAME == ARGV[1] { q[$c["quantity"]] = 1
        if ($c["kind"] == "independent" && (!("control_verdict" in c) || $c["control_verdict"] == "-"))
          { print "independent row without a control: " $c["quantity"]; exit }
        if ($c["kind"] == "independent" && $c["control_verdict"] == "reproduced" && $c["verdict"] != "not reproduced")
          { print "independent row that passes and whose control is reproduced: " $c["quantity"]; exit }
        next }
      NF != 5 { print "claim " $1 ": " NF " cells, wanted 5"; exit }
      $c["decided_by"] == "-" && ($c["why_not"] == "" || $c["why_not"] == "-") {
        print "claim " $c["id"] ": neither a verdict row nor a reason"; exit }
      $c["decided_by"] != "-" && !($c["decided_by"] in q) {
        print "claim " $c["id"] ": no verdict row \"" $c["decided_by"] "\""; exit }' "$v" "$inv")"
    [ -z "$bad" ] || fail "$e ($dir): $bad"
  done
done <"$list"

spread="$root/data/blas_spread.tsv"
[ -f "$spread" ] || fail "no $spread"
while IFS= read -r e; do
  [ -n "$e" ] || continue
  q="$root/results/quick/$e"
  for t in "$q"/*.tsv; do
    # run.tsv and times.tsv: the run's timings, untracked (docs/experiments.md)
    case "$(basename "$t")" in manifest.tsv|checks.tsv|verdicts.tsv|run.tsv|times.tsv) continue ;; esac
    # Columns with a number in any row (the cells bench/blas-spread.sh measures),
    # less those the committed checks.tsv ignores, without a quick-scale spread.
    miss="$(awk -F'\t' -v e="$e" -v t="$(basename "$t")" '
      FILENAME == ARGV[1] { if (FNR > 1 && $1 == e && $2 == "quick" && $3 == t) have[$4] = 1; next }
      FILENAME == ARGV[2] { if (FNR > 1 && $1 == t && $3 == "ignore") ign[$2] = 1; next }
      FNR == 1 { for (i = 1; i <= NF; i++) name[i] = $i; next }
      { for (i = 1; i <= NF; i++) if ($i ~ /^[-+]?([0-9]|\.[0-9])/) num[i] = 1 }
      END {
        if ("*" in ign) exit
        for (i in num) if (!(name[i] in have) && !(name[i] in ign)) { print name[i]; exit }
      }' "$spread" "$q/checks.tsv" "$t")"
    [ -z "$miss" ] || fail "$t: column $miss has no measured spread in data/blas_spread.tsv" \
      "(bash bench/blas-spread.sh --quick $e)"
  done
done <"$list"
