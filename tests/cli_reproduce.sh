#!/usr/bin/env bash
# scripts/noiselab reproduce, check and bench as a user runs them:
#  - a bad seed or experiment is one line and exit 2, and writes nothing;
#  - REPORT.md is 0644, dated by SOURCE_DATE_EPOCH when set, never written
#    when nothing ran, and names complete folders only;
#  - SIGINT / SIGTERM during gnuplot stop it (and check) with exit 130 / 143, SIGKILL
#    leaves no figure under its final name that is not whole and no folder
#    with a manifest but without its figures; a rerun recovers;
#  - a rerun that fails or is stopped keeps the previous complete folder,
#    REPORT.md and report.html; REPORT.md follows each completed folder at
#    once, so a run killed later leaves it current;
#  - a second reproduce into the same folder names the first and exits 1,
#    also when both start together; SIGKILL stops what the run started;
#  - a rerun removes the outputs an earlier run listed and it did not write,
#    never a file no run listed;
#  - list (id, name, title) and params EXPERIMENT answer as TSV tables;
#  - bench runs every benchmark, skips meson's bench_*.p/ folders, and fails
#    at the end naming the failed ones.
# The runs use A1 (0.05 s: tables and one figure, no image, so no
# OpenImageIO start-up) and S4 (a texture image), for the test's CPU time;
# which experiments run does not matter to what is tested here.
# Args: NOISELAB_SCRIPT EXPECT OUTDIR. A fake gnuplot on PATH writes half a
# PNG where gnuplot would, then sleeps, so the signal lands mid-figure.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$3"
root="$(cd "$(dirname "$nl")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out/bin"
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
unset SOURCE_DATE_EPOCH
fail() { echo "cli_reproduce: $*"; exit 1; }

one_line_exit2() {   # WANT_FRAGMENT ARGS...
  local want="$1"; shift
  local err rc=0
  err="$("$nl" "$@" 2>&1 >/dev/null)" || rc=$?
  { [ "$rc" = 2 ] && [ "$(printf '%s\n' "$err" | wc -l)" = 1 ] && [[ "$err" == *"$want"* ]]; } \
    || fail "noiselab $*: rc=$rc, wanted exit 2 and one line with '$want'; got: $err"
}
one_line_exit2 "unknown experiment 'Z9'" check Z9
one_line_exit2 "unknown experiment 'Z9'" params Z9
# list and params: TSV with a header, read by column name
# shellcheck source=tests/tsv.sh
. "$root/tests/tsv.sh"
"$nl" list > "$out/list.tsv" || fail "list failed"
[ "$(tsv_awk 'FNR > 1 && v("title") != "" { k++ } END { print k }' "$out/list.tsv")" = "$(($(wc -l < "$out/list.tsv") - 1))" ] \
  || fail "list: a row without a title: $(cat "$out/list.tsv")"
[ "$(tsv_awk 'v("id") == "S3" { print v("name") }' "$out/list.tsv")" = s3_fbm ] || fail "list: no S3"
"$nl" params S3 > "$out/params.tsv" || fail "params S3 failed"
[ "$(tsv_awk 'v("name") == "octaves" { print v("default") }' "$out/params.tsv")" = 6 ] || fail "params S3: $(cat "$out/params.tsv")"
one_line_exit2 "--seed: '99999999999' is not an integer in 0..4294967295" reproduce --quick --seed 99999999999 --out "$out/seed" S3
one_line_exit2 "--seed: '4294967296'" reproduce --quick --seed 4294967296 --out "$out/seed" S3
[ ! -e "$out/seed" ] || fail "a refused seed made $out/seed"

r="$out/r"
# A complete run of two experiments: REPORT.md 0644, dated by SOURCE_DATE_EPOCH.
SOURCE_DATE_EPOCH=86400 "$nl" reproduce --quick --seed 4294967295 --out "$r" A1 S4 2>"$out/first.log" || { cat "$out/first.log"; fail "first reproduce failed"; }
[ "$(stat -c %a "$r/REPORT.md")" = 644 ] || fail "REPORT.md mode $(stat -c %a "$r/REPORT.md"), wanted 644"
grep -q 'on 1970-01-02\.' "$r/REPORT.md" || fail "REPORT.md not dated by SOURCE_DATE_EPOCH"
grep -q $'^seed\t4294967295$' "$r/a1_bounds/manifest.tsv" || fail "seed 4294967295 did not reach the experiment"
# The verdict table: every complete folder's verdicts.tsv, read by column
# name (planted here for S4, beside A1's own), counted: independent rows as
# verdicts, the others by kind, a fitted row capped below "reproduced".
{ printf 'reason\tquantity\tsource\tpaper\tours\tours_sd\trule\tkind\tverdict\tcontrol\tcontrol_ours\tcontrol_verdict\n'
  printf 'why\tgain\tx.tsv:g\t2\t2.08\t0.01\trel 0.05 0.25\tindependent\treproduced\ta flat image\t0.912345\tnot reproduced\n'
  printf 'fit\tslope |s|\tx.tsv:s\t2\t2.01\t-\trel 0.05 0.25\tfitted 2/4\tconsistent after fit\t-\t-\t-\n'
  printf 'set\tF_inf\tx.tsv:f\t1\t1\t-\tabs 0 0\tby construction\tby construction\t-\t-\t-\n'
} >"$r/s4_marble/verdicts.tsv"
SOURCE_DATE_EPOCH=86400 "$nl" reproduce --quick --seed 4294967295 --out "$r" A1 2>"$out/verdict.log" || { cat "$out/verdict.log"; fail "reproduce A1 failed"; }
grep -q '^## Did it reproduce?' "$r/REPORT.md" || fail "REPORT.md has no verdict table"
# a quick run says first, on the terminal and at the top of the report, that
# its verdicts are about the harness, not the papers
awk '/quick scale .*verdicts test the harness, not the papers/ { c = NR } /\[1\/1\]/ && !r { r = NR }
  END { exit !(c && c < r) }' "$out/verdict.log" || fail "no quick-scale caveat before the run: $(cat "$out/verdict.log")"
grep -q '^\*\*Quick scale: .*the harness, not the papers' "$r/REPORT.md" || fail "no quick caveat in REPORT.md"
a1_count() { [ -f "$r/a1_bounds/verdicts.tsv" ] || { echo 0; return; }; tsv_awk -v w="$1" 'FNR > 1 && index(v("kind"), w) == 1 { cnt++ } END { print cnt + 0 }' "$r/a1_bounds/verdicts.tsv"; }
ni=$(( $(a1_count independent) + 1 )); nf=$(( $(a1_count fitted) + 1 ))
grep -qE "^$ni independent verdicts \(" "$r/REPORT.md" || fail "verdict count wrong: $(grep 'independent verdicts' "$r/REPORT.md")"
grep -qE "^Not counted above: $nf fitted to the paper \([0-9]+ consistent after fit\)" "$r/REPORT.md" || fail "fitted count wrong: $(grep 'Not counted' "$r/REPORT.md")"
# a row: the rule's thresholds in their own column, the reason as the experiment gave it
# and its negative control: the same rule on a baseline without the method
row='| [S4](#s4_marble) | gain | independent | 2 | 2.08 +- 0.01 | **reproduced** | 5% / 25% | a flat image: 0.9123, not reproduced | why |'
grep -qF "$row" "$r/REPORT.md" || fail "verdict row: $(grep -F gain "$r/REPORT.md")"
row='| [S4](#s4_marble) | F_inf | by construction | 1 | 1 | *by construction* | equal | - | set |'
grep -qF "$row" "$r/REPORT.md" || fail "by-construction row: $(grep -F F_inf "$r/REPORT.md")"
# one summary line per experiment, above the table: its independent rows
# counted by verdict, the others by kind and never under a verdict's word
sum='^- \[S4 - [^]]*\]\(#s4_marble\): \*\*1 reproduced\*\*; not counted: 1 fitted \(1 consistent\), '
grep -qE "$sum"'1 by construction$' "$r/REPORT.md" ||
  fail "summary line: $(grep -F '(#s4_marble):' "$r/REPORT.md")"
# the answer per paper (S4: Shaffer's slides; A1: Arnerin's), first: its
# citation, its independent verdicts counted, the rest by kind, the sentence
grep -qE '^\| \*\*Shaffer\*\* Eric Shaffer\. .* \| 1 \| 0 \| 0 \| 1 fitted \(1 consistent\), 1 by construction \| .* \| Every counted number reproduces: 1 of 1\. \|$' \
  "$r/REPORT.md" || fail "per-paper row: $(grep -F '**Shaffer**' "$r/REPORT.md")"
grep -qE '^\| \*\*Arnerin 2009\*\* Reynald Arnerin\. ' "$r/REPORT.md" || fail "no per-paper row for Arnerin"
at() { grep -n -m1 "$1" "$r/REPORT.md" | cut -d: -f1; }
[ "$(at '(#s4_marble):')" -lt "$(at '^| id | quantity')" ] || fail "the summary is below the table"
[ "$(at '^| paper |')" -lt "$(at '(#s4_marble):')" ] || fail "the per-paper table is below the experiment lines"
# a | inside a cell is escaped, or it would split the row
grep -qF '| [S4](#s4_marble) | slope \|s\| | fitted 2/4 |' "$r/REPORT.md" || fail "a | in a cell: $(grep -F slope "$r/REPORT.md")"
rm "$r/s4_marble/verdicts.tsv"

# Nothing ran (the experiment cannot make its folder): no REPORT.md written.
mkdir -p "$out/none"; : >"$out/none/a1_bounds"
rc=0; "$nl" reproduce --quick --out "$out/none" A1 2>"$out/none.log" || rc=$?
[ "$rc" != 0 ] || fail "reproduce into a blocked folder passed"
[ ! -e "$out/none/REPORT.md" ] || fail "REPORT.md written when nothing ran"

# Whole PNG: the signature first and the IEND chunk last.
png_ok() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] && [ "$(tail -c 12 "$1" | head -c 8 | tail -c 4)" = IEND ]; }
consistent() {   # LABEL: every final PNG whole; a manifest only with all figures; REPORT.md names complete folders only
  local label="$1" f d e gp fig
  while IFS= read -r f; do png_ok "$f" || fail "$label: $f is not a whole PNG"; done < <(find "$r" -name '*.png' -not -path '*/.fig-*')
  for d in "$r"/*/; do
    e="$(basename "$d")"
    [ -f "$d/manifest.tsv" ] || continue
    for gp in "$root"/scripts/gnuplot/"$e"-*.gp; do
      [ -e "$gp" ] || continue
      fig="$(basename "$gp" .gp)"; fig="${fig#"$e"-}"
      [ -s "$d/$fig.png" ] || fail "$label: $e has a manifest but no $fig.png"
    done
  done
  if [ -f "$r/REPORT.md" ]; then
    while IFS= read -r e; do
      [ -f "$r/$e/manifest.tsv" ] || fail "$label: REPORT.md names $e, which has no manifest"
    done < <(sed -n 's/^<a id="\(.*\)"><\/a>$/\1/p' "$r/REPORT.md")
  fi
}
consistent "complete run"

cat >"$out/bin/gnuplot" <<'FAKE'
#!/usr/bin/env bash
# Fake gnuplot: half a PNG where the script's `set output dir.'/X.png'` says, then waits.
dir=""; gp=""
while [ $# -gt 0 ]; do
  case "$1" in -e) dir="$(printf '%s' "$2" | sed -n "s/^dir='\(.*\)'$/\1/p")"; shift ;; *) gp="$1" ;; esac
  shift
done
# FAKE_GNUPLOT_ONLY: only scripts whose path holds it; the others go to the real one.
if [ -n "${FAKE_GNUPLOT_ONLY:-}" ] && [[ "$gp" != *"$FAKE_GNUPLOT_ONLY"* ]]; then
  exec "$REAL_GNUPLOT" -e "dir='$dir'" "$gp"
fi
f="$(sed -n "s/^set output dir\.'\(.*\)'.*/\1/p" "$gp" | head -n 1)"
printf '\211PNG\r\n\032\n\000\000\000\rIHDR' >"$dir$f"
echo $$ >"$FAKE_GNUPLOT_MARK"
exec sleep 60   # the pid in the mark is the one to stop
FAKE
chmod +x "$out/bin/gnuplot"

start_slow() {   # EXPERIMENT: reproduce in the background with the fake gnuplot; sets PID once gnuplot runs
  rm -f "$out/mark"
  # Job control on: without it bash starts background jobs with SIGINT
  # ignored, and an ignored signal cannot be trapped.
  set -m
  FAKE_GNUPLOT_MARK="$out/mark" PATH="$out/bin:$PATH" "$nl" reproduce --quick --out "$r" "$1" 2>"$out/slow.log" &
  PID=$!
  local k
  for ((k = 0; k < 600; k++)); do   # 60 s
    [ -s "$out/mark" ] && { set +m; return 0; }
    kill -0 "$PID" 2>/dev/null || break
    sleep 0.1
  done
  set +m
  cat "$out/slow.log"; fail "the fake gnuplot never ran"
}
stop_slow() {   # SIGNAL WANT_RC
  local rc=0
  kill -"$1" "$PID"
  wait "$PID" || rc=$?
  [ "$rc" = "$2" ] || { cat "$out/slow.log"; fail "reproduce got SIG$1 during gnuplot: exit $rc, wanted $2"; }
}

# SIGINT during gnuplot: exit 130, A1 incomplete, REPORT.md rewritten with S4 only.
start_slow A1
# Meanwhile a second run into the same folder names the first and exits 1.
rc=0; err="$("$nl" reproduce --quick --out "$r" S4 2>&1 >/dev/null)" || rc=$?
{ [ "$rc" = 1 ] && [[ "$err" == *"in use"*"pid $PID"*"reproduce"* ]]; } \
  || fail "second reproduce: rc=$rc: $err"
stop_slow INT 130
consistent "SIGINT"

# Two runs started together: the one that finds the lock taken names the
# other's pid and command, never "holder unknown". A slow `date` (the
# holder's start time, asked once) keeps the first between taking the lock
# and writing its line, where the second used to find an empty lock file.
mkdir -p "$out/slowdate"
cat >"$out/slowdate/date" <<'FAKE'
#!/usr/bin/env bash
if [[ "$*" == *T%H:%M:%SZ* ]] && mkdir "$SLOW_DATE_ONCE" 2>/dev/null; then sleep 3; fi
exec /usr/bin/date "$@"
FAKE
chmod +x "$out/slowdate/date"
lk="$out/lockrace"; mkdir -p "$lk"
# shellcheck disable=SC2016  # the inner scripts' own $1 and $2
SLOW_DATE_ONCE="$out/slowdate/once" PATH="$out/slowdate:$PATH" \
  bash -c 'source "$1"; REPRO_ARGS="--quick A1"; take_lock "$2"; exec sleep 30' _ "$nl" "$lk" \
  2>"$out/race1.log" &
first=$!
for ((k = 0; k < 100; k++)); do
  [ ! -e "$lk/.noiselab.lock" ] || break
  sleep 0.1
done
# shellcheck disable=SC2016
rc=0; err="$(bash -c 'source "$1"; take_lock "$2"' _ "$nl" "$lk" 2>&1)" || rc=$?
kill "$first" 2>/dev/null || true
wait "$first" 2>/dev/null || true
{ [ "$rc" = 1 ] && [[ "$err" == *"in use"*"pid $first"*"reproduce --quick A1"* ]]; } \
  || fail "two runs at once: the second said (rc=$rc): $err"
# The stopped rerun of A1 took nothing away: its previous complete run
# (seed 4294967295) and REPORT.md's section stay.
grep -q $'^seed\t4294967295$' "$r/a1_bounds/manifest.tsv" || fail "SIGINT: a1_bounds lost its previous run"
{ grep -q '<a id="s4_marble">' "$r/REPORT.md" \
  && grep -q '<a id="a1_bounds">' "$r/REPORT.md"; } \
  || fail "SIGINT: REPORT.md does not name the complete folders"
[ -z "$(find "$r" -name '.fig-*' -o -name '.stage-*')" ] || fail "SIGINT left temporary folders"

# SIGTERM: exit 143; S4's previous run and REPORT.md stay as they were.
cp "$r/REPORT.md" "$out/report-before-term.md"
start_slow S4
stop_slow TERM 143
consistent "SIGTERM"
{ [ -f "$r/s4_marble/manifest.tsv" ] && cmp -s "$r/REPORT.md" "$out/report-before-term.md"; } \
  || fail "SIGTERM: the previous S4 run or REPORT.md was not kept"

# SIGKILL: nothing runs after it. The processes it started (here the fake
# gnuplot) hold the folder's lock; its watchdog stops them, so they neither
# write into the folder nor keep the next run out.
# (A process that has exited counts as gone even before its new parent
# reaps it: this machine's init reaps orphans about a second late.)
running() { [ -e "/proc/$1" ] && ! grep -q '^[0-9]* ([^)]*) Z' "/proc/$1/stat" 2>/dev/null; }
start_slow A1
g="$(cat "$out/mark")"
stop_slow KILL 137
# 10 s: the watchdog stops it at once, but a loaded 2-core CI machine may
# take seconds to schedule it.
for ((k = 0; k < 100; k++)); do
  running "$g" || break
  sleep 0.1
done
if running "$g"; then
  kill "$g"
  fail "SIGKILL: gnuplot (pid $g), started by the killed run, still runs 10 s later"
fi
consistent "SIGKILL"

# A rerun recovers: both complete, no leftovers.
"$nl" reproduce --quick --out "$r" S4 A1 2>"$out/rerun.log" || { cat "$out/rerun.log"; fail "rerun failed"; }
consistent "rerun"
{ [ -f "$r/a1_bounds/manifest.tsv" ] && [ -f "$r/s4_marble/manifest.tsv" ]; } \
  || fail "rerun: a folder is incomplete"
[ -z "$(find "$r" -name '.fig-*' -o -name '.manifest-pending.tsv' -o -name '.stage-*')" ] \
  || fail "rerun left temporaries"

# A rerun that fails (here every figure: a full disk did the same) keeps the
# previous complete folder, REPORT.md and report.html byte for byte, and
# says so.
mkdir -p "$out/failbin"; printf '#!/bin/sh\nexit 1\n' >"$out/failbin/gnuplot"; chmod +x "$out/failbin/gnuplot"
for f in REPORT.md report.html s4_marble/manifest.tsv s4_marble/report.md; do cp "$r/$f" "$out/keep-${f//\//-}"; done
rc=0; PATH="$out/failbin:$PATH" "$nl" reproduce --quick --seed 9 --out "$r" S4 2>"$out/failrerun.log" || rc=$?
if [ "$rc" != 2 ] || ! grep -q "^noiselab: s4_marble: figure .* was not made .*; the previous run in $r/s4_marble is kept$" \
     "$out/failrerun.log"; then
  cat "$out/failrerun.log"; fail "failed rerun: rc=$rc"
fi
for f in REPORT.md report.html s4_marble/manifest.tsv s4_marble/report.md; do
  cmp -s "$r/$f" "$out/keep-${f//\//-}" || fail "a failed rerun changed $f"
done
[ -z "$(find "$r" -name '.stage-*')" ] || fail "failed rerun left its stage"
# A full disk is named as such (less than 1 MB free where the run writes).
mkdir -p "$out/fullbin"
# shellcheck disable=SC2016  # the fake's own $1 and $@
printf '#!/bin/sh\n[ "$1" = -f ] && { echo "100 4096"; exit 0; }\nexec /usr/bin/stat "$@"\n' >"$out/fullbin/stat"
chmod +x "$out/fullbin/stat"
# shellcheck disable=SC2016
[ "$(PATH="$out/fullbin:$PATH" bash -c 'source "$1"; space_note /x' _ "$nl")" = ", the disk holding /x is full (400 KB free)" ] \
  || fail "space_note: $(PATH="$out/fullbin:$PATH" bash -c 'source "$1"; space_note /x' _ "$nl")"

# --jobs (default: the number of cores; the rerun above ran S4 and A1 at
# once): the same tables, figures' data and report sections as --jobs 1, and
# the messages in report order (A1, 0.05 s, ends long before S4, which loads
# OpenImageIO); a failed experiment fails the whole run with its message
# while the others finish.
j1="$out/j1"
"$nl" reproduce --quick --jobs 1 --out "$j1" A1 S4 2>"$out/j1.log" || { cat "$out/j1.log"; fail "reproduce --jobs 1 failed"; }
for f in "$j1"/*/*.tsv "$j1"/*/report.md; do
  case "$f" in */run.tsv) continue ;; esac   # the times: the manifests must agree
  cmp -s "$f" "$r/${f#"$j1"/}" || fail "--jobs 1 and --jobs $(nproc) differ in ${f#"$j1"/}"
done
[ "$(grep -o '^noiselab: \[[0-9]/2\] [a-z0-9_]*\|^noiselab: [a-z0-9_]* done in' "$out/rerun.log" | sed 's/ done in//')" = \
  "$(printf 'noiselab: [1/2] s4_marble\nnoiselab: s4_marble\nnoiselab: [2/2] a1_bounds\nnoiselab: a1_bounds')" ] \
  || fail "--jobs: messages not in report order: $(cat "$out/rerun.log")"
jf="$out/jfail"; mkdir -p "$jf"; : >"$jf/a1_bounds"
rc=0; "$nl" reproduce --quick --jobs 2 --out "$jf" A1 S4 2>"$out/jfail.log" || rc=$?
{ [ "$rc" = 2 ] && grep -q '^noiselab: a1_bounds: .*/jfail/a1_bounds is not a folder (a file or a link)' "$out/jfail.log" \
  && [ "$(tail -n 1 "$out/jfail.log")" = "noiselab: reproduce: 1 experiment(s) failed" ] \
  && [ -f "$jf/s4_marble/manifest.tsv" ] && grep -q '<a id="s4_marble">' "$jf/REPORT.md" \
  && [ -z "$(find "$jf" -name '.log-*')" ]; } \
    || fail "--jobs 2 with a failing experiment: rc=$rc: $(cat "$out/jfail.log")"

# A run replaces the outputs of an earlier one: a table an earlier run
# listed in its manifest ("output" lines) and this one did not write goes;
# a file no run listed (the user's notes) stays. After an interrupted run
# (no manifest) the list is in .outputs-previous.tsv.
st="$out/stale"
a4="$st/a4_normalised"
rerun_a4() {   # N: the N-th run of A4 into st
  "$nl" reproduce --quick --out "$st" A4 2>"$out/stale$1.log" \
    || { cat "$out/stale$1.log"; fail "run $1 of A4 failed"; }
}
rerun_a4 1
grep -q $'^output\taliasing.tsv$' "$a4/manifest.tsv" \
  || fail "the manifest lists no outputs: $(cat "$a4/manifest.tsv")"
printf 'x\n1\n' >"$a4/sweep_headline.tsv"
printf 'output\tsweep_headline.tsv\n' >>"$a4/manifest.tsv"
echo "my notes" >"$a4/notes.txt"
printf 'x\n1\n' >"$a4/mine.tsv"
rerun_a4 2
[ ! -e "$a4/sweep_headline.tsv" ] \
  || fail "a table listed by the earlier run and not written now survived the rerun"
{ [ "$(cat "$a4/notes.txt")" = "my notes" ] && [ -f "$a4/mine.tsv" ]; } \
  || fail "the rerun removed a file no run wrote"
printf 'x\n1\n' >"$a4/old_table.tsv"
printf 'output\nold_table.tsv\n' >"$a4/.outputs-previous.tsv"
rm "$a4/manifest.tsv"
rerun_a4 3
{ [ ! -e "$a4/old_table.tsv" ] && [ ! -e "$a4/.outputs-previous.tsv" ] \
  && [ -f "$a4/notes.txt" ]; } \
  || fail "after an interrupted run: $(ls -a "$a4")"

# bench: every regular executable bench_* runs; a failure is reported at the end.
b="$out/bench"; mkdir -p "$b/bench_cellular.p"
printf '#!/bin/sh\necho ran-a >>"%s/ran"\n' "$b" >"$b/bench_a"
printf '#!/bin/sh\necho ran-c >>"%s/ran"\nexit 3\n' "$b" >"$b/bench_c"
printf '#!/bin/sh\necho ran-d >>"%s/ran"\n' "$b" >"$b/bench_d"
chmod +x "$b"/bench_*
rc=0; err="$(bash -c 'source "$1"; run_benchmarks "$2"' _ "$nl" "$b" 2>&1 >/dev/null)" || rc=$?
{ [ "$rc" = 2 ] && [[ "$err" == *"1 benchmark(s) failed: bench_c"* ]]; } \
  || fail "bench: rc=$rc: $err"
[ "$(tr '\n' ' ' <"$b/ran")" = "ran-a ran-c ran-d " ] || fail "bench: ran $(cat "$b/ran")"
# check stopped by a signal: exit 128 + its number, as reproduce and sweep;
# the experiment it was running is stopped, its folder removed.
stop_check() {   # SIGNAL WANT_RC
  local rc=0 k pid exp=""
  : >"$out/check-stamp"
  set -m
  "$nl" check --quick C1 >/dev/null 2>"$out/check-stop.log" &
  pid=$!
  set +m
  for ((k = 0; k < 600; k++)); do
    exp="$(pgrep -f "^$root/build/experiments/c1_textures --out $root/build/check-quick\\." \
           || true)"
    [ -z "$exp" ] || break
    sleep 0.1
  done
  [ -n "$exp" ] || fail "check --quick C1 never ran c1_textures: $(cat "$out/check-stop.log")"
  kill -"$1" "$pid"
  wait "$pid" || rc=$?
  [ "$rc" = "$2" ] || fail "check got SIG$1: exit $rc, wanted $2: $(cat "$out/check-stop.log")"
  ! kill -0 "$exp" 2>/dev/null || { kill "$exp"; fail "check got SIG$1: c1_textures still runs"; }
  [ -z "$(find "$root/build" -maxdepth 1 -name 'check-quick.*' -newer "$out/check-stamp")" ] \
    || fail "check got SIG$1: its folder is left: $(ls -d "$root"/build/check-quick.*)"
}
stop_check INT 130
stop_check TERM 143
# check --quick with an unknown id: the one line of resolve, nothing after it.
one_line_exit2 "unknown experiment 'Q9'" check --quick Q9
# Without --out, reproduce writes into the git-tracked results/ and says so
# before it starts. The lock on results/ is held here, so it stops right
# after the warning ("in use", exit 1) and writes nothing; skipped when a
# real run holds that lock.
exec 8<>"$root/results/.noiselab.lock"
if flock -n 8; then
  rc=0; err="$("$nl" reproduce A1 2>&1 >/dev/null)" || rc=$?
  { [ "$rc" = 1 ] \
    && [[ "$(printf '%s\n' "$err" | head -n 1)" == \
    *"writing into results/, the committed (git-tracked) results"* ]]; } \
    || fail "reproduce without --out: rc=$rc, no warning first: $err"
fi
exec 8>&-
# --resume skips a folder whose manifest has the requested seed, seeds,
# --quick and commit, and names it; another seed reruns it (the rerun
# above made A1 and S4 with seed 1). An ETA line follows every experiment
# but the last.
rs="$r"
grep -q '^noiselab: 1/2 done, elapsed [0-9]* s, ETA [0-9]' "$out/rerun.log" || fail "no ETA line: $(cat "$out/rerun.log")"
"$nl" reproduce --quick --resume --out "$rs" A1 S4 2>"$out/resume2.log" || { cat "$out/resume2.log"; fail "reproduce --resume failed"; }
{ grep -q '^noiselab: reproduce --resume: skipped 2 of 2 (.*): a1_bounds s4_marble$' \
  "$out/resume2.log" \
  && ! grep -q ' done in ' "$out/resume2.log"; } \
    || fail "--resume did not skip both: $(cat "$out/resume2.log")"
"$nl" reproduce --quick --resume --seed 2 --out "$rs" A1 2>"$out/resume3.log" || { cat "$out/resume3.log"; fail "reproduce --resume --seed 2 failed"; }
{ grep -q '^noiselab: reproduce --resume: skipped 0 of 1 (manifest with seed 2, --quick, ' \
  "$out/resume3.log" \
  && grep -q 'a1_bounds done in' "$out/resume3.log" \
    && grep -q $'^seed\t2$' "$rs/a1_bounds/manifest.tsv"; } \
  || fail "--resume with another seed did not rerun: $(cat "$out/resume3.log")"
# The rule itself: another commit or another seeds count is not finished.
matches() { bash -c 'source "$1"; shift; resume_matches "$@"' _ "$nl" "$@"; }
c="$(awk -F'\t' '$1 == "commit" { print $2 }' "$rs/s4_marble/manifest.tsv")"
matches "$rs/s4_marble/manifest.tsv" s4_marble 1 1 "$c" || fail "resume_matches: the run itself does not match"
! matches "$rs/s4_marble/manifest.tsv" s4_marble 1 1 "0000$c" || fail "resume_matches: another commit matches"
! matches "$rs/s4_marble/manifest.tsv" s4_marble 1 0 "$c" || fail "resume_matches: a --quick run matches a full one"
sed $'s/^seeds\t.*/seeds\t7/' "$rs/s4_marble/manifest.tsv" >"$out/seeds7.tsv"
! matches "$out/seeds7.tsv" s4_marble 1 1 "$c" || fail "resume_matches: another seeds count matches"
sed $'s/^images\t.*/images\tno/' "$rs/s4_marble/manifest.tsv" >"$out/noimages.tsv"
{ grep -q $'^images\tno$' "$out/noimages.tsv" \
  && ! matches "$out/noimages.tsv" s4_marble 1 1 "$c"; } \
  || fail "resume_matches: a --no-images run matches"
# A package held at its version (apt-mark hold) is installed: no apt-get.
mkdir -p "$out/dpkg"
printf '#!/bin/sh\nprintf "gnuplot-nox hold ok installed\\nmeson install ok installed\\n"\n' \
  >"$out/dpkg/dpkg-query"
chmod +x "$out/dpkg/dpkg-query"
# shellcheck disable=SC2016
missing="$(PATH="$out/dpkg:$PATH" bash -c 'source "$1"; missing_packages gnuplot-nox meson pandoc' _ "$nl")"
[ "$missing" = "pandoc " ] || fail "missing_packages with gnuplot-nox held: '$missing', wanted 'pandoc '"
# ETA: previous times scaled by this run's pace, the mean so far for the rest.
[ "$(bash -c 'source "$1"; repro_eta 10 1 5 20 -' _ "$nl")" = "1/3 done, elapsed 10 s, ETA 50 s (previous times and mean so far x 2)" ] \
  || fail "repro_eta: $(bash -c 'source "$1"; repro_eta 10 1 5 20 -' _ "$nl")"
# A fast experiment (0 s of 0.5 s before) gives no scale ("x 0"), and the
# last line no ETA.
# shellcheck disable=SC2016
[ "$(bash -c 'source "$1"; repro_eta 0 1 0.5 3' _ "$nl")" = "1/2 done, elapsed 0 s, ETA 3 s (previous times)" ] \
  || fail "repro_eta fast: $(bash -c 'source "$1"; repro_eta 0 1 0.5 3' _ "$nl")"
# shellcheck disable=SC2016
[ "$(bash -c 'source "$1"; repro_eta 7 2 3 4' _ "$nl")" = "2/2 done, elapsed 7 s" ] \
  || fail "repro_eta last: $(bash -c 'source "$1"; repro_eta 7 2 3 4' _ "$nl")"
# SIGKILL after A1 finished a seed-3 run into a complete folder (A1 seed 2,
# S4 seed 1), while S4's figure is made: REPORT.md already lists A1's seed-3
# run (written with its folder) and S4's previous run, which is kept;
# report.html follows at the end of a run, so it is behind. The next
# reproduce into the folder, even one that runs nothing (--resume skips
# A1), makes report.html agree first.
rm -f "$out/mark"
FAKE_GNUPLOT_ONLY=s4_marble REAL_GNUPLOT="$(command -v gnuplot)" FAKE_GNUPLOT_MARK="$out/mark" \
  PATH="$out/bin:$PATH" "$nl" reproduce --quick --jobs 1 --seed 3 --out "$rs" A1 S4 \
  2>"$out/kill3.log" &
PID=$!
for ((k = 0; k < 600; k++)); do   # 60 s
  [ -s "$out/mark" ] && break
  kill -0 "$PID" 2>/dev/null || break
  sleep 0.1
done
[ -s "$out/mark" ] || { cat "$out/kill3.log"; fail "seed 3: the fake gnuplot never ran for S4"; }
kill -KILL "$PID"; wait "$PID" 2>/dev/null || true
g="$(cat "$out/mark")"; kill "$g" 2>/dev/null || true
while kill -0 "$g" 2>/dev/null; do sleep 0.1; done   # it held the folder's lock
{ grep -q $'^seed\t3$' "$rs/a1_bounds/manifest.tsv" && grep -q $'^seed\t1$' "$rs/s4_marble/manifest.tsv" \
  && grep -q '^| \[a1_bounds\](#a1_bounds) | 3 |' "$rs/REPORT.md" \
  && grep -q '<a id="s4_marble">' "$rs/REPORT.md" && [ "$rs/REPORT.md" -nt "$rs/report.html" ]; } \
  || fail "seed 3 killed: A1's run not in REPORT.md or S4's previous run lost: $(cat "$out/kill3.log")"
"$nl" reproduce --quick --resume --seed 3 --out "$rs" A1 2>"$out/resume4.log" \
  || { cat "$out/resume4.log"; fail "reproduce --resume --seed 3 failed"; }
grep -q '^noiselab: reproduce --resume: skipped 1 of 1 ' "$out/resume4.log" \
  || fail "--resume --seed 3: $(cat "$out/resume4.log")"
consistent "SIGKILL of --seed 3, then --resume"
grep -q '^| \[a1_bounds\](#a1_bounds) | 3 |' "$rs/REPORT.md" \
  || fail "REPORT.md does not list A1's seed-3 run: $(grep -F '| [a1_bounds]' "$rs/REPORT.md")"
{ [ ! "$rs/REPORT.md" -nt "$rs/report.html" ] && grep -q s4_marble "$rs/report.html"; } \
  || fail "report.html not made again from REPORT.md"
echo "cli_reproduce: ok"
