#!/usr/bin/env bash
# scripts/sweep.sh - runs the tasks of a parameter sweep on this machine with
# GNU parallel (progress, job log, resumable). Called by `scripts/noiselab
# sweep`, which builds first; it can run alone with NL_BUILD=BUILD_DIR (the
# tests do). Everything else is build/tools/noiselab-sweep (tools/sweep.c):
# checking the options, specs and parameters (the experiment's --params),
# the sweep folder (sweep.tsv, tasks.tsv), the job lines (jobs.txt), the
# Slurm array script (--emit slurm), the sweep's state and `merge`.
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

# One line each, whatever input they quote (message_line, experiments.sh).
say() { message_line "$@"; printf '%s\n' "$REPLY" >&2; }
die() { message_line "$@"; printf 'noiselab sweep: %s\n' "$REPLY" >&2; exit 2; }
# shellcheck source=scripts/experiments.sh
source "$ROOT/scripts/experiments.sh"   # resolve
# shellcheck source=scripts/lock.sh
source "$ROOT/scripts/lock.sh"          # lock_take

progress() {   # DIR TOTAL DONE0 T0 JOBLOG_LINES0 FINAL
  local dir="$1" total="$2" done0="$3" t0="$4" jl0="$5" final="$6"
  local ndone fail=0 el eta="?"
  read -r _ ndone < <("$TOOL" status "$dir")
  # the joblog appears with the first finished job
  [ -f "$dir/joblog" ] && fail="$(awk -F'\t' -v s="$jl0" 'NR > s && $1 != "Seq" && ($7 != 0 || $8 != 0)' "$dir/joblog" | wc -l)"
  el=$((SECONDS - t0))
  if [ "$ndone" -gt "$done0" ]; then eta="$(( el * (total - ndone) / (ndone - done0) )) s"; fi
  local msg="sweep: $ndone/$total done, $fail failed, ${el} s elapsed, ETA $eta"
  if [ -t 2 ]; then
    printf '\r\033[K%s' "$msg" >&2; [ "$final" = 1 ] && printf '\n' >&2
  elif [ "$final" = 1 ] || [ "$ndone/$fail" != "${LAST_KEY:-}" ] || [ $((el - ${LAST_T:-0})) -ge 30 ]; then
    say "$msg"; LAST_KEY="$ndone/$fail"; LAST_T=$el   # a log file gets a line per change
  fi
  return 0
}

# The trap of a running sweep: stops GNU parallel and its tasks, exits CODE.
sweep_stop() {   # CODE (uses run_local's pid and pending)
  trap '' INT TERM   # a second signal does not cut the stop short
  kill -TERM "$pid" 2>/dev/null || true
  sleep 0.2
  kill -TERM "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  rm -f "$pending"
  say ""
  say "sweep: interrupted; the same command continues it"
  exit "$1"
}

run_local() {   # DIR JOBS
  local dir="$1" jobs="$2" total done0 jl0=0 pending pid t0=$SECONDS
  command -v parallel >/dev/null || die "GNU parallel is not installed (apt-get install parallel; scripts/noiselab setup does it)"
  local rc=0
  lock_take "$dir/.lock" "scripts/noiselab sweep $SWEEP_ARGS" || rc=$?
  [ "$rc" = 0 ] || die "$dir: another sweep is running in this folder ($LOCK_HOLDER)"
  # Leftovers of a sweep killed outright (SIGKILL runs no trap): the lock is
  # ours, so no live process owns them.
  rm -f "$dir"/.pending.* "$dir/.parallel.err"
  read -r total done0 < <("$TOOL" status "$dir")
  [ -f "$dir/joblog" ] && jl0="$(wc -l <"$dir/joblog")"
  pending="$(mktemp "$dir/.pending.XXXXXX")"
  # Only unfinished tasks go to parallel, so the joblog records real runs.
  "$TOOL" status "$dir" pending >"$pending"
  say "sweep: $total tasks, $done0 already done, $(wc -l <"$pending") to run on $jobs job(s) -> $dir"
  # The tasks run from the repository, as reproduce's experiments do: their
  # default data/ folders are there. dir and the job lines are absolute
  # (noiselab-sweep prepare), so the user's own paths keep their meaning.
  # The tasks' shell is noiselab-sweep -c (tools/sweep.c): each task dies
  # with parallel, even when a SIGKILL of this sweep's process group ends
  # parallel without its clean-up.
  (cd "$ROOT" && PARALLEL_SHELL="$TOOL" exec parallel --will-cite --jobs "$jobs" --joblog "+$dir/joblog" --halt never \
     <"$pending" >/dev/null 2>"$dir/.parallel.err") &
  pid=$!
  # Exit 128 + the signal's number, as the shell and reproduce do. GNU
  # parallel stops starting tasks at the first SIGTERM and stops the running
  # ones at the second; it is waited for, so no task outlives the sweep.
  trap 'sweep_stop 130' INT
  trap 'sweep_stop 143' TERM
  while kill -0 "$pid" 2>/dev/null; do progress "$dir" "$total" "$done0" "$t0" "$jl0" 0; sleep 1; done
  wait "$pid" || true
  trap - INT TERM
  rm -f "$pending"
  progress "$dir" "$total" "$done0" "$t0" "$jl0" 1
  [ -s "$dir/.parallel.err" ] && sed 's/^/parallel: /' "$dir/.parallel.err" >&2
  rm -f "$dir/.parallel.err"
  "$TOOL" status "$dir" failures || { say "sweep: some tasks failed; fix and run the same command to retry them"; exit 1; }
  say "sweep: all $total tasks done; merge: scripts/noiselab sweep merge $(printf '%q' "$dir")"
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

SWEEP_ARGS="$*"
main() {
  [ -x "$TOOL" ] || die "no $TOOL (scripts/noiselab setup)"
  case "${1:-}" in
    "") "$TOOL" usage >&2; exit 2 ;;
    -h|--help) "$TOOL" usage; exit 0 ;;
    merge) shift; merge "$@"; exit 0 ;;
    -*) die "which experiment? It comes first (scripts/noiselab sweep --help)" ;;
  esac
  local exp plan out jobs
  exp="$(resolve "$1")"; shift
  plan="$("$TOOL" prepare --experiment "$exp" --exe "$BUILD/experiments/$exp" --root "$ROOT" "$@")" || exit 2
  [ -n "$plan" ] || exit 0   # --emit: the files are written, nothing runs here
  IFS=$'\t' read -r out jobs <<<"$plan"
  run_local "$out" "$jobs"
}

main "$@"
