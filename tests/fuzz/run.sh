#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Builds the API fuzzer (clang, libFuzzer, AddressSanitizer +
# UndefinedBehaviorSanitizer) in build-fuzz/ and runs it for SECONDS seconds
# (default 60) starting from the seed corpus tests/fuzz/corpus/; then the 3DMF
# reader's fuzzer for Q3_FUZZ_3DMF_SECONDS (default 20) from
# tests/fuzz/corpus-3dmf/. Inputs it
# finds interesting go to build-fuzz/corpus/, never into the repository (copy
# one into tests/fuzz/corpus/ by hand to keep it as a seed); an input that
# crashes, leaks or times out is saved in build-fuzz/findings/ and fails the
# script. Further arguments go to libFuzzer, e.g. -jobs=2 or a finding's
# file name to replay it.
#
# Usage: tests/fuzz/run.sh [SECONDS] [libFuzzer arguments...]
# Environment: Q3_JOBS (build parallelism, default 2), Q3_FUZZ_BUILD_DIR.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
seconds="${1:-60}"
shift || true
build="${Q3_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${Q3_JOBS:-2}"

# -O1 with line tables: what the sanitizers' documentation recommends, enough
# for file:line in every report, and about 15 % less compile time than
# RelWithDebInfo's -O2 -g.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DQ3_BUILD_FUZZERS=ON -DQ3_BUILD_SAMPLES=OFF -DQ3_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build "$build" -j"$jobs" --target q3_fuzz_api q3_fuzz_3dmf q3_fuzz_seeds

mkdir -p "$build/corpus" "$build/corpus-3dmf" "$build/findings"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# -timeout: no input may take this long. The fuzzer stops drawing once its
# draws have taken 2 s, but the draw that crosses that line may be a surface
# at kQ3SubdivisionMaxTrianglesPerSurface, and under AddressSanitizer and
# coverage an attempt that builds a whole cap takes about 12 s on the 2-core
# machine (0.4 s in a Release build); a measured surface may make
# quadric::kMaxDoublings + 1 such attempts, and CI's machine runs about 30 %
# slower. 60 s is above that and still catches a hang.
# -rss_limit_mb: one such surface peaks near 1 GB under AddressSanitizer, on
# top of the fuzzer's own 0.9-1.8 GB (corpus, quarantine), above libFuzzer's
# default 2 GB. New inputs go to the first corpus directory only.
"$build/tests/fuzz/q3_fuzz_api" -max_total_time="$seconds" -timeout=60 -rss_limit_mb=4096 -max_len=4096 \
  -print_final_stats=1 -artifact_prefix="$build/findings/" "$@" \
  "$build/corpus" "$root/tests/fuzz/corpus"

# The 3DMF reader, over files: a short run keeps CI's total fuzz time modest.
"$build/tests/fuzz/q3_fuzz_3dmf" -max_total_time="${Q3_FUZZ_3DMF_SECONDS:-20}" -timeout=10 -max_len=65536 \
  -print_final_stats=1 -artifact_prefix="$build/findings/" \
  "$build/corpus-3dmf" "$root/tests/fuzz/corpus-3dmf"
