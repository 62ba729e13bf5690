#!/usr/bin/env bash
# arch-spread.sh - how far every table of an experiment moves on arm64:
# each experiment of the arm64 cross build (build-aarch64/, made by
# `scripts/noiselab check --arch aarch64`) runs under qemu-aarch64 with the
# seed of its committed x86-64 reference, --no-images, and every cell of
# every table is compared with the reference's: the same text (the tables
# print doubles with 17 digits, so the same bits), or how far apart.
#
#   bash bench/arch-spread.sh [--quick] [--out DIR] [--compare-only] EXPERIMENT...
#   bash bench/arch-spread.sh [--out DIR] --rows
#   bash bench/arch-spread.sh [--out DIR] --merge
# (--compare-only: the runs already in DIR, compared again; --rows: the
# measured rows in data/blas_spread.tsv's columns, configs "aarch64-qemu",
# on stdout, ignored columns left out; --merge: those rows folded into
# data/blas_spread.tsv, each column's spread the larger of the two and
# "aarch64-qemu:armv8" added to its configs, so the regression check's
# tolerances cover arm64 too; rows of columns not measured here, such as
# every paper-scale one, stay as they are)
#
# A measurement made by hand, like bench/blas-spread.sh: only --merge
# writes under data/, and nothing writes under results/. Rows of DIR/arch-spread.tsv (default DIR:
# build-aarch64/arch-spread; rows of the same experiment and scale are
# replaced), one per table and column:
#   experiment scale table column rule cells identical max_rel max_abs
# rule: the committed checks.tsv's rule for the column (exact when none);
# cells: the numeric cells; identical: those with the reference's text;
# max_rel: the largest |a - b| / max(|a|, |b|). Text cells that differ are
# counted as cells and not identical, with no distance. DIR/check.txt gets
# noiselab-check's verdict on each run (the rules of the committed
# checks.tsv), or that it failed to run. Exit 1 when one failed to run.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
XB="$ROOT/build-aarch64"
quick=0 out="$XB/arch-spread" names=() failed=0 compare_only=0 rows=0 merge=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --compare-only) compare_only=1 ;;
    --rows) rows=1 ;;
    --merge) merge=1 ;;
    --out) out="$2"; shift ;;
    -h|--help) sed -n '2,28p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "arch-spread: unknown option $1" >&2; exit 2 ;;
    *) names+=("$1") ;;
  esac
  shift
done
arch_rows() {
  awk -F'\t' -v OFS='\t' 'NR == 1 {print "experiment", "scale", "table", "column", "max_rel_spread",
      "max_abs_spread", "cells_differing", "cells", "configs"; next}
    $5 != "ignore" {print $1, $2, $3, $4, $8, $9, $6 - $7, $6, "aarch64-qemu:armv8"}' "$out/arch-spread.tsv"
}
if [ "$rows" = 1 ] || [ "$merge" = 1 ]; then
  [ -f "$out/arch-spread.tsv" ] || { echo "arch-spread: no $out/arch-spread.tsv yet" >&2; exit 2; }
  [ "$merge" = 1 ] || { arch_rows; exit 0; }
  data="$ROOT/data/blas_spread.tsv"
  # Columns by name in both files; a row of the arm64 measurement either
  # widens the row of its column or, for a column the x86-64 measurement
  # lacks, is added. The new file replaces the old one only when complete.
  arch_rows | awk -F'\t' -v OFS='\t' '
    FNR == 1 { file++
      split("experiment scale table column max_rel_spread max_abs_spread cells_differing cells configs", need, " ")
      for (k in need) { c[file, need[k]] = 0; for (i = 1; i <= NF; i++) if ($i == need[k]) c[file, need[k]] = i
        if (!c[file, need[k]]) { print "arch-spread: no column " need[k] > "/dev/stderr"; exit 2 } }
      if (file == 2) print
      next }
    function f(n, name) { return $(c[n, name]) }
    file == 1 { key = f(1, "experiment") SUBSEP f(1, "scale") SUBSEP f(1, "table") SUBSEP f(1, "column")
      arel[key] = f(1, "max_rel_spread"); aabs[key] = f(1, "max_abs_spread"); adiff[key] = f(1, "cells_differing")
      arow[key] = $0; order[++na] = key; next }
    { key = f(2, "experiment") SUBSEP f(2, "scale") SUBSEP f(2, "table") SUBSEP f(2, "column")
      if (key in arel) {
        if (arel[key] + 0 > f(2, "max_rel_spread") + 0) $(c[2, "max_rel_spread"]) = arel[key]
        if (aabs[key] + 0 > f(2, "max_abs_spread") + 0) $(c[2, "max_abs_spread"]) = aabs[key]
        if (adiff[key] + 0 > f(2, "cells_differing") + 0) $(c[2, "cells_differing"]) = adiff[key]
        if (index(" " f(2, "configs") " ", " aarch64-qemu:armv8 ") == 0)
          $(c[2, "configs"]) = f(2, "configs") " aarch64-qemu:armv8"
        done[key] = 1
      }
      print }
    END { for (i = 1; i <= na; i++) if (!(order[i] in done)) print arow[order[i]] }
  ' - "$data" >"$data.new" || { rm -f "$data.new"; exit 2; }
  mv "$data.new" "$data"
  echo "arch-spread: merged $(($(wc -l <"$out/arch-spread.tsv") - 1)) measured columns into data/blas_spread.tsv" >&2
  exit 0
fi
[ ${#names[@]} -gt 0 ] || { echo "arch-spread: name at least one experiment" >&2; exit 2; }
command -v qemu-aarch64 >/dev/null || { echo "arch-spread: no qemu-aarch64 (scripts/noiselab check --arch aarch64 installs it)" >&2; exit 2; }
scale=full ref="$ROOT/results"
[ "$quick" = 1 ] && { scale=quick; ref="$ROOT/results/quick"; }
mkdir -p "$out/$scale"
spread="$out/arch-spread.tsv"
[ -f "$spread" ] || printf 'experiment\tscale\ttable\tcolumn\trule\tcells\tidentical\tmax_rel\tmax_abs\n' >"$spread"

for name in "${names[@]}"; do
  exe="$XB/experiments/$name" m="$ref/$name/manifest.tsv"
  [ -x "$exe" ] || { echo "arch-spread: $exe is not built" >&2; exit 2; }
  [ -f "$m" ] || { echo "arch-spread: no reference $m" >&2; exit 2; }
  seed="$(awk -F'\t' '$1 == "seed" {print $2}' "$m")"
  seeds="$(awk -F'\t' '$1 == "seeds" {print $2}' "$m")"
  args=(--seed "$seed" --seeds "$seeds" --no-images)
  [ "$quick" = 1 ] && args+=(--quick)
  d="$out/$scale/$name"
  if [ "$compare_only" = 1 ]; then
    [ -f "$d/manifest.tsv" ] || { echo "arch-spread: no run $d to compare" >&2; exit 2; }
  else
    rm -rf "$d"
    t0=$SECONDS
    echo "arch-spread: $name ($scale) under qemu-aarch64" >&2
    if ! qemu-aarch64 "$exe" --out "$d" "${args[@]}" >/dev/null 2>"$d.log"; then
      cat "$d.log" >&2
      printf 'check: %s: failed to run under qemu (%s)\n' "$name" "$d.log" >>"$out/check.txt"
      failed=$((failed + 1))
      continue
    fi
    echo "arch-spread: $name ran in $((SECONDS - t0)) s" >&2
  fi
  tmp="$(mktemp)"
  for tf in "$ref/$name"/*.tsv; do
    t="$(basename "$tf")"
    case "$t" in manifest.tsv|checks.tsv) continue ;; esac
    awk -F'\t' -v ex="$name" -v scale="$scale" -v table="$t" -v checks="$ref/$name/checks.tsv" '
      BEGIN {
        while ((getline line < checks) > 0) {
          split(line, f, "\t")
          if (f[1] == table) rule[f[2]] = f[3]
          if (f[1] == "*" && !(f[2] in rule)) rule[f[2]] = f[3]
        }
      }
      function isnum(x) { return x ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ || x ~ /^[-+]?(inf|nan)$/ }
      FNR == 1 { file++; if (file == 1) for (i = 1; i <= NF; i++) name[i] = $i; next }
      file == 1 { for (i = 1; i <= NF; i++) ref[FNR, i] = $i; next }
      {
        for (i = 1; i in name; i++) {
          if (!((FNR, i) in ref)) continue
          a = ref[FNR, i]; b = $i
          # compared as strings: awk compares two numeric fields as numbers,
          # and mawk reads 17 digits to the nearest double only roughly
          if (!isnum(a) && "" a == "" b) continue   # a text label
          cells[i]++
          if ("" a == "" b) { same[i]++; continue }
          if (!isnum(a) || !isnum(b)) continue
          d = a - b; if (d < 0) d = -d
          m = (a < 0 ? -a : a); h = (b < 0 ? -b : b); if (h > m) m = h
          r = m > 0 ? d / m : 0
          if (d > abs_[i]) abs_[i] = d
          if (r > rel[i]) rel[i] = r
        }
      }
      END {
        for (i = 1; i in name; i++) if (i in cells) {
          r = name[i] in rule ? rule[name[i]] : ("*" in rule ? rule["*"] : "exact")
          printf "%s\t%s\t%s\t%s\t%s\t%d\t%d\t%.3g\t%.3g\n", ex, scale, table, name[i], r, cells[i], same[i] + 0, rel[i] + 0, abs_[i] + 0
        }
      }' "$tf" "$d/$t" >>"$tmp"
  done
  awk -F'\t' -v e="$name" -v s="$scale" 'NR == 1 || !($1 == e && $2 == s)' "$spread" >"$spread.new"
  cat "$tmp" >>"$spread.new"; rm -f "$tmp"
  mv "$spread.new" "$spread"
  awk -F'\t' -v e="$name" -v s="$scale" '$1 == e && $2 == s {c += $6; i += $7}
    $1 == e && $2 == s && $6 > $7 {printf "  %s %s (%s): %d of %d differ, rel %s\n", $3, $4, $5, $6 - $7, $6, $8}
    END {printf "  %s: %d of %d cells identical\n", e, i, c}' "$spread" >&2
  [ "$compare_only" = 0 ] || continue
  rc=0
  qemu-aarch64 "$XB/tools/noiselab-check" "$ref/$name" "$d" >"$d.check" 2>&1 || rc=$?
  awk -v e="$name" -v rc="$rc" '{print} END {if (rc == 2) print "check: " e ": bad input"}' "$d.check" \
    >>"$out/check.txt"
done
[ "$failed" = 0 ] || { echo "arch-spread: $failed experiment(s) failed to run (above)" >&2; exit 1; }
