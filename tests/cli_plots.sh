#!/usr/bin/env bash
# Every curve of every figure is the data its legend says:
#   tests/cli_plots.sh ROOT OUTDIR
# For each ROOT/scripts/gnuplot/NAME-FIG.gp (sweep.gp aside: it draws a
# sweep's merge, not a committed folder) gnuplot runs the script on the
# committed ROOT/results/NAME in table mode (each `set output` becomes
# `set table`, appended, so multiplots and several outputs all land in one
# file) and prints every curve's points; tests/plots.tsv says, per curve,
# what those points are, by a second path: awk expressions over the columns
# of the named TSV (by header name), on the rows a condition selects.
#
# tests/plots.tsv: plot, panel, curve, table, x, y, extra, when, note.
#   plot   the script's file name
#   panel  0-based index of the plot/splot command in the script's output
#          (the panels of a multiplot, the iterations of a loop, in order)
#   curve  the title gnuplot prints, or #N: the N-th curve of the panel
#          (0-based; for untitled curves)
#   table  a file of results/NAME; matrix:FILE for matrix data (each cell a
#          row, with i its column, j its row, v its value, nc the columns);
#          "-" for a function curve with no table; "(not tabulated)" for a
#          curve gnuplot draws but cannot print (pm3d), checked to print
#          no points, so that the day it can its spec must be written
#   x, y   awk expressions: c("name") a column as a number, s("name") as
#          text, r the 0-based data row, nan() an undefined value; x "*"
#          is a function curve: y is evaluated at each abscissa gnuplot
#          sampled (variable x), on the one row `when` selects (or none)
#   extra  the values gnuplot prints between y and the point type (error
#          bars' ylow yhigh, xlow xhigh ylow yhigh; a label; a 3D plot's z),
#          ';'-separated expressions, "*" for one not compared (a colour),
#          "-" for none
#   when   an awk condition selecting the rows, or 1
# A row whose x, y or an extra is undefined (nan(), a NaN or empty cell) is
# left out, as gnuplot leaves out undefined points (type u), which are
# skipped on its side too. Values compare to 1e-7 relative (1e-9 absolute
# near 0): gnuplot is made to print 10 significant digits (every `format`
# of the script becomes %.10g: tics formats also shape the table).
# Fails with one line per curve that differs (its first differing point and
# the count), per curve without a spec row and per spec row whose curve is
# not plotted.
set -euo pipefail
root="$(realpath "${1:?usage: cli_plots.sh ROOT OUTDIR}")"
out="${2:?usage: cli_plots.sh ROOT OUTDIR}"
command -v gnuplot >/dev/null || { echo "plots: no gnuplot (skipped)" >&2; exit 77; }
mkdir -p "$out"
out="$(realpath "$out")"
fail() { printf 'plots: %s\n' "$*" >&2; exit 1; }
# the spec without its comment lines
spec="$out/plots.tsv"
grep -v '^#' "$root/tests/plots.tsv" >"$spec" || fail "$root/tests/plots.tsv: no rows"
head -1 "$spec" | grep -qx $'plot\tpanel\tcurve\ttable\tx\ty\textra\twhen\tnote' ||
  fail "tests/plots.tsv: header is not plot, panel, curve, table, x, y, extra, when, note"
bad="$(awk -F'\t' 'NF != 9 { print "row " FNR ": " NF " cells, wanted 9"; exit }' "$spec")"
[ -z "$bad" ] || fail "tests/plots.tsv: $bad"

# The comparison, one awk per plot: it reads gnuplot's table (ARGV[1]) and
# then, per spec row K (from 1; ev(K) and its metadata written by gen below),
# the TSV.
# shellcheck disable=SC2016  # awk's $ fields, for awk, not for the shell
lib='
BEGIN { FS = "\t"; TOL_REL = 1e-7; TOL_ABS = 1e-9; NPANEL = -1; NC_ = 0; NBAD = 0 }
# ---- gnuplot table: curves of panels
FILENAME == ARGV[1] {
  if (substr($0, 1, 1) != "#") {
    if ($0 ~ /^[ \t]*$/) next
    m_ = ++CN[NC_]; PL[NC_, m_] = $0; T_ = substr($0, length($0))
    PT[NC_, m_] = (CHT[NC_] && (T_ == "i" || T_ == "o" || T_ == "u") && substr($0, length($0) - 1, 1) == " ") ? T_ : "i"
    next
  }
  if ($0 ~ /^# (Curve|Surface) [0-9]+ of [0-9]+/) {
    split($0, W_, " ")
    if (W_[3] + 0 == 0) NPANEL++
    NC_++; CP[NC_] = NPANEL; CK[NC_] = (W_[2] == "Surface" ? 0 : W_[3] + 0)
    CT[NC_] = ""; CN[NC_] = 0; CH[NC_] = 0; CTITLED[NC_] = 0
    next
  }
  if ($0 ~ /^# Curve title: /) {
    T_ = $0; sub(/^# Curve title: "/, "", T_); sub(/"$/, "", T_)
    CT[NC_] = T_; CTITLED[NC_] = 1; next
  }
  if ($0 ~ /^# x /) {
    H_ = $0; sub(/^# /, "", H_); CH[NC_] = split(H_, W_, " "); CHT[NC_] = (W_[CH[NC_]] == "type")
    for (q_ = 1; q_ <= CH[NC_]; q_++) CHN[NC_, q_] = W_[q_]
    next
  }
  next
}
# point m of curve cv into TK[1..NT], its type left out
function point(cv, m) {
  tokens(PL[cv, m])
  if (CHT[cv] && NT > 0 && TK[NT] == PT[cv, m] && NT == CH[cv]) NT--
}
# split a table line on blanks, a "quoted label" as one token
function tokens(line,   rest, p) {
  if (!index(line, "\"")) { NT = split(line, TK, " "); return }
  NT = 0; rest = line
  while (1) {
    sub(/^[ \t]+/, "", rest)
    if (rest == "") break
    if (substr(rest, 1, 1) == "\"") {
      p = index(substr(rest, 2), "\""); TK[++NT] = substr(rest, 2, p - 1); rest = substr(rest, p + 2)
    } else {
      p = match(rest, /[ \t]/); if (!p) { TK[++NT] = rest; break }
      TK[++NT] = substr(rest, 1, p - 1); rest = substr(rest, p)
    }
  }
}
# ---- the spec side
function c(name,   t) {
  if (!(name in HD)) { printf "plots: %s: spec row %d (%s): no column \"%s\" in %s\n", PLOT, SK, SC[SK], name, ST[SK] > "/dev/stderr"; ERR = 1; UNDEF = 1; return 0 }
  t = FD[HD[name]]
  if (t == "" || tolower(t) ~ /^[-+]?(nan|inf)/) { UNDEF = 1; return 0 }
  return t + 0
}
function s(name) {
  if (!(name in HD)) { printf "plots: %s: spec row %d (%s): no column \"%s\" in %s\n", PLOT, SK, SC[SK], name, ST[SK] > "/dev/stderr"; ERR = 1; return "" }
  return FD[HD[name]] ""
}
function nan() { UNDEF = 1; return 0 }
function isnum(t) { return t ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
function finite(v) { return v == v && v - v == 0 }
function near(a, b, rel,   d, m) {
  if (a == b) return 1
  d = a - b; if (d < 0) d = -d
  m = (a < 0 ? -a : a); if ((b < 0 ? -b : b) > m) m = (b < 0 ? -b : b)
  return d <= TOL_ABS || d <= rel * m
}
# one value: printed token against the expected value (a number or a text);
# an image pixel is printed with 6 digits (%g) whatever the format
function same(tok, val, name,   rel) {
  if (val == "*") return 1
  rel = (name == "pixel" ? 1e-5 : TOL_REL)
  if (val == val + 0) return tok ~ /^[-+]?[.0-9]/ && near(tok + 0, val + 0, rel)
  return tok "" == val ""
}
function load_header(file,   line, n, k) {
  split("", HD)
  if ((getline line < file) <= 0) { printf "plots: %s: cannot read %s\n", PLOT, file > "/dev/stderr"; ERR = 1; return 0 }
  n = split(line, W_, "\t"); for (k = 1; k <= n; k++) HD[W_[k]] = k
  return n
}
# the expected points of spec row k into EX[n, 0..] (0: count of values)
function expect_rows(k,   file, line, n, nf, q) {
  n = 0; r = -1; NROW = 0; split("", ORD); NORD = 0; split("", CMAX)
  if (ST[k] == "-") return 0
  if (ST[k] ~ /^matrix:/) {
    file = DIR "/" substr(ST[k], 8)
    nc = load_header(file); j = -1
    while ((getline line < file) > 0) {
      if (line ~ /^#/ || line ~ /^[ \t]*$/) continue
      j++; nf = split(line, FD, "\t"); nc = nf
      for (i = 0; i < nf; i++) {
        v = FD[i + 1]; r++
        if (v == "" || tolower(v) ~ /^[-+]?(nan|inf)/) continue
        v += 0; UNDEF = 0
        if (!ev(k)) continue
        n = keep(n)
      }
    }
    close(file); return n
  }
  file = DIR "/" ST[k]
  load_header(file)
  while ((getline line < file) > 0) if (line !~ /^#/ && line !~ /^[ \t]*$/) ROW[NROW++] = line
  close(file)
  for (r = 0; r < NROW; r++) {
    split(ROW[r], FD, "\t"); UNDEF = 0
    if (!ev(k)) continue
    n = keep(n)
  }
  return n
}
# helpers for the spec: a ratio (undefined over 0), the 0-based rank of a
# key by first appearance among the rows this spec row selected so far, the
# largest value of a column over the table, Poisson p(m), arcsine
function div(a, b) { if (b == 0) return nan(); return a / b }
function ord(key) { if (!(key in ORD)) ORD[key] = NORD++; return ORD[key] }
function colmax(name,   q, t, m, F2) {
  if (name in CMAX) return CMAX[name]
  if (!(name in HD)) return c(name)
  m = ""
  for (q = 0; q < NROW; q++) { split(ROW[q], F2, "\t"); t = F2[HD[name]] + 0; if (m == "" || t > m) m = t }
  CMAX[name] = m; return m
}
function pois(m, lambda,   q, p) { p = exp(-lambda); for (q = 1; q <= m; q++) p *= lambda / q; return p }
function asin(z) { return atan2(z, sqrt(1 - z * z)) }
function keep(n,   q) {
  if (UNDEF || !finite(XE) || !finite(YE)) return n
  for (q = 1; q <= NE; q++) if (EE[q] != "*" && isnum(EE[q] "") && !finite(EE[q] + 0)) return n
  n++; EX[n, 1] = XE; EX[n, 2] = YE
  for (q = 1; q <= NE; q++) EX[n, 2 + q] = EE[q]
  EX[n, 0] = 2 + NE
  return n
}
# the one row a function curve reads its constants from (or none)
function one_row(k,   file, line, n, keepl) {
  if (ST[k] == "-") { split("", HD); split("", FD); return 1 }
  file = DIR "/" ST[k]; load_header(file); n = 0
  while ((getline line < file) > 0) {
    if (line ~ /^#/ || line ~ /^[ \t]*$/) continue
    split(line, FD, "\t"); UNDEF = 0
    if (SW_(k)) { n++; keepl = line }
  }
  close(file)
  if (n != 1) { printf "plots: %s panel %d curve %s: when selects %d rows of %s, wanted 1 for a function curve\n", PLOT, SP[k], SC[k], n, ST[k] > "/dev/stderr"; ERR = 1; return 0 }
  split(keepl, FD, "\t"); return 1
}
function report(k, msg) { printf "plots: %s panel %d curve %s: %s\n", PLOT, SP[k], SC[k], msg > "/dev/stderr"; NBAD++ }
function fmtpt(cv, m,   q, t) {
  t = PL[cv, m]; sub(/^[ \t]+/, "", t)
  return t
}
function fmtex(m,   q, t) {
  t = ""; for (q = 1; q <= EX[m, 0]; q++) t = t (q > 1 ? " " : "") (isnum(EX[m, q] "") ? sprintf("%.10g", EX[m, q]) : EX[m, q])
  return t
}
function check(k,   cv, found, a, m, n, q, nd, first, ok, exp_u) {
  SK = k; found = 0
  for (a = 1; a <= NC_; a++) {
    if (CP[a] != SP[k]) continue
    if (SC[k] ~ /^#[0-9]+$/ ? CK[a] == substr(SC[k], 2) + 0 : (CTITLED[a] && CT[a] == SC[k])) { found++; cv = a }
  }
  if (found == 0) { report(k, "not plotted (spec row " k ")"); return }
  if (found > 1) { report(k, found " curves of this title: name it #N"); return }
  if (USED[cv]++) { report(k, "a second spec row for this curve"); return }
  if (ST[k] == "(not tabulated)") {
    if (CH[cv] || CN[cv]) report(k, "spec says not tabulated, gnuplot printed " CN[cv] " points")
    return
  }
  if (!CH[cv]) { report(k, "gnuplot printed no points (a style set table cannot print?)"); return }
  if (CH[cv] - CHT[cv] != 2 + NEXTRA[k]) { report(k, "gnuplot prints " CH[cv] - CHT[cv] " values a point, spec gives " 2 + NEXTRA[k]); return }
  nd = 0; first = ""
  if (SX[k] == "*") {
    if (!one_row(k)) return
    for (m = 1; m <= CN[cv]; m++) {
      point(cv, m); x = TK[1] + 0; UNDEF = 0; ev(k)
      exp_u = UNDEF || !finite(YE)
      if (exp_u) { if (PT[cv, m] != "u") { nd++; if (first == "") first = "point " m ": " fmtpt(cv, m) ", expected undefined" } ; continue }
      ok = PT[cv, m] != "u" && same(TK[2], YE, "y")
      for (q = 1; ok && q <= NE; q++) ok = same(TK[2 + q], EE[q], CHN[cv, 2 + q])
      if (!ok) { nd++; if (first == "") first = "point " m ": " fmtpt(cv, m) " (" PT[cv, m] "), expected y " sprintf("%.10g", YE) }
    }
  } else {
    split("", EX); n = expect_rows(k); m = 0
    for (a = 1; a <= CN[cv]; a++) {
      if (PT[cv, a] == "u") continue
      m++
      if (m > n) { nd++; if (first == "") first = "point " m ": " fmtpt(cv, a) ", not in the table"; continue }
      point(cv, a); ok = (NT == EX[m, 0])
      for (q = 1; ok && q <= EX[m, 0]; q++) ok = same(TK[q], EX[m, q], CHN[cv, q])
      if (!ok) { nd++; if (first == "") first = "point " m ": " fmtpt(cv, a) ", expected " fmtex(m) }
    }
    if (m < n) { nd += n - m; if (first == "") first = "point " m + 1 ": missing, expected " fmtex(m + 1) }
    if (m != n) first = m " points plotted, " n " in the table; " first
  }
  if (nd) report(k, nd " points differ; " first)
}
END {
  for (k = 1; k <= NSPEC; k++) check(k)
  for (a = 1; a <= NC_; a++) if (!USED[a]) {
    printf "plots: %s panel %d curve #%d (title \"%s\"): plotted, no spec row\n", PLOT, CP[a], CK[a], CT[a] > "/dev/stderr"; NBAD++
  }
  if (ERR) NBAD++
  exit (NBAD > 0)
}
'

# awk source for the spec rows of plot $1: their metadata and ev(k), which
# sets XE, YE, EE[1..NE] on the current row (or at the abscissa x) and
# returns 0 when `when` rejects it; SW_(k) is `when` alone.
gen() {
  awk -F'\t' -v plot="$1" '
    function esc(t) { gsub(/\\/, "\\\\", t); gsub(/"/, "\\\"", t); return t }
    NR == 1 || $1 != plot { next }
    {
      k++
      meta = meta sprintf("SP[%d] = %d; SC[%d] = \"%s\"; ST[%d] = \"%s\"; SX[%d] = \"%s\"\n", k, $2, k, esc($3), k, esc($4), k, esc($5))
      if ($4 == "(not tabulated)") next
      ne = ($7 == "-" ? 0 : split($7, E, ";"))
      meta = meta sprintf("NEXTRA[%d] = %d\n", k, ne)
      body = body sprintf("  if (k == %d) {\n    if (!(%s)) return 0\n    UNDEF = 0\n", k, $8)
      if ($5 != "*") body = body sprintf("    XE = (%s)\n", $5)
      body = body sprintf("    YE = (%s)\n    NE = %d\n", $6, ne)
      for (q = 1; q <= ne; q++) {
        e = E[q]; gsub(/^ +| +$/, "", e)
        body = body (e == "*" ? sprintf("    EE[%d] = \"*\"\n", q) : sprintf("    EE[%d] = (%s)\n", q, e))
      }
      body = body "    return 1\n  }\n"
      when = when sprintf("  if (k == %d) return (%s)\n", k, $8)
    }
    END {
      printf "BEGIN {\nNSPEC = %d\n%s}\n", k, meta
      printf "function ev(k) {\n%s  return 0\n}\n", body
      printf "function SW_(k) {\n%s  return 0\n}\n", when
    }' "$spec"
}

status=0 nplots=0 ncurves=0
for gp in "$root"/scripts/gnuplot/*.gp; do
  fig="${gp##*/}"; fig="${fig%.gp}"
  [ "$fig" != sweep ] || continue
  name="${fig%%-*}"
  dir="$root/results/$name"
  [ -d "$dir" ] || { echo "plots: $fig.gp: no folder $dir" >&2; status=1; continue; }
  tab="$out/$fig.table" script="$out/$fig.gp"
  : >"$tab"
  # pngcairo -> no terminal (the table is all), outputs -> one table,
  # every format -> 10 digits
  {
    printf "set terminal unknown\nset format '%%.10g'\n"
    sed -E -e "/^[[:space:]]*set terminal /d" \
           -e "s|^([[:space:]]*)set output .*|\\1set table '$tab' append|" \
           -e "s/format( [a-z0-9]+)? *(\"[^\"]*\"|'[^']*')/format\\1 '%.10g'/g" "$gp"
  } >"$script"
  if ! gnuplot -e "dir='$dir'" "$script" 2>"$out/$fig.log"; then
    echo "plots: $fig.gp failed in table mode: $(grep -v -e '^WARNING: Plotting with an' -e '^No output will be' "$out/$fig.log" | head -3 | tr '\n' ' ')" >&2
    status=1; continue
  fi
  nplots=$((nplots + 1))
  ncurves=$((ncurves + $(grep -cE '^# (Curve|Surface) [0-9]+ of' "$tab" || true)))
  gen "$fig.gp" >"$out/$fig.awk"
  cat "$out/$fig.awk" - >"$out/$fig.prog.awk" <<<"$lib"
  awk -v PLOT="$fig.gp" -v DIR="$dir" -f "$out/$fig.prog.awk" "$tab" || status=1
done
# spec rows of plots that are not there
missing="$(cd "$root/scripts/gnuplot" && awk -F'\t' 'NR > 1 { if ((getline t < $1) < 0) print $1; close($1) }' "$spec" | sort -u)"
[ -z "$missing" ] || { echo "plots: spec rows for scripts that are not there: $missing" >&2; status=1; }
echo "plots: $nplots plots, $ncurves curves checked against $(($(wc -l <"$spec") - 1)) spec rows" >&2
exit "$status"
