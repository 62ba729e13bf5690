#!/bin/bash
# Outputs are never lost: tests/cli_outputs.sh RENDER STAT.
# A full disk (a file size limit with SIGXFSZ ignored, so writes fail with
# EFBIG as they would with ENOSPC) fails the command with one line and keeps
# the old file; a symbolic link is followed and kept, a FIFO and a device are
# written through and stay what they are (devices: private copies made with
# mknod, as root only); a command with several outputs checks them all
# before writing any and replaces all or none.
set -u
RENDER=$(realpath "${1:?usage: cli_outputs.sh RENDER STAT}")
STAT=$(realpath "${2:?usage: cli_outputs.sh RENDER STAT}")
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

echo "cli_outputs: $pass passed, $fail failed"
[ "$fail" = 0 ]
