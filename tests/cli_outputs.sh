#!/bin/bash
# Outputs are never lost: tests/cli_outputs.sh RENDER STAT.
# A full disk (a file size limit with SIGXFSZ ignored, so writes fail with
# EFBIG as they would with ENOSPC) fails the command with one line and keeps
# the old file; a symbolic link is followed and kept, a FIFO and a device are
# written through and stay what they are (devices: private copies made with
# mknod, as root only); a command with several outputs checks them all
# before writing any and replaces all or none.
# A result printed on stdout is an output too: every command that prints one
# fails when stdout cannot take it (> /dev/full), with a line on stderr.
# Args: RENDER STAT EXAMPLE PATTERNS CHECK SWEEP S3_FBM [NOISELAB_SCRIPT].
set -u
use="usage: cli_outputs.sh RENDER STAT EXAMPLE PATTERNS CHECK SWEEP S3_FBM [NOISELAB_SCRIPT]"
RENDER=$(realpath "${1:?$use}")
STAT=$(realpath "${2:?$use}")
EXAMPLE=$(realpath "${3:?$use}")
PATTERNS=$(realpath "${4:?$use}")
CHECKTOOL=$(realpath "${5:?$use}")
SWEEP=$(realpath "${6:?$use}")
S3=$(realpath "${7:?$use}")
NL="${8:+$(realpath "$8")}"
SRC="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
pass=0 fail=0

ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
check() { if "$@"; then ok; else bad "$*"; fi; }
one_line() { [ "$(wc -l <"$1")" = 1 ] && grep -q "$2" "$1"; }
no_hidden() { [ -z "$(find "${1:-.}" -maxdepth 1 -name '.*' ! -name . -print -quit)" ]; }

# Runs a command with a file size limit of $1 kB (SIGXFSZ ignored).
limited() {
  local kb="$1"
  shift
  (trap '' XFSZ; ulimit -f "$kb"; "$@")
}

# ---- a full disk: non-zero, one line naming the file, the old file kept
"$RENDER" fbm --size 16 --seed 1 -o good.png 2>/dev/null
cp good.png keep.png
limited 8 "$RENDER" fbm --size 512 --seed 2 -o good.png >out 2>err
check test $? -ne 0
check one_line err 'good.png: write failed: File too large'
check cmp -s good.png keep.png
check no_hidden
for ext in exr tif; do
  "$RENDER" fbm --size 16 --seed 1 -o "good.$ext" 2>/dev/null
  cp "good.$ext" "keep.$ext"
  limited 8 "$RENDER" fbm --size 512 --seed 2 -o "good.$ext" >out 2>err
  check test $? -ne 0
  check one_line err "good.$ext"
  check cmp -s "good.$ext" "keep.$ext"
done

# ---- a file size limit without the shell's help: the tools ignore SIGXFSZ
# themselves, so the write fails with EFBIG, the command says so and exits
# non-zero, and no temporary is left beside the output
seq 0 299 | awk '{ print ($1 * 7919) % 1000 }' >pts.tsv
for cmd in "$RENDER fbm --size 256 --seed 2 -o big.png" "$RENDER fbm --size 256 -o big.tsv" \
           "$STAT hclust pts.tsv --linkage ward --clusters 3 --merges big.tsv" \
           "$PATTERNS bigpat --size 256"; do
  # shellcheck disable=SC2086  # the command's words
  (ulimit -f 1; exec $cmd) >out 2>err
  rc=$?
  if [ "$rc" != 0 ] && [ "$rc" -lt 128 ] && grep -q 'File too large' err && no_hidden . && \
     { [ ! -d bigpat ] || no_hidden bigpat; }; then
    ok
  else
    bad "ulimit -f 1; $cmd: exit $rc, stderr: $(head -c 200 err), left: $(ls -A)"
  fi
  rm -rf big.png big.tsv bigpat
done

# ---- a temporary left by a writer killed outright (SIGKILL: no clean-up)
# is removed by the next writer of that output once its pid is no process;
# a live writer's is kept
sh -c 'exit 0' & dead=$!
wait "$dead"
: >".kill.$dead.AbC123.png"
: >".kill.$$.dEf456.png"
"$RENDER" fbm --size 8 -o kill.png 2>/dev/null
check test ! -e ".kill.$dead.AbC123.png"
check test -e ".kill.$$.dEf456.png"
check test -s kill.png
rm -f ".kill.$$.dEf456.png"

# ---- several outputs: a bad second path leaves the first file untouched
seq 0 299 | awk '{ print ($1 * 7919) % 1000 }' >pts.tsv
echo old >old.tsv
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels old.tsv --merges nodir/m.tsv \
  >out 2>err
check test $? = 2
check one_line err 'nodir/m.tsv: directory nodir does not exist'
check test "$(cat old.tsv)" = old
check no_hidden
# ... and so does a second output that does not fit (labels ~600 bytes, merges ~12 kB)
echo old >m.tsv
limited 4 "$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels old.tsv --merges m.tsv \
  >out 2>err
check test $? -ne 0
check one_line err 'm.tsv: write failed'
check test "$(cat old.tsv)" = old
check test "$(cat m.tsv)" = old
check no_hidden

# ---- a symbolic link is followed and stays a link; one to nothing is refused
ln -s good.png link.png
"$RENDER" fbm --size 32 --seed 3 -o link.png >out 2>err
check test $? = 0
check test -L link.png
check test "$(head -c 4 good.png | tail -c 3)" = PNG
ln -s missing.tsv dangling.tsv
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels dangling.tsv >out 2>err
check test $? -ne 0
check one_line err 'dangling.tsv: symbolic link to a missing file'
check test -L dangling.tsv

# ---- a FIFO is written through
mkfifo fifo.tsv
timeout 60 cat fifo.tsv >from_fifo.tsv &
reader=$!
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels fifo.tsv >out 2>err
check test $? = 0
wait "$reader"
check test -p fifo.tsv
check test "$(head -1 from_fifo.tsv)" = label
check test "$(wc -l <from_fifo.tsv)" = 301

# ---- /dev/stdout (a link to the pipe) and /dev/null need no writable /dev
check test "$("$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels /dev/stdout | head -1)" \
  = label
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels /dev/null >out 2>err
check test $? = 0
check test -c /dev/null

# ---- devices (root: private copies of /dev/null and /dev/full)
if [ "$(id -u)" = 0 ] && mknod null c 1 3 2>/dev/null && mknod full c 1 7 2>/dev/null; then
  "$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels null --merges null >out 2>err
  check test $? = 0
  check test -c null
  "$STAT" gmm pts.tsv --k 1 --params null >out 2>err
  check test $? = 0
  check test -c null
  "$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels full >out 2>err
  check test $? -ne 0
  check one_line err 'full: write failed: No space left on device'
  check test -c full
else
  echo "cli_outputs: not root, device nodes not tested" >&2
fi

# ---- an output never replaces an input, nor the program's own sources:
# refused before any work, one line, exit 1, the file untouched
replaces() {   # WANTED LABEL FILE CMD...: FILE must be untouched
  local want="$1" label="$2" file="$3" sum rc
  shift 3
  sum="$(cksum <"$file")"
  "$@" >out 2>err
  rc=$?
  if [ "$rc" = 1 ] && one_line err "$want" && [ "$(cksum <"$file")" = "$sum" ] && no_hidden .; then
    ok
  else
    bad "$label: exit $rc, stderr: $(head -c 300 err)"
  fi
}
"$RENDER" fbm --size 32 --seed 5 -o ex.png 2>/dev/null
replaces "ex.png: is the input ex.png" "example analyse x.png -o x.png" ex.png \
  "$EXAMPLE" analyse ex.png -o ex.png
cp pts.tsv d.tsv
replaces "d.tsv: is the input d.tsv" "stat hclust d.tsv --labels d.tsv" d.tsv \
  "$STAT" hclust d.tsv --linkage ward --clusters 3 --labels d.tsv
replaces "is the input d.tsv" "stat hclust d.tsv --merges ./d.tsv" d.tsv \
  "$STAT" hclust d.tsv --linkage ward --clusters 3 --merges ./d.tsv
ln -s d.tsv dlink.tsv
replaces "dlink.tsv: is the input d.tsv" "stat gmm --params LINK-TO-INPUT" d.tsv \
  "$STAT" gmm d.tsv --k 1 --params dlink.tsv
mkdir sub
replaces "is the input sub/../d.tsv" "stat hclust --labels: the input by another path" d.tsv \
  "$STAT" hclust sub/../d.tsv --linkage ward --clusters 3 --labels "$TMP/d.tsv"
replaces "a file of the noiselab sources" "render -o experiments/s3_fbm/main.c" \
  "$SRC/experiments/s3_fbm/main.c" "$RENDER" fbm --size 8 -o "$SRC/experiments/s3_fbm/main.c"
replaces "a file of the noiselab sources" "stat --labels README.md" "$SRC/README.md" \
  "$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels "$SRC/README.md"
replaces "a file of the noiselab sources" "patterns data/patterns" \
  "$SRC/data/patterns/flower.png" "$PATTERNS" "$SRC/data/patterns" --size 8
# an untracked name in the repository, or a new one, is the user's to write
"$RENDER" fbm --size 8 -o "$TMP/fresh.png" 2>/dev/null
check test -s fresh.png

# ---- stdout is an output: a result that cannot be written fails, saying so
# Runs CMD with stdout on /dev/full: it must exit non-zero with a line on
# stderr naming the failed write.
# FULL_LINES: how many lines stderr may have (1; check adds its summary).
full() {   # LABEL CMD...
  local label="$1" rc
  shift
  "$@" >/dev/full 2>err
  rc=$?
  if [ "$rc" != 0 ] && grep -q 'write error on standard output\|write failed: No space left' err \
     && [ "$(wc -l <err)" -le "${FULL_LINES:-1}" ]; then
    ok
  else
    bad "$label > /dev/full: exit $rc, stderr: $(head -c 300 err)"
  fi
}
awk 'BEGIN { srand(3); for (i = 0; i < 200; i++) printf "%.6f\n", rand() }' >u.tsv
awk 'BEGIN { srand(4); for (i = 0; i < 200; i++) printf "%.6f\n", rand() }' >v.tsv
full "stat ks" "$STAT" ks u.tsv --uniform 0 1
full "stat ks2" "$STAT" ks2 u.tsv v.tsv
full "stat kuiper" "$STAT" kuiper u.tsv
full "stat chisq" "$STAT" chisq u.tsv --bins 4
full "stat hclust" "$STAT" hclust pts.tsv --linkage ward --clusters 3
full "stat gmm" "$STAT" gmm pts.tsv --k 1
full "stat --help" "$STAT" --help
full "stat ks --help" "$STAT" ks --help
full "render -o -" "$RENDER" fbm --size 8 -o -
full "render --help" "$RENDER" --help
full "example --help" "$EXAMPLE" --help
full "patterns" "$PATTERNS" pat --size 8
full "patterns --help" "$PATTERNS" --help
ref="$SRC/results/quick/s3_fbm"
full "check" "$CHECKTOOL" "$ref" "$ref"
full "check --help" "$CHECKTOOL" --help
full "sweep expand" "$SWEEP" expand a=1,2
full "sweep plan" "$SWEEP" plan --experiment s3_fbm a=1,2
full "sweep usage" "$SWEEP" usage
full "sweep --help" "$SWEEP" --help
full "experiment --params" "$S3" --params
full "experiment --help" "$S3" --help
if [ -n "$NL" ]; then
  full "noiselab help" "$NL" help
  full "noiselab list" "$NL" list
  full "noiselab params S3" "$NL" params S3
  full "noiselab stat ks" "$NL" stat ks u.tsv --uniform 0 1
  full "noiselab render -o -" "$NL" render fbm --size 8 -o -
  full "noiselab patterns" "$NL" patterns pat2 --size 8
  full "noiselab sweep --help" "$NL" sweep --help
  for c in reproduce check list setup test bench params; do
    full "noiselab $c --help" "$NL" "$c" --help
  done
  # check: a fake experiment writes the committed quick tables of A1, so the
  # comparison (noiselab-check, its lines on stdout) runs in a second.
  mkdir -p fakebuild/experiments
  # shellcheck disable=SC2016  # the fake's own $ are its shell's
  printf '%s\n' '#!/bin/sh' 'while [ $# -gt 0 ]; do [ "$1" = --out ] && o="$2"; shift; done' \
    'mkdir -p "$o" && cp -r "$FAKE_REF"/. "$o"/' >fakebuild/experiments/a1_bounds
  chmod +x fakebuild/experiments/a1_bounds
  FAKE_REF="$SRC/results/quick/a1_bounds" CHECK_BUILD="$TMP/fakebuild" FULL_LINES=3 \
    full "noiselab check" "$NL" check --quick A1
  # bench: its programs' printouts go through tee to stdout
  mkdir -p fakebench
  printf '%s\n' '#!/bin/sh' 'echo "bench line"' >fakebench/bench_fake
  chmod +x fakebench/bench_fake
  # shellcheck disable=SC2016  # the inner shell's arguments
  "$BASH" -c 'source "$1"; run_benchmarks "$2"' _ "$NL" "$TMP/fakebench" >/dev/full 2>err
  rc=$?
  if [ "$rc" != 0 ] && [ -s err ]; then ok; else bad "bench > /dev/full: exit $rc: $(head -c 300 err)"; fi
fi

echo "cli_outputs: $pass passed, $fail failed"
[ "$fail" = 0 ]
