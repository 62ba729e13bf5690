#!/usr/bin/env bash
# noiselab sweep: a small A1 sweep (quick, 2 values x 2 seeds) runs with GNU
# parallel and merges; it resumes without rerunning finished tasks; a failed
# task is reported with its log while the others finish; bad input and a
# folder holding another sweep are refused (exit 2, nothing overwritten);
# the job file and the Slurm script are written; a signal stops it with
# 128 + its number, and SIGKILL leaves nothing running nor behind for the
# next run. With a Slurm cluster (scripts/slurm-local.sh), the same sweep
# goes through sbatch and must merge into identical tables.
set -euo pipefail
tool="$1" expect="$2" out="$3"
src="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
NL_BUILD="$(cd "$(dirname "$tool")/.." && pwd)"
export NL_BUILD
sweep=(bash "$src/scripts/sweep.sh")
rm -rf "$out"; mkdir -p "$out"
# A1: tables and a figure, no image (no OpenImageIO start-up per task: S3's
# tasks would make this test 2.5 times dearer). The bad input and the
# emitted job files below use S3's parameters; they run no task.
def=(a1_bounds --quick --param 'points=500,1000' --seeds 2)
dir="$out/local sweep"   # a space in the path on purpose

"${sweep[@]}" "${def[@]}" --jobs 2 --out "$dir" 2>"$out/run1.err"
grep -q 'sweep: 4/4 done, 0 failed' "$out/run1.err"
"$expect" "$dir/tasks.tsv" rows=4 'points>=500' 'points<=1000'
"${sweep[@]}" merge "$dir" --table bounds.tsv --y max_abs 2>/dev/null
# 2 points x 2 seeds x 8 octave counts (quick); the table's own points column
# is renamed task_points beside the parameter's.
"$expect" "$dir/merged/bounds.tsv" rows=32 'points>=500' 'seed>=1' 'seed<=2' 'max_abs<=bound' 'task_points==points'
"$expect" "$dir/merged/bounds_summary.tsv" rows=16 'n==2' 'max_abs_spread>=0' file:plot.png
# The plot's series colours: 20 distinct (gnuplot's own cycle has 8, so a
# sweep of 10 values drew pairs alike).
{ sed -n '/^array C/,/^shape/p' "$src/scripts/gnuplot/sweep.gp"; echo 'do for [i=0:19] { print col(i) }'; } \
  >"$out/colours.gp"
[ "$(gnuplot "$out/colours.gp" 2>&1 | sort -u | wc -l)" = 20 ] || { echo "sweep.gp: not 20 colours"; exit 1; }

# Resumable: nothing reruns; a task without a manifest (interrupted) does.
jl="$(wc -l <"$dir/joblog")"
"${sweep[@]}" "${def[@]}" --jobs 2 --out "$dir" 2>"$out/run2.err"
grep -q '4 already done, 0 to run' "$out/run2.err"
rm "$dir/tasks/0002/manifest.tsv"
"${sweep[@]}" "${def[@]}" --jobs 2 --out "$dir" 2>"$out/run3.err"
grep -q '3 already done, 1 to run' "$out/run3.err"
[ "$(wc -l <"$dir/joblog")" -eq $((jl + 1)) ]

# A failed task: reported with its log, the others finish, exit 1.
fdir="$out/fail"
rc=0
"${sweep[@]}" "${def[@]}" --out "$fdir" --emit parallel 2>/dev/null
printf 'not a folder\n' >"$fdir/tasks/0001"
"${sweep[@]}" "${def[@]}" --jobs 2 --out "$fdir" 2>"$out/fail.err" || rc=$?
[ "$rc" = 1 ] || { echo "failed task: exit $rc"; cat "$out/fail.err"; exit 1; }
grep -q "task 0001 .*failed; log: $fdir/logs/0001.log" "$out/fail.err"
grep -q '3/4 done, 1 failed' "$out/fail.err"
[ -f "$fdir/tasks/0003/manifest.tsv" ]

# Stopped by a signal, a sweep exits 128 + its number (SIGINT 130, SIGTERM
# 143), as reproduce does. Killed outright (SIGKILL runs no trap), the
# tasks it started stop with it, and the next run into the folder removes
# its leftovers (.pending.*) and finishes the sweep.
kdef=(a1_bounds --quick --param 'points=500,600,700,800,900,1000' --seeds 2 --jobs 1)
stop_sweep() {   # DIR SIGNAL WANT_RC: stopped once its first task has finished
  local d="$1" rc=0 k pid
  set -m   # else a background job starts with SIGINT ignored
  "${sweep[@]}" "${kdef[@]}" --out "$d" 2>"$out/stop.err" &
  pid=$!
  set +m
  for ((k = 0; k < 1200; k++)); do
    compgen -G "$d/tasks/*/manifest.tsv" >/dev/null && break
    sleep 0.05
  done
  kill -"$2" "$pid"
  wait "$pid" || rc=$?
  [ "$rc" = "$3" ] \
    || { cat "$out/stop.err"; echo "sweep stopped by SIG$2: exit $rc, wanted $3"; exit 1; }
}
stop_sweep "$out/stopped" TERM 143
stop_sweep "$out/stopped" INT 130
kdir="$out/killed"
stop_sweep "$kdir" KILL 137
# 10 s: the watchdog stops them at once, but a loaded 2-core CI machine may
# take seconds to schedule it
for ((k = 0; k < 200; k++)); do pgrep -f -- "$kdir/" >/dev/null || break; sleep 0.05; done
left="$(pgrep -a -f -- "$kdir/" || true)"
[ -z "$left" ] || { echo "SIGKILL of the sweep left its tasks running after 10 s: $left"; exit 1; }
"${sweep[@]}" "${kdef[@]}" --out "$kdir" 2>"$out/rerun.err" \
  || { cat "$out/rerun.err"; echo "rerun after SIGKILL failed"; exit 1; }
grep -q 'sweep: 12/12 done, 0 failed' "$out/rerun.err" || { cat "$out/rerun.err"; exit 1; }
left="$(find "$kdir" -name '.pending.*' -o -name '.parallel.err')"
[ -z "$left" ] || { echo "rerun after SIGKILL left $left"; exit 1; }

# A SIGKILL of the sweep's whole process group (the shell, its watchdog and
# GNU parallel, which starts each task in a group of its own) stops the
# tasks too: they die with parallel (noiselab-sweep -c, parallel's shell).
# The tasks of a fake build sleep until killed.
fake="$out/fakebuild"
mkdir -p "$fake/experiments" "$fake/tools"
ln -sf "$(realpath "$tool")" "$fake/tools/noiselab-sweep"
printf 'a1_bounds\n' >"$fake/experiments/experiments.txt"
"$NL_BUILD/experiments/a1_bounds" --params >"$out/a1.params"
cat >"$fake/experiments/a1_bounds" <<FAKE
#!/usr/bin/env bash
if [ "\$1" = --params ]; then cat "$out/a1.params"; exit 0; fi
exec -a "$fake/experiments/a1_bounds-task" sleep 300
FAKE
chmod +x "$fake/experiments/a1_bounds"
gdir="$out/group killed"
NL_BUILD="$fake" setsid "${sweep[@]}" a1_bounds --param 'points=1,2' --jobs 2 --out "$gdir" \
  2>"$out/group.err" &
gpid=$!
for ((k = 0; k < 600; k++)); do
  [ "$(pgrep -c -f "$fake/experiments/a1_bounds-task" || true)" = 2 ] && break
  sleep 0.05
done
[ "$k" -lt 600 ] || { cat "$out/group.err"; echo "the fake sweep's tasks did not start"; exit 1; }
kill -KILL -- "-$gpid"
wait "$gpid" 2>/dev/null || true
for ((k = 0; k < 200; k++)); do pgrep -f "$fake/experiments/a1_bounds-task" >/dev/null || break; sleep 0.05; done
left="$(pgrep -a -f "$fake/experiments/a1_bounds-task" || true)"
if [ -n "$left" ]; then
  # shellcheck disable=SC2046  # one pid a word
  kill $(pgrep -f "$fake/experiments/a1_bounds-task") 2>/dev/null || true
  echo "SIGKILL of the sweep's process group left its tasks running after 10 s: $left"; exit 1
fi

# Bad input: one line, exit 2, and the sweep folder untouched.
cp "$dir/sweep.tsv" "$out/sweep.before"
bad() {   # WANT_FRAGMENT ARGS...
  local want="$1"; shift
  local err rc=0
  err="$("${sweep[@]}" "$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
    echo "sweep $*: rc=$rc err='$err' (wanted '$want')"; exit 1
  fi
}
bad "unknown experiment 'nosuch'" nosuch --param z=1 --out "$out/x"
bad "--param gain: unknown parameter for s3_fbm" s3_fbm --quick --param gain=0:1:5 --out "$out/x"
bad "--param size: 8 is outside [16, 4096]" s3_fbm --quick --param size=8 --out "$out/x"
bad "empty range" s3_fbm --param z=0:1:0 --out "$out/x"
bad "a log range needs positive ends" s3_fbm --param z=0:1:log5 --out "$out/x"
bad "a log range needs positive ends" s3_fbm --param z=1:-2:log5 --out "$out/x"
bad "no --param" s3_fbm --out "$out/x"
bad "holds a different sweep" "${def[@]}" --seeds 3 --out "$dir"
bad "holds a different sweep" a1_bounds --quick --param points=500,2000 --seeds 2 --out "$dir"
[ ! -e "$out/x" ]
cmp "$dir/sweep.tsv" "$out/sweep.before"
"${sweep[@]}" merge "$out/nonexistent" 2>/dev/null && exit 1

# Job files: GNU parallel's and Slurm's (one array index per task).
edir="$out/emit"
"${sweep[@]}" s3_fbm --quick --param 'z=1e-2:1:log3' --param size=32 --seeds 2 --out "$edir" --emit slurm --cpus 1 --mem 500M --time 00:10:00 2>/dev/null
[ "$(wc -l <"$edir/jobs.txt")" = 6 ]
grep -q -- '--set '"'"'z=0.1'"'"'' "$edir/jobs.txt"
# Tasks write tables only (--no-images) unless --images is given.
[ "$(grep -c -- ' --no-images ' "$edir/jobs.txt")" = 6 ] && grep -q $'^images\tno$' "$edir/sweep.tsv"
"${sweep[@]}" s3_fbm --quick --images --param size=32,48 --out "$out/emit_images" --emit parallel 2>/dev/null
! grep -q -- '--no-images' "$out/emit_images/jobs.txt" && grep -q $'^images\tyes$' "$out/emit_images/sweep.tsv"
grep -q '^#SBATCH --array=0-5$' "$edir/sweep.slurm"
grep -q '^#SBATCH --mem=500M$' "$edir/sweep.slurm"
[ ! -e "$edir/tasks/0000/manifest.tsv" ]   # emitting runs nothing

# Slurm for real, when there is a cluster to submit to.
if ! command -v sbatch >/dev/null; then
  echo "cli_sweep: Slurm part skipped: sbatch not installed (scripts/slurm-local.sh starts a one-node cluster)"
elif ! timeout 10 sinfo -h -o '%t' 2>/dev/null | grep -Eq 'idle|mix|alloc'; then
  echo "cli_sweep: Slurm part skipped: no idle Slurm node answers (scripts/slurm-local.sh starts one)"
else
  sdir="$out/slurm sweep"
  "${sweep[@]}" "${def[@]}" --out "$sdir" --emit slurm --mem 500M --time 00:10:00 2>/dev/null
  timeout 300 sbatch --wait --quiet "$sdir/sweep.slurm" || { cat "$sdir"/logs/* >&2; echo "sbatch failed"; exit 1; }
  "${sweep[@]}" merge "$sdir" --table bounds.tsv --y max_abs 2>/dev/null
  for f in "$dir"/merged/*.tsv; do cmp "$f" "$sdir/merged/$(basename "$f")"; done
  merged=("$dir"/merged/*.tsv)
  echo "cli_sweep: Slurm sweep identical to the local one (${#merged[@]} tables)"
fi
echo "cli_sweep: ok"
