#!/usr/bin/env bash
# The run harness (src/harness/nl_harness.c, nl_study_cheng_open): a rejected run
# touches nothing. Bad options, bad or unknown --set values and a missing or
# broken patterns folder give one line and exit 2, leave a finished run's
# manifest and tables as they were, and make no folder.
# Args: S3_BINARY C2_BINARY OUTDIR
set -euo pipefail
s3="$1" c2="$2" out="$3"
rm -rf "$out"; mkdir -p "$out"
pat="$(cd "$(dirname "$0")/../data/patterns" && pwd)"
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"

# A finished run of each: a real quick S3, and a C2 folder that looks finished.
"$s3" --quick --seeds 1 --out "$out/s3" >/dev/null
mkdir -p "$out/c2"; printf 'key\tvalue\nexperiment\tc2_ks_vs_chisq\n' >"$out/c2/manifest.tsv"
printf 'a\n1\n' >"$out/c2/summary.tsv"
snap() { (cd "$out" && find s3 c2 -type f -print0 | LC_ALL=C sort -z | xargs -0 sha256sum); }
before="$(snap)"

rejected() {   # WANT_FRAGMENT BINARY ARGS...
  local want="$1" bin="$2"; shift 2
  local err rc=0
  err="$("$bin" "$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
    echo "$(basename "$bin") $*: rc=$rc err='$err' (wanted exit 2, one line with '$want')"; exit 1
  fi
  [ "$(snap)" = "$before" ] || { echo "$(basename "$bin") $*: changed a finished run"; exit 1; }
}
for o in "$out/s3" "$out/fresh"; do
  rejected "'nan' is not an integer" "$s3" --quick --out "$o" --set octaves=nan
  rejected "outside" "$s3" --quick --out "$o" --set octaves=0
  rejected "--set nosuch: unknown parameter" "$s3" --quick --out "$o" --set nosuch=1
  rejected "is not NAME=VALUE" "$s3" --quick --out "$o" --set =1
  rejected "--seed" "$s3" --quick --out "$o" --seed 4294967296
  rejected "--seeds: missing value" "$s3" --quick --out "$o" --seeds
  rejected "--frobnicate: unknown option" "$s3" --out "$o" --frobnicate
done
rejected "--out: empty" "$s3" --out ""
# A side whose Fourier transforms are O(n^2) (1021 is prime: 1.9 s per
# transform, S3 --quick 58 s against 4.35 s at 1024) is a bad value,
# refused before any work, and so by a sweep's --params --set check.
t0=$SECONDS
rejected "--set size=1021: 1021 x 1021 pixels: width 1021 has the prime factor 1021" \
  "$s3" --quick --out "$out/fresh" --set size=1021
rejected "--set size=1021: 1021 x 1021 pixels" "$s3" --params --set size=1021
[ $((SECONDS - t0)) -lt 10 ] || { echo "s3 --set size=1021 took $((SECONDS - t0)) s to refuse"; exit 1; }
c2o="$out/c2"
rejected "--patterns /nonexistent" "$c2" --quick --out "$c2o" --patterns /nonexistent
rejected "--patterns: missing value" "$c2" --quick --out "$c2o" --patterns
rejected "not a folder" "$c2" --quick --out "$c2o" --patterns "$pat/flower.png"
# A folder missing one pattern, and one with a broken PNG.
mkdir -p "$out/pat-missing" "$out/pat-broken"
cp "$pat"/*.png "$out/pat-missing/"; rm "$out/pat-missing/rings.png"
cp "$pat"/*.png "$out/pat-broken/"; printf 'not a png' >"$out/pat-broken/x.png"
rejected "rings.png" "$c2" --quick --out "$c2o" --patterns "$out/pat-missing"
rejected "x.png" "$c2" --quick --out "$c2o" --patterns "$out/pat-broken"
rejected "--set nosuch: unknown parameter" "$c2" --quick --out "$c2o" --patterns "$pat" --set nosuch=1
rejected "'x' is not a number" "$c2" --quick --out "$c2o/new" --patterns "$pat" --set w1=x
# No empty folders from rejected runs.
[ ! -e "$out/fresh" ] || { echo "a rejected run made $out/fresh"; exit 1; }
[ ! -e "$c2o/new" ] || { echo "a rejected run made $c2o/new"; exit 1; }

# A wrong --set name's one line names the valid parameters.
err="$("$s3" --quick --out "$out/fresh" --set nosuch=1 2>&1 >/dev/null)" || true
[[ "$err" == *"(valid: size, extent, z, octaves)" ]] || { echo "unknown --set does not list the names: '$err'"; exit 1; }

# --params: a header and one TSV line per parameter (5 fields, a meaning),
# exit 0, no folder; a --set given with it is checked as for a run.
p="$("$s3" --params --out "$out/params" --set octaves=2)" || { echo "--params failed"; exit 1; }
rejected "outside" "$s3" --params --out "$out/params" --set octaves=99
rejected "(valid: size, extent, z, octaves)" "$s3" --params --out "$out/params" --set nosuch=1
[ "$(printf '%s\n' "$p" | head -n 1)" = $'name\tdefault\tmin\tmax\tmeaning' ] || { echo "--params header: '$p'"; exit 1; }
grep -q $'^octaves\t6\t1\t30\t[a-z]' <<<"$p" || { echo "--params has no octaves line: '$p'"; exit 1; }
printf '%s\n' "$p" | tsv_awk 'NF != 5 || v("meaning") == "" { bad = 1 } END { exit bad }' - || { echo "--params lines need 5 fields and a meaning: '$p'"; exit 1; }
[ "$(printf '%s\n' "$p" | wc -l)" = 5 ] || { echo "--params: wanted 4 parameters: '$p'"; exit 1; }
[ "$("$s3" --quick --params | tsv_awk 'v("name") == "size" { print v("default") }' -)" = 128 ] || { echo "--params --quick: size default is not the quick one"; exit 1; }
pc="$("$c2" --params --patterns "$pat")" || { echo "c2 --params failed"; exit 1; }
grep -q $'^w1\t0.995\t' <<<"$pc" || { echo "c2 --params has no w1: '$pc'"; exit 1; }
[ ! -e "$out/params" ] || { echo "--params made a folder"; exit 1; }

# --help writes nothing either and lists the parameters with their meanings;
# an accepted run still replaces the old one.
h="$("$s3" --help --out "$out/help")" || { echo "--help failed"; exit 1; }
[[ "$h" == *"usage: s3_fbm"* && "$h" == *"--params"* ]] || { echo "--help has no usage: '$h'"; exit 1; }
grep -q '^  octaves .*1, 30.*octaves summed' <<<"$h" || { echo "--help does not list octaves: '$h'"; exit 1; }
[ ! -e "$out/help" ] || { echo "--help made a folder"; exit 1; }
"$s3" --quick --seeds 1 --out "$out/s3" --set octaves=2 >/dev/null
grep -q $'^param\toctaves=2$' "$out/s3/manifest.tsv" || { echo "accepted run did not write its manifest"; exit 1; }

# The manifest names what moves a value's last bits across machines: the
# architecture and glibc's libm variant, as glibc sees the CPU, so a run with
# FMA turned off by GLIBC_TUNABLES says so (the regression check names both).
mval() { tsv_awk -v k="$1" 'v("key") == k { print v("value") }' "$2"; }
[ "$(mval arch "$out/s3/manifest.tsv")" = "$(uname -m)" ] \
  || { echo "manifest: arch is not uname -m"; exit 1; }
libm="$(mval libm "$out/s3/manifest.tsv")"
if grep -qi glibc <<<"$(ldd --version 2>&1)" && [ "$(uname -m)" = x86_64 ] &&
   grep -qw fma /proc/cpuinfo && grep -qw avx2 /proc/cpuinfo; then
  [[ "$libm" == "glibc 2."*" fma" ]] \
    || { echo "manifest: libm '$libm', wanted glibc's fma variant"; exit 1; }
  GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA,-FMA4,-AVX512F \
    "$s3" --quick --seeds 1 --out "$out/s3-nofma" --set octaves=2 >/dev/null
  libm="$(mval libm "$out/s3-nofma/manifest.tsv")"
  [[ "$libm" == "glibc 2."*" (CPU's fma turned off)" && "$libm" != *" fma ("* ]] \
    || { echo "manifest under -FMA: libm '$libm', wanted fma turned off"; exit 1; }
fi
echo "cli_run: ok"
