#!/usr/bin/env bash
# blas-spread.sh - measure how far every table of an experiment moves when
# only the CPU-dependent parts of the computation change: the OpenBLAS
# kernel (OpenBLAS picks one per CPU at load time), BLAS's thread count, and
# glibc's libm variants (exp, log, pow, sin have FMA versions chosen per CPU).
# Its output, data/blas_spread.tsv, is what the experiments' regression
# tolerances are set from (nl_harness_check_measured in src/harness/nl_harness.h).
#
#   bash bench/blas-spread.sh [--quick] [--out DIR] [--configs A,B,...] EXPERIMENT...
#
# A measurement made by hand, never by tests, CI or the entry script: it is
# the one place where OPENBLAS_CORETYPE is set (README, "Experiments", on the measured tolerances: some CPUs need
# the value their machine sets). The kernels tried are those this CPU can
# run; on a CPU without AVX-512 drop SkylakeX and Zen from CONFIGS.
#
# Each configuration reruns the experiment with the seed of its committed
# reference (results/NAME or results/quick/NAME), then for every numeric
# cell the range over configurations, (max - min) / max(|max|, |min|), is
# taken and its largest value kept, per table and column (columns the experiment declares `ignore`,
# timings, are skipped). Rows of the output (appended, replacing earlier rows
# of the same experiment and scale):
#   experiment scale table column max_rel_spread max_abs_spread cells_differing cells configs
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$ROOT/build"
quick=0 out="$BUILD/blas-spread" names=() only=""
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --out) out="$2"; shift ;;
    --configs) only=",$2,"; shift ;;   # e.g. Prescott,Haswell,Haswell-nofma-libm
    -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) names+=("$1") ;;
  esac
  shift
done
[ ${#names[@]} -gt 0 ] || { echo "blas-spread: name at least one experiment" >&2; exit 2; }
scale=full ref="$ROOT/results"
[ "$quick" = 1 ] && { scale=quick; ref="$ROOT/results/quick"; }

# name|environment (env -u/-i words). "default" is what the machine picks
# with neither variable set (on a Cooper Lake CPU: Cooperlake, which
# cannot be chosen by name in OpenBLAS 0.3.21).
CONFIGS=(
  "Prescott|OPENBLAS_CORETYPE=Prescott"
  "Core2|OPENBLAS_CORETYPE=Core2"
  "Nehalem|OPENBLAS_CORETYPE=Nehalem"
  "Sandybridge|OPENBLAS_CORETYPE=Sandybridge"
  "Haswell|OPENBLAS_CORETYPE=Haswell"
  "Zen|OPENBLAS_CORETYPE=Zen"
  "SkylakeX|OPENBLAS_CORETYPE=SkylakeX"
  "default|-u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE"
  "Haswell-1thread|OPENBLAS_CORETYPE=Haswell OPENBLAS_NUM_THREADS=1"
  "Haswell-nofma-libm|OPENBLAS_CORETYPE=Haswell GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA,-FMA4,-AVX512F"
)

spread_file="$ROOT/data/blas_spread.tsv"
[ -f "$spread_file" ] || printf 'experiment\tscale\ttable\tcolumn\tmax_rel_spread\tmax_abs_spread\tcells_differing\tcells\tconfigs\n' >"$spread_file"

# Private copies of the programs, so that a rebuild during the measurement
# does not pull a binary from under it.
mkdir -p "$out/bin"
for name in "${names[@]}"; do
  [ -x "$BUILD/experiments/$name" ] || { echo "blas-spread: unknown experiment $name" >&2; exit 2; }
  cp "$BUILD/experiments/$name" "$out/bin/$name"
done

for name in "${names[@]}"; do
  m="$ref/$name/manifest.tsv"
  [ -f "$m" ] || { echo "blas-spread: no reference $m" >&2; exit 2; }
  seed="$(awk -F'\t' '$1 == "seed" {print $2}' "$m")"
  seeds="$(awk -F'\t' '$1 == "seeds" {print $2}' "$m")"
  args=(--seed "$seed" --seeds "$seeds")
  [ "$quick" = 1 ] && args+=(--quick)
  dirs=() labels=()
  for c in "${CONFIGS[@]}"; do
    label="${c%%|*}" envs="${c#*|}"
    [ -z "$only" ] || [[ "$only" == *",$label,"* ]] || continue
    d="$out/$scale/$label/$name"
    rm -rf "$d"; mkdir -p "$d"
    # shellcheck disable=SC2086
    core="$(env $envs OPENBLAS_VERBOSE=2 "$out/bin/$name" --help 2>&1 | awk '/^Core:/ {print $2; exit}')"
    echo "blas-spread: $name ($scale) under $label (kernel ${core:-?})" >&2
    # shellcheck disable=SC2086
    env $envs NL_MEASURING=1 "$out/bin/$name" --out "$d" "${args[@]}" >/dev/null 2>"$d.log" || { cat "$d.log" >&2; exit 1; }
    dirs+=("$d"); labels+=("$label:${core:-?}")
  done
  tmp="$(mktemp)"
  for tf in "${dirs[0]}"/*.tsv; do
    t="$(basename "$tf")"
    case "$t" in manifest.tsv|checks.tsv) continue ;; esac
    files=(); for d in "${dirs[@]}"; do files+=("$d/$t"); done
    awk -F'\t' -v ex="$name" -v scale="$scale" -v table="$t" -v configs="${labels[*]}" \
        -v checks="${dirs[0]}/checks.tsv" '
      BEGIN {
        while ((getline line < checks) > 0) {
          split(line, f, "\t")
          if (f[1] == table && f[3] == "ignore") ign[f[2]] = 1
        }
      }
      FNR == 1 { file++; for (i = 1; i <= NF; i++) name[i] = $i; next }
      {
        for (i = 1; i <= NF; i++) {
          if (name[i] in ign || ("*" in ign)) continue
          key = FNR SUBSEP i
          if (file == 1) {
            if ($i ~ /^[-+]?([0-9]|\.[0-9])/) { num[key] = 1; lo[key] = hi[key] = $i + 0; cells[i]++ }
            continue
          }
          if (!(key in num)) continue
          v = $i + 0
          if (v < lo[key]) lo[key] = v
          if (v > hi[key]) hi[key] = v
          d = hi[key] - lo[key]
          m = (lo[key] < 0 ? -lo[key] : lo[key]); h = (hi[key] < 0 ? -hi[key] : hi[key]); if (h > m) m = h
          r = (m > 0) ? d / m : 0
          if (d > 0 && !(key in differs)) { differs[key] = 1; ndiff[i]++ }
          if (r > rel[i]) rel[i] = r
          if (d > abs_[i]) abs_[i] = d
        }
      }
      END {
        for (i = 1; i in name; i++) if (i in cells)
          printf "%s\t%s\t%s\t%s\t%.3g\t%.3g\t%d\t%d\t%s\n", ex, scale, table, name[i], rel[i] + 0, abs_[i] + 0, ndiff[i] + 0, cells[i], configs
      }' "${files[@]}" >>"$tmp"
  done
  # Replace this experiment's rows at this scale.
  awk -F'\t' -v e="$name" -v s="$scale" 'NR == 1 || !($1 == e && $2 == s)' "$spread_file" >"$spread_file.new"
  cat "$tmp" >>"$spread_file.new"; rm -f "$tmp"
  mv "$spread_file.new" "$spread_file"
  awk -F'\t' -v e="$name" -v s="$scale" '$1 == e && $2 == s && $5 > 0 {printf "  %s %s: rel %s (%s of %s cells)\n", $3, $4, $5, $7, $8}' "$spread_file" >&2
done
