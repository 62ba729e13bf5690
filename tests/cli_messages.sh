#!/bin/bash
# Messages and output names: tests/cli_messages.sh RENDER STAT EXAMPLE PATTERNS SWEEP [NOISELAB].
# A message quoting a path of 3000 bytes still ends with its reason (the
# path loses its middle, never the reason); a path or a value holding a
# newline, a tab or another control character gives one escaped line and a
# non-zero exit, from the C tools and from the entry script (NOISELAB, given
# in the release build only); any name the folder accepts (255 bytes) can be
# written and leaves no temporary beside it; every output is checked before
# the work starts (stat gmm --params before EM, render -o before the noise,
# patterns' files before the first is written).
set -u
usage='usage: cli_messages.sh RENDER STAT EXAMPLE PATTERNS SWEEP [NOISELAB]'
RENDER=$(realpath "${1:?$usage}")
STAT=$(realpath "${2:?$usage}")
EXAMPLE=$(realpath "${3:?$usage}")
PATTERNS=$(realpath "${4:?$usage}")
SWEEP=$(realpath "${5:?$usage}")
NOISELAB="${6:+$(realpath "$6")}"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
pass=0 fail=0

ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }
check() { if "$@"; then ok; else bad "$*"; fi; }
# FILE holds exactly one line, and it contains TEXT (fixed string)
one_line() { [ "$(wc -l <"$1")" = 1 ] && grep -qF -- "$2" "$1"; }
# FILE holds exactly one line, and it ends with TEXT
ends_with() { [ "$(wc -l <"$1")" = 1 ] && [ "$(tail -c $((${#2} + 1)) "$1")" = "$2" ]; }
# Runs CMD...; passes when it exits non-zero with one line on stderr holding TEXT.
refused() {
  local text="$1"; shift
  "$@" >out 2>err
  local rc=$?
  if [ "$rc" != 0 ] && one_line err "$text"; then ok
  else bad "$* (exit $rc): $(head -c 300 err)"; fi
}

seq 0 299 | awk '{ print ($1 * 7919) % 1000 }' >pts.tsv

# ---- a path of 3000 bytes: the message ends with its reason
seg=$(printf 'd%.0s' $(seq 196))
long=.
for _ in $(seq 15); do long="$long/$seg"; done
"$STAT" ks "$long/in.tsv" >out 2>err
check test $? = 2
check ends_with err 'cannot open: No such file or directory'
"$RENDER" fbm --size 8 -o "$long/out.png" >out 2>err
check test $? = 2
check ends_with err 'does not exist'
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels "$long/labels.tsv" >out 2>err
check test $? = 2
check ends_with err 'does not exist'
"$EXAMPLE" analyse "$long/photo.png" -o params.tsv >out 2>err
check test $? = 2
check ends_with err 'No such file or directory'
# the middle of the path goes, its start and its file name stay
check grep -qF -- '...' err
check grep -qF -- '/photo.png: ' err

# ---- a newline, a tab or another control character: one escaped line
nl=$'a\nb'
refused 'a\nb/x.png: directory a\nb does not exist' "$RENDER" fbm --size 8 -o "$nl/x.png"
refused 'a\tb\x01/x.png' "$RENDER" fbm --size 8 -o $'a\tb\x01/x.png'
refused "'a\\nb' is not" "$RENDER" fbm --size 8 --basis "$nl" -o x.png
refused 'a\nb: unknown noise' "$RENDER" "$nl" -o x.png
refused 'a\nb: cannot open' "$STAT" ks "$nl"
refused "--format: 'a\\nb' is not" "$STAT" ks pts.tsv --format "$nl"
refused "unknown subcommand 'a\\nb'" "$STAT" "$nl" pts.tsv
refused 'a\nb/p.tsv' "$STAT" gmm pts.tsv --k 1 --params "$nl/p.tsv"
refused "unknown command 'a\\nb'" "$EXAMPLE" "$nl"
refused 'a\nb' "$EXAMPLE" analyse "$nl" -o params.tsv
refused "unexpected argument 'a\\nb'" "$PATTERNS" pat "$nl"
refused "'a\\nb' is not a number" "$SWEEP" expand "x=$nl"
check test ! -e pat

# ---- names of 248-255 bytes: written, nothing else left in the folder
n255=$(printf 'n%.0s' $(seq 251))
mkdir names
for f in "$n255.png" "${n255:0:244}.png" "$n255.tsv" "a.$(printf 'e%.0s' $(seq 253))"; do
  case "$f" in
    *.png) "$RENDER" fbm --size 16 -o "names/$f" >out 2>err ;;
    *) "$STAT" gmm pts.tsv --k 1 --params "names/$f" >out 2>err ;;
  esac
  check test $? = 0
  check test -s "names/$f"
done
"$STAT" hclust pts.tsv --linkage ward --clusters 3 --labels "names/$n255.tsv" \
  --merges "names/${n255:0:250}.tsv" >out 2>err
check test $? = 0
check test "$(head -1 "names/$n255.tsv")" = label
check test "$(find names -mindepth 1 | wc -l)" = 5
# a name one byte too long is refused, naming the file system's reason
refused 'File name too long' "$STAT" gmm pts.tsv --k 1 --params "names/x$n255.tsv"
check test "$(find names -mindepth 1 | wc -l)" = 5

# ---- every output is checked before the work starts
# stat gmm --params: refused before EM (no fit line on stdout), the path named
refused 'nodir/p.tsv: directory nodir does not exist' \
  "$STAT" gmm pts.tsv --k 2 --params nodir/p.tsv
check test ! -s out
mkdir adir
refused 'adir: is a directory' "$STAT" gmm pts.tsv --k 2 --params adir
check test ! -s out
ln -s missing.tsv dangling.tsv
refused 'dangling.tsv: symbolic link to a missing file' \
  "$STAT" gmm pts.tsv --k 2 --params dangling.tsv
check test ! -s out
check test -L dangling.tsv
# render -o: a link to nothing is named before the noise is set up (whose
# own error would otherwise come first)
ln -s missing.png dangling.png
refused 'dangling.png: symbolic link to a missing file' \
  "$RENDER" fbm --octaves 30 --lacunarity 1e6 --size 8 -o dangling.png
# patterns: a name taken by a directory refuses the lot, nothing written
mkdir -p pats/spiral.png
refused 'pats/spiral.png: is a directory' "$PATTERNS" pats --size 16
check test "$(find pats -mindepth 1 | wc -l)" = 1
if [ "$(id -u)" != 0 ]; then
  mkdir ro && chmod a-w ro
  refused 'ro/p.tsv: directory ro is not writable' "$STAT" gmm pts.tsv --k 2 --params ro/p.tsv
  check test ! -s out
  chmod u+w ro
fi

# ---- an image given where a text file belongs is named as an image
"$RENDER" fbm --size 16 -o img.png >/dev/null 2>&1
refused 'img.png: a PNG image, not a table' "$STAT" ks img.png
refused 'img.png: a PNG image, not a parameter file' "$EXAMPLE" synthesize img.png --size 8 -o s.png
check test ! -e s.png
# a pipe is read, not sniffed (its first bytes cannot be put back)
seq 1 9 | awk '{ print $1 / 10 }' >u.tsv
"$STAT" ks /dev/stdin --uniform 0 1 <u.tsv >out 2>err
check grep -q 'n=9 ' out
# each example subcommand's --help is its own
"$EXAMPLE" synthesize --help >out 2>err
check grep -q '^usage: noiselab example synthesize' out
check test "$(grep -c 'noiselab example' out)" = 1

# ---- the entry script: messages quoting what the user typed are one line
if [ -n "$NOISELAB" ]; then
  refused "unknown experiment 'a\\nb'" "$NOISELAB" params "$nl"
  refused "unknown experiment 'a\\nb'" "$NOISELAB" reproduce "$nl"
  refused "unknown experiment 'a\\nb'" "$NOISELAB" sweep "$nl"
  refused "'a\\nb' is not a number" "$NOISELAB" sweep s3 --param "octaves=$nl" --out sw
  # --help of a command answers, it is not an experiment's name
  "$NOISELAB" params --help >out 2>err
  check test $? = 0
  check grep -q '^  params EXPERIMENT' out
  touch afile
  refused 'afile/a\nb: Not a directory' "$NOISELAB" reproduce --out "afile/$nl" S3
  # a sweep folder's name goes into one-line job lines: refused
  refused "--out: 'sw\\nx': a control character" \
    "$NOISELAB" sweep s3 --param octaves=2 --quick --emit parallel --out $'sw\nx'
  check test ! -e sw
  check test -z "$(find . -maxdepth 1 -name 'sw*' -print -quit)"
  # a rerun still removes the short temporaries a SIGKILL left beside
  # outputs of long names (.nl.XXXXXX.EXT, .nl.XXXXXX)
  mkdir -p rep/s3_fbm
  touch rep/s3_fbm/.nl.Ab3dE9.png rep/s3_fbm/.nl.Zz09aB
  "$NOISELAB" reproduce --quick --out rep S3 >out 2>err
  check test $? = 0
  check test -f rep/s3_fbm/manifest.tsv
  check test -z "$(find rep/s3_fbm -name '.nl.*' -print -quit)"
fi

echo "cli_messages: $pass passed, $fail failed"
[ "$fail" = 0 ]
