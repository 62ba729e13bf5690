#!/usr/bin/env bash
# REPORT.md's answer adds up (scripts/noiselab, verdict_table): write_report
# on a small fixture (three experiment folders with hand-made verdicts.tsv,
# among them a failed fitted row and a failed selected row), then
#  - the experiment lines, summed per counted word, equal the headline's
#    counts, and their "not counted" rows summed per kind equal the "Not
#    counted above" line;
#  - the per-paper table's rows, summed, equal the headline, and each
#    paper's row equals the sum of its experiments' lines;
#  - the failed fitted and selected rows appear under "not counted" with
#    their kind only, never counted as "partly" or "not reproduced", and in
#    report.html with a colour that is not a counted verdict's;
#  - the paper -> program -> output table has one row per experiment, with
#    the manifest's outputs.
# The same sums then hold on a report write_report makes from the committed
# results/ (its verdicts, manifests and sections copied), and on the
# committed results/REPORT.md and results/quick/REPORT.md once they have the
# per-paper table.
# Args: NOISELAB_SCRIPT OUTDIR.
set -euo pipefail
nl="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" out="$2"
root="$(cd "$(dirname "$nl")/.." && pwd)"
rm -rf "$out"; mkdir -p "$out"
for v in $(env | sed -n 's/^\(NL_[A-Za-z0-9_]*\)=.*/\1/p'); do unset "$v"; done
fail() { echo "cli_report: $*"; exit 1; }
write_report() { SOURCE_DATE_EPOCH=86400 bash -c 'source "$1"; write_report "$2"' _ "$nl" "$1" 2>"$out/write.log" ||
                   { cat "$out/write.log"; fail "write_report $1 failed"; }; }

# report_sums REPORT.md: prints nothing when every sum holds, else what differs.
report_sums() {
  awk '
    function words(s, into, key,   t, n, w) {   # "**3 reproduced**, **1 partly**" -> into[key, word] += n
      while (match(s, /\*\*[0-9]+ [a-z ]+\*\*/)) {
        t = substr(s, RSTART + 2, RLENGTH - 4); s = substr(s, RSTART + RLENGTH)
        n = t; sub(/ .*/, "", n); w = t; sub(/^[0-9]+ /, "", w); into[key, w] += n } }
    /^[0-9]+ independent verdicts \(/ {
      h = $0; sub(/.*: /, "", h); n = split(h, part, ", ")
      for (i = 1; i <= n; i++) { w = part[i]; sub(/[.]$/, "", w); c = w; sub(/ .*/, "", c); sub(/^[0-9]+ /, "", w); head[w] = c }
      nhead = 1 }
    /^Not counted above: / {
      h = $0; sub(/^Not counted above: /, "", h)
      if (match(h, /[0-9]+ fitted/)) nc["fitted"] = substr(h, RSTART, RLENGTH) + 0
      if (match(h, /[0-9]+ selected/)) nc["selected"] = substr(h, RSTART, RLENGTH) + 0
      if (match(h, /[0-9]+ equal to the paper by construction/)) nc["by construction"] = substr(h, RSTART, RLENGTH) + 0
      if (match(h, /[0-9]+ qualitative/)) nc["qualitative"] = substr(h, RSTART, RLENGTH) + 0 }
    /^\| paper \| reproduced \| partly \| not reproduced \|/ { intab = 1; next }
    intab && /^\|---/ { next }
    intab && /^\|/ { np++; split($0, f, "|"); pr += f[3]; ppa += f[4]; pno += f[5]
                     name = f[2]; sub(/^ *\*\*/, "", name); sub(/\*\*.*/, "", name); paper[np] = name
                     prow[name, "reproduced"] = f[3] + 0; prow[name, "partly"] = f[4] + 0; prow[name, "not reproduced"] = f[5] + 0
                     next }
    intab { intab = 0 }
    /^### Each experiment, by paper/ { inexp = 1; next }
    inexp && /^<\/div>/ { inexp = 0 }
    inexp && /^#### / { cur = $0; sub(/^#### /, "", cur); sub(/:.*/, "", cur); next }
    inexp && /^- \[/ {
      nexp++; line = $0; sub(/^- \[[^]]*\]\([^)]*\): /, "", line)
      counted = line; rest = ""
      if (index(line, "not counted: ")) { counted = substr(line, 1, index(line, "not counted: ") - 1)
                                          rest = substr(line, index(line, "not counted: ") + 13) }
      if (rest ~ /partly|not reproduced/) bad = bad "a counted word among the rows not counted: " $0 "\n"
      words(counted, ex, "all"); words(counted, ex, cur)
      n = split(rest, part, ", ")
      for (i = 1; i <= n; i++) if (match(part[i], /^[0-9]+ (fitted|selected|by construction|qualitative)/)) {
        k = part[i]; c = k; sub(/ .*/, "", c); sub(/^[0-9]+ /, "", k); sub(/ \(.*/, "", k); kind[k] += c } }
    END {
      if (!nhead) bad = bad "no headline\n"
      if (!np) bad = bad "no per-paper table\n"
      if (!nexp) bad = bad "no experiment lines\n"
      split("reproduced|partly|not reproduced", cw, "|")
      for (i = 1; i <= 3; i++) if (ex["all", cw[i]] + 0 != head[cw[i]] + 0)
        bad = bad sprintf("experiment lines: %d %s, headline %d\n", ex["all", cw[i]], cw[i], head[cw[i]])
      if (pr != head["reproduced"] || ppa != head["partly"] || pno != head["not reproduced"])
        bad = bad sprintf("paper rows: %d/%d/%d, headline %d/%d/%d\n", pr, ppa, pno,
                          head["reproduced"], head["partly"], head["not reproduced"])
      for (j = 1; j <= np; j++) for (i = 1; i <= 3; i++)
        if (prow[paper[j], cw[i]] != ex[paper[j], cw[i]] + 0)
          bad = bad sprintf("paper %s: %d %s, its experiments %d\n", paper[j], prow[paper[j], cw[i]], cw[i], ex[paper[j], cw[i]])
      split("fitted|selected|by construction|qualitative", ks, "|")
      for (i = 1; i <= 4; i++) if (kind[ks[i]] + 0 != nc[ks[i]] + 0)
        bad = bad sprintf("experiment lines: %d %s not counted, the line above %d\n", kind[ks[i]], ks[i], nc[ks[i]])
      printf "%s", bad }' "$1"
}

# The fixture: S4 and A2 (two papers) and C5, with the layout a run leaves.
fx="$out/fixture"
folder() {   # NAME TITLE OUTPUT... ; verdict rows on stdin
  mkdir -p "$fx/$1"
  { printf 'key\tvalue\nexperiment\t%s\nseed\t1\nseeds\t2\nquick\tyes\nseconds\t0.1\n' "$1"
    local o; for o in "${@:3}"; do printf 'output\t%s\n' "$o"; done; } >"$fx/$1/manifest.tsv"
  printf '## %s\n\nThe section.\n' "$2" >"$fx/$1/report.md"
  { printf 'quantity\tsource\tpaper\tours\tours_sd\trule\tkind\tverdict\treason\tcontrol\tcontrol_ours\tcontrol_verdict\n'; cat; } >"$fx/$1/verdicts.tsv"
}
folder s4_marble "S4 - Marble" panels.png bend.tsv report.md verdicts.tsv <<'EOF'
gain	x.tsv:g	2	2.08	0.01	rel 0.05 0.25	independent	reproduced	why	a flat image	0.9	not reproduced
bend	x.tsv:b	2	3	-	rel 0.05 0.25	independent	not reproduced	why	a flat image	0.9	not reproduced
slope	x.tsv:s	2	9	-	rel 0.05 0.25	fitted 2/4	not consistent after fit	fit	-	-	-
veins	panels.png	veins	panels.png	-	-	qualitative	see figure	the figure decides	-	-	-
EOF
folder a2_raymarch "A2 - Ray marching" timing.tsv <<'EOF'
ratio	t.tsv:r	3	3.5	-	rel 0.1 0.25	independent	partly	why	plain	1	not reproduced
speed	t.tsv:s	3	3.5	-	rel 0.1 0.25	fitted 1/6	partly consistent after fit	fit	-	-	-
EOF
folder c5_pools "C5 - Pools" pools.tsv aic.tsv <<'EOF'
K	p.tsv:k	30	31	-	rel 0.05 0.25	independent	reproduced	why	random	3	not reproduced
AIC	p.tsv:a	-15079449	-9000000	-	rel 0.05 0.25	selected 1/8	not consistent after selection	closest	-	-	-
F_inf	p.tsv:f	1	1	-	abs 0 0	by construction	by construction	set	-	-	-
EOF
write_report "$fx"
r="$fx/REPORT.md"
[ -f "$r" ] || fail "no REPORT.md from the fixture"
grep -q '^4 independent verdicts (.*): 2 reproduced, 1 partly, 1 not reproduced\.$' "$r" ||
  fail "headline: $(grep 'independent verdicts' "$r")"
bad="$(report_sums "$r")"; [ -z "$bad" ] || fail "fixture: $bad"
# the failed fitted and selected rows: under "not counted" with their kind
grep -qxF -- '- [S4 - Marble](#s4_marble): **1 reproduced**, **1 not reproduced**; not counted: 1 fitted (0 consistent), 1 qualitative' "$r" ||
  fail "S4's line: $(grep -F '(#s4_marble):' "$r")"
grep -qxF -- '- [A2 - Ray marching](#a2_raymarch): **1 partly**; not counted: 1 fitted (0 consistent)' "$r" ||
  fail "A2's line: $(grep -F '(#a2_raymarch):' "$r")"
grep -qxF -- '- [C5 - Pools](#c5_pools): **1 reproduced**; not counted: 1 selected (0 consistent), 1 by construction' "$r" ||
  fail "C5's line: $(grep -F '(#c5_pools):' "$r")"
grep -qF '| slope | fitted 2/4 | 2 | 9 | **not consistent after fit** |' "$r" || fail "the fitted row: $(grep -F '| slope |' "$r")"
# per paper: its citation, its counts, its sentence (the rule, not the paper, picks it)
grep -qE '^\| \*\*Shaffer\*\* Eric Shaffer\. .* \| 1 \| 0 \| 1 \| 1 fitted \(0 consistent\), 1 qualitative \| .* \| Mixed: ' "$r" ||
  fail "Shaffer's row: $(grep -F '**Shaffer**' "$r")"
grep -qE '^\| \*\*Arnerin 2009\*\* Reynald Arnerin\. .* \| 0 \| 1 \| 0 \| .* \| Mixed: of 1 counted verdict, 0 reproduced, 1 partly, 0 not reproduced\. \|$' "$r" ||
  fail "Arnerin's row: $(grep -F '**Arnerin' "$r")"
grep -qE '^\| \*\*Cheng 2009\*\* .* \| Every counted number reproduces: 1 of 1\. \|$' "$r" ||
  fail "Cheng's row: $(grep -F '**Cheng' "$r")"
at() { grep -n -m1 -- "$1" "$r" | cut -d: -f1; }
[ "$(at '^| paper |')" -lt "$(at '(#s4_marble):')" ] || fail "the per-paper table is below the experiment lines"
if ! { [ "$(at '^#### Shaffer')" -lt "$(at '(#s4_marble):')" ] && [ "$(at '^#### Cheng')" -lt "$(at '(#c5_pools):')" ] &&
        [ "$(at '(#c5_pools):')" -lt "$(at '^#### Arnerin')" ]; }; then
  fail "experiment lines not under their paper"
fi
# the paper -> program -> output map: every experiment, its item and outputs
# shellcheck disable=SC2016  # the backquotes are Markdown, not a command
grep -qF '| [S4](#s4_marble) | slides: marble through a colour ramp | `experiments/s4_marble/main.c` -> `build/experiments/s4_marble` | `panels.png`, `bend.tsv` |' "$r" ||
  fail "S4's program row: $(grep -F '| [S4](#s4_marble) | slides' "$r")"
grep -qF '| [C5](#c5_pools) | sec 3.5, Tables 4.2-4.4 |' "$r" || fail "C5's program row"
# report.html: the failed fit is not coloured as a failed verdict
h="$out/report.txt"; tr '\n' ' ' <"$fx/report.html" >"$h"
grep -qF '<span class="verdict v-fit-not"><strong>not consistent after fit</strong></span>' "$h" ||
  fail "report.html: $(grep -oE '<span[^>]*><strong>[^<]*after fit' "$h" | head -3)"
grep -qF '<span class="verdict v-fit-partly"><strong>partly consistent after fit</strong></span>' "$h" ||
  fail "report.html: partly consistent after fit"
grep -qF '<span class="verdict v-fit-not"><strong>not consistent after selection</strong></span>' "$h" ||
  fail "report.html: not consistent after selection"

# The sums can fail: a line that counts a fitted row as "not reproduced".
sed 's/^\(- \[S4 - Marble\](#s4_marble): \*\*1 reproduced\*\*, \*\*1 not reproduced\*\*\); not counted: 1 fitted (0 consistent)/\1, **1 not reproduced**; not counted:/' "$r" >"$out/bad.md"
cmp -s "$r" "$out/bad.md" && fail "the broken copy is unchanged"
[ -n "$(report_sums "$out/bad.md")" ] || fail "a summary line that counts a fitted row passed the sums"

# The same sums on a report of the committed results (at paper scale).
cr="$out/committed"
for d in "$root"/results/*/; do
  e="$(basename "$d")"
  [ -f "$d/manifest.tsv" ] || continue
  mkdir -p "$cr/$e"
  cp "$d/manifest.tsv" "$d/report.md" "$cr/$e/"
  [ ! -f "$d/verdicts.tsv" ] || cp "$d/verdicts.tsv" "$cr/$e/"
done
write_report "$cr"
bad="$(report_sums "$cr/REPORT.md")"; [ -z "$bad" ] || fail "committed results: $bad"
grep -q 'Arnerin' "$cr/REPORT.md" || fail "committed results: the report does not name Arnerin"
# And on the committed REPORT.md files themselves, once a rerun wrote them
# with the per-paper table (a report of the earlier layout has no such table).
for f in "$root/results/REPORT.md" "$root/results/quick/REPORT.md"; do
  grep -q '^### Did each paper reproduce?' "$f" || { echo "cli_report: $f predates the per-paper table: not summed"; continue; }
  bad="$(report_sums "$f")"; [ -z "$bad" ] || fail "$f: $bad"
done
echo "REPORT.md: the lines, the papers and the headline agree"
