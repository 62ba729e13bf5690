#!/bin/bash
# Integration test of the stat command line: tests/cli_stat.sh PATH/TO/noiselab-stat
# Known values come from scipy 1.10 / scikit-learn 1.2 (tests/data/stats, made by
# tests/reference/make_stats_vectors.py); bad inputs must give exit 2 and one
# line on stderr naming the input.
set -u
STAT=${1:?usage: cli_stat.sh PATH/TO/noiselab-stat [PATH/TO/expect]}
# json_get (tests/json_get.c) is built beside expect: strict JSON, values by path.
JSON_GET=$(dirname "${2:-$(dirname "$STAT")/../tests/expect}")/json_get
HERE=$(cd "$(dirname "$0")" && pwd)
DATA=$HERE/data/stats
# shellcheck source=tests/tsv.sh
. "$HERE/tsv.sh"   # tables by column name
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
pass=0 fail=0

ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAIL: $*" >&2; }

# expect_value "LINE" KEY WANT TOL: KEY=value in LINE within TOL of WANT (relative)
expect_value() {
  local got
  got=$(printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p")
  if [ -n "$got" ] && awk -v a="$got" -v b="$3" -v t="$4" \
       'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m + 1e-300) }'; then
    ok
  else
    bad "$2: got '$got', want $3 (line: $1)"
  fi
}

# expect_error NEEDLE CMD...: exit 2, exactly one stderr line containing NEEDLE, no stdout
expect_error() {
  local needle=$1; shift
  "$@" >"$TMP/out" 2>"$TMP/err" </dev/null
  local rc=$? lines
  lines=$(wc -l <"$TMP/err")
  if [ "$rc" = 2 ] && [ "$lines" = 1 ] && grep -q -- "$needle" "$TMP/err" && [ ! -s "$TMP/out" ]; then
    ok
  else
    bad "expected exit 2 with one line containing '$needle' from: $* (rc=$rc, stderr: $(cat "$TMP/err"))"
  fi
}

TWO_PI=6.283185307179586

# ---- known values --------------------------------------------------------------
line=$("$STAT" ks "$DATA/ks_facts_512.tsv" --uniform 0 $TWO_PI)
expect_value "$line" D 0.06383549510032682 1e-15
expect_value "$line" p 0.02947543990965429 1e-10
expect_value "$line" n 512 0
case $line in *method=pelz-good*) ok ;; *) bad "ks method: $line" ;; esac

line=$("$STAT" ks "$DATA/ks_pow1.3_5000_s2.tsv" --uniform 0 $TWO_PI)
expect_value "$line" p "$(tsv_awk 'v("file") == "ks_pow1.3_5000_s2.tsv" { print v("p") }' "$DATA/ks_one.tsv")" 1e-10

line=$(tsv_awk 'NR > 1 { printf "%.17g\n", n("x0") / 6.283185307179586 }' "$DATA/ks_unif_100_s0.tsv" | "$STAT" ks - --uniform 0 1)
expect_value "$line" D "$(tsv_awk 'v("file") == "ks_unif_100_s0.tsv" { print v("d") }' "$DATA/ks_one.tsv")" 1e-12

line=$("$STAT" ks2 "$DATA/ks2_1_a.tsv" "$DATA/ks2_1_b.tsv")
expect_value "$line" D 0.43333333333333335 1e-15
expect_value "$line" p "$(tsv_awk 'v("file1") == "ks2_1_a.tsv" { print v("p") }' "$DATA/ks2.tsv")" 1e-10

line=$("$STAT" kuiper "$DATA/ks_facts_512.tsv" --uniform 0 $TWO_PI)
expect_value "$line" V "$(tsv_awk 'v("file") == "ks_facts_512.tsv" { print v("v") }' "$DATA/kuiper_one.tsv")" 1e-15
expect_value "$line" p "$(tsv_awk 'v("file") == "ks_facts_512.tsv" { print v("p") }' "$DATA/kuiper_one.tsv")" 1e-9

line=$("$STAT" chisq "$DATA/chisq_0.tsv" --bins 500 --uniform 0 $TWO_PI 2>"$TMP/err")
expect_value "$line" chi2 "$(tsv_awk 'v("file") == "chisq_0.tsv" { print v("chi2") }' "$DATA/chisq.tsv")" 1e-12
expect_value "$line" p "$(tsv_awk 'v("file") == "chisq_0.tsv" { print v("p") }' "$DATA/chisq.tsv")" 1e-10
expect_value "$line" df 499 0
expect_value "$line" min_expected 1.024 1e-15
if grep -q "unreliable" "$TMP/err"; then ok
else bad "chisq: no warning for expected counts < 5"; fi

# hclust: labels and merges against scipy
line=$("$STAT" hclust "$DATA/hclust_X.tsv" --linkage average --clusters 5 \
       --labels "$TMP/lab.tsv" --merges "$TMP/merges.tsv")
expect_value "$line" clusters 5 0
if cmp -s <(tail -n +2 "$TMP/lab.tsv") <(tsv_cut "$DATA/hclust_average_labels.tsv" maxclust_5 | tail -n +2); then ok
else bad "hclust labels differ from scipy's fcluster maxclust 5"; fi
if tsv_awk 'FNR == 1 { next }
     NR == FNR { a[FNR] = n("a"); b[FNR] = n("b"); dist[FNR] = n("dist"); size[FNR] = n("size"); next }
     { d = n("dist") - dist[FNR]; if (d < 0) d = -d
       if (n("a") != a[FNR] || n("b") != b[FNR] || n("size") != size[FNR] || d > 1e-12 * dist[FNR]) bad = 1 }
     END { exit bad }' "$DATA/hclust_average_Z.tsv" "$TMP/merges.tsv"; then ok; else bad "hclust merges differ from scipy's linkage"; fi
line=$("$STAT" hclust "$DATA/hclust_X.tsv" --linkage single --cutoff 1e9)
expect_value "$line" clusters 1 0

# gmm: the k-means++ start finds sklearn's optimum on this data (k = 3)
line=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --params "$TMP/params.tsv")
expect_value "$line" loglik -5069.630131017421 1e-8
expect_value "$line" aic 10227.260262034843 1e-8
expect_value "$line" bic 10430.543483122177 1e-8
expect_value "$line" converged 1 0
if [ "$(grep -c weight "$TMP/params.tsv")" = 3 ]; then ok
else bad "gmm --params: expected 3 weights"; fi
out=$("$STAT" gmm "$DATA/gmm_X.tsv" --select-aic 1 20 --covariance full)
case $out in *selected=3*) ok ;; *) bad "gmm --select-aic 1 20: $out" ;; esac
if [ "$(printf '%s\n' "$out" | grep -c '^k=')" = 4 ]; then ok
else bad "gmm selection path should list k = 1..4: $out"; fi

# constant column: finite result, exit 0, a note on stderr
printf '1 5\n2 5\n3 5\n4 5\n10 5\n11 5\n12 5\n' >"$TMP/const.txt"
line=$("$STAT" gmm "$TMP/const.txt" --k 2 2>"$TMP/err")
rc=$?
if [ $rc = 0 ] && ! printf '%s' "$line" | grep -qi nan && grep -q "column 2 is constant" "$TMP/err"; then ok
else bad "constant column: rc=$rc line=$line err=$(cat "$TMP/err")"; fi

# help
if "$STAT" gmm --help | grep -q "usage: noiselab stat gmm"; then ok; else bad "gmm --help"; fi
if "$STAT" --help | grep -q "hclust"; then ok; else bad "--help"; fi

# ---- bad input: exit 2, one line ---------------------------------------------
: >"$TMP/empty.tsv"
printf 'x\n0.5\n' >"$TMP/one.tsv"
printf '0.1\nnan\n0.3\n' >"$TMP/nan.tsv"
printf '0.1\ninf\n0.3\n' >"$TMP/inf.tsv"
printf '0.1\n0.2\nabc\n' >"$TMP/word.tsv"
printf '0.1 0.2\n0.3\n0.4 0.5\n' >"$TMP/ragged.tsv"
printf '0.1 0.2\n0.3 0.4\n0.5 0.7\n' >"$TMP/three.tsv"
expect_error "empty.tsv" "$STAT" ks "$TMP/empty.tsv"
expect_error "one.tsv" "$STAT" ks "$TMP/one.tsv"
expect_error "nan.tsv:2" "$STAT" ks "$TMP/nan.tsv"
expect_error "inf.tsv:2" "$STAT" kuiper "$TMP/inf.tsv"
expect_error "word.tsv:3" "$STAT" chisq "$TMP/word.tsv" --bins 4
expect_error "ragged.tsv:2" "$STAT" hclust "$TMP/ragged.tsv" --linkage single --clusters 2
expect_error "only 3 rows" "$STAT" gmm "$TMP/three.tsv" --k 4
# A byte-order mark is skipped (all 1000 rows are data); a first line "inf"
# is a row of data, refused on line 1, not a header that drops a row.
{ printf '\357\273\277'; awk 'BEGIN { for (i = 0; i < 1000; i++) print (i + 0.5) / 1000 }'; } \
  >"$TMP/bom.tsv"
case $("$STAT" ks "$TMP/bom.tsv" --uniform 0 1) in
  *"n=1000 "*) ok ;;
  *) bad "ks on a file with a BOM: not n=1000" ;;
esac
{ echo inf; awk 'BEGIN { for (i = 1; i < 1000; i++) print (i + 0.5) / 1000 }'; } >"$TMP/inf1.tsv"
expect_error "inf1.tsv:1: column 'c1' holds 'inf'" "$STAT" ks "$TMP/inf1.tsv"
# Finite values whose squared distances overflow: refused, whatever the linkage.
printf '0\n1e160\n' >"$TMP/huge2.tsv"
printf '0\n1e200\n3e200\n' >"$TMP/huge3.tsv"
for link in single complete average ward; do
  expect_error "huge2.tsv: the points span a distance of 1e+160" \
    "$STAT" hclust "$TMP/huge2.tsv" --linkage "$link" --clusters 1
  expect_error "huge3.tsv: .*rescale the data" \
    "$STAT" hclust "$TMP/huge3.tsv" --linkage "$link" --clusters 1 --labels "$TMP/huge_labels.tsv"
done
if [ ! -e "$TMP/huge_labels.tsv" ]; then ok; else bad "a refused hclust wrote its labels"; fi
expect_error "--bins" "$STAT" chisq "$DATA/chisq_0.tsv" --bins 1
expect_error "--cutoff" "$STAT" hclust "$DATA/hclust_X.tsv" --linkage single --cutoff -1
expect_error "outside" "$STAT" chisq "$DATA/chisq_0.tsv" --bins 10
expect_error "cannot open" "$STAT" ks "$TMP/missing.tsv"
expect_error "unknown option" "$STAT" ks "$DATA/ks_facts_512.tsv" --bogus
expect_error "no column 2" "$STAT" ks "$DATA/ks_facts_512.tsv" --column 2
expect_error "unknown linkage 'medoid' (single, complete, average, weighted, ward, centroid or" \
  "$STAT" hclust "$DATA/hclust_X.tsv" --linkage medoid --clusters 2
expect_error "exactly one" "$STAT" gmm "$DATA/gmm_X.tsv"
expect_error "one file needs two columns to compare: --column C1 --column C2" \
  "$STAT" ks2 "$DATA/ks2_1_a.tsv"
expect_error "unknown subcommand" "$STAT" frobnicate x

# NUL bytes, endless lines, endless non-regular files,
# requests beyond the machine's memory: refused at once, input named.
printf 'a\tb\n1\t2\n3\t4\0005\n' >"$TMP/nul.tsv"
expect_error "nul.tsv:3: NUL byte in column 2" "$STAT" ks "$TMP/nul.tsv"
expect_error "/dev/zero:1: line longer than 1048576 bytes" timeout 120 "$STAT" ks /dev/zero
expect_error "/dev/urandom:" timeout 120 "$STAT" kuiper /dev/urandom
expect_error "read error: Is a directory" "$STAT" ks "$TMP"
awk 'BEGIN { for (i = 0; i < 1000000; i++) print i % 97, i % 13 }' >"$TMP/big.tsv"
expect_error "big.tsv: 1000000 rows need 4 TB for the distance matrix; " \
  timeout 120 "$STAT" hclust "$TMP/big.tsv" --linkage complete --clusters 3
expect_error "big.tsv: 1000000 rows of 2 columns with 100000 components need" \
  timeout 120 "$STAT" gmm "$TMP/big.tsv" --k 100000
expect_error "big.tsv: 1000000 rows of 2 columns with 100000 components need" \
  timeout 120 "$STAT" gmm "$TMP/big.tsv" --select-aic 1 0.5 --max-k 100000
rm -f "$TMP/big.tsv"
awk 'BEGIN { for (i = 0; i < 20; i++) { for (j = 0; j < 100000; j++) printf "%d ", (i * j) % 7; print "" } }' >"$TMP/wide.tsv"
expect_error "wide.tsv: 20 rows of 100000 columns with 3 components need" timeout 120 "$STAT" gmm "$TMP/wide.tsv" --k 3
expect_error "parent $TMP/nul.tsv is not a directory" "$STAT" hclust "$DATA/hclust_X.tsv" --linkage single --clusters 2 --labels "$TMP/nul.tsv/x.tsv"

# ---- scipy's habits -----------------------------------------------------------
# Reference: tests/reference/stat_cli (tests/reference/make_stat_cli_vectors.py,
# scipy 1.10.1). Measured against it: D within 1.2e-15 relative (glibc's erf
# against cephes' ndtr), p within 4e-13 relative, V within 1e-15; Ward's
# linkage matrix bit-identical. Tolerances below: D and V 1e-13, p 1e-10.
REF=$HERE/reference/stat_cli
# json_value JSON KEY: the number or string after "KEY": in a one-line object
json_value() { printf '%s\n' "$1" | sed -n "s/.*\"$2\": \"\{0,1\}\([^,\"}]*\).*/\1/p"; }
expect_json() {
  local got; got=$(json_value "$1" "$2")
  if [ -n "$got" ] && awk -v a="$got" -v b="$3" -v t="$4" \
       'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m + 1e-300) }'; then ok
  else bad "json $2: got '$got', want $3 (line: $1)"; fi
}
rows=0
while IFS=$'\t' read -r f dist loc scale D p V; do
  [ "$f" = file ] && continue
  rows=$((rows + 1))
  case $dist in
    *.tsv) how=(--cdf "$REF/$dist") ;;
    *) how=(--dist "$dist" --loc "$loc" --scale "$scale") ;;
  esac
  js=$("$STAT" ks "$REF/$f" "${how[@]}" --format json)
  expect_json "$js" D "$D" 1e-13
  expect_json "$js" p "$p" 1e-10
  line=$("$STAT" kuiper "$REF/$f" "${how[@]}")
  expect_value "$line" V "$V" 1e-13
done <"$REF/ks_dist.tsv"
if [ "$rows" = 10 ]; then ok; else bad "ks_dist.tsv: $rows cases read, want 10"; fi
# Every named distribution with scipy's (shapes, loc, scale): ks_shapes.tsv
# (make_stat_cli_vectors.py, scipy.stats.kstest). Measured: D and V within
# 1.1e-14 relative (GSL's incomplete beta against cephes'), p within 2.5e-12.
# Tolerances: D and V 1e-13, p 1e-10, as above.
rows=0
while IFS=$'\t' read -r f dist shape loc scale D p _ _ _ _ V; do
  [ "$f" = file ] && continue
  rows=$((rows + 1))
  how=(--dist "$dist" --loc "$loc" --scale "$scale")
  [ "$shape" != - ] && how+=(--shape "$shape")
  line=$("$STAT" ks "$REF/$f" --column value "${how[@]}")
  expect_value "$line" D "$D" 1e-13
  expect_value "$line" p "$p" 1e-10
  expect_value "$("$STAT" kuiper "$REF/$f" "${how[@]}")" V "$V" 1e-13
done <"$REF/ks_shapes.tsv"
if [ "$rows" = 28 ]; then ok; else bad "ks_shapes.tsv: $rows cases read, want 28"; fi
expect_error "--dist gamma needs --shape A (1 value, scipy's order), got 0" \
  "$STAT" ks "$REF/u01_100.tsv" --dist gamma
expect_error "--dist beta needs --shape A,B (2 values, scipy's order), got 1" \
  "$STAT" ks "$REF/u01_100.tsv" --dist beta --shape 2
expect_error "--dist norm takes no --shape" "$STAT" ks "$REF/u01_100.tsv" --dist norm --shape 1
expect_error "--shape: gamma's a must be positive, got 0" \
  "$STAT" ks "$REF/u01_100.tsv" --dist gamma --shape 0
expect_error "--shape: '1,2,3' has more than 2 values" \
  "$STAT" ks "$REF/u01_100.tsv" --dist beta --shape 1,2,3
# --alternative less|greater as scipy's kstest (one-sided exact p: ksone) and
# ks_2samp (Hodges' path count; asymptotic past 10000 or when the counts overflow).
# Measured: D within 2.8e-14 relative, p within 5.6e-13. Tolerances: 1e-13, 1e-10.
while IFS=$'\t' read -r f dist shape loc scale _ _ Dl pl Dg pg _; do
  [ "$f" = file ] && continue
  how=(--dist "$dist" --loc "$loc" --scale "$scale")
  [ "$shape" != - ] && how+=(--shape "$shape")
  line=$("$STAT" ks "$REF/$f" "${how[@]}" --alternative less)
  expect_value "$line" D "$Dl" 1e-13
  expect_value "$line" p "$pl" 1e-10
  line=$("$STAT" ks "$REF/$f" "${how[@]}" --alternative=greater)
  expect_value "$line" D "$Dg" 1e-13
  expect_value "$line" p "$pg" 1e-10
done <"$REF/ks_shapes.tsv"
rows=0
while IFS=$'\t' read -r f1 f2 alt D p; do
  [ "$f1" = file1 ] && continue
  rows=$((rows + 1))
  line=$("$STAT" ks2 "$REF/$f1" "$REF/$f2" --alternative "$alt")
  expect_value "$line" D "$D" 1e-13
  expect_value "$line" p "$p" 1e-10
done <"$REF/ks2_alt.tsv"
if [ "$rows" = 18 ]; then ok; else bad "ks2_alt.tsv: $rows cases read, want 18"; fi
# ks2 on two columns of one table: the same samples as two files, so scipy's
# ks_2samp values of ks2_alt.tsv (by name, by number, and a file's two columns
# named once for each file)
paste "$REF/ks2_40_40_a.tsv" "$REF/ks2_40_40_b.tsv" | sed '1s/.*/a\tb/' >"$TMP/ab.tsv"
while IFS=$'\t' read -r f1 f2 alt D p; do
  if [ "$f1" != ks2_40_40_a.tsv ] || [ "$f2" != ks2_40_40_b.tsv ]; then continue; fi
  for cols in "--column a --column b" "--column=1 --column=2"; do
    # shellcheck disable=SC2086
    line=$("$STAT" ks2 "$TMP/ab.tsv" $cols --alternative "$alt")
    expect_value "$line" D "$D" 1e-13
    expect_value "$line" p "$p" 1e-10
  done
  line=$("$STAT" ks2 "$TMP/ab.tsv" "$TMP/ab.tsv" --column a --column b --alternative "$alt")
  expect_value "$line" D "$D" 1e-13
done <"$REF/ks2_alt.tsv"
expect_error "--column given three times" "$STAT" ks2 "$TMP/ab.tsv" --column a --column b --column a
expect_error "--column given twice" "$STAT" ks "$TMP/ab.tsv" --column a --column b --uniform 0 1
expect_error "ab.tsv: no column 'c'" "$STAT" ks2 "$TMP/ab.tsv" --column a --column c
# ks names its null distribution: scipy's kstest has no default CDF
expect_error "the null distribution is required: --uniform A B, --dist NAME or --cdf TABLE" \
  "$STAT" ks "$REF/u01_100.tsv"
expect_error "--alternative: unknown alternative 'lower' (two-sided, less or greater)" \
  "$STAT" ks "$REF/u01_100.tsv" --alternative lower
expect_error "--alternative is for ks and ks2" "$STAT" kuiper "$REF/u01_100.tsv" --alternative less
# the issue's own command, GNU spellings, and the other formats
js=$("$STAT" ks "$REF/norm_200.tsv" --dist norm --loc 0 --scale 1 --format json)
case $js in '{"D": '*', "p": '*', "n": 200, "method": "'*'"}') ok ;; *) bad "json shape: $js" ;; esac
if [ "$("$STAT" ks "$REF/norm_200.tsv" --dist=norm --format=json)" = "$js" ]; then ok
else bad "--dist=norm (defaults loc 0, scale 1) differs"; fi
tsv=$("$STAT" ks "$REF/norm_200.tsv" --dist norm --format tsv)
if [ "$(printf '%s\n' "$tsv" | head -1)" = "$(printf 'D\tp\tn\tmethod')" ] \
  && [ "$(printf '%s\n' "$tsv" | wc -l)" = 2 ]; then ok
else bad "--format tsv: $tsv"; fi
expect_value "$("$STAT" ks "$REF/unif_80.tsv" --uniform=2 5)" D \
  "$(tsv_awk 'v("file") == "unif_80.tsv" && n("loc") == 2 { print v("D") }' "$REF/ks_dist.tsv")" 1e-13
# CSV: detected, or forced; the same numbers as the TSV
if [ "$("$STAT" ks "$REF/norm_200.csv" --dist norm --format json)" = "$js" ]; then ok
else bad "CSV not read as the TSV"; fi
if [ "$("$STAT" ks --csv - --dist norm --format json <"$REF/norm_200.csv")" = "$js" ]; then ok
else bad "--csv on stdin"; fi
expect_value "$("$STAT" ks "$REF/norm_200.csv" --column=2 --dist norm --scale 2)" D "$(json_value "$js" D)" 1e-15
# --column by the header's name, as tables are addressed everywhere else
if [ "$("$STAT" ks "$REF/norm_200.csv" --column twice --dist norm --scale 2)" \
     = "$("$STAT" ks "$REF/norm_200.csv" --column 2 --dist norm --scale 2)" ]; then ok
else bad "--column twice differs from --column 2"; fi
if [ "$("$STAT" ks2 "$REF/norm_200.csv" "$REF/norm_200.tsv" --column=x)" \
     = "$("$STAT" ks2 "$REF/norm_200.csv" "$REF/norm_200.tsv")" ]; then ok
else bad "ks2 --column=x"; fi
expect_error "norm_200.csv: no column 'value' (the table's columns: x, twice)" \
  "$STAT" ks "$REF/norm_200.csv" --column value
expect_error "--column: 0 is outside" "$STAT" chisq "$REF/u01_100.tsv" --bins 4 --column 0
expect_error "--column is for ks, ks2, kuiper and chisq (gmm uses every column)" \
  "$STAT" gmm "$DATA/gmm_X.tsv" --k 2 --column x0
expect_error "--metric is for hclust" "$STAT" ks "$REF/u01_100.tsv" --metric cosine
printf 'x\ty\n0.1,0.2\t0.3\n0.4\t0.5\n' >"$TMP/mixed.tsv"
expect_error "holds '0.1,0.2', not a number (commas: a CSV file?" "$STAT" ks "$TMP/mixed.tsv"
# Ward against scipy.cluster.hierarchy.linkage(X, 'ward') and fcluster
line=$("$STAT" hclust "$REF/ward_X.tsv" --method=ward --clusters 4 --labels "$TMP/wl.tsv" --merges "$TMP/wz.tsv")
expect_value "$line" clusters 4 0
if tsv_awk 'FNR == 1 { next }
     NR == FNR { a[FNR] = n("a"); b[FNR] = n("b"); dist[FNR] = n("dist"); size[FNR] = n("size"); next }
     { d = n("dist") - dist[FNR]; if (d < 0) d = -d
       if (n("a") != a[FNR] || n("b") != b[FNR] || n("size") != size[FNR] || d > 1e-12 * dist[FNR]) bad = 1 }
     END { exit bad }' "$REF/ward_Z.tsv" "$TMP/wz.tsv"; then ok; else bad "ward merges differ from scipy's linkage"; fi
if cmp -s <(tail -n +2 "$TMP/wl.tsv") \
  <(tsv_cut "$REF/ward_labels.tsv" maxclust_4 | tail -n +2); then ok
else bad "ward maxclust 4 labels"; fi
"$STAT" hclust "$REF/ward_X.tsv" --linkage ward --cutoff 6 --labels "$TMP/wl6.tsv" >/dev/null
if cmp -s <(tail -n +2 "$TMP/wl6.tsv") \
  <(tsv_cut "$REF/ward_labels.tsv" distance_6 | tail -n +2); then ok
else bad "ward distance 6 labels"; fi
# pdist's metrics with single, complete, average and weighted linkage, and
# centroid and median linkage (Euclidean; the generic algorithm, Z in merge
# order) against scipy (metric_Z.tsv, metric_labels.tsv): a, b and size equal,
# dist within 1e-11 relative (measured: 0 but cosine and correlation, 7.9e-13:
# 1 - cos cancels), fcluster maxclust 4 labels equal.
cases=0
while IFS=$'\t' read -r method metric; do
  cases=$((cases + 1))
  "$STAT" hclust "$REF/metric_X.tsv" --linkage "$method" --metric "$metric" --clusters 4 \
    --merges "$TMP/mz.tsv" --labels "$TMP/ml.tsv" >/dev/null
  if tsv_awk -v m="$method" -v d="$metric" '
       NR == FNR { if (v("method") == m && v("metric") == d) { k++; a[k] = n("a"); b[k] = n("b")
                   dist[k] = n("dist"); size[k] = n("size") }; next }
       FNR > 1 { i = FNR - 1; e = n("dist") - dist[i]; if (e < 0) e = -e
                 if (n("a") != a[i] || n("b") != b[i] || n("size") != size[i] \
                     || e > 1e-11 * dist[i]) bad = 1 }
       END { exit bad || FNR - 1 != k || k != 41 }' "$REF/metric_Z.tsv" "$TMP/mz.tsv"; then ok
  else bad "hclust --linkage $method --metric $metric: Z differs from scipy's"; fi
  if cmp -s <(tail -n +2 "$TMP/ml.tsv") <(tsv_awk -v m="$method" -v d="$metric" \
              'v("method") == m && v("metric") == d { print v("maxclust_4") }' \
              "$REF/metric_labels.tsv"); then ok
  else bad "hclust --linkage $method --metric $metric: labels differ from scipy's fcluster"; fi
done < <(tail -n +2 "$REF/metric_Z.tsv" | cut -f1,2 | uniq)
if [ "$cases" = 31 ]; then ok; else bad "metric_Z.tsv: $cases cases, want 31"; fi
expect_error "--linkage ward needs --metric euclidean, not cosine (as scipy's linkage)" \
  "$STAT" hclust "$REF/metric_X.tsv" --linkage ward --metric cosine --clusters 2
expect_error "--linkage centroid needs --metric euclidean, not cityblock" \
  "$STAT" hclust "$REF/metric_X.tsv" --linkage centroid --metric cityblock --clusters 2
expect_error "--metric: unknown metric 'manhattan' (euclidean, sqeuclidean, cityblock" \
  "$STAT" hclust "$REF/metric_X.tsv" --linkage single --metric manhattan --clusters 2
# gmm: score (sklearn's mean log-likelihood per row) beside the total
line=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3)
expect_value "$line" score "$(awk 'BEGIN { printf "%.17g", -5069.630131017421 / 750 }')" 1e-8
js=$("$STAT" gmm "$DATA/gmm_X.tsv" --select-aic 1 20 --format json)
if [ "$(printf '%s\n' "$js" | grep -c '"selected": true')" != 1 ]; then
  bad "select json: one selected row expected: $js"
else
  case $js in '['*']') ok ;; *) bad "select json: $js" ;; esac
fi
# JSON: valid (strict) for every subcommand, flags as true/false, and complete:
# hclust gives scipy's linkage matrix and the labels, gmm its parameters.
for cmd in "ks $REF/u01_100.tsv --uniform 0 1" "kuiper $REF/u01_100.tsv" "chisq $REF/u01_100.tsv --bins 4" \
           "ks2 $REF/ks2_40_40_a.tsv $REF/ks2_40_40_b.tsv" "gmm $DATA/gmm_X.tsv --k 3" \
           "gmm $DATA/gmm_X.tsv --select-aic 1 20" \
           "hclust $REF/ward_X.tsv --linkage ward --clusters 4"; do
  # shellcheck disable=SC2086 # the command's words
  if "$STAT" $cmd --format json | "$JSON_GET" . >/dev/null; then ok; else bad "json of $cmd"; fi
done
js=$("$STAT" hclust "$REF/ward_X.tsv" --linkage ward --clusters 4 --format json)
if [ "$(printf '%s' "$js" | "$JSON_GET" clusters Z labels linkage | tr '\n' ' ')" \
     = "4 array 59 array 60 ward " ]; then ok; else bad "hclust json: $js"; fi
# every element of Z against scipy's (ward_Z.tsv), as --merges is checked above
paths=$(awk 'BEGIN { for (i = 0; i < 59; i++) for (j = 0; j < 4; j++) printf "Z.%d.%d ", i, j }')
# shellcheck disable=SC2086 # one path per word
if printf '%s' "$js" | "$JSON_GET" $paths | paste - - - - \
   | tsv_awk 'NR == FNR { if (FNR > 1) { a[FNR] = n("a"); b[FNR] = n("b"); d[FNR] = n("dist")
                                          s[FNR] = n("size") }; next }
              { r = FNR + 1; e = $3 - d[r]; if (e < 0) e = -e
                if ($1 != a[r] || $2 != b[r] || $4 != s[r] || e > 1e-12 * d[r]) bad = 1 }
              END { exit bad || FNR != 59 }' "$REF/ward_Z.tsv" -; then ok
else bad "hclust json Z differs from scipy's linkage"; fi
paths=$(awk 'BEGIN { for (i = 0; i < 60; i++) printf "labels.%d ", i }')
# shellcheck disable=SC2086 # one path per word
if cmp -s <(printf '%s' "$js" | "$JSON_GET" $paths) \
          <(tsv_cut "$REF/ward_labels.tsv" maxclust_4 | tail -n +2); then ok
else bad "hclust json labels differ from scipy's fcluster"; fi
js=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --format json)
if [ "$(printf '%s' "$js" | "$JSON_GET" converged weights means.2 covariances.1 covariances.1.0 \
        | tr '\n' ' ')" = "true array 3 array 4 array 4 array 4 " ]; then ok
else bad "gmm json: $js"; fi
if [ "$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --covariance diag --format json \
        | "$JSON_GET" covariances.2 covariances.2.3)" != "" ]; then ok
else bad "gmm diag json covariances"; fi
# Every covariance type (sklearn's covariance_type) at k = 3: the k-means++ start
# finds sklearn's optimum (gmm_fit.tsv: sklearn from its KMeans labels), so
# loglik, AIC and BIC agree within 1e-8 relative and --labels equals sklearn's
# predict on all 750 rows up to renaming the components (measured: 1e-15).
same_partition() {   # two label columns (header skipped): one-to-one on every row
  paste <(tail -n +2 "$1") <(tail -n +2 "$2") | awk -F'\t' '
    { if (($1 in f) && f[$1] != $2 || ($2 in b) && b[$2] != $1) bad = 1
      f[$1] = $2; b[$2] = $1; n++ }
    END { exit bad || n != 750 }'
}
for cov in full diag tied spherical; do
  want=$(tsv_awk -v c=$cov \
         'v("k") == 3 && v("covariance") == c { print v("loglik"), v("aic"), v("bic") }' \
         "$DATA/gmm_fit.tsv")
  line=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --covariance $cov --labels "$TMP/gl.tsv")
  expect_value "$line" loglik "${want%% *}" 1e-8
  expect_value "$line" aic "$(echo "$want" | cut -d' ' -f2)" 1e-8
  expect_value "$line" bic "${want##* }" 1e-8
  if same_partition "$TMP/gl.tsv" "$DATA/gmm_predict_k3_$cov.tsv"; then ok
  else bad "gmm --covariance $cov --labels differ from sklearn's predict"; fi
done
js=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --covariance tied --format json)
if [ "$(printf '%s' "$js" | "$JSON_GET" covariance_type covariances covariances.3 labels \
        | tr '\n' ' ')" \
     = "tied array 4 array 4 array 750 " ]; then ok; else bad "gmm tied json: $js"; fi
js=$("$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --covariance spherical --format json)
if [ "$(printf '%s' "$js" | "$JSON_GET" covariances | tr '\n' ' ')" = "array 3 " ]; then ok
else bad "gmm spherical json: $js"; fi
expect_error "--covariance: unknown covariance type 'round' (full, diag, tied or spherical)" \
  "$STAT" gmm "$DATA/gmm_X.tsv" --k 3 --covariance round
# more parameters than numbers: one warning line
awk 'BEGIN { for (i = 0; i < 20; i++) print (i * 37 % 20) / 20, (i * 11 % 20) / 20 }' >"$TMP/g20.tsv"
"$STAT" gmm "$TMP/g20.tsv" --k 8 >/dev/null 2>"$TMP/err"
if [ "$(wc -l <"$TMP/err")" = 1 ] \
  && grep -q "47 free parameters, more than the 40 numbers" "$TMP/err"; then ok
else bad "gmm over-parameterised: $(cat "$TMP/err")"; fi
"$STAT" gmm "$TMP/g20.tsv" --k 2 >/dev/null 2>"$TMP/err"
if [ ! -s "$TMP/err" ]; then ok; else bad "gmm k=2 on 20 x 2 warned: $(cat "$TMP/err")"; fi
# refusals
printf 'x\tF\n0\t0\n0.5\t0.6\n0.4\t0.7\n' >"$TMP/badcdf.tsv"
expect_error "x = 0.4 does not increase" "$STAT" ks "$REF/u01_100.tsv" --cdf "$TMP/badcdf.tsv"
expect_error "unknown distribution 'gumbel' (uniform, norm, expon, gamma" \
  "$STAT" ks "$REF/u01_100.tsv" --dist gumbel
expect_error "--scale 0 must be positive" "$STAT" ks "$REF/u01_100.tsv" --dist norm --scale 0
# a negative scale or shape gets the same message as zero, not a range
expect_error "--scale -1 must be positive" "$STAT" ks "$REF/u01_100.tsv" --dist norm --scale -1
expect_error "--shape: gamma's a must be positive, got -2" \
  "$STAT" ks "$REF/u01_100.tsv" --dist gamma --shape -2
expect_error "--shape, --loc and --scale go with --dist" "$STAT" ks "$REF/u01_100.tsv" --loc 1
expect_error "give one of --uniform A B, --dist NAME and --cdf TABLE" "$STAT" ks "$REF/u01_100.tsv" --uniform 0 1 --dist norm
expect_error "--format: 'xml' is not kv, tsv or json" "$STAT" ks "$REF/u01_100.tsv" --format xml
expect_error "--bogus: unknown option" "$STAT" ks "$REF/u01_100.tsv" --bogus=1
expect_error "--column: missing value" "$STAT" ks "$REF/u01_100.tsv" --column
expect_error "--uniform: needs 2 values" "$STAT" ks "$REF/u01_100.tsv" --uniform 0
expect_error "--csv: takes no value" "$STAT" ks "$REF/u01_100.tsv" --csv=yes

# ---- distances that are not finite ---------------------------------------------
# Where scipy's pdist gives inf or NaN (Bray-Curtis of x and -x, cosine of a
# zero row, correlation of a constant row) its linkage refuses; so does every
# linkage here, with the pair named (complete, average and weighted used to
# corrupt the heap: exit 134). Where scipy's distance is finite it is given:
# a zero row is at Bray-Curtis distance 1 from the others.
printf 'x\ty\n1\t2\n-1\t-2\n3\t1\n' >"$TMP/b.tsv"
printf 'x\ty\n1\t2\n0\t0\n3\t1\n' >"$TMP/z.tsv"
printf 'x\ty\tz\n0.1\t0.1\t0.1\n1\t2\t3\n3\t1\t2\n' >"$TMP/c.tsv"
for link in single complete average weighted; do
  expect_error "b.tsv: points 1 and 2: the braycurtis distance is x/0" \
    "$STAT" hclust "$TMP/b.tsv" --linkage "$link" --metric braycurtis --clusters 2
  expect_error "z.tsv: points 1 and 2: the cosine distance is 0/0 (point 2 is zero)" \
    "$STAT" hclust "$TMP/z.tsv" --linkage "$link" --metric cosine --clusters 2
  expect_error "c.tsv: points 1 and 2: the correlation distance is 0/0 (point 1 is constant)" \
    "$STAT" hclust "$TMP/c.tsv" --linkage "$link" --metric correlation --clusters 2
  "$STAT" hclust "$TMP/z.tsv" --linkage "$link" --metric braycurtis --clusters 1 --merges "$TMP/zm.tsv" >/dev/null
  if [ "$(tail -n 1 "$TMP/zm.tsv")" = "$(printf '1\t3\t1\t3')" ]; then ok
  else bad "hclust --linkage $link --metric braycurtis with a zero row: $(tr '\n' ' ' <"$TMP/zm.tsv")"; fi
done
# Coordinates of 1e-200: squares underflow; cosine is scale-free and
# Euclidean scales with the points, so the heights are those at 1 (times 1e-200).
printf '1e-200\t-2e-200\n3e-200\t1e-200\n-1e-200\t-1e-200\n' >"$TMP/tiny.tsv"
printf '1\t-2\n3\t1\n-1\t-1\n' >"$TMP/unit.tsv"
for link in single complete; do
  for metric in cosine euclidean; do
    "$STAT" hclust "$TMP/tiny.tsv" --linkage $link --metric $metric --clusters 1 --merges "$TMP/tm.tsv" >/dev/null
    "$STAT" hclust "$TMP/unit.tsv" --linkage $link --metric $metric --clusters 1 --merges "$TMP/um.tsv" >/dev/null
    if awk -v m=$metric 'NR == FNR { h[FNR] = $3; next }
         FNR > 1 { w = m == "cosine" ? h[FNR] : h[FNR] * 1e-200; e = $3 - w; if (e < 0) e = -e
                   if (!(w > 0) || e > 1e-12 * w) bad = 1 } END { exit bad }' "$TMP/um.tsv" "$TMP/tm.tsv"
    then ok; else bad "hclust --linkage $link --metric $metric at 1e-200: $(tr '\n' ' ' <"$TMP/tm.tsv")"; fi
  done
done

# ---- an option the subcommand does not use is refused, not ignored ---------------
U=$REF/u01_100.tsv
expect_error "--bins is for chisq (ks does not use it" "$STAT" ks "$U" --bins 4 --linkage ward
expect_error "--uniform is for ks, kuiper and chisq (gmm does not use it" "$STAT" gmm "$U" --uniform 0 1 --k 1
expect_error "--linkage is for hclust (ks2 does not use it" "$STAT" ks2 "$U" "$U" --linkage ward
expect_error "--k is for gmm (hclust does not use it" "$STAT" hclust "$U" --linkage single --clusters 2 --k 3
expect_error "--metric is for hclust (kuiper does not use it" "$STAT" kuiper "$U" --metric=cosine
expect_error "--dist is for ks and kuiper (chisq does not use it" "$STAT" chisq "$U" --bins 4 --dist norm
expect_error "--merges is for hclust (gmm does not use it" "$STAT" gmm "$U" --k 1 --merges "$TMP/m.tsv"
expect_error "--method is for hclust (chisq does not use it" "$STAT" chisq "$U" --bins 4 --method single
expect_error "--seed is for gmm (ks does not use it" "$STAT" ks "$U" --seed 3
if [ ! -e "$TMP/m.tsv" ]; then ok; else bad "a refused gmm wrote --merges"; fi

# ---- numbers: decimal, and nothing lost to underflow ------------------------------
# A cell of 1e-400 (read as 0 by strtod and numpy) or 0x10 (16) is refused
# with its line and column; a subnormal option value is a finite number.
printf 'x\n0.5\n1e-400\n0.25\n' >"$TMP/under.tsv"
printf 'x\n0.5\n0x10\n0.25\n' >"$TMP/hex.tsv"
expect_error "under.tsv:3: column 'x' holds '1e-400', which underflows to 0" "$STAT" ks "$TMP/under.tsv"
expect_error "hex.tsv:3: column 'x' holds '0x10', which is hexadecimal" "$STAT" kuiper "$TMP/hex.tsv"
expect_error "--shape: '1e-400' underflows to 0" "$STAT" ks "$U" --dist gamma --shape 1e-400
expect_error "--loc: '0x1p3' is hexadecimal" "$STAT" ks "$U" --dist norm --loc 0x1p3
if line=$("$STAT" ks "$U" --dist gamma --shape 1e-308 2>"$TMP/err"); then
  expect_value "$line" n 100 0
else bad "ks --shape 1e-308 (subnormal, finite) refused: $(cat "$TMP/err")"; fi

echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
