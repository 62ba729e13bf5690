#!/usr/bin/env bash
# A bounded libFuzzer run, registered by tests/fuzz/meson.build:
#   run_fuzz.sh FUZZER CORPUS WORKDIR RUNS [libFuzzer options...]
# Runs FUZZER from the seed corpus CORPUS for RUNS executions (-1: until
# another limit such as -max_total_time=S, or a finding) with a fixed
# seed (the same inputs every time for the same build). New inputs go to
# WORKDIR/corpus (never into the committed seed corpus), a crashing input to
# WORKDIR/crash-* (leak-*, timeout-*, oom-*, slow-unit-*): give a WORKDIR in
# /tmp. Exit 77 (skipped) when FUZZER is empty: clang or libFuzzer was absent
# at configure time. OpenImageIO is held to one thread: a run takes one core.
#
# Long runs (release build; `ninja -C build tests/fuzz/fuzz_NAME`), with the
# limits a finding is judged by: 2 GB of memory, 10 s per input.
#   L="-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048"
#   bash tests/fuzz/run_fuzz.sh build/tests/fuzz/fuzz_stats tests/fuzz/corpus/stats \
#     /tmp/fz-stats 1000000 $L
#   bash tests/fuzz/run_fuzz.sh build/tests/fuzz/fuzz_image tests/fuzz/corpus/image \
#     /tmp/fz-image -1 $L -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
#     -max_total_time=3600
# Fork mode (-fork=1: one child process at a time, each fuzzing for a few
# seconds to minutes) keeps going past a finding and counts it; the run
# fails if it counted any. Reached with these limits on 2 cores shared with
# other work, no finding: fuzz_stats (every linkage x metric, every stat
# option) 10^6 executions in 227 s (4,405 per second); fuzz_table 10^6 in
# 69 s, fuzz_options 10^6 in 25 s, fuzz_params 10^6 in 68 s; fuzz_image
# 10^6 in one run of 3,069 s (325 per second: OpenImageIO tries every format
# on a damaged file, decodes up to NL_IMAGE_MAX_EXPANSION times the input's
# 8 KB, and each input's new allocations are checked for leaks), after the
# two inputs it had found joined the corpus (tiff-tiles-length-error,
# tiff-rows-per-strip).
set -euo pipefail
# Outside meson test (longer runs by hand) the same sanitizer options.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$(cd "$(dirname "$0")" && pwd)/lsan.supp}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
export OPENIMAGEIO_THREADS="${OPENIMAGEIO_THREADS:-1}"
fuzzer="$1" corpus="$2" work="$3" runs="$4"; shift 4
if [ -z "$fuzzer" ]; then
  echo "fuzz: clang with libFuzzer not found at configure time (Debian: clang libclang-rt-14-dev)"
  exit 77
fi
if [ ! -d "$corpus" ] || [ -z "$(ls -A "$corpus")" ]; then
  echo "fuzz: no seed corpus in $corpus"
  exit 1
fi
rm -rf "$work"; mkdir -p "$work/corpus"
log="$work/fuzz.log"
# The targets write each input to a file in $TMPDIR: in memory when possible
# (on a disk each write can cost milliseconds: 10x fewer executions).
tmp="$(mktemp -d -p /dev/shm nl_fuzz.XXXXXX 2>/dev/null || mktemp -d -p "$work")"
trap 'rm -rf "$tmp"' EXIT
rc=0
TMPDIR="$tmp" "$fuzzer" -runs="$runs" -seed=1 -max_len=8192 -timeout=20 -rss_limit_mb=2048 \
  -artifact_prefix="$work/" -print_final_stats=1 "$@" "$work/corpus" "$corpus" >"$log" 2>&1 || rc=$?
crash="$(find "$work" -maxdepth 1 \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
  -o -name 'oom-*' -o -name 'slow-unit-*' \) -print -quit)"
if [ "$rc" != 0 ] || [ -n "$crash" ]; then
  tail -n 60 "$log"
  echo "fuzz: $(basename "$fuzzer") failed (exit $rc); reproduce: $fuzzer ${crash:-<input>}"
  exit 1
fi
# Fork mode prints no 'Done' line: its last '#N: cov: ...' line holds the
# executions and the findings it went past (oom/timeout/crash: a/b/c).
if [[ " $* " == *" -fork="* ]]; then
  last="$(grep -E '^#[0-9]+: cov: ' "$log" | tail -n 1 || true)"
  if [ -z "$last" ] || ! [[ "$last" =~ oom/timeout/crash:\ 0/0/0 ]]; then
    tail -n 30 "$log"
    echo "fuzz: $(basename "$fuzzer") fork mode: ${last:-no progress line}"
    exit 1
  fi
  n="${last%%:*}"
  echo "fuzz: $(basename "$fuzzer") fork mode: ${n#\#} runs, no finding ($last)"
  exit 0
fi
# A run that stopped early (or never started) is a failure too.
done_line="$(grep -E '^Done [0-9]+ runs' "$log" || true)"
n="$(printf '%s' "$done_line" | awk '{print $2}')"
if [ -z "$n" ] || [ "$n" -lt "$runs" ]; then
  tail -n 30 "$log"
  echo "fuzz: $(basename "$fuzzer") did not complete $runs runs (${done_line:-no 'Done' line})"
  exit 1
fi
grep -E '^(INFO: Seed|INFO: seed corpus|#[0-9]+ +(INITED|DONE)|stat::|Done )' "$log" || true
echo "fuzz: $(basename "$fuzzer") $done_line"
