#!/usr/bin/env bash
# The replication package's licence and citation: LICENSE is the GPL version
# 3 that CITATION.cff and the README name; CITATION.cff is valid Citation File
# Format 1.2.0 (the schema in tests/data/cff, checked with Debian's
# python3-jsonschema and python3-yaml; Debian has no cffconvert) and cites, for
# each paper an experiment reproduces, that paper (its author's family name in
# references). The check must also fail: a copy without its title, one with a
# wrong type of reference and one that drops a paper are refused.
# Args: SOURCE_ROOT OUTDIR.
set -euo pipefail
root="$1" out="$2"
fail() { echo "cli_citation: $*"; exit 1; }
py=/usr/bin/python3
"$py" -c 'import jsonschema, yaml' 2>/dev/null || { echo "python3-jsonschema or python3-yaml missing"; exit 77; }
rm -rf "$out"; mkdir -p "$out"

head -n 3 "$root/LICENSE" | grep -q 'GNU GENERAL PUBLIC LICENSE' || fail "LICENSE is not the GPL"
grep -q 'Version 3, 29 June 2007' "$root/LICENSE" || fail "LICENSE is not the GPL version 3"
grep -q 'GPL-3.0-or-later' "$root/README.md" || fail "the README does not name the licence"

# The papers, by the family name of their first author, from the letters of
# the experiments' folders (experiments/LETTERn_name): a new paper must be cited.
letters="$(cd "$root/experiments" && for d in */; do printf '%s\n' "${d:0:1}"; done | sort -u | tr -d '\n')"
[ "$letters" = aclqs ] || fail "experiments of papers '$letters': name the new paper's author below"
authors="Arnerin Cheng Lagae Qin Shaffer"

validate() {   # CFF -> 0 when valid and every author is cited
  "$py" - "$1" "$root/tests/data/cff/schema-1.2.0.json" "$authors" <<'PY'
import json, sys
import jsonschema, yaml
cff = yaml.safe_load(open(sys.argv[1], encoding="utf-8"))
schema = json.load(open(sys.argv[2], encoding="utf-8"))
errors = sorted(jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())
                .iter_errors(cff), key=str)
for e in errors[:3]:
    print("%s: %s" % ("/".join(map(str, e.absolute_path)) or "(top)", e.message))
cited = {a.get("family-names") for r in cff.get("references", []) for a in r.get("authors", [])[:1]}
missing = [a for a in sys.argv[3].split() if a not in cited]
if missing:
    print("no reference by " + ", ".join(missing))
if cff.get("license") != "GPL-3.0-or-later":
    print("license %r, not the LICENSE file's GPL-3.0-or-later" % cff.get("license"))
sys.exit(1 if errors or missing or cff.get("license") != "GPL-3.0-or-later" else 0)
PY
}

validate "$root/CITATION.cff" >"$out/valid.log" 2>&1 || fail "CITATION.cff: $(cat "$out/valid.log")"

# Each broken copy must be refused, for the reason it was broken.
refused() {   # LABEL WANTED SED_SCRIPT
  sed "$3" "$root/CITATION.cff" >"$out/$1.cff"
  if validate "$out/$1.cff" >"$out/$1.log" 2>&1; then fail "$1: accepted"; fi
  grep -q "$2" "$out/$1.log" || fail "$1: refused for another reason: $(cat "$out/$1.log")"
}
refused no-title "'title' is a required property" '/^title:/d'
refused bad-type "is not one of" 's/^  - type: slides/  - type: lecture/'
refused no-lagae "no reference by Lagae" '/family-names: Lagae/,/given-names: Ares/d'
echo "cli_citation: CITATION.cff valid, the five papers cited, LICENSE GPL-3"
