#!/usr/bin/env bash
# noiselab patterns: the control patterns written, GNU-style options (nl_opt),
# bad input refused with one line and exit 2.
set -euo pipefail
patterns="$1" out="$3"
rm -rf "$out"; mkdir -p "$out"
"$patterns" "$out/a" --size=16 >"$out/list"
"$patterns" --size 16 "$out/b" >/dev/null
[ "$(wc -l <"$out/list")" -ge 2 ] || { echo "patterns: no files listed"; exit 1; }
for f in "$out"/a/*.png; do cmp "$f" "$out/b/$(basename "$f")"; done
bad() {   # WANT_FRAGMENT ARGS...
  local want="$1"; shift
  local err rc=0
  err="$("$patterns" "$@" 2>&1 >/dev/null)" || rc=$?
  if [ "$rc" -ne 2 ] || [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
    echo "patterns $*: rc=$rc err='$err' (wanted '$want')"; exit 1
  fi
}
bad "--bogus: unknown option" "$out/c" --bogus
bad "--size: missing value" "$out/c" --size
bad "--size: 2 is outside [8, 4096]" "$out/c" --size=2
bad "unexpected argument 'd'" "$out/c" d
bad "missing output folder" --size 16
[ ! -e "$out/c" ]
# DIR is made, its missing parents are not (as render's -o): named, exit 2.
bad "$out/no/such: directory $out/no does not exist" "$out/no/such" --size 16
[ ! -e "$out/no" ]
echo "cli_patterns: ok"
