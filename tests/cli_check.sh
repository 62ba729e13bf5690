#!/usr/bin/env bash
# noiselab check: passes on an unchanged run, fails on drift (a bit-level
# change under `exact`, a mean shifted beyond Welch's test, a relative
# tolerance exceeded, a missing or unreadable table or changed parameter),
# passes on noise-level differences under the statistical rules, and
# refuses bad input (a rule naming a table or column the reference lacks)
# with one line and exit 2.
set -euo pipefail
# shellcheck source=tests/tsv.sh
. "$(dirname "$0")/tsv.sh"   # tables by column name
check="$1" out="$3"   # $2, expect, is not needed: the tests read check's messages
rm -rf "$out"; mkdir -p "$out"
ref="$out/ref"; mkdir -p "$ref"

tsv() { local f="$1"; shift; printf '%s\n' "$@" | tr '|' '\t' >"$f"; }
# A committed run: 10 seeds; dist.tsv holds means over seeds with their sds.
tsv "$ref/manifest.tsv" 'key|value' 'experiment|t1' 'seed|1' 'seeds|10' 'quick|no' 'param|size=8' 'seconds|1.5'
tsv "$ref/checks.tsv" 'table|column|rule' 'dist.tsv|mean|welch mean_sd 1e-3' 'dist.tsv|mean_sd|ftest 1e-3' \
    'dist.tsv|secs|ignore' 'spec.tsv|*|rel 1e-9'
tsv "$ref/dist.tsv" 'label|mean|mean_sd|secs|count' '(a) one|0.5|0.1|3.2|17' '(b) two|1.5|0|1.1|4'
tsv "$ref/spec.tsv" 'freq|power' '0.125|0.0077449593835423221' '0.375|0.0033590302577136471'

copy() { rm -rf "${out:?}/${1:?}"; cp -r "$ref" "$out/$1"; }
edit() {   # DIR FILE ROW COLUMN VALUE (row 1 = first data row; COLUMN by name)
  tsv_awk -v r="$3" -v c="$4" -v x="$5" 'BEGIN {OFS = "\t"} NR == r + 1 {$col(c) = x} {print}' "$out/$1/$2" >"$out/$1/.x"
  mv "$out/$1/.x" "$out/$1/$2"
}
run() {   # WANT_RC NAME [GREP...]: runs the check of ref against NAME
  local want="$1" name="$2"; shift 2
  local rc=0 log="$out/$name.out"
  "$check" "$ref" "$out/$name" >"$log" 2>"$out/$name.err" || rc=$?
  if [ "$rc" != "$want" ]; then echo "check $name: exit $rc, wanted $want"; cat "$log" "$out/$name.err"; exit 1; fi
  local g
  for g in "$@"; do grep -q -- "$g" "$log" "$out/$name.err" || { echo "check $name: no '$g' in:"; cat "$log" "$out/$name.err"; exit 1; }; done
}

# Unchanged: passes, and says how much it compared.
copy same
run 0 same 'check: t1: 2 tables, .* 0 drifted'

# A column the reference ignores (a time) may be gone from the run; any
# other missing column is drift.
copy notime
cut -f1-3,5 "$out/notime/dist.tsv" >"$out/notime/.x" && mv "$out/notime/.x" "$out/notime/dist.tsv"
run 0 notime 'check: t1: 2 tables, .* 0 drifted'
copy nocount
cut -f1-4 "$out/nocount/dist.tsv" >"$out/nocount/.x" && mv "$out/nocount/.x" "$out/nocount/dist.tsv"
run 1 nocount $'^t1\tdist.tsv\t-\tcount\tcolumn\tmissing'

# exact: one unit in the last place of an undeclared column is drift.
copy ulp; edit ulp dist.tsv 1 count 17.000000000000004
run 1 ulp $'t1\tdist.tsv\t1 \\[(a) one\\]\tcount\t17\t17.000000000000004\texact' '1 drifted'

# welch: a shift of 0.5 when the per-seed sd is 0.1 over 10 seeds (t ~ 11).
copy shifted; edit shifted dist.tsv 1 mean 1.0
run 1 shifted $'\tmean\t0.5\t1\twelch mean_sd 1e-3: p = ' '1 drifted'

# welch and ftest: noise-level differences pass (another random stream):
# mean moved by 0.03 (t ~ 0.7), its sd by 20 %, the ignored timing anything.
copy noise; edit noise dist.tsv 1 mean 0.53; edit noise dist.tsv 1 mean_sd 0.12; edit noise dist.tsv 1 secs 99
run 0 noise '0 drifted'

# ftest: a spread ten times larger is drift; a value with both sds 0 is exact.
copy spread; edit spread dist.tsv 1 mean_sd 1.0
run 1 spread $'\tmean_sd\t0.1\t1\tftest 1e-3'
copy zero; edit zero dist.tsv 2 mean 1.5000000000000002
run 1 zero 'both spreads 0, compared exactly'

# rel 1e-9: 1e-12 relative passes, 1e-6 does not.
copy relok; edit relok spec.tsv 1 power 0.0077449593835500
run 0 relok
copy relbad; edit relbad spec.tsv 2 power 0.0033590336
run 1 relbad $'spec.tsv\t2\tpower' 'rel 1e-9'

# Shape and run: a missing table, an extra row, another parameter.
copy notable; rm "$out/notable/spec.tsv"
run 1 notable $'spec.tsv\t-\t-\ttable\tmissing'
# The other way round: a table the run wrote (its manifest's "output" lines)
# that the committed folder lacks (deleted by hand, never committed) is
# drift, not a table compared by none; a file the run did not write (a
# test's own table beside it) is not the run's.
copy extra; tsv "$out/extra/more.tsv" 'a|b' '1|2'; printf 'output\tmore.tsv\n' >>"$out/extra/manifest.tsv"
run 1 extra $'more.tsv\t-\t-\tmissing\ttable' '1 drifted'
copy beside; tsv "$out/beside/mine.tsv" 'a|b' '1|2'
run 0 beside '0 drifted'
# A table the run wrote but the reader refuses (NUL bytes; nothing but
# NULs) is drift that names the reader's complaint, never "missing".
copy nul; { printf 'freq\tpower\n0.125\t0.0'; printf '\000'; printf '77\n'; } >"$out/nul/spec.tsv"
run 1 nul $'spec.tsv\t-\t-\ttable\tunreadable: '"$out/nul/spec.tsv:2: NUL byte" '1 drifted'
copy zeros; head -c 64 /dev/zero >"$out/zeros/spec.tsv"
run 1 zeros "unreadable: $out/zeros/spec.tsv:1: NUL byte" '1 drifted'
copy rows; printf '0.625\t0.001\n' >>"$out/rows/spec.tsv"
run 1 rows '2 rows'
copy param; edit param manifest.tsv 5 value size=16
run 1 param $'manifest.tsv\t-\tparam\tsize=8'

# Several experiments under two roots.
mkdir -p "$out/r1" "$out/r2"; cp -r "$ref" "$out/r1/t1"; cp -r "$ref" "$out/r2/t1"
r="$("$check" "$out/r1" "$out/r2" t1)"
grep -q 'check: t1: 2 tables' <<<"$r"

# Many drifted values: the first 10 lines and a count; --all every line. The
# summary names the experiment and the platform of both runs, what differs
# first: the reference predates the platform keys ("unknown"), then another
# BLAS kernel, then another libm variant on the same CPU and kernel.
copy many
for i in $(seq 12); do printf '%s\t0.001\n' "$i" >>"$out/many/spec.tsv"; done
cp -r "$out/many" "$out/many12"
for i in $(seq 12); do edit many12 spec.tsv $((i + 2)) power 0.002; done
cp "$ref/spec.tsv" "$out/spec.orig"; cp "$ref/manifest.tsv" "$out/manifest.orig"; cp "$out/many/spec.tsv" "$ref/spec.tsv"
rc=0; "$check" "$ref" "$out/many12" >"$out/many.out" || rc=$?
[ "$rc" = 1 ] || { echo "many: exit $rc"; cat "$out/many.out"; exit 1; }
[ "$(grep -c $'^t1\tspec.tsv\t' "$out/many.out")" = 10 ] || { echo "many: wanted 10 value lines"; cat "$out/many.out"; exit 1; }
want='^check: t1: 12 drifted (first 10 shown; --all for every one); reference vs this run: '
want+='CPU unknown (reference: not recorded, this run: not recorded), architecture unknown (.*), '
want+='BLAS kernel unknown (.*), libm unknown (.*)$'
grep -q "$want" "$out/many.out" \
  || { echo "many: summary line"; cat "$out/many.out"; exit 1; }
grep -q 'check: t1: 2 tables, .* 12 drifted' "$out/many.out" || { echo "many: total"; cat "$out/many.out"; exit 1; }
rc=0; "$check" --all "$ref" "$out/many12" >"$out/all.out" || rc=$?
{ [ "$rc" = 1 ] && [ "$(grep -c $'^t1\tspec.tsv\t' "$out/all.out")" = 12 ] \
  && grep -q '^check: t1: 12 drifted; ' "$out/all.out"; } \
  || { echo "--all: rc=$rc"; cat "$out/all.out"; exit 1; }
cp "$out/many12/manifest.tsv" "$out/manifest.many12"
platform() {   # DIR CPU ARCH BLAS_CORE LIBM
  printf 'cpu\t%s\narch\t%s\nblas_core\t%s\nlibm\t%s\n' "$2" "$3" "$4" "$5" >>"$1/manifest.tsv"
}
platform "$ref" 'AMD EPYC' x86_64 SkylakeX 'glibc 2.36 fma'
platform "$out/many12" 'AMD EPYC' x86_64 Haswell 'glibc 2.36 fma'
printf 'started\t2030-01-01T00:00:00Z\nseconds\t99\npeak_rss_mb\t1\nblas_threads\t7\n' \
  >>"$out/many12/manifest.tsv"
"$check" "$ref" "$out/many12" >"$out/plat.out" || true
want='^check: t1: 12 drifted.*; reference vs this run: '
want+='BLAS kernel other (reference SkylakeX, this run Haswell), CPU same (AMD EPYC), '
want+='architecture same (x86_64), libm same (glibc 2.36 fma)$'
grep -q "$want" "$out/plat.out" \
  || { echo "platform: summary"; cat "$out/plat.out"; exit 1; }
cp "$out/manifest.many12" "$out/many12/manifest.tsv"
platform "$out/many12" 'AMD EPYC' x86_64 SkylakeX "glibc 2.36 avx (CPU's fma turned off)"
"$check" "$ref" "$out/many12" >"$out/libm.out" || true
want='^check: t1: 12 drifted.*; reference vs this run: libm other (reference glibc 2.36 fma, '
want+="this run glibc 2.36 avx (CPU's fma turned off)), CPU same (AMD EPYC), "
want+='architecture same (x86_64), BLAS kernel same (SkylakeX)$'
grep -q "$want" "$out/libm.out" \
  || { echo "libm: summary"; cat "$out/libm.out"; exit 1; }
# Platform and timing lines are never compared: same tables, other platform, no drift.
cp -r "$ref" "$out/plat"
sed -i '/^\(cpu\|arch\|blas_core\|libm\)\t/d' "$out/plat/manifest.tsv"
platform "$out/plat" 'Other CPU' aarch64 Prescott 'glibc 2.41 sse2'
sed -i 's/^seconds\t.*/seconds\t42/' "$out/plat/manifest.tsv"
# ... and the totals line says that the reference was made on another
# architecture and libm (the CPU and BLAS kernel are not named there).
want='0 drifted; reference made elsewhere: architecture other (reference x86_64, this run aarch64), '
want+='libm other (reference glibc 2.36 fma, this run glibc 2.41 sse2)$'
run 0 plat "$want"
grep -q 'same (\|Prescott' "$out/plat.out" && { echo "plat: more than arch and libm named"; cat "$out/plat.out"; exit 1; }
# Another CPU alone, same architecture and libm: nothing named.
sed -i 's/^arch\taarch64$/arch\tx86_64/; s/^libm\tglibc 2.41 sse2$/libm\tglibc 2.36 fma/' "$out/plat/manifest.tsv"
run 0 plat '0 drifted$'
cp "$out/spec.orig" "$ref/spec.tsv"; cp "$out/manifest.orig" "$ref/manifest.tsv"
rm -rf "$out/many" "$out/many12" "$out/plat" "$out/manifest.many12"
copy same; run 0 same '0 drifted'

# Bad input: one line, exit 2.
bad() {   # WANT_FRAGMENT ARGS...
  local want="$1"; shift
  local err rc=0
  err="$("$check" "$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
    echo "check $*: rc=$rc err='$err' (wanted '$want')"; exit 1
  fi
}
bad "manifest.tsv" "$ref" "$out/nonexistent"
bad "wanted COMMITTED NEW" "$ref"
bad "--frob: unknown option" --frob "$ref" "$out/same"
bad "--all: takes no value" --all=1 "$ref" "$out/same"   # GNU-style options (nl_opt)
bad "-x: unknown option" "$ref" "$out/same" -x
copy badrule; printf 'dist.tsv\tcount\twelch\n' >>"$out/badrule/checks.tsv"
bad "welch needs SDCOL ALPHA" "$out/badrule" "$ref"
copy nocol; printf 'dist.tsv\tcount\twelch nosuch 1e-3\n' >>"$out/nocol/checks.tsv"
bad "no column 'nosuch'" "$out/nocol" "$ref"
# A rule for a table or column the reference does not have would check
# nothing: bad input naming the rule, the table and the folder.
copy ruletable; printf 'nosuch.tsv\tx\trel 1e-3\n' >>"$out/ruletable/checks.tsv"
bad "$out/ruletable/checks.tsv:6: rule 'rel 1e-3' for nosuch.tsv column x: $out/ruletable has no \
table nosuch.tsv" "$out/ruletable" "$ref"
copy rulecol; printf 'spec.tsv\tnosuch\trel 1e-3\n' >>"$out/rulecol/checks.tsv"
bad "$out/rulecol/checks.tsv:6: rule 'rel 1e-3' for spec.tsv column nosuch: \
$out/rulecol/spec.tsv has no such column" "$out/rulecol" "$ref"
copy ragged; printf '1\t2\t3\n' >>"$out/ragged/spec.tsv"
bad "spec.tsv:4" "$out/ragged" "$ref"
echo "cli_check: ok"
