#!/usr/bin/env bash
# results/report.html opened in a real browser (Debian's chromium, headless;
# installed by `scripts/noiselab test`): after a quick reproduce of S3 (plots
# and images) and C4 (the verdict table), every figure of the page loads
# (naturalWidth > 0), every in-page link has its target, every relative link
# names a file that exists, and every gnuplot figure has its SVG beside the
# PNG. In a 1280 x 800 window, as a reader sees it (tests/report_probe.js):
# the per-paper table on the first screen, no element past the window's
# right edge (a wide table scrolls inside its own box), no cell cut,
# "reproduced" and "not reproduced" in different colours. The probe must
# also fail: a copy of the page with one figure missing, one without its
# stylesheet, and one with a table of 30 columns whose box does not scroll
# are reported broken, the last naming the widest element.
# Args: NOISELAB_SCRIPT OUTDIR.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$2"
root="$(cd "$(dirname "$nl")/.." && pwd)"
fail() { echo "cli_report_html: $*"; exit 1; }
command -v chromium >/dev/null || { echo "chromium not installed"; exit 77; }
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
rm -rf "$out"; mkdir -p "$out"
r="$out/r"
"$nl" reproduce --quick --out "$r" S3 C4 2>"$out/reproduce.log" || { cat "$out/reproduce.log"; fail "reproduce failed"; }
[ -s "$r/report.html" ] || fail "no report.html"
grep -q '<h2 id="did-it-reproduce">' "$r/report.html" || fail "report.html has no verdict section"

probe() {   # HTML_IN_DIR -> prints the probe's line
  local page="$1" copy
  copy="$(dirname "$page")/.probe-$(basename "$page")"
  { sed 's#</body>##' "$page"; printf '<script>\n'; cat "$root/tests/report_probe.js"; printf '</script>\n</body>\n'; } >"$copy"
  # --no-sandbox: CI runs as root; a fresh profile each time.
  timeout 120 chromium --headless --no-sandbox --disable-gpu --user-data-dir="$out/profile" \
    --window-size=1280,800 --hide-scrollbars --virtual-time-budget=20000 --dump-dom "file://$copy" \
    2>"$out/chromium.log" | grep -oE 'NL-PROBE images=[0-9]+[^<]*' || true
  rm -f "$copy"
}

line="$(probe "$r/report.html")"
[[ "$line" == "NL-PROBE images="*" OK" ]] || { cat "$out/chromium.log" >&2; fail "browser: ${line:-no probe line (page did not load)}"; }
n="$(sed -E 's/.*images=([0-9]+).*/\1/' <<<"$line")"
[ "$n" -ge 5 ] || fail "only $n images on the page"
# relative links to files (figures, tables) exist
grep -oE '(src|href)="[^"#:]+"' "$r/report.html" | sed -E 's/^(src|href)="//; s/"$//' | sort -u | while read -r f; do
  [ -e "$r/$f" ] || fail "report.html links $f, which does not exist"
done
# every gnuplot figure also as SVG
for gp in "$root"/scripts/gnuplot/s3_fbm-*.gp "$root"/scripts/gnuplot/c4_weights-*.gp; do
  f="$(basename "$gp" .gp)"; e="${f%%-*}"; f="${f#*-}"
  [ -s "$r/$e/$f.svg" ] || fail "no $e/$f.svg beside $f.png"
  grep -q '<svg' "$r/$e/$f.svg" || fail "$e/$f.svg is not SVG"
done
# the probe can fail: one figure gone
mkdir -p "$out/broken"
cp -r "$r"/. "$out/broken/"
rm "$out/broken/s3_fbm/gain_spectrum.png"
line="$(probe "$out/broken/report.html")"
[[ "$line" == *"BROKEN: image s3_fbm/gain_spectrum.png"* ]] || fail "a missing figure was not reported: $line"
# the probe can fail: the page without its stylesheet (pandoc's default
# alone) has its verdicts in one colour
sed '/<style id="report-css">/,/<\/style>/d' "$r/report.html" >"$r/bare.html"
grep -q 'v-reproduced {' "$r/bare.html" && fail "the stylesheet was not removed from the copy"
line="$(probe "$r/bare.html")"
rm "$r/bare.html"
[[ "$line" == *"verdicts in one colour"* ]] || fail "a page without its stylesheet was not reported: $line"
# a table of 30 columns of numbers, as an experiment's widest (C5: 23, L3:
# 24) but wider, after the first section: it scrolls in its box and the page
# passes; with the box's rule gone it runs past the window and the probe
# names it
wide="$(printf '<div class="table-wrap widest"><table><tr>'
        for i in $(seq 30); do printf '<td>-15079449.07%02d</td>' "$i"; done
        printf '</tr></table></div>')"
awk -v t="$wide" '{print} /^<h2 id="did-it-reproduce">/ && !done {print t; done = 1}' "$r/report.html" >"$r/wide.html"
line="$(probe "$r/wide.html")"
[[ "$line" == "NL-PROBE images="*" OK" ]] || fail "a wide table in its scrolling box was reported: $line"
sed '/^ *\.table-wrap {$/,/^ *}$/d' "$r/wide.html" >"$r/wide-bare.html"
grep -q '^ *\.table-wrap {' "$r/wide-bare.html" && fail "the .table-wrap rule was not removed from the copy"
line="$(probe "$r/wide-bare.html")"
rm "$r/wide.html" "$r/wide-bare.html"
[[ "$line" == *"widest element "*" (30 columns) wider than the window"* && "$line" == *"page scrolls sideways"* ]] ||
  fail "a table past the window was not reported: $line"
echo "report.html: $n images, links and figures whole"
