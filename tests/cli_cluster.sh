#!/usr/bin/env bash
# reproduce on a cluster (scripts/noiselab reproduce --emit, docs/cluster.md):
#  - --emit parallel writes tasks (C5's shards, A1 whole) and a merge; run
#    here by GNU parallel they give the tables, figures and REPORT.md of the
#    local `reproduce --quick` (timing files aside), and .shards-*/.parts
#    are gone after the merge;
#  - a task that fails is named with its log and the merge names the shard
#    that did not finish; rerunning runs only the rest (the finished shards
#    are kept) and then completes;
#  - slurm: --emit slurm writes one script (array + merge with afterok);
#    submitted with sbatch --wait on a cluster (scripts/slurm-local.sh) it
#    gives the same tables and REPORT.md. Without sbatch or an answering
#    node this part is skipped: exit 77 (meson's skip) after the rest passed.
# Args: NOISELAB_SCRIPT MODE(parallel|slurm) OUTDIR.
set -euo pipefail
nl="$1" mode="$2" out="$3"
rm -rf "$out"; mkdir -p "$out"
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
export SOURCE_DATE_EPOCH=1700000000
fail() { echo "cli_cluster: $*"; exit 1; }
exps=(c5_pools a1_bounds)

same_as_local() {   # DIR
  local e
  for e in "${exps[@]}"; do
    diff -r -x run.tsv -x times.tsv "$out/local/$e" "$1/$e" >"$1.diff" || fail "$1/$e differs from the local run: $(head -5 "$1.diff")"
  done
  cmp -s "$out/local/REPORT.md" "$1/REPORT.md" || fail "$1/REPORT.md differs from the local one"
  if [ -e "$1/.shards-c5_pools" ] || [ -e "$1/.parts" ]; then fail "$1: shards or parts left after the merge"; fi
}

if [ "$mode" = slurm ]; then
  command -v sbatch >/dev/null || { echo "cli_cluster: skipped: sbatch not installed (scripts/slurm-local.sh starts a one-node cluster)"; exit 77; }
  timeout 10 sinfo -h -o '%t' 2>/dev/null | grep -Eq 'idle|mix|alloc' \
    || { echo "cli_cluster: skipped: no Slurm node answers (scripts/slurm-local.sh starts one)"; exit 77; }
fi
"$nl" reproduce --quick --out "$out/local" "${exps[@]}" 2>/dev/null || fail "local reproduce failed"

if [ "$mode" = parallel ]; then
  d="$out/parallel"
  "$nl" reproduce --quick --out "$d" --emit parallel "${exps[@]}" 2>/dev/null
  [ "$(grep -c -- '--shard ' "$d/cluster/tasks.txt")" = "$(grep -c ' shard ' "$d/cluster/what.txt")" ] || fail "tasks and what.txt disagree"
  grep -qx 'a1_bounds' "$d/cluster/what.txt" || fail "A1 is not a task"
  [ ! -e "$d/c5_pools" ] || fail "emitting ran something"
  # a failing shard (its file's name taken by a folder): named with its
  # log, the merge names it, nothing merged
  n="$(grep -c ' shard ' "$d/cluster/what.txt")"
  mkdir "$d/.shards-c5_pools/1-of-$n.tsv"
  err="$("$d/cluster/reproduce.parallel" -j 2 2>&1 >/dev/null)" && fail "a run with a failed shard passed"
  rmdir "$d/.shards-c5_pools/1-of-$n.tsv"
  [[ "$err" == *"c5_pools shard 1/$n failed; its log: $d/cluster/logs/1/stderr"* ]] || fail "the failed shard is not named with its log: $err"
  [[ "$err" == *"c5_pools: shard 1/$n did not finish"* ]] || fail "the merge does not name the missing shard: $err"
  [ ! -e "$d/c5_pools/manifest.tsv" ] || fail "merged with a shard missing"
  [ -f "$d/a1_bounds/manifest.tsv" ] || fail "A1 was not adopted beside the failed C5"
  # the rerun runs shard 1 only (the others' files are there: their tasks
  # end at once), then merges
  "$d/cluster/reproduce.parallel" -j 2 --joblog "$out/joblog2" 2>/dev/null || fail "the rerun failed"
  awk -F'\t' -v n="$n" 'NR > 2 && NR <= n + 1 && $4 > 1.5 { bad = 1 } END { exit bad }' "$out/joblog2" \
    || fail "the rerun ran finished shards again: $(cat "$out/joblog2")"
  same_as_local "$d"
  echo "cli_cluster: GNU parallel: tables and REPORT.md as the local run; a failed shard named, the rerun resumed"
  exit 0
fi

d="$out/slurm"
"$nl" reproduce --quick --out "$d" --emit slurm "${exps[@]}" 2>/dev/null
grep -q '^#SBATCH --job-name=noiselab-reproduce$' "$d/cluster/reproduce.slurm" || fail "no Slurm header"
grep -q -- '--dependency="afterok:' "$d/cluster/reproduce.slurm" || fail "no afterok merge"
timeout 600 sbatch --wait --quiet "$d/cluster/reproduce.slurm" || { cat "$d"/cluster/logs/* >&2; fail "sbatch failed"; }
same_as_local "$d"
echo "cli_cluster: Slurm (sbatch --wait): tables and REPORT.md as the local run"
