#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Builds the benchmarks in a build directory of their own and runs every
# comparison, then prints the ratio tables (benchmarks/ratios.py).
#
# Build: CMAKE_BUILD_TYPE=Release, i.e. -O3 -DNDEBUG, and no -march: Q3 is
# compiled for the same baseline x86-64 (SSE2) that Debian's libGLU, its peer,
# is built for. Its two hot loops pick AVX2 versions at run time where the CPU
# has it, as the installed library does; the *_baseline rows force the SSE2
# versions. Set Q3_BENCH_CXXFLAGS (e.g. -march=x86-64-v3) to compile
# everything for a newer instruction set; the flags are printed with the
# results.
#
# Each round runs every benchmark executable once with
# --benchmark_repetitions=N and random interleaving of the repetitions; the
# Q3 and GLU tessellation processes alternate, so both see the same machine.
# ratios.py pools all repetitions of all rounds and reports medians. Then
# outside.py runs issue 30's two outside programs (q3_bench_public_outside,
# q3_bench_glu_count) in turns, 5 runs each per round.
#
# Usage: benchmarks/run.sh [--build-dir DIR] [--repetitions N] [--rounds R]
#   defaults: <checkout>/build-bench, 5 repetitions, 2 rounds.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source_dir="$(dirname "$here")"
build_dir="$source_dir/build-bench"
repetitions=5
rounds=2
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift 2 ;;
    --repetitions) repetitions="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    *) echo "usage: $0 [--build-dir DIR] [--repetitions N] [--rounds R]" >&2; exit 2 ;;
  esac
done
if [ "$repetitions" -lt 3 ]; then
  echo "run.sh: at least 3 repetitions are needed for a median" >&2
  exit 2
fi

generator=()
if command -v ninja > /dev/null; then generator=(-G Ninja); fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$source_dir" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
    -DQ3_BUILD_TESTS=OFF -DQ3_BUILD_SAMPLES=OFF -DQ3_BUILD_BENCHMARKS=ON \
    -DCMAKE_CXX_FLAGS="${Q3_BENCH_CXXFLAGS:-}" > /dev/null
else
  cmake "$build_dir" -DCMAKE_CXX_FLAGS="${Q3_BENCH_CXXFLAGS:-}" > /dev/null
fi
cmake --build "$build_dir" --target benchmarks

bin="$build_dir/benchmarks"
for exe in q3_bench_tessellate q3_bench_glu q3_bench_glu_patch q3_bench_frame q3_bench_memory q3_bench_mesh q3_bench_model \
           q3_bench_public_outside q3_bench_glu_count; do
  if [ ! -x "$bin/$exe" ]; then
    echo "run.sh: $bin/$exe was not built (is libglu1-mesa-dev installed? see scripts/setup.sh)" >&2
    exit 1
  fi
done

results="$build_dir/results/$(date -u +%Y%m%dT%H%M%SZ)"
mkdir -p "$results"
flags=(--benchmark_repetitions="$repetitions" --benchmark_enable_random_interleaving=true
       --benchmark_out_format=json)

run() { # name round
  echo "  $1" >&2
  "$bin/$1" "${flags[@]}" --benchmark_out="$results/$1-$2.json" > "$results/$1-$2.log" 2>&1
}

for round in $(seq 1 "$rounds"); do
  echo "round $round of $rounds:" >&2
  run q3_bench_tessellate "$round"
  run q3_bench_glu "$round"
  run q3_bench_glu_patch "$round"
  run q3_bench_frame "$round"
  run q3_bench_mesh "$round"
  run q3_bench_model "$round"
done
run q3_bench_memory 1
# Issue 30's outside comparison: its two programs in turns, 5 runs each per round.
echo "  outside.py" >&2
python3 "$here/outside.py" "$build_dir" --runs $((5 * rounds)) > "$results/outside.md"

{
  echo "Date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "Machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), load average now $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "Build: $(grep '^CMAKE_CXX_COMPILER:' "$build_dir/CMakeCache.txt" | cut -d= -f2) Release (-O3 -DNDEBUG) ${Q3_BENCH_CXXFLAGS:-without -march}"
  echo "Command: benchmarks/run.sh --build-dir $build_dir --repetitions $repetitions --rounds $rounds"
  echo "Raw results: $results"
  echo
  python3 "$here/ratios.py" "$results"/*.json
  echo
  echo "### The public path against GLU, measured from outside (issue 30; benchmarks/outside.py)"
  echo
  cat "$results/outside.md"
} | tee "$results/ratios.md"
