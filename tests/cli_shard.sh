#!/usr/bin/env bash
# Experiments as shards and a merge (nl_harness_units, nl_harness.h):
#  - for every experiment whose source declares units, at --quick, the
#    shards K/N (K = 1..N, run at once) merged with --merge give the folder
#    of the unsharded run file for file, for N = 1, 2 and 5 (the timing files
#    run.tsv and times.tsv aside); the merge removes the spent .shards/;
#  - a shard writes its shard file only (no table, report or manifest);
#  - a merge with a shard missing, or a shard made with other parameters, is
#    one line naming it, exit 2, nothing written; --shard on an experiment
#    without units, and a malformed K/N, likewise.
# Args: SOURCE_ROOT BUILD_ROOT OUTDIR.
set -euo pipefail
root="$1" build="$2" out="$3"
rm -rf "$out"; mkdir -p "$out"
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
fail() { echo "cli_shard: $*"; exit 1; }
cd "$root"   # the experiments read data/patterns

mapfile -t sharded < <(grep -El 'nl_harness_units(_weighted)?\(' experiments/*/*.c | cut -d/ -f2 | sort -u)
[ ${#sharded[@]} -gt 0 ] || fail "no experiment declares units"
grep -q '^c5_pools$' <(printf '%s\n' "${sharded[@]}") || fail "C5 declares no units"

one_line_exit2() {   # WANT_FRAGMENT PROGRAM ARGS...
  local want="$1"; shift
  local err rc=0
  err="$("$@" 2>&1 >/dev/null)" || rc=$?
  { [ "$rc" = 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" = 1 ] && [[ "$err" == *"$want"* ]]; } \
    || fail "$*: rc=$rc, wanted exit 2 and one line with '$want'; got: $err"
}

for e in "${sharded[@]}"; do
  x="$build/experiments/$e"
  "$x" --quick --out "$out/$e/whole" 2>/dev/null || fail "$e: the unsharded run failed"
  for n in 1 2 5; do
    d="$out/$e/n$n" pids=()
    for k in $(seq 1 "$n"); do "$x" --quick --out "$d" --shard "$k/$n" 2>/dev/null & pids+=($!); done
    for p in "${pids[@]}"; do wait "$p" || fail "$e: a shard of $n failed"; done
    left="$(cd "$d" && find . -path ./.shards -prune -o -type f -print)"
    [ -z "$left" ] || fail "$e: shards of $n wrote more than their shard files: $left"
    [ "$(find "$d/.shards" -type f | wc -l)" = "$n" ] || fail "$e: $n shards did not write $n shard files"
    "$x" --quick --out "$d" --merge 2>/dev/null || fail "$e: the merge of $n shards failed"
    [ ! -e "$d/.shards" ] || fail "$e: the merge of $n shards left .shards/"
    diff -r -x run.tsv -x times.tsv "$out/$e/whole" "$d" >"$out/$e/diff-$n" \
      || fail "$e: $n shards merged differ from the unsharded run: $(head -5 "$out/$e/diff-$n")"
  done
  # a missing shard: named, nothing written
  d="$out/$e/missing"
  "$x" --quick --out "$d" --shard 1/3 2>/dev/null
  "$x" --quick --out "$d" --shard 3/3 2>/dev/null
  one_line_exit2 "shard 2 of 3 missing ($d/.shards/2-of-3.tsv)" "$x" --quick --out "$d" --merge
  [ -z "$(find "$d" -path "$d/.shards" -prune -o -type f -print)" ] || fail "$e: a refused merge wrote into $d"
  # a shard of another run (its parameters or seed differ) is not merged
  d="$out/$e/other"
  "$x" --quick --out "$d" --shard 1/1 --seed 2 2>/dev/null
  one_line_exit2 "1-of-1.tsv was made by another run" "$x" --quick --out "$d" --merge
done

one_line_exit2 "s3_fbm declares no units to shard" "$build/experiments/s3_fbm" --quick --out "$out/s3" --shard 1/2
[ ! -e "$out/s3" ] || fail "a refused --shard made $out/s3"
one_line_exit2 "--shard: '3/2' is not K/N" "$build/experiments/c5_pools" --quick --out "$out/bad" --shard 3/2
one_line_exit2 "--merge: not with --shard" "$build/experiments/c5_pools" --quick --out "$out/bad" --shard 1/2 --merge
echo "cli_shard: ${sharded[*]}: N = 1, 2, 5 merged as the unsharded run"
