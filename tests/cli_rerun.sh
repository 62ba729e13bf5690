#!/usr/bin/env bash
# A rerun changes no tracked file but the timings by nature that
# docs/experiments.md lists ("What a rerun changes"): the experiments with
# times in their tables (A2, C1, C5, C6, C9) and S4 (figures and images) run
# twice at quick scale into two folders, and every file must be byte for
# byte the same, except run.tsv and times.tsv (untracked, and in no
# manifest's output lines) and the listed files. commit_id names the last
# commit that touched what results are made from (RESULT_SOURCES), also
# after a commit of results or of a test, in a scratch git repository.
# Args: NOISELAB_SCRIPT OUTDIR.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$2"
root="$(cd "$(dirname "$nl")/.." && pwd)"
fail() { echo "cli_rerun: $*"; exit 1; }
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
rm -rf "$out"; mkdir -p "$out"

# The documented list: the backquoted paths of the section's second list
# (its items' first lines).
# shellcheck disable=SC2016  # backquotes of Markdown, not a command
mapfile -t listed < <(awk '/^## What a rerun changes/ { s = 1; next } s && /^## / { exit }
  s && /timings by nature/ { t = 1 } s && t && /^- /' "$root/docs/experiments.md" |
  grep -o '`[A-Za-z0-9_./]*`' | tr -d '`' | grep -E '^(REPORT\.md|report\.html|[a-z0-9_]+/[^/]+)$')
[ "${#listed[@]}" -ge 3 ] || fail "no list of timing files in docs/experiments.md: ${listed[*]:-none}"

for k in 1 2; do
  "$nl" reproduce --quick --out "$out/r$k" A2 C1 C5 C6 C9 S4 2>"$out/r$k.log" \
    || { cat "$out/r$k.log"; fail "reproduce $k failed"; }
done
differ=()
while read -r f; do
  rel="${f#"$out/r1/"}"
  case "${rel##*/}" in run.tsv|times.tsv|.noiselab.lock) continue ;; esac
  cmp -s "$f" "$out/r2/$rel" && continue
  known=0
  for l in "${listed[@]}"; do [ "$l" = "$rel" ] && known=1; done
  [ "$known" = 1 ] || differ+=("$rel")
done < <(find "$out/r1" -type f | LC_ALL=C sort)
[ "${#differ[@]}" = 0 ] || fail "a rerun changed files docs/experiments.md does not list: ${differ[*]}"
# the same files in both runs
[ "$(cd "$out/r1" && find . -type f | LC_ALL=C sort)" = "$(cd "$out/r2" && find . -type f | LC_ALL=C sort)" ] \
  || fail "the two runs wrote different files"
# every listed file is one a run writes (the list is not stale)
for l in "${listed[@]}"; do
  [ -f "$out/r1/$l" ] || fail "docs/experiments.md lists $l, which the run did not write"
done

# Without the timing experiments REPORT.md and report.html are the same
# bytes too (the commit's date, no times in the header).
for k in 1 2; do
  "$nl" reproduce --quick --out "$out/s$k" S4 C9 2>"$out/s$k.log" || { cat "$out/s$k.log"; fail "reproduce S4 C9 $k failed"; }
done
for f in REPORT.md report.html; do cmp -s "$out/s1/$f" "$out/s2/$f" || fail "two runs of S4 C9 differ in $f"; done

# run.tsv and times.tsv: written, no manifest output, ignored by git under results/
for e in a2_raymarch c1_textures c5_pools c6_reproduce c9_amplitudes; do
  for f in run.tsv times.tsv; do
    [ -s "$out/r1/$e/$f" ] || fail "$e: no $f"
    ! grep -q $'^output\t'"$f"'$' "$out/r1/$e/manifest.tsv" || fail "$e: $f is a manifest output"
    git -C "$root" check-ignore -q "results/$e/$f" || fail "results/$e/$f is not ignored by git"
  done
done
[ -s "$out/r1/s4_marble/run.tsv" ] || fail "s4_marble: no run.tsv"
[ ! -e "$out/r1/s4_marble/times.tsv" ] || fail "s4_marble has no time column, but a times.tsv"
grep -q $'^seconds\t[0-9.]*$' "$out/r1/s4_marble/run.tsv" || fail "run.tsv: no seconds: $(cat "$out/r1/s4_marble/run.tsv")"
! grep -q $'^\\(started\\|seconds\\|cpu_seconds\\|peak_rss_mb\\)\t' "$out/r1/s4_marble/manifest.tsv" \
  || fail "the manifest still holds times"

# commit_id and report_date in a scratch repository: a commit of results/,
# or of a test, after the code's commit changes neither.
g="$out/git"; mkdir -p "$g/scripts" "$g/results"
cp "$nl" "$root/scripts/experiments.sh" "$root/scripts/lock.sh" "$g/scripts/"
git -C "$g" init -q
git -C "$g" -c user.name=t -c user.email=t@t add scripts
GIT_COMMITTER_DATE='2001-02-03T04:05:06Z' git -C "$g" -c user.name=t -c user.email=t@t commit -q -m code
code="$(git -C "$g" rev-parse --short=12 HEAD)"
echo x >"$g/results/REPORT.md"
git -C "$g" -c user.name=t -c user.email=t@t add results
GIT_COMMITTER_DATE='2009-02-03T04:05:06Z' git -C "$g" -c user.name=t -c user.email=t@t commit -q -m results
mkdir -p "$g/tests"; echo t >"$g/tests/t.sh"
git -C "$g" -c user.name=t -c user.email=t@t add tests
GIT_COMMITTER_DATE='2010-02-03T04:05:06Z' git -C "$g" -c user.name=t -c user.email=t@t commit -q -m test
# shellcheck disable=SC2016  # the inner shell's arguments
got="$(bash -c 'source "$1"; commit_id; echo; report_date' _ "$g/scripts/noiselab")"
[ "$got" = "$code"$'\n'"2001-02-03" ] || fail "commit_id, report_date after a results and a test commit: '$got', wanted $code and 2001-02-03"
echo y >"$g/scripts/note.txt"   # a file not committed: the tree is modified
# shellcheck disable=SC2016
got="$(bash -c 'source "$1"; commit_id' _ "$g/scripts/noiselab")"
[ "$got" = "$code+dirty" ] || fail "commit_id of a modified tree: '$got'"
echo "cli_rerun: ok"
