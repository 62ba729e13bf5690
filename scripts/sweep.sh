#!/usr/bin/env bash
# scripts/sweep.sh - parameter sweeps of an experiment, on this machine (GNU
# parallel) or a cluster (a GNU parallel job file for --sshlogin, or a Slurm
# array script). Called by `scripts/noiselab sweep`, which builds first; it
# can run alone with NL_BUILD=BUILD_DIR (the tests do).
#
# The exact parts (value specs, the task list, merging tables) are in
# tools/sweep.c (build/tools/noiselab-sweep); this file runs the tasks.
# A sweep folder:
#   sweep.tsv   the definition; a folder holding another sweep is refused
#   tasks.tsv   task, folder, seed, parameter values
#   jobs.txt    one self-contained shell line per task (skips itself when done)
#   tasks/N/    each task's own results folder (manifest.tsv = finished)
#   logs/N.log  each task's output;  joblog: GNU parallel's record of runs
#   sweep.slurm the Slurm array script (--emit slurm)
#   merged/     after `sweep merge`: merged tables, summaries, plot.png
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${NL_BUILD:-$ROOT/build}"
TOOL="$BUILD/tools/noiselab-sweep"

say() { printf '%s\n' "$*" >&2; }
die() { printf 'noiselab sweep: %s\n' "$*" >&2; exit 2; }

usage() {
  cat <<'USAGE'
usage: scripts/noiselab sweep EXPERIMENT --param NAME=SPEC... [options]
       scripts/noiselab sweep merge DIR [--table T] [--y COL[,COL2]] [--x NAME]

Runs EXPERIMENT once per point of the cartesian product of the parameters
(--set NAME=VALUE) and per seed; every task writes its own folder.
  SPEC          a list 0,0.1,0.5; a linear range A:B:N (N values, A to B);
                a log range A:B:logN (N values evenly spaced in log; A, B > 0)
  --seeds N     seeds per point (default 1): S, S+K, ..., S+(N-1)K
  --seed S      first seed (default 1)
  --task-seeds K  seeds each task averages over itself (the experiment's
                --seeds; default 1), so that no two tasks share a seed
  --quick       the experiments' quick sizes
  --out DIR     the sweep folder (default sweeps/EXPERIMENT-NAMES); running
                again continues an interrupted sweep, skipping finished tasks
  --jobs N      tasks at once on this machine (default: cores)
  --emit parallel  write DIR/jobs.txt for GNU parallel (e.g. --sshlogin, with
                the folder on a shared file system) instead of running
  --emit slurm  write DIR/sweep.slurm, a Slurm array job (one index a task)
  --cpus N --mem SIZE --time T
                Slurm resources per task (default 1, 2G, 01:00:00)
merge: DIR/merged/TABLE (parameters and seed as leading columns) for every
table, TABLE_summary.tsv (mean and spread over seeds per point) and
plot.png: COL (mean, error bars the sd over seeds) against the first
parameter (or --x), one line per row label; a second COL on the right axis.
Exit 2 on bad input, 1 when a task failed (its log is named).
USAGE
}

# POSIX single quotes, so job lines run under any sh (parallel --sshlogin).
q() { local s="${1//\'/\'\\\'\'}"; printf "'%s'" "$s"; }

resolve() {   # S3, s3 or s3_fbm -> s3_fbm
  local want e
  want="$(printf '%s' "$1" | tr 'A-Z' 'a-z')"
  [ -f "$BUILD/experiments/experiments.txt" ] || die "no build in $BUILD (scripts/noiselab setup)"
  while IFS= read -r e; do
    [ -n "$e" ] || continue
    if [ "$e" = "$want" ] || [ "${e%%_*}" = "$want" ]; then printf '%s\n' "$e"; return 0; fi
  done <"$BUILD/experiments/experiments.txt"
  die "unknown experiment '$1' (scripts/noiselab list shows them)"
}

# A dry run: every --set plus one name no experiment has. nl_run_params_done
# refuses that name (exit 2) after the real names and values were checked,
# before any work is done; any other message is the user's error.
probe() {   # EXE QUICK PARAM_ARGS...
  local exe="$1" quick="$2"; shift 2
  local tmp err rc=0
  tmp="$(mktemp -d)"
  local args=(--out "$tmp/probe" --seeds 1)
  [ "$quick" = 1 ] && args+=(--quick)
  err="$(timeout 120 "$exe" "${args[@]}" "$@" --set nl_sweep_probe=1 2>&1 >/dev/null)" || rc=$?
  rm -rf "$tmp"
  [[ "$rc" = 2 && "$err" == *"--set nl_sweep_probe: unknown parameter"* ]] && return 0
  [ "$rc" = 2 ] && die "$(printf '%s\n' "$err" | tail -n 1)"
  die "dry run of $(basename "$exe") $* failed (exit $rc): $(printf '%s\n' "$err" | tail -n 1)"
}

# One dry run per position in the value lists covers every name and value.
probe_all() {   # EXE QUICK NAME=SPEC...
  local exe="$1" quick="$2"; shift 2
  local -a names=() lists=()
  local p v max=0 i k
  for p in "$@"; do
    names+=("${p%%=*}")
    v="$("$TOOL" expand "$p")" || exit 2
    lists+=("$v")
    k="$(printf '%s\n' "$v" | wc -l)"; [ "$k" -gt "$max" ] && max="$k"
  done
  for ((i = 0; i < max; i++)); do
    local -a set=()
    for k in "${!names[@]}"; do
      mapfile -t vals <<<"${lists[$k]}"
      set+=(--set "${names[$k]}=${vals[$((i % ${#vals[@]}))]}")
    done
    probe "$exe" "$quick" "${set[@]}"
  done
}

# jobs.txt: one line per task; a finished task (manifest) skips itself.
write_jobs() {   # DIR EXE QUICK TASK_SEEDS CPUS
  local dir="$1" exe="$2" quick="$3" ks="$4" cpus="$5"
  local tmp header line
  tmp="$(mktemp "$dir/.jobs.XXXXXX")"
  {
    read -r header
    IFS=$'\t' read -r -a names <<<"$header"
    while IFS=$'\t' read -r -a f; do
      local task="${f[1]}" id="${f[1]##*/}"
      line="test -f $(q "$dir/$task/manifest.tsv") || OPENBLAS_NUM_THREADS=$cpus OMP_NUM_THREADS=$cpus NL_COMMIT=$(q "${NL_COMMIT:-unknown}")"
      line+=" $(q "$exe") --out $(q "$dir/$task") --seed ${f[2]} --seeds $ks"
      [ "$quick" = 1 ] && line+=" --quick"
      for ((k = 3; k < ${#f[@]}; k++)); do line+=" --set $(q "${names[$k]}=${f[$k]}")"; done
      line+=" >$(q "$dir/logs/$id.log") 2>&1"
      printf '%s\n' "$line"
    done
  } <"$dir/tasks.tsv" >"$tmp"
  mv "$tmp" "$dir/jobs.txt"
}

write_slurm() {   # DIR EXPERIMENT NTASKS CPUS MEM TIME
  local dir="$1" exp="$2" n="$3" cpus="$4" mem="$5" time="$6" tmp
  tmp="$(mktemp "$dir/.slurm.XXXXXX")"
  cat >"$tmp" <<EOF
#!/bin/bash
# Slurm array job for the noiselab sweep in this folder: one array index per
# line of jobs.txt (a task). Submit: sbatch $(q "$dir/sweep.slurm")
# Finished tasks skip themselves, so resubmitting continues a sweep.
#SBATCH --job-name=noiselab-$exp
#SBATCH --array=0-$((n - 1))
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=$cpus
#SBATCH --mem=$mem
#SBATCH --time=$time
#SBATCH --output="$dir/logs/slurm-%A_%a.out"
set -euo pipefail
line="\$(awk -v n="\$((SLURM_ARRAY_TASK_ID + 1))" 'NR == n' $(q "$dir/jobs.txt"))"
[ -n "\$line" ] || { echo "no task \$SLURM_ARRAY_TASK_ID in jobs.txt" >&2; exit 2; }
exec bash -c "\$line"
EOF
  chmod +x "$tmp"
  mv "$tmp" "$dir/sweep.slurm"
}

count_done() {   # DIR -> number of tasks with a manifest
  local dir="$1" n=0 f
  while IFS=$'\t' read -r _ f _; do [ -f "$dir/$f/manifest.tsv" ] && n=$((n + 1)); done < <(tail -n +2 "$dir/tasks.tsv")
  printf '%d' "$n"
}

progress() {   # DIR TOTAL DONE0 T0 JOBLOG_LINES0 FINAL
  local dir="$1" total="$2" done0="$3" t0="$4" jl0="$5" final="$6"
  local done fail el eta="?"
  done="$(count_done "$dir")"
  fail=0   # the joblog appears with the first finished job
  [ -f "$dir/joblog" ] && fail="$(awk -F'\t' -v s="$jl0" 'NR > s && $1 != "Seq" && ($7 != 0 || $8 != 0)' "$dir/joblog" | wc -l)"
  el=$((SECONDS - t0))
  if [ "$done" -gt "$done0" ]; then eta="$(( el * (total - done) / (done - done0) )) s"; fi
  local msg="sweep: $done/$total done, $fail failed, ${el} s elapsed, ETA $eta"
  if [ -t 2 ]; then
    printf '\r\033[K%s' "$msg" >&2; [ "$final" = 1 ] && printf '\n' >&2
  elif [ "$final" = 1 ] || [ "$done/$fail" != "${LAST_KEY:-}" ] || [ $((el - ${LAST_T:-0})) -ge 30 ]; then
    say "$msg"; LAST_KEY="$done/$fail"; LAST_T=$el   # a log file gets a line per change
  fi
  return 0
}

report_failures() {   # DIR -> 1 if a task has no manifest
  local dir="$1" f id bad=0 rest
  while IFS=$'\t' read -r _ f rest; do
    [ -f "$dir/$f/manifest.tsv" ] && continue
    id="${f##*/}"; bad=$((bad + 1))
    say "sweep: task $id (seed, params: ${rest//$'\t'/ }) failed; log: $dir/logs/$id.log: $(tail -n 1 "$dir/logs/$id.log" 2>/dev/null || echo 'no log')"
  done < <(tail -n +2 "$dir/tasks.tsv")
  [ "$bad" = 0 ]
}

run_local() {   # DIR JOBS
  local dir="$1" jobs="$2" total done0 jl0 pending pid t0=$SECONDS
  command -v parallel >/dev/null || die "GNU parallel is not installed (apt-get install parallel; scripts/noiselab setup does it)"
  total="$(($(wc -l <"$dir/tasks.tsv") - 1))"
  done0="$(count_done "$dir")"
  [ -f "$dir/joblog" ] && jl0="$(wc -l <"$dir/joblog")" || jl0=0
  pending="$(mktemp "$dir/.pending.XXXXXX")"
  # Only unfinished tasks go to parallel, so the joblog records real runs.
  paste <(tail -n +2 "$dir/tasks.tsv" | cut -f2) "$dir/jobs.txt" |
    while IFS=$'\t' read -r f line; do [ -f "$dir/$f/manifest.tsv" ] || printf '%s\n' "$line"; done >"$pending"
  say "sweep: $total tasks, $done0 already done, $(wc -l <"$pending") to run on $jobs job(s) -> $dir"
  parallel --will-cite --jobs "$jobs" --joblog "+$dir/joblog" --halt never <"$pending" >/dev/null 2>"$dir/.parallel.err" &
  pid=$!
  trap 'kill -TERM "$pid" 2>/dev/null; sleep 0.2; kill -TERM "$pid" 2>/dev/null; rm -f "$pending"; say ""; say "sweep: interrupted; the same command continues it"; exit 130' INT TERM
  while kill -0 "$pid" 2>/dev/null; do progress "$dir" "$total" "$done0" "$t0" "$jl0" 0; sleep 1; done
  wait "$pid" || true
  trap - INT TERM
  rm -f "$pending"
  progress "$dir" "$total" "$done0" "$t0" "$jl0" 1
  [ -s "$dir/.parallel.err" ] && sed 's/^/parallel: /' "$dir/.parallel.err" >&2
  rm -f "$dir/.parallel.err"
  report_failures "$dir" || { say "sweep: some tasks failed; fix and run the same command to retry them"; exit 1; }
  say "sweep: all $total tasks done; merge: scripts/noiselab sweep merge $(q "$dir")"
}

merge() {   # DIR [--table T] [--y COL] [--x NAME]
  [ $# -ge 1 ] || die "merge: which sweep folder?"
  local dir="$1" vars
  [ -f "$dir/sweep.tsv" ] || die "$dir: not a sweep folder (no sweep.tsv)"
  vars="$("$TOOL" merge "$@")" || exit 2
  rm -f "$dir/merged/plot.png"
  if ! gnuplot -e "$vars" "$ROOT/scripts/gnuplot/sweep.gp" 2>"$dir/merged/.gnuplot.log" || [ ! -s "$dir/merged/plot.png" ]; then
    cat "$dir/merged/.gnuplot.log" >&2; rm -f "$dir/merged/.gnuplot.log"
    say "noiselab sweep: the plot was not made"; exit 1
  fi
  rm -f "$dir/merged/.gnuplot.log"
  say "sweep: merged into $dir/merged (plot.png)"
}

main() {
  [ $# -ge 1 ] || { usage >&2; exit 2; }
  case "$1" in -h|--help) usage; exit 0 ;; merge) shift; merge "$@"; exit 0 ;; esac
  [ -x "$TOOL" ] || die "no $TOOL (scripts/noiselab setup)"
  local exp="" out="" quick=0 seeds=1 seed=1 ks=1 jobs emit="" cpus=1 mem=2G time=01:00:00
  local -a params=()
  jobs="$(nproc 2>/dev/null || echo 1)"
  while [ $# -gt 0 ]; do
    case "$1" in
      --param|--seeds|--seed|--task-seeds|--out|--jobs|--emit|--cpus|--mem|--time)
        [ $# -ge 2 ] || die "$1: missing value" ;;&
      --param) params+=("$2"); shift ;;
      --seeds) seeds="$2"; shift ;;
      --seed) seed="$2"; shift ;;
      --task-seeds) ks="$2"; shift ;;
      --out) out="$2"; shift ;;
      --jobs) jobs="$2"; shift ;;
      --emit) emit="$2"; shift ;;
      --cpus) cpus="$2"; shift ;;
      --mem) mem="$2"; shift ;;
      --time) time="$2"; shift ;;
      --quick) quick=1 ;;
      -h|--help) usage; exit 0 ;;
      -*) die "unknown option $1 (scripts/noiselab sweep --help)" ;;
      *) [ -z "$exp" ] || die "one experiment per sweep ('$exp', '$1')"; exp="$1" ;;
    esac
    shift
  done
  [ -n "$exp" ] || die "which experiment? (scripts/noiselab sweep --help)"
  [ ${#params[@]} -gt 0 ] || die "no --param NAME=SPEC given"
  [[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "--jobs: '$jobs' is not a positive integer"
  [[ "$cpus" =~ ^[1-9][0-9]*$ ]] || die "--cpus: '$cpus' is not a positive integer"
  [[ "$mem" =~ ^[1-9][0-9]*[KMGT]?$ ]] || die "--mem: '$mem' is not a size like 2G"
  [[ "$time" =~ ^[0-9:-]+$ ]] || die "--time: '$time' is not a Slurm time like 01:00:00"
  case "$emit" in ""|parallel|slurm) ;; *) die "--emit: '$emit' is neither parallel nor slurm" ;; esac
  exp="$(resolve "$exp")"
  local exe="$BUILD/experiments/$exp" plan p names=""
  [ -x "$exe" ] || die "$exp is not built in $BUILD"
  plan=(plan --experiment "$exp" --seed "$seed" --seeds "$seeds" --task-seeds "$ks" --quick "$quick")
  "$TOOL" "${plan[@]}" "${params[@]}" >/dev/null || exit 2     # the specs, before any run
  probe_all "$exe" "$quick" "${params[@]}"
  for p in "${params[@]}"; do names+="-${p%%=*}"; done
  [ -n "$out" ] || out="$ROOT/sweeps/$exp$names"
  mkdir -p "$(dirname "$out")"
  out="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")"   # absolute: job lines run anywhere
  "$TOOL" "${plan[@]}" --out "$out" "${params[@]}" || exit 2
  mkdir -p "$out/logs" "$out/tasks"
  exec 9>"$out/.lock"
  flock -n 9 || die "$out: another sweep is running in this folder"
  write_jobs "$out" "$exe" "$quick" "$ks" "$cpus"
  local n=$(($(wc -l <"$out/tasks.tsv") - 1))
  case "$emit" in
    parallel)
      say "sweep: wrote $out/jobs.txt ($n tasks). Run, e.g. across hosts sharing this path:"
      say "  parallel --will-cite --joblog $(q "$out/joblog") --sshlogin 8/host1,8/host2 < $(q "$out/jobs.txt")" ;;
    slurm)
      write_slurm "$out" "$exp" "$n" "$cpus" "$mem" "$time"
      say "sweep: wrote $out/sweep.slurm ($n array tasks, each $cpus cpu, $mem, $time). Submit:"
      say "  sbatch $(q "$out/sweep.slurm")    # or sbatch --wait; then scripts/noiselab sweep merge $(q "$out")" ;;
    *) run_local "$out" "$jobs" ;;
  esac
}

main "$@"
