#!/bin/bash
# SPDX-License-Identifier: MIT
# Copyright (c) 2026 The Q3 authors
#
# Compares two builds of q3_bench_model on ModelFrame (issue 26, item 8):
# runs them alternately, RUNS times each (3 repetitions a run), and prints
# per run the median per-turn ratio Q3 / raw peer and each side's CPU per
# frame on the calling thread and on llvmpipe's rasterizer threads.
# glibc's heap trimming is switched off for both (benchmarks/RESULTS.md,
# "Third round": the two sides share one heap).
#
# Usage: benchmarks/ab_model.sh A_BINARY B_BINARY [RUNS]
# Exit codes: 0 done; 2 bad arguments.
set -u
if [ $# -lt 2 ] || [ ! -x "$1" ] || [ ! -x "$2" ]; then
    echo "usage: $0 A_BINARY B_BINARY [RUNS]" >&2
    exit 2
fi
export GLIBC_TUNABLES=glibc.malloc.trim_threshold=268435456:glibc.malloc.mmap_threshold=33554432
runs=${3:-3}
for ((i = 0; i < runs; ++i)); do
    for side in A B; do
        binary=$1
        [ "$side" = B ] && binary=$2
        line=$("$binary" --benchmark_filter='ModelFrame/' --benchmark_repetitions=3 \
            --benchmark_report_aggregates_only=true 2>&1 | grep 'real_time_median')
        echo "$side $(echo "$line" | grep -o 'q3_over_raw_median=[0-9.]*\|q3_main_cpu_ms=[0-9.]*\|raw_main_cpu_ms=[0-9.]*\|q3_raster_cpu_ms=[0-9.]*\|raw_raster_cpu_ms=[0-9.]*' | tr '\n' ' ')"
    done
done
