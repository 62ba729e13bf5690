#!/usr/bin/env bash
# scripts/noiselab as a user runs it from a folder of their own, and two
# commands at once:
#  - every path typed is relative to the folder it was typed in: stat's
#    input and --labels, render -o, example's files, patterns DIR,
#    reproduce --out, sweep --out and sweep merge DIR all land there, and
#    nothing lands in the repository; check takes names from any folder;
#  - a command started while another holds the build lock waits for it (seen
#    blocked on the lock in /proc/locks), then finds the build done and runs;
#  - two checks at once compare their own runs: the second one's start does
#    not remove the first one's tables (a fake experiment, in a fake build
#    folder named by CHECK_BUILD, writes the reference's tables and waits on
#    a lock the test holds, so the two runs overlap by construction).
# Args: NOISELAB_SCRIPT EXPECT OUTDIR.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$3"   # $2, expect: not needed
root="$(cd "$(dirname "$nl")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out"
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
# What the commands below write, by the names they are given: none of them
# may appear in the repository (removed there again when one did).
names=(nl-cwd-test-labels.tsv nl-cwd-test.png nl-cwd-test.params nl-cwd-test-syn.png
       nl-cwd-test-patterns nl-cwd-test-r nl-cwd-test-sweep nl-cwd-test-sweep-c3)
strays() { local n; for n in "${names[@]}"; do [ ! -e "$root/$n" ] || printf '%s ' "$n"; done; }
fail() {
  local s; s="$(strays)"
  # shellcheck disable=SC2086  # the names are ours, without spaces
  [ -z "$s" ] || (cd "$root" && rm -rf $s)
  echo "cli_entry: $*"; exit 1
}
ok() {   # LABEL CMD...: runs CMD, its stderr kept for a failure
  local label="$1"; shift
  "$@" >"$out/last.out" 2>"$out/last.err" || fail "$label: exit $?: $(cat "$out/last.err")"
}

# ---- unknown options and stray words: refused before any set-up -----------
# The set-up's programs are fakes here that leave a mark: a refused command
# must not reach them (bench --frob once ran apt-get and every benchmark).
fake="$out/fakebin"; mkdir -p "$fake"
for p in dpkg-query apt-get sudo meson ninja parallel gnuplot; do
  printf '#!/bin/sh\n: >"%s/ran-%s"\nexit 1\n' "$fake" "$p" >"$fake/$p"
  chmod +x "$fake/$p"
done
refused() {   # WANTED_LINE ARGS...
  local want="$1" rc=0
  shift
  PATH="$fake:$PATH" "$nl" "$@" >"$out/ref.out" 2>"$out/ref.err" || rc=$?
  [ "$rc" = 1 ] || fail "$*: exit $rc, wanted 1: $(cat "$out/ref.err")"
  [ "$(cat "$out/ref.err")" = "$want" ] || fail "$*: said '$(cat "$out/ref.err")', wanted '$want'"
  [ ! -s "$out/ref.out" ] || fail "$*: printed $(cat "$out/ref.out")"
  [ -z "$(find "$fake" -name 'ran-*' -print -quit)" ] || fail "$*: ran $(find "$fake" -name 'ran-*')"
}
refused "noiselab bench: unknown option --frob" bench --frob
refused "noiselab test: unknown option --frob" test --frob
refused "noiselab setup: unknown option --frob" setup --frob
refused "noiselab list: unknown option --frob" list --frob
refused "noiselab help: unknown option --frob" help --frob
refused "noiselab params: unknown option --frob" params S3 --frob
refused "noiselab list: unexpected argument 'S3' (list takes none; scripts/noiselab list --help)" list S3
refused "noiselab test: unexpected argument 'cli' (test takes none; scripts/noiselab test --help)" test cli
refused "noiselab setup: unexpected argument 'x' (setup takes none; scripts/noiselab setup --help)" setup x
refused "noiselab bench: unknown option --hlep (did you mean --help?)" bench --hlep
refused "noiselab check: unknown option --quik (did you mean --quick?)" check --quik A1
refused "noiselab reproduce: unknown option --resum (did you mean --resume?)" reproduce --resum
refused "noiselab reproduce: unknown option --frob" reproduce --quick --frob A1
refused "noiselab reproduce: unknown option --quik (did you mean --quick?)" reproduce --quik
# bare: a command left out is an error (help on stderr, exit 2), as git's
rc=0; PATH="$fake:$PATH" "$nl" >"$out/ref.out" 2>"$out/ref.err" || rc=$?
[ "$rc" = 2 ] || fail "bare noiselab: exit $rc, wanted 2"
[ ! -s "$out/ref.out" ] || fail "bare noiselab: printed on stdout"
head -n 1 "$out/ref.err" | grep -q '^noiselab - ' || fail "bare noiselab: no help on stderr"

# ---- a failed build keeps its log inside the build folder ------------------
# (beside it, build.ninja.log landed in the repository's root)
fb2="$out/logs"; mkdir -p "$fb2/bin" "$fb2/b"
printf '#!/bin/sh\nexit 0\n' >"$fb2/bin/meson"
printf '#!/bin/sh\necho "FAILED: fake compile"\nexit 1\n' >"$fb2/bin/ninja"
chmod +x "$fb2/bin/meson" "$fb2/bin/ninja"
: >"$fb2/b/build.ninja"
rc=0
# shellcheck disable=SC2016  # the inner shell's arguments
PATH="$fb2/bin:$PATH" bash -c 'source "$1"; build_locked "$2"' _ "$nl" "$fb2/b" >/dev/null \
  2>"$out/build.err" || rc=$?
[ "$rc" = 2 ] || fail "a failed build: exit $rc: $(cat "$out/build.err")"
grep -q 'FAILED: fake compile' "$out/build.err" || fail "a failed build: no log shown: $(cat "$out/build.err")"
[ "$(ls -A "$fb2")" = "$(printf 'b\nbin')" ] || fail "a failed build left beside its folder: $(ls -A "$fb2")"

# ---- off a terminal the build says a line per stage, and nothing when it
# has no work (ninja -n lists what it would do, "[K/N] ...")
sb="$out/stages"; mkdir -p "$sb/bin" "$sb/b"
printf '#!/bin/sh\nexit 0\n' >"$sb/bin/meson"
# shellcheck disable=SC2016  # the fake ninja's own script
printf '#!/bin/sh\ncase " $* " in *" -n "*) cat "$(dirname "$0")/plan" ;; esac\nexit 0\n' >"$sb/bin/ninja"
chmod +x "$sb/bin/meson" "$sb/bin/ninja"
printf '[1/3] cc a.o\n[2/3] cc b.o\n[3/3] link x\n' >"$sb/bin/plan"
# shellcheck disable=SC2016  # the inner shell's arguments
PATH="$sb/bin:$PATH" bash -c 'source "$1"; build_locked "$2"' _ "$nl" "$sb/b" >/dev/null 2>"$out/stages.err" \
  || fail "build stages: $(cat "$out/stages.err")"
[ "$(sed 's/done in [0-9]* s/done in N s/' "$out/stages.err")" = "$(printf 'noiselab: configuring %s/\nnoiselab: building %s/ (3 steps)\nnoiselab: build done in N s' "${sb#"$root"/}/b" "${sb#"$root"/}/b")" ] \
  || fail "build stages: $(cat "$out/stages.err")"
echo 'ninja: no work to do.' >"$sb/bin/plan"
: >"$sb/b/build.ninja"   # configured (the fake meson wrote none)
# shellcheck disable=SC2016
PATH="$sb/bin:$PATH" bash -c 'source "$1"; build_locked "$2"' _ "$nl" "$sb/b" >/dev/null 2>"$out/stages.err" \
  || fail "build, nothing to do: $(cat "$out/stages.err")"
[ ! -s "$out/stages.err" ] || fail "an up-to-date build said: $(cat "$out/stages.err")"

# ---- paths relative to the user's folder ----------------------------------
w="$out/elsewhere"; mkdir -p "$w"
cd "$w"
readme="$(cksum <"$root/README.md")"
awk 'BEGIN { srand(7); for (i = 0; i < 1000; i++) printf "%.6f\n", rand() }' >u1000.tsv
printf '0 0\n0.1 0\n5 5\n5.1 5\n10 0\n10 0.1\n' >pts.tsv
ok "stat ks u1000.tsv" "$nl" stat ks u1000.tsv --uniform 0 1
grep -q 'n=1000' "$out/last.out" || fail "stat ks: $(cat "$out/last.out")"
ok "stat hclust --labels" "$nl" stat hclust pts.tsv --linkage ward --clusters 3 --labels nl-cwd-test-labels.tsv
[ "$(wc -l <nl-cwd-test-labels.tsv)" = 7 ] || fail "hclust --labels: not a header and 6 labels in $w"
ok "render -o" "$nl" render fbm --size 32 -o nl-cwd-test.png
[ -s nl-cwd-test.png ] || fail "render -o nl-cwd-test.png: nothing in $w"
ok "example analyse" "$nl" example analyse nl-cwd-test.png -o nl-cwd-test.params
ok "example synthesize" "$nl" example synthesize nl-cwd-test.params --size 16 -o nl-cwd-test-syn.png
[ -s nl-cwd-test-syn.png ] || fail "example synthesize: nothing in $w"
ok "patterns" "$nl" patterns nl-cwd-test-patterns --size 16
[ -n "$(find nl-cwd-test-patterns -name '*.png')" ] || fail "patterns: no PNG in $w/nl-cwd-test-patterns"
ok "reproduce --out" "$nl" reproduce --quick --jobs 1 --out nl-cwd-test-r A1
{ [ -f nl-cwd-test-r/a1_bounds/manifest.tsv ] && [ -f nl-cwd-test-r/REPORT.md ]; } \
  || fail "reproduce --out nl-cwd-test-r: no complete run in $w"
ok "sweep --out" "$nl" sweep A1 --quick --param points=500,1000 --jobs 2 --out nl-cwd-test-sweep
[ "$(find nl-cwd-test-sweep/tasks -name manifest.tsv | wc -l)" = 2 ] || fail "sweep --out: not 2 tasks in $w"
ok "sweep merge" "$nl" sweep merge nl-cwd-test-sweep --table bounds.tsv --y max_abs
[ -s nl-cwd-test-sweep/merged/plot.png ] || fail "sweep merge: no plot in $w"
# The sweep's tasks still find the experiments' data/ folders (C3 reads
# data/patterns from the repository).
ok "sweep C3" "$nl" sweep C3 --quick --param grid=64 --jobs 1 --out nl-cwd-test-sweep-c3
[ "$(find nl-cwd-test-sweep-c3/tasks -name manifest.tsv | wc -l)" = 1 ] \
  || fail "sweep C3 from another folder: $(cat nl-cwd-test-sweep-c3/logs/*.log)"
# The tools refuse an unknown option too (nl_opt): one line naming it,
# non-zero, nothing written.
for c in "example analyse nl-cwd-test.png -o nl-cwd-test-x.params --frob" \
         "sweep A1 --quick --param points=500 --out nl-cwd-test-x --frob" \
         "render fbm -o nl-cwd-test-x.png --frob" "patterns nl-cwd-test-x --frob" \
         "stat ks u1000.tsv --frob"; do
  rc=0
  # shellcheck disable=SC2086  # the command's words
  "$nl" $c >/dev/null 2>"$out/unk.err" || rc=$?
  { [ "$rc" != 0 ] && grep -q -- '--frob' "$out/unk.err" && [ "$(wc -l <"$out/unk.err")" = 1 ]; } \
    || fail "$c: exit $rc: $(cat "$out/unk.err")"
  [ -z "$(find . -maxdepth 1 -name 'nl-cwd-test-x*')" ] || fail "$c: wrote $(ls -d nl-cwd-test-x*)"
done
# check takes names, not paths: from here it runs (0, or 1 on drift) and
# leaves this folder as it was.
before="$(ls -A)"
rc=0; "$nl" check --quick A1 >/dev/null 2>"$out/check.err" || rc=$?
[ "$rc" -le 1 ] || fail "check --quick A1 from another folder: exit $rc: $(cat "$out/check.err")"
kept="$(sed -n "s/.*; this check's runs: \(.*\))$/\1/p" "$out/check.err")"
[ -z "$kept" ] || rm -rf "$kept"   # a drift keeps them for a look; not needed here
[ "$(ls -A)" = "$before" ] || fail "check wrote into the user's folder: $(ls -A)"
s="$(strays)"
[ -z "$s" ] || fail "written into the repository instead of $w: $s"
[ "$(cksum <"$root/README.md")" = "$readme" ] || fail "the repository's README.md changed"
cd "$out"

# ---- the build lock: one builder, the others wait -------------------------
lockf="$root/build/.noiselab-build.lock"
if [ -r /proc/locks ]; then
  # Held here as a build would hold it; two commands started meanwhile must
  # both block on it, and both run once it is free.
  exec 7>>"$lockf"
  flock 7
  ino="$(stat -c %i "$lockf")"
  waiting() {   # how many of PID... wait on the lock (through their flock)
    local w pp p n=0
    while read -r w; do
      pp="$(awk '/^PPid:/ {print $2}' "/proc/$w/status" 2>/dev/null)" || continue
      for p in "$@"; do [ "$pp" != "$p" ] || n=$((n + 1)); done
    done < <(awk -v i=":$ino" '$2 == "->" && substr($7, length($7) - length(i) + 1) == i {print $6}' \
               /proc/locks)
    echo "$n"
  }
  # (7>&-: a command that inherited the descriptor would hold the lock too.)
  "$nl" stat ks "$w/u1000.tsv" --uniform 0 1 >"$out/wait1.out" 2>"$out/wait1.err" 7>&- &
  p1=$!
  "$nl" render fbm --size 16 -o "$out/wait2.png" >/dev/null 2>"$out/wait2.err" 7>&- &
  p2=$!
  for ((k = 0; k < 600; k++)); do   # 60 s
    [ "$(waiting "$p1" "$p2")" = 2 ] && break
    kill -0 "$p1" 2>/dev/null || { exec 7>&-; fail "stat ks ran while another command held the build lock"; }
    kill -0 "$p2" 2>/dev/null || { exec 7>&-; fail "render ran while another command held the build lock"; }
    sleep 0.1
  done
  exec 7>&-
  [ "$k" -lt 600 ] || fail "two commands did not wait on the build lock within 60 s"
  wait "$p1" || fail "stat ks after waiting for the build: $(cat "$out/wait1.err")"
  wait "$p2" || fail "render after waiting for the build: $(cat "$out/wait2.err")"
  grep -q 'n=1000' "$out/wait1.out" || fail "stat ks after the wait: $(cat "$out/wait1.out")"
  [ -s "$out/wait2.png" ] || fail "render after the wait wrote nothing"
else
  echo "cli_entry: no /proc/locks; the build lock is not tested"
fi

# ---- two checks at once -----------------------------------------------------
fb="$out/fakebuild"; mkdir -p "$fb/experiments"
cat >"$fb/experiments/a1_bounds" <<'FAKE'
#!/usr/bin/env bash
# Stands in for A1 under check: the reference's tables into --out, early
# (before waiting on FAKE_LOCK) or late (after), then a mark.
set -euo pipefail
o=""
while [ $# -gt 0 ]; do case "$1" in --out) o="$2"; shift ;; esac; shift; done
mkdir -p "$o"
if [ "$FAKE_WHEN" = early ]; then cp -r "$FAKE_REF"/. "$o"/; fi
: >"$FAKE_MARK"
flock "$FAKE_LOCK" true
if [ "$FAKE_WHEN" = late ]; then cp -r "$FAKE_REF"/. "$o"/; fi
FAKE
chmod +x "$fb/experiments/a1_bounds"
export FAKE_REF="$root/results/quick/a1_bounds"
[ -f "$FAKE_REF/manifest.tsv" ] || fail "no reference $FAKE_REF"
waitmark() {   # MARK PID LOG
  local k
  for ((k = 0; k < 600; k++)); do
    [ -e "$1" ] && return 0
    kill -0 "$2" 2>/dev/null || fail "check ended before its experiment ran: $(cat "$3")"
    sleep 0.1
  done
  fail "check's experiment did not start within 60 s"
}
exec 5>"$out/lockA" 6>"$out/lockB"
flock 5; flock 6
# A's experiment writes its tables, then waits; B starts meanwhile, its
# experiment waits before writing; A then compares while B still waits.
CHECK_BUILD="$fb" FAKE_WHEN=early FAKE_LOCK="$out/lockA" FAKE_MARK="$out/markA" \
  "$nl" check --quick A1 >/dev/null 2>"$out/checkA.err" 5>&- 6>&- &
pa=$!
waitmark "$out/markA" "$pa" "$out/checkA.err"
CHECK_BUILD="$fb" FAKE_WHEN=late FAKE_LOCK="$out/lockB" FAKE_MARK="$out/markB" \
  "$nl" check --quick A1 >/dev/null 2>"$out/checkB.err" 5>&- 6>&- &
pb=$!
waitmark "$out/markB" "$pb" "$out/checkB.err"
exec 5>&-
rc=0; wait "$pa" || rc=$?
exec 6>&-
[ "$rc" = 0 ] || fail "check A, with check B started during its run: exit $rc: $(cat "$out/checkA.err")"
rc=0; wait "$pb" || rc=$?
[ "$rc" = 0 ] || fail "check B: exit $rc: $(cat "$out/checkB.err")"
[ -z "$(find "$fb" -mindepth 1 -maxdepth 1 -name 'check*')" ] \
  || fail "passed checks left their runs: $(ls "$fb")"
# ---- a check killed outright: the next check removes its folder ------------
# (SIGKILL runs no trap; the folder's name holds the dead check's pid). A
# folder kept after a drift (no pid) and a live check's stay.
exec 5>"$out/lockK"; flock 5
CHECK_BUILD="$fb" FAKE_WHEN=late FAKE_LOCK="$out/lockK" FAKE_MARK="$out/markK" \
  "$nl" check --quick A1 >/dev/null 2>"$out/checkK.err" 5>&- &
pk=$!
waitmark "$out/markK" "$pk" "$out/checkK.err"
kill -KILL "$pk"
wait "$pk" 2>/dev/null || true
exec 5>&-   # the fake experiment, left alone, finishes
for ((k = 0; k < 100; k++)); do pgrep -f "$fb/experiments/a1_bounds" >/dev/null || break; sleep 0.1; done
left="$(find "$fb" -mindepth 1 -maxdepth 1 -name "check-quick.$pk.*")"
[ -n "$left" ] || fail "a check killed outright left no folder to test with: $(ls "$fb")"
mkdir "$fb/check-quick.Kept01" "$fb/check-quick.$$.Live01"
CHECK_BUILD="$fb" FAKE_WHEN=early FAKE_LOCK="$out/lockA" FAKE_MARK="$out/markA" \
  "$nl" check --quick A1 >/dev/null 2>"$out/checkK2.err" || fail "check after a killed one: $(cat "$out/checkK2.err")"
[ ! -e "$left" ] || fail "the next check kept the killed check's folder $left"
[ -d "$fb/check-quick.Kept01" ] || fail "the next check removed a kept folder"
[ -d "$fb/check-quick.$$.Live01" ] || fail "the next check removed a live check's folder"
rm -rf "$fb/check-quick.Kept01" "$fb/check-quick.$$.Live01"
echo "cli_entry: ok"
